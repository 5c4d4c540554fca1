// `doorplate_eval ocr`: the text-reading experiment (paper Table I, Figure 12) on one world file.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "doorplate_localization/sim/world_loader.h"
#include "eval_args.h"
#include "eval_commands.h"
#include "ocr_eval.h"
#include "ocr_eval_json.h"

namespace doorplate_localization {
namespace {

std::vector<OptionSpec> OcrOptions() {
  std::vector<OptionSpec> specs = CommonOptions();
  specs.push_back({"band", "on", "extractor searches the fixed image band (on) or the full image (off)"});
  specs.push_back({"known-rooms", "off", "give the validator the world's room list (on) or not (off: open vocabulary)"});
  specs.push_back({"ocr-mode", "default", "Tesseract segmentation: line, word, or default (TesseractOcrOptions)"});
  specs.push_back({"detector-every", "1", "run the Figure 12 detector modes on every n-th frame (0: never)"});
  specs.push_back({"max-pass-seconds", "1800", "simulated seconds after which an unfinished sweep ends the pass"});
  return specs;
}

void PrintSummary(const OcrEvalResult& r, const OcrEvalOptions& o) {
  std::printf("world %s: %d pass(es), seed %llu, band %s, known rooms %s, OCR %s, %d frames\n", r.world_name.c_str(),
              o.passes, static_cast<unsigned long long>(o.seed), o.band ? "on" : "off", o.known_rooms ? "on" : "off",
              o.extractor.ocr.line_mode == OcrLineMode::kSingleWord ? "single word" : "single line", r.Frames());
  for (size_t i = 0; i < r.passes.size(); ++i) {
    const OcrPassResult& p = r.passes[i];
    std::printf("  pass %zu: %d/%d plates correct, %d false reads, %d spurious, %d duplicates, %.0f s simulated "
                "in %.0f s%s\n",
                i, p.score.plates_correct, p.score.plates_passed, p.score.false_reads, p.score.spurious,
                p.score.duplicates, p.sim_seconds, p.wall_seconds, p.sweep_done ? "" : " (sweep NOT finished)");
  }
  const int total = r.PlatesTotal();
  std::printf("  accuracy %d/%d = %.1f %%; extractor %.2f ms/frame, %.2f boxes/frame\n", r.PlatesCorrect(), total,
              total > 0 ? 100.0 * r.PlatesCorrect() / total : 0.0, 1000.0 * r.extractor_seconds / std::max(1, r.Frames()),
              static_cast<double>(r.extractor_boxes) / std::max(1, r.Frames()));
  for (const DetectorModeStats& d : r.detectors) {
    if (d.frames == 0) continue;
    std::printf("  figure 12 %-14s %.2f boxes/frame (plate in view %.2f, none %.2f), %.2f ms/frame\n", d.name.c_str(),
                static_cast<double>(d.boxes) / d.frames,
                static_cast<double>(d.boxes_plate_in_view) / std::max(1, d.frames_plate_in_view),
                static_cast<double>(d.boxes - d.boxes_plate_in_view) / std::max(1, d.frames - d.frames_plate_in_view),
                1000.0 * d.seconds / d.frames);
  }
  for (const OcrEvalEvent& e : r.events) {
    std::printf("  %s pass %d t=%.2f s: reported '%s', truth '%s' (%s)%s%s\n", e.kind.c_str(), e.pass, e.stamp_s,
                e.reported.c_str(), e.truth.c_str(), e.plate.c_str(), e.image.empty() ? "" : " -> ", e.image.c_str());
  }
}

}  // namespace

int RunOcrCommand(const std::vector<std::string>& args, const std::string& command_line) {
  EvalArgs parsed("ocr", OcrOptions());
  parsed.Parse(args);
  if (parsed.help_requested()) {
    std::cout << "Text reading on a simulated corridor sweep (paper Table I, Figure 12).\n" << parsed.Usage();
    return 0;
  }
  const CommonArgs common = ReadCommonArgs(parsed);
  OcrEvalOptions options;
  options.passes = common.passes;
  options.seed = common.seed;
  options.speed_mps = common.speed_mps;
  options.dump_dir = common.dump_dir;
  options.band = parsed.OnOff("band");
  options.known_rooms = parsed.OnOff("known-rooms");
  const std::string ocr_mode = parsed.String("ocr-mode");
  if (ocr_mode == "line") {
    options.extractor.ocr.line_mode = OcrLineMode::kSingleLine;
  } else if (ocr_mode == "word") {
    options.extractor.ocr.line_mode = OcrLineMode::kSingleWord;
  } else if (ocr_mode != "default") {
    throw UsageError("ocr: --ocr-mode: '" + ocr_mode + "' must be line, word or default");
  }
  options.detector_every_n_frames = parsed.Integer("detector-every", 0);
  options.max_pass_time_s = parsed.Number("max-pass-seconds");
  if (options.max_pass_time_s <= 0) throw UsageError("ocr: --max-pass-seconds must be > 0");

  if (!common.json_path.empty()) {
    const std::filesystem::path parent = std::filesystem::path(common.json_path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent)) {
      throw UsageError("ocr: --json: folder " + parent.string() + " does not exist");
    }
  }
  const World world = LoadWorldFile(common.world_path);
  const OcrEvalResult result = RunOcrEval(world, options);
  PrintSummary(result, options);
  if (!common.json_path.empty()) {
    std::ofstream out(common.json_path);
    if (!out) throw std::runtime_error("cannot write " + common.json_path);
    JsonWriter json(&out);
    WriteOcrEvalJson(result, {common.world_path, command_line, options}, &json);
    if (!out) throw std::runtime_error("error writing " + common.json_path);
  }
  return 0;
}

}  // namespace doorplate_localization
