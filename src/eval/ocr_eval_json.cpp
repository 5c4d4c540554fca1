#include "ocr_eval_json.h"

namespace doorplate_localization {
namespace {

double Ratio(double numerator, double denominator) { return denominator > 0 ? numerator / denominator : 0.0; }

void WriteDetector(const DetectorModeStats& d, JsonWriter* json) {
  const int other_frames = d.frames - d.frames_plate_in_view;
  json->BeginObject()
      .Field("name", d.name)
      .Field("band", d.band)
      .Field("nms", d.nms)
      .Field("frames", d.frames)
      .Field("boxes_per_frame", Ratio(static_cast<double>(d.boxes), d.frames))
      .Field("frames_plate_in_view", d.frames_plate_in_view)
      .Field("boxes_per_frame_plate_in_view", Ratio(static_cast<double>(d.boxes_plate_in_view), d.frames_plate_in_view))
      .Field("boxes_per_frame_no_plate",
             Ratio(static_cast<double>(d.boxes - d.boxes_plate_in_view), other_frames))
      .Field("ms_per_frame", Ratio(1000.0 * d.seconds, d.frames))
      .EndObject();
}

void WriteEvent(const OcrEvalEvent& e, JsonWriter* json) {
  json->BeginObject()
      .Field("kind", e.kind)
      .Field("pass", e.pass)
      .Field("stamp_s", e.stamp_s)
      .Field("reported", e.reported)
      .Field("truth", e.truth)
      .Field("plate", e.plate);
  json->Key("box_px").BeginArray().Value(e.box_px.x).Value(e.box_px.y).Value(e.box_px.width).Value(e.box_px.height).EndArray();
  json->Field("image", e.image).EndObject();
}

void WritePass(const OcrPassResult& p, const std::vector<PlateTruth>& plates, JsonWriter* json) {
  const PassScore& s = p.score;
  json->BeginObject()
      .Field("seed", p.seed)
      .Field("sweep_done", p.sweep_done)
      .Field("plates_total", s.plates_passed)
      .Field("plates_correct", s.plates_correct)
      .Field("false_reads", s.false_reads)
      .Field("spurious", s.spurious)
      .Field("duplicates", s.duplicates)
      .Field("reports", s.reports)
      .Field("frames", p.frames)
      .Field("sim_seconds", p.sim_seconds)
      .Field("seconds", p.wall_seconds);
  json->Key("plates").BeginArray();
  for (size_t i = 0; i < plates.size(); ++i) {
    const PlatePassRecord& r = s.plates[i];
    json->BeginObject()
        .Field("plate", plates[i].label)
        .Field("text", plates[i].text)
        .Field("passed", r.passed)
        .Field("correct", r.passed && r.correct_reports > 0);
    json->Key("reported").BeginArray();
    for (const std::string& text : r.reported_texts) json->Value(text);
    json->EndArray().EndObject();
  }
  json->EndArray().EndObject();
}

}  // namespace

void WriteOcrEvalJson(const OcrEvalResult& r, const OcrEvalRunInfo& info, JsonWriter* json) {
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
  json->BeginObject()
      .Field("command", "ocr")
      .Field("world", r.world_name)
      .Field("world_file", info.world_file)
      .Field("command_line", info.command_line)
      .Field("seed", info.options.seed)
      .Field("passes", info.options.passes)
      .Field("speed_mps", info.options.speed_mps)
      .Field("band", info.options.band)
      .Field("known_rooms", info.options.known_rooms)
      .Field("detector", ToString(info.options.extractor.detector_type))
      .Field("recognizer", ToString(info.options.extractor.recognizer_type))
      .Field("ocr_mode", info.options.extractor.ocr.line_mode == OcrLineMode::kSingleWord ? "word" : "line")
      .Field("plates_in_world", static_cast<int>(r.plates.size()))
      .Field("plates_total", r.PlatesTotal())
      .Field("plates_correct", r.PlatesCorrect())
      .Field("accuracy", Ratio(r.PlatesCorrect(), r.PlatesTotal()))
      .Field("false_reads", false_reads)
      .Field("spurious", spurious)
      .Field("duplicates", duplicates)
      .Field("reports", reports)
      .Field("frames", frames)
      .Field("sim_seconds", sim_seconds)
      .Field("seconds", wall_seconds)
      .Field("extractor_ms_per_frame", Ratio(1000.0 * r.extractor_seconds, frames))
      .Field("extractor_boxes_per_frame", Ratio(r.extractor_boxes, frames));
  json->Key("figure12").BeginArray();
  for (const DetectorModeStats& d : r.detectors) WriteDetector(d, json);
  json->EndArray();
  json->Key("per_pass").BeginArray();
  for (const OcrPassResult& p : r.passes) WritePass(p, r.plates, json);
  json->EndArray();
  json->Key("events").BeginArray();
  for (const OcrEvalEvent& e : r.events) WriteEvent(e, json);
  json->EndArray().EndObject();
}

}  // namespace doorplate_localization
