#include "ocr_eval_json.h"

namespace doorplate_localization {
namespace {

double Ratio(double numerator, double denominator) { return denominator > 0 ? numerator / denominator : 0.0; }

Json DetectorJson(const DetectorModeStats& d) {
  const int other_frames = d.frames - d.frames_plate_in_view;
  Json json;
  json["name"] = d.name;
  json["band"] = d.band;
  json["nms"] = d.nms;
  json["frames"] = d.frames;
  json["boxes_per_frame"] = Ratio(static_cast<double>(d.boxes), d.frames);
  json["frames_plate_in_view"] = d.frames_plate_in_view;
  json["boxes_per_frame_plate_in_view"] = Ratio(static_cast<double>(d.boxes_plate_in_view), d.frames_plate_in_view);
  json["boxes_per_frame_no_plate"] = Ratio(static_cast<double>(d.boxes - d.boxes_plate_in_view), other_frames);
  json["ms_per_frame"] = Ratio(1000.0 * d.seconds, d.frames);
  return json;
}

Json EventJson(const OcrEvalEvent& e) {
  Json json;
  json["kind"] = e.kind;
  json["pass"] = e.pass;
  json["stamp_s"] = e.stamp_s;
  json["reported"] = e.reported;
  json["truth"] = e.truth;
  json["plate"] = e.plate;
  json["box_px"] = {e.box_px.x, e.box_px.y, e.box_px.width, e.box_px.height};
  json["image"] = e.image;
  return json;
}

Json PassJson(const OcrPassResult& p, const std::vector<PlateTruth>& plates) {
  const PassScore& s = p.score;
  Json json;
  json["seed"] = p.seed;
  json["sweep_done"] = p.sweep_done;
  json["plates_total"] = s.plates_passed;
  json["plates_correct"] = s.plates_correct;
  json["false_reads"] = s.false_reads;
  json["spurious"] = s.spurious;
  json["duplicates"] = s.duplicates;
  json["reports"] = s.reports;
  json["frames"] = p.frames;
  json["sim_seconds"] = p.sim_seconds;
  json["seconds"] = p.wall_seconds;
  json["plates"] = Json::array();
  for (size_t i = 0; i < plates.size(); ++i) {
    const PlatePassRecord& r = s.plates[i];
    json["plates"].push_back({{"plate", plates[i].label},
                              {"text", plates[i].text},
                              {"passed", r.passed},
                              {"correct", r.passed && r.correct_reports > 0},
                              {"reported", r.reported_texts}});
  }
  return json;
}

}  // namespace

Json OcrEvalJson(const OcrEvalResult& r, const OcrEvalRunInfo& info) {
  int false_reads = 0, spurious = 0, duplicates = 0, reports = 0;
  double sim_seconds = 0.0, wall_seconds = 0.0;
  for (const OcrPassResult& p : r.passes) {
    false_reads += p.score.false_reads;
    spurious += p.score.spurious;
    duplicates += p.score.duplicates;
    reports += p.score.reports;
    sim_seconds += p.sim_seconds;
    wall_seconds += p.wall_seconds;
  }
  const int frames = r.Frames();
  Json json;
  json["command"] = "ocr";
  json["world"] = r.world_name;
  json["world_file"] = info.world_file;
  json["command_line"] = info.command_line;
  json["seed"] = info.options.seed;
  json["passes"] = info.options.passes;
  json["speed_mps"] = info.options.speed_mps;
  json["band"] = info.options.band;
  json["known_rooms"] = info.options.known_rooms;
  json["detector"] = ToString(info.options.extractor.detector_type);
  json["recognizer"] = ToString(info.options.extractor.recognizer_type);
  json["ocr_mode"] = info.options.extractor.ocr.line_mode == OcrLineMode::kSingleWord ? "word" : "line";
  json["plates_in_world"] = static_cast<int>(r.plates.size());
  json["plates_total"] = r.PlatesTotal();
  json["plates_correct"] = r.PlatesCorrect();
  json["accuracy"] = Ratio(r.PlatesCorrect(), r.PlatesTotal());
  json["false_reads"] = false_reads;
  json["spurious"] = spurious;
  json["duplicates"] = duplicates;
  json["reports"] = reports;
  json["frames"] = frames;
  json["sim_seconds"] = sim_seconds;
  json["seconds"] = wall_seconds;
  json["extractor_ms_per_frame"] = Ratio(1000.0 * r.extractor_seconds, frames);
  json["extractor_boxes_per_frame"] = Ratio(r.extractor_boxes, frames);
  json["figure12"] = Json::array();
  for (const DetectorModeStats& d : r.detectors) json["figure12"].push_back(DetectorJson(d));
  json["per_pass"] = Json::array();
  for (const OcrPassResult& p : r.passes) json["per_pass"].push_back(PassJson(p, r.plates));
  json["events"] = Json::array();
  for (const OcrEvalEvent& e : r.events) json["events"].push_back(EventJson(e));
  return json;
}

}  // namespace doorplate_localization
