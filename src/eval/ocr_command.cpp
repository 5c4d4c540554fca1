// `doorplate_eval ocr`: the text-reading experiment (paper Table I, Figure 12) on one world file.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "cli_app.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/sim/camera_renderer.h"
#include "doorplate_localization/sim/world_loader.h"
#include "doorplate_localization/text/band_geometry.h"
#include "eval_args.h"
#include "eval_commands.h"
#include "ocr_eval.h"
#include "ocr_eval_json.h"
#include "output_guard.h"

namespace doorplate_localization {
namespace {

struct OcrArgs {
  CommonArgs common;
  bool band = true, known_rooms = false, band_geometry = false;
  std::string detector = "mser", recognizer = "tesseract", ocr_mode = "default", camera_px;
  int detector_every = 1;
  double max_pass_seconds = 1800, progress_s = 60;
};

void AddOcrOptions(CLI::App* ocr, OcrArgs* a) {
  AddCommonOptions(ocr, &a->common);
  ocr->add_option("--band", a->band, "extractor searches the fixed image band (on) or the full image (off)")
      ->transform(tools::OnOff())->default_str("on");
  ocr->add_option("--known-rooms", a->known_rooms, "give the validator the world's room list (on) or not (off: open "
                  "vocabulary)")->transform(tools::OnOff())->default_str("off");
  ocr->add_option("--detector", a->detector, "text detector: mser or db (the learned one; scripts/fetch_ocr_models.sh)")
      ->capture_default_str();
  ocr->add_option("--recognizer", a->recognizer, "recogniser: tesseract or ppocr (the learned one)")->capture_default_str();
  ocr->add_option("--ocr-mode", a->ocr_mode, "Tesseract segmentation: line, word, or default (TesseractOcrOptions)")
      ->capture_default_str()->check(CLI::IsMember({"line", "word", "default"}));
  ocr->add_option("--detector-every", a->detector_every, "run the Figure 12 detector modes on every n-th frame (0: never)")
      ->capture_default_str()->transform(tools::WholeNumber(0));
  ocr->add_option("--max-pass-seconds", a->max_pass_seconds, "simulated seconds after which an unfinished sweep ends "
                  "the pass")->capture_default_str()->check(tools::PositiveNumber());
  ocr->add_option("--camera-px", a->camera_px, "WIDTHxHEIGHT: render at this size instead of the world's (e.g. "
                  "1280x720; same horizontal field of view, derived intrinsics)");
  ocr->add_option("--band-geometry", a->band_geometry, "on: band rows from the camera's intrinsics and mount and the "
                  "world's plate heights (BandFromGeometry) instead of the fixed fractions")
      ->transform(tools::OnOff())->default_str("off");
  ocr->add_option("--progress-s", a->progress_s, "a progress line on stderr every this many simulated seconds "
                  "(rewritten in place twice a second on a terminal; 0: none)")->capture_default_str()
      ->check(tools::Number(0.0));
}

// "1280x720" → the world's camera at that size with its other intrinsics derived again.
void SetCameraSize(const std::string& size, World* world) {
  int width = 0, height = 0;
  char x = 0, extra = 0;
  if (std::sscanf(size.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 || x != 'x' || width < 16 ||
      height < 16 || width > 8192 || height > 8192) {
    throw UsageError("ocr: --camera-px: '" + size + "' must be WIDTHxHEIGHT, each in 16..8192");
  }
  CameraOptions& camera = world->sensors.camera;
  camera.width_px = width;
  camera.height_px = height;
  camera.fx_px = camera.fy_px = camera.cx_px = camera.cy_px = 0.0;
}

// The band for the world's camera: its intrinsics and mount, the world's plates from top to bottom edge
// (photo plates have their text anywhere on the face), read 1.0-3.5 m away (BandGeometryOptions).
BandOptions BandForWorld(const World& world) {
  const CameraOptions& camera = world.sensors.camera;
  const CameraIntrinsics k = IntrinsicsFromOptions(camera);
  BandGeometryOptions g;
  g.image_height_px = k.height_px;
  g.fy_px = k.fy_px;
  g.cy_px = k.cy_px;
  g.mount_height_m = camera.mount_height_m;
  g.pitch_up_deg = camera.pitch_deg;
  const std::vector<const TextSign*> plates = world.Plates();
  if (plates.empty()) throw std::invalid_argument("ocr: --band-geometry: the world has no plates");
  g.text_bottom_min_m = g.text_top_max_m = plates[0]->center_height_m;
  for (const TextSign* plate : plates) {
    g.text_bottom_min_m = std::min(g.text_bottom_min_m, plate->center_height_m - plate->height_m / 2);
    g.text_top_max_m = std::max(g.text_top_max_m, plate->center_height_m + plate->height_m / 2);
  }
  return BandFromGeometry(g);
}

void PrintSummary(const OcrEvalResult& r, const OcrEvalOptions& o) {
  std::printf("world %s: %d pass(es), seed %llu, band %s, known rooms %s, %s + %s (Tesseract %s), %d frames\n",
              r.world_name.c_str(), o.passes, static_cast<unsigned long long>(o.seed), o.band ? "on" : "off",
              o.known_rooms ? "on" : "off", ToString(o.extractor.detector_type).c_str(),
              ToString(o.extractor.recognizer_type).c_str(),
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

int RunOcr(const OcrArgs& a, const std::string& command_line) {
  const CommonArgs& common = a.common;
  OcrEvalOptions options;
  options.passes = common.passes;
  options.seed = common.seed;
  options.speed_mps = common.speed_mps;
  options.dump_dir = common.dump_dir;
  options.band = a.band;
  options.known_rooms = a.known_rooms;
  if (a.ocr_mode == "line") options.extractor.ocr.line_mode = OcrLineMode::kSingleLine;
  if (a.ocr_mode == "word") options.extractor.ocr.line_mode = OcrLineMode::kSingleWord;
  try {
    options.extractor.detector_type = ParseTextDetectorType(a.detector, "ocr: --detector");
    options.extractor.recognizer_type = ParseTextRecognizerType(a.recognizer, "ocr: --recognizer");
    UseReadingScheduleFor(options.extractor.recognizer_type, &options.extractor.tracker);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  options.detector_every_n_frames = a.detector_every;
  options.max_pass_time_s = a.max_pass_seconds;
  options.progress_every_s = a.progress_s;

  World world = LoadWorldFile(common.world_path);
  if (!a.camera_px.empty()) SetCameraSize(a.camera_px, &world);
  if (a.band_geometry) {
    options.extractor.detector.band = BandForWorld(world);
    std::printf("band rows [%d, %d) of %d from geometry\n", options.extractor.detector.band.top_px,
                options.extractor.detector.band.bottom_px, world.sensors.camera.height_px);
  }
  tools::RefuseOverwritingInputs({{"--world", common.world_path}},  // issue 18: an output never replaces an input
                                 {{"--json", common.json_path}});
  const OcrEvalResult result = RunOcrEval(world, options);
  PrintSummary(result, options);
  if (!common.json_path.empty()) {
    WriteFileAtomically(common.json_path, ResultJsonText(OcrEvalJson(result, {common.world_path, command_line, options})));
  }
  return 0;
}

}  // namespace

EvalCommand AddOcrCommand(CLI::App* eval, const std::string& command_line) {
  auto args = std::make_shared<OcrArgs>();
  CLI::App* ocr = eval->add_subcommand("ocr", "Text reading on a simulated corridor sweep (paper Table I, Figure 12).");
  AddOcrOptions(ocr, args.get());
  return {ocr, [args, command_line] { return RunOcr(*args, command_line); }};
}

}  // namespace doorplate_localization
