#include "text_extractor_options.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

#include <xmlrpcpp/XmlRpcValue.h>

#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {
namespace {

// A range rule on a number and its wording for the error message.
struct Rule {
  std::function<bool(double)> ok;
  std::string text;
};

std::string Num(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}
Rule AtLeast(double min) { return {[min](double v) { return v >= min; }, ">= " + Num(min)}; }
Rule Above(double min) { return {[min](double v) { return v > min; }, "> " + Num(min)}; }
Rule Closed(double lo, double hi) {
  return {[lo, hi](double v) { return v >= lo && v <= hi; }, "in [" + Num(lo) + ", " + Num(hi) + "]"};
}

// The parameter's value (or `fallback`), finite and satisfying `rule`; else ParameterError naming it.
template <typename T>
T Read(const ros::NodeHandle& nh, const std::string& name, T fallback, const Rule& rule) {
  const T value = ReadParam(nh, name, fallback);
  RequireParam(std::isfinite(static_cast<double>(value)) && rule.ok(static_cast<double>(value)), nh, name,
               rule.text, value);
  return value;
}

std::vector<std::string> ReadStringList(const ros::NodeHandle& nh, const std::string& name) {
  if (!nh.hasParam(name)) return {};
  XmlRpc::XmlRpcValue list;
  nh.getParam(name, list);
  const std::string rule = " must be a list of strings (quote room numbers: ['201', '202A'])";
  if (list.getType() != XmlRpc::XmlRpcValue::TypeArray) throw ParameterError(nh.resolveName(name) + rule);
  std::vector<std::string> out;
  for (int i = 0; i < list.size(); ++i) {
    if (list[i].getType() != XmlRpc::XmlRpcValue::TypeString) {
      throw ParameterError(nh.resolveName(name) + rule + "; entry " + std::to_string(i) + " is not");
    }
    out.push_back(static_cast<std::string>(list[i]));
  }
  return out;
}

void ReadDetector(const ros::NodeHandle& nh, MserBandDetectorOptions& d) {
  BandOptions& b = d.band;
  b.enabled = ReadParam(nh, "detector/band/enabled", b.enabled);
  b.top_fraction = Read(nh, "detector/band/top_fraction", b.top_fraction,
                        {[](double v) { return v >= 0.0 && v < 1.0; }, "in [0, 1)"});
  b.bottom_fraction = Read(nh, "detector/band/bottom_fraction", b.bottom_fraction, Closed(0.0, 1.0));
  b.top_px = Read(nh, "detector/band/top_px", b.top_px, AtLeast(-1));
  b.bottom_px = Read(nh, "detector/band/bottom_px", b.bottom_px, AtLeast(-1));
  RequireParam((b.top_px >= 0) == (b.bottom_px >= 0), nh, "detector/band/bottom_px",
               "set (>= 0) together with detector/band/top_px, or both -1", b.bottom_px);
  if (b.top_px >= 0) {
    RequireParam(b.bottom_px > b.top_px, nh, "detector/band/bottom_px", "> detector/band/top_px", b.bottom_px);
  } else {
    RequireParam(b.bottom_fraction > b.top_fraction, nh, "detector/band/bottom_fraction",
                 "> detector/band/top_fraction", b.bottom_fraction);
  }
  MserOptions& m = d.mser;
  m.delta = Read(nh, "detector/mser/delta", m.delta, AtLeast(1));
  m.min_area_px = Read(nh, "detector/mser/min_area_px", m.min_area_px, AtLeast(1));
  m.max_area_px = Read(nh, "detector/mser/max_area_px", m.max_area_px, Above(m.min_area_px));
  m.max_variation = Read(nh, "detector/mser/max_variation", m.max_variation, Above(0.0));
  CharacterFilterOptions& c = d.character;
  c.min_char_height_px = Read(nh, "detector/character/min_char_height_px", c.min_char_height_px, AtLeast(1));
  c.max_char_height_px =
      Read(nh, "detector/character/max_char_height_px", c.max_char_height_px, AtLeast(c.min_char_height_px));
  c.min_char_aspect = Read(nh, "detector/character/min_char_aspect", c.min_char_aspect, AtLeast(0.0));
  c.max_char_aspect = Read(nh, "detector/character/max_char_aspect", c.max_char_aspect, AtLeast(c.min_char_aspect));
  c.min_fill_ratio = Read(nh, "detector/character/min_fill_ratio", c.min_fill_ratio, Closed(0.0, 1.0));
  c.max_fill_ratio =
      Read(nh, "detector/character/max_fill_ratio", c.max_fill_ratio, Closed(c.min_fill_ratio, 1.0));
  c.min_contrast_grey = Read(nh, "detector/character/min_contrast_grey", c.min_contrast_grey, Closed(0.0, 255.0));
  LineGroupingOptions& g = d.grouping;
  g.max_nested_coverage = Read(nh, "detector/grouping/max_nested_coverage", g.max_nested_coverage,
                               {[](double v) { return v > 0.0 && v <= 1.0; }, "in (0, 1]"});
  g.max_height_ratio = Read(nh, "detector/grouping/max_height_ratio", g.max_height_ratio, AtLeast(1.0));
  g.max_center_offset_to_height =
      Read(nh, "detector/grouping/max_center_offset_to_height", g.max_center_offset_to_height, AtLeast(0.0));
  g.max_gap_to_height = Read(nh, "detector/grouping/max_gap_to_height", g.max_gap_to_height, AtLeast(0.0));
  g.max_ink_difference_grey =
      Read(nh, "detector/grouping/max_ink_difference_grey", g.max_ink_difference_grey, Closed(0.0, 255.0));
  g.min_chars_per_line = Read(nh, "detector/grouping/min_chars_per_line", g.min_chars_per_line, AtLeast(1));
  g.min_line_aspect = Read(nh, "detector/grouping/min_line_aspect", g.min_line_aspect, AtLeast(0.0));
  g.max_line_aspect = Read(nh, "detector/grouping/max_line_aspect", g.max_line_aspect, AtLeast(g.min_line_aspect));
  d.box_padding_to_height = Read(nh, "detector/box_padding_to_height", d.box_padding_to_height, AtLeast(0.0));
  d.reference_width_px = Read(nh, "detector/reference_width_px", d.reference_width_px, AtLeast(0));
  d.nms_enabled = ReadParam(nh, "detector/nms_enabled", d.nms_enabled);
  d.nms_max_iou = Read(nh, "detector/nms_max_iou", d.nms_max_iou, Closed(0.0, 1.0));
}

void ReadOcr(const ros::NodeHandle& nh, TesseractOcrOptions& o) {
  o.tessdata_dir = ReadParam(nh, "ocr/tessdata_dir", o.tessdata_dir);
  o.language = ReadParam(nh, "ocr/language", o.language);
  RequireParam(!o.language.empty(), nh, "ocr/language", "a Tesseract language name such as eng", "''");
  const std::string mode = ReadParam(nh, "ocr/line_mode", std::string("single_line"));
  RequireParam(mode == "single_line" || mode == "single_word", nh, "ocr/line_mode",
               "'single_line' or 'single_word'", mode);
  o.line_mode = mode == "single_word" ? OcrLineMode::kSingleWord : OcrLineMode::kSingleLine;
  o.whitelist = ReadParam(nh, "ocr/whitelist", o.whitelist);
  OcrPreprocessOptions& p = o.preprocess;
  p.target_text_height_px = Read(nh, "ocr/preprocess/target_text_height_px", p.target_text_height_px, AtLeast(8));
  p.border_px = Read(nh, "ocr/preprocess/border_px", p.border_px, AtLeast(0));
  p.min_text_height_px = Read(nh, "ocr/preprocess/min_text_height_px", p.min_text_height_px, AtLeast(1));
  p.ink_thinning_px = Read(nh, "ocr/preprocess/ink_thinning_px", p.ink_thinning_px, AtLeast(0));
  const std::string model = ResolveTessdataDir(o) + "/" + o.language + ".traineddata";
  if (!std::ifstream(model).good()) {
    throw ParameterError(nh.resolveName("ocr/tessdata_dir") + " = '" + o.tessdata_dir + "' and " +
                         nh.resolveName("ocr/language") + " = '" + o.language + "': Tesseract model " + model +
                         " not found (empty tessdata_dir: $TESSDATA_PREFIX, else Debian's tesseract-ocr-" +
                         o.language + " folder)");
  }
}

// ~detector_type / ~recognizer_type and the learned models' options (db_text_detector.h,
// ppocr_recognizer.h). A learned model that is chosen must be installed: checked here, naming the file.
void ReadModels(const ros::NodeHandle& nh, TextExtractorOptions& o) {
  const std::string detector = ReadParam(nh, "detector_type", ToString(o.detector_type));
  const std::string recognizer = ReadParam(nh, "recognizer_type", ToString(o.recognizer_type));
  try {
    o.detector_type = ParseTextDetectorType(detector, nh.resolveName("detector_type"));
    o.recognizer_type = ParseTextRecognizerType(recognizer, nh.resolveName("recognizer_type"));
  } catch (const std::invalid_argument& e) {
    throw ParameterError(e.what());
  }
  const std::string model_dir = ReadParam(nh, "model_dir", std::string());
  o.db_detector.model_dir = o.ppocr.model_dir = model_dir;
  DbTextDetectorOptions& d = o.db_detector;
  d.target_short_side_px = Read(nh, "db/target_short_side_px", d.target_short_side_px, AtLeast(32));
  d.max_input_side_px = Read(nh, "db/max_input_side_px", d.max_input_side_px, AtLeast(d.target_short_side_px));
  d.binary_threshold = Read(nh, "db/binary_threshold", d.binary_threshold,
                            {[](double v) { return v > 0.0 && v < 1.0; }, "in (0, 1)"});
  d.box_threshold = Read(nh, "db/box_threshold", d.box_threshold,
                         {[](double v) { return v > 0.0 && v < 1.0; }, "in (0, 1)"});
  d.unclip_ratio = Read(nh, "db/unclip_ratio", d.unclip_ratio, Above(0.0));
  d.min_box_side_px = Read(nh, "db/min_box_side_px", d.min_box_side_px, AtLeast(1));
  PpOcrRecognizerOptions& r = o.ppocr;
  r.allowed_characters = ReadParam(nh, "ppocr/allowed_characters", r.allowed_characters);
  r.min_confidence = Read(nh, "ppocr/min_confidence", r.min_confidence, Closed(0.0, 1.0));
  o.ocr.min_confidence = Read(nh, "ocr/min_confidence", o.ocr.min_confidence, Closed(0.0, 1.0));
  const std::string dir = ResolveOcrModelDir(model_dir);
  const bool wants_models = o.detector_type == TextDetectorType::kDb ||
                            o.recognizer_type == TextRecognizerType::kPpOcr;
  const std::string probe = dir + (o.recognizer_type == TextRecognizerType::kPpOcr ? "/ppocrv4_rec_dict.txt"
                                                                                  : "/ppocrv4_det.onnx");
  if (wants_models && !std::ifstream(probe).good()) {
    throw ParameterError(nh.resolveName("detector_type") + " = '" + detector + "', " +
                         nh.resolveName("recognizer_type") + " = '" + recognizer + "' need the learned models, but " +
                         probe + " is not there (" + nh.resolveName("model_dir") + " = '" + model_dir +
                         "'; install them with scripts/fetch_ocr_models.sh)");
  }
}

void ReadValidator(const ros::NodeHandle& nh, PlateReadingValidatorOptions& v) {
  // ~room_pattern (the name the mapping nodelet shares); ~validator/pattern is its older name.
  if (nh.hasParam("room_pattern") && nh.hasParam("validator/pattern")) {
    throw ParameterError(nh.resolveName("room_pattern") + " and " + nh.resolveName("validator/pattern") +
                         " are the same option (the older name): set only one");
  }
  const std::string name = nh.hasParam("validator/pattern") ? "validator/pattern" : "room_pattern";
  v.pattern = ReadParam(nh, name, v.pattern);
  try {
    RoomIdGrammar check(v.pattern);
  } catch (const std::invalid_argument& e) {
    throw ParameterError(nh.resolveName(name) + " must be an ECMAScript regex of the building's room numbers "
                         "(canonical form, docs/text-map-format.md), got '" + v.pattern + "': " + e.what());
  }
  v.known_rooms = ReadStringList(nh, "validator/known_rooms");
  v.max_edit_distance = Read(nh, "validator/max_edit_distance", v.max_edit_distance, AtLeast(0));
  try {
    PlateReadingValidator check(v);  // every known room must match the pattern
  } catch (const std::invalid_argument& e) {
    throw ParameterError(nh.resolveName("validator/known_rooms") + ": " + e.what());
  }
}

void ReadTracker(const ros::NodeHandle& nh, PlateTrackerOptions& t) {
  t.max_center_jump_px = Read(nh, "tracker/max_center_jump_px", t.max_center_jump_px, Above(0.0));
  t.max_vertical_offset_to_height =
      Read(nh, "tracker/max_vertical_offset_to_height", t.max_vertical_offset_to_height, AtLeast(0.0));
  t.max_height_ratio = Read(nh, "tracker/max_height_ratio", t.max_height_ratio, AtLeast(1.0));
  t.max_missed_frames = Read(nh, "tracker/max_missed_frames", t.max_missed_frames, AtLeast(0));
  t.min_voted_frames = Read(nh, "tracker/min_voted_frames", t.min_voted_frames, AtLeast(1));
  t.read_every_n_frames = Read(nh, "tracker/read_every_n_frames", t.read_every_n_frames, AtLeast(1));
  t.max_readings_per_track = Read(nh, "tracker/max_readings_per_track", t.max_readings_per_track, AtLeast(0));
  t.enough_votes = Read(nh, "tracker/enough_votes", t.enough_votes, AtLeast(0));
}

}  // namespace

std::optional<BandGeometryOptions> LoadBandGeometryOptions(const ros::NodeHandle& nh) {
  if (!ReadParam(nh, "detector/band_from_geometry", false)) return std::nullopt;
  BandGeometryOptions g;
  const std::string p = "detector/band_geometry/";
  g.mount_height_m = Read(nh, p + "camera_height_m", g.mount_height_m, Above(0.0));
  g.pitch_up_deg = Read(nh, p + "camera_pitch_up_deg", g.pitch_up_deg, Closed(-80.0, 80.0));
  g.text_bottom_min_m = Read(nh, p + "text_bottom_min_m", g.text_bottom_min_m, AtLeast(0.0));
  g.text_top_max_m = Read(nh, p + "text_top_max_m", g.text_top_max_m, Above(g.text_bottom_min_m));
  g.min_distance_m = Read(nh, p + "min_distance_m", g.min_distance_m, Above(0.0));
  g.max_distance_m = Read(nh, p + "max_distance_m", g.max_distance_m, AtLeast(g.min_distance_m));
  g.margin_px = Read(nh, p + "margin_px", g.margin_px, AtLeast(0.0));
  return g;
}

TextExtractorOptions LoadTextExtractorOptions(const ros::NodeHandle& nh) {
  TextExtractorOptions o;
  ReadDetector(nh, o.detector);
  ReadOcr(nh, o.ocr);
  ReadModels(nh, o);
  ReadValidator(nh, o.validator);
  UseReadingScheduleFor(o.recognizer_type, &o.tracker);  // the recogniser's schedule; parameters override it
  ReadTracker(nh, o.tracker);
  // 0 is legal for the core but would make a node that never reads anything.
  o.max_regions_per_frame = Read(nh, "max_regions_per_frame", o.max_regions_per_frame, AtLeast(1));
  // The core's own checks, in case they grow stricter than the rules above (cheap: no model is loaded).
  try {
    MserBandDetector detector(o.detector);
    PlateTracker tracker(o.tracker);
    ValidateOcrPreprocessOptions(o.ocr.preprocess);
  } catch (const std::invalid_argument& e) {
    throw ParameterError(nh.resolveName("") + ": " + e.what());
  }
  return o;
}

}  // namespace doorplate_localization
