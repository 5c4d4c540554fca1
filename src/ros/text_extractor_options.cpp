// TextExtractorNodelet's parameter table and loader: every parameter once (name, field, default, rule, doc);
// rules between fields are the core's (MserBandDetector, PlateTracker, ValidateOcrPreprocessOptions,
// PlateReadingValidator, ValidateBandGeometryOptions).
#include "text_extractor_options.h"

#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "doorplate_localization/common/room_id.h"
#include "doorplate_localization/text/mser_band_detector.h"
#include "doorplate_localization/text/ocr_preprocess.h"
#include "doorplate_localization/text/plate_reading_validator.h"
#include "doorplate_localization/text/plate_tracker.h"
#include "doorplate_localization/text/ppocr_recognizer.h"
#include "doorplate_localization/text/tesseract_ocr.h"

namespace doorplate_localization {
namespace {

using O = TextExtractorNodeOptions;

ParamRule Fraction01Open() {  // [0, 1)
  return param_rules::Holds("in [0, 1)", [](double v) { return v >= 0.0 && v < 1.0; });
}
ParamRule OpenUnit() {  // (0, 1)
  return param_rules::Holds("in (0, 1)", [](double v) { return v > 0.0 && v < 1.0; });
}
ParamRule Grey() {
  return param_rules::Holds("in [0, 255]", [](double v) { return v >= 0.0 && v <= 255.0; });
}

ParamTable<O> DetectorRows() {
  namespace r = param_rules;
  return {
      Param<O>("detector/band/enabled", DOORPLATE_PARAM_FIELD(extractor.detector.band.enabled),
               "search only the band of rows where plates appear; false: the whole image"),
      Param<O>("detector/band/top_fraction", DOORPLATE_PARAM_FIELD(extractor.detector.band.top_fraction),
               "band top row as a fraction of the image height", Fraction01Open()),
      Param<O>("detector/band/bottom_fraction", DOORPLATE_PARAM_FIELD(extractor.detector.band.bottom_fraction),
               "band bottom row as a fraction of the image height; > top_fraction", r::Probability()),
      Param<O>("detector/band/top_px", DOORPLATE_PARAM_FIELD(extractor.detector.band.top_px),
               "both >= 0: band rows [top_px, bottom_px) instead of the fractions; -1: unset",
               r::Holds(">= -1", [](double v) { return v >= -1; })),
      Param<O>("detector/band/bottom_px", DOORPLATE_PARAM_FIELD(extractor.detector.band.bottom_px),
               "see top_px; > top_px", r::Holds(">= -1", [](double v) { return v >= -1; })),
      Param<O>("detector/band_from_geometry", DOORPLATE_PARAM_FIELD(band_from_geometry),
               "true: the band rows are computed from every `camera_info` (height, fy = K[4], cy = K[5]) and the "
               "camera mount and plate ranges below (`BandFromGeometry`, text/band_geometry.h), so any resolution "
               "or lens gets a fitting band; `~detector/band/*` are then unused"),
      Param<O>("detector/band_geometry/camera_height_m", DOORPLATE_PARAM_FIELD(band_geometry.mount_height_m),
               "optical centre above the floor (the simulator's `mount_height_m`)", r::Positive()),
      Param<O>("detector/band_geometry/camera_pitch_up_deg", DOORPLATE_PARAM_FIELD(band_geometry.pitch_up_deg),
               "upward tilt of the camera (the simulator's `pitch_deg`)",
               r::Holds("in (-80, 80)", [](double v) { return v > -80.0 && v < 80.0; })),
      Param<O>("detector/band_geometry/text_bottom_min_m", DOORPLATE_PARAM_FIELD(band_geometry.text_bottom_min_m),
               "lowest bottom edge of plate text above the floor", r::Finite()),
      Param<O>("detector/band_geometry/text_top_max_m", DOORPLATE_PARAM_FIELD(band_geometry.text_top_max_m),
               "highest top edge of plate text above the floor; > text_bottom_min_m", r::Finite()),
      Param<O>("detector/band_geometry/min_distance_m", DOORPLATE_PARAM_FIELD(band_geometry.min_distance_m),
               "nearest wall distance along the optical axis at which plates are read", r::Positive()),
      Param<O>("detector/band_geometry/max_distance_m", DOORPLATE_PARAM_FIELD(band_geometry.max_distance_m),
               "farthest such distance; >= min_distance_m", r::Positive()),
      Param<O>("detector/band_geometry/margin_px", DOORPLATE_PARAM_FIELD(band_geometry.margin_px),
               "rows added above and below, then clipped to the image", r::NonNegative()),
      Param<O>("detector/mser/delta", DOORPLATE_PARAM_FIELD(extractor.detector.mser.delta),
               "cv::MSER delta; the fine delta and small areas find the 6-8 px glyphs of small grey-on-grey plates",
               r::AtLeast(1)),
      Param<O>("detector/mser/min_area_px", DOORPLATE_PARAM_FIELD(extractor.detector.mser.min_area_px),
               "cv::MSER smallest region (band pixels)", r::AtLeast(1)),
      Param<O>("detector/mser/max_area_px", DOORPLATE_PARAM_FIELD(extractor.detector.mser.max_area_px),
               "cv::MSER largest region (band pixels); > min_area_px", r::AtLeast(1)),
      Param<O>("detector/mser/max_variation", DOORPLATE_PARAM_FIELD(extractor.detector.mser.max_variation),
               "cv::MSER max variation", r::Positive()),
      Param<O>("detector/character/min_char_height_px",
               DOORPLATE_PARAM_FIELD(extractor.detector.character.min_char_height_px), "glyph height range: lowest",
               r::AtLeast(1)),
      Param<O>("detector/character/max_char_height_px",
               DOORPLATE_PARAM_FIELD(extractor.detector.character.max_char_height_px),
               "glyph height range: highest; >= min_char_height_px", r::AtLeast(1)),
      Param<O>("detector/character/min_char_aspect", DOORPLATE_PARAM_FIELD(extractor.detector.character.min_char_aspect),
               "glyph width / height range: lowest", r::NonNegative()),
      Param<O>("detector/character/max_char_aspect", DOORPLATE_PARAM_FIELD(extractor.detector.character.max_char_aspect),
               "glyph width / height range: highest; >= min_char_aspect", r::NonNegative()),
      Param<O>("detector/character/min_fill_ratio", DOORPLATE_PARAM_FIELD(extractor.detector.character.min_fill_ratio),
               "region pixels / box area: lowest", r::Probability()),
      Param<O>("detector/character/max_fill_ratio", DOORPLATE_PARAM_FIELD(extractor.detector.character.max_fill_ratio),
               "region pixels / box area: highest; >= min_fill_ratio", r::Probability()),
      Param<O>("detector/character/min_contrast_grey",
               DOORPLATE_PARAM_FIELD(extractor.detector.character.min_contrast_grey),
               "glyph vs. background grey difference", Grey()),
      Param<O>("detector/grouping/max_nested_coverage",
               DOORPLATE_PARAM_FIELD(extractor.detector.grouping.max_nested_coverage),
               "a glyph this much inside a larger one is dropped (holes of 0, 4, 8...)",
               r::Holds("in (0, 1]", [](double v) { return v > 0.0 && v <= 1.0; })),
      Param<O>("detector/grouping/max_height_ratio", DOORPLATE_PARAM_FIELD(extractor.detector.grouping.max_height_ratio),
               "neighbouring glyphs: taller / shorter height", r::Holds(">= 1", [](double v) { return v >= 1.0; })),
      Param<O>("detector/grouping/max_center_offset_to_height",
               DOORPLATE_PARAM_FIELD(extractor.detector.grouping.max_center_offset_to_height),
               "neighbouring glyphs: vertical centre offset / height", r::NonNegative()),
      Param<O>("detector/grouping/max_gap_to_height",
               DOORPLATE_PARAM_FIELD(extractor.detector.grouping.max_gap_to_height),
               "neighbouring glyphs: horizontal gap / height (bridges a printed `-` or `.`, too small to be a "
               "glyph, also on thin widely spaced faces)",
               r::NonNegative()),
      Param<O>("detector/grouping/max_ink_difference_grey",
               DOORPLATE_PARAM_FIELD(extractor.detector.grouping.max_ink_difference_grey),
               "neighbouring glyphs: ink grey difference", Grey()),
      Param<O>("detector/grouping/min_chars_per_line",
               DOORPLATE_PARAM_FIELD(extractor.detector.grouping.min_chars_per_line), "glyphs a text line needs",
               r::AtLeast(1)),
      Param<O>("detector/grouping/min_line_aspect", DOORPLATE_PARAM_FIELD(extractor.detector.grouping.min_line_aspect),
               "text line width / height range: lowest", r::NonNegative()),
      Param<O>("detector/grouping/max_line_aspect", DOORPLATE_PARAM_FIELD(extractor.detector.grouping.max_line_aspect),
               "text line width / height range: highest; >= min_line_aspect", r::NonNegative()),
      Param<O>("detector/box_padding_to_height", DOORPLATE_PARAM_FIELD(extractor.detector.box_padding_to_height),
               "padding on each side of a line for the OCR, fraction of its height", r::NonNegative()),
      Param<O>("detector/reference_width_px", DOORPLATE_PARAM_FIELD(extractor.detector.reference_width_px),
               "the MSER areas and character heights above are for an image this wide and scale with the image "
               "width (areas with its square), so a 1280 x 720 camera with the same field of view needs no other "
               "change; 0: no scaling",
               r::AtLeast(0)),
      Param<O>("detector/nms_enabled", DOORPLATE_PARAM_FIELD(extractor.detector.nms_enabled),
               "non-maximum suppression of overlapping lines"),
      Param<O>("detector/nms_max_iou", DOORPLATE_PARAM_FIELD(extractor.detector.nms_max_iou),
               "lines overlapping more (intersection over union) are suppressed", r::Probability()),
  };
}

ParamTable<O> ModelRows() {
  namespace r = param_rules;
  return {
      Param<O>("max_regions_per_frame", DOORPLATE_PARAM_FIELD(extractor.max_regions_per_frame),
               "at most this many text boxes per image go to the OCR (largest first)", r::AtLeast(1)),
      EnumParam<O>("detector_type", DOORPLATE_PARAM_FIELD(extractor.detector_type),
                   {{"mser", TextDetectorType::kMser}, {"db", TextDetectorType::kDb}},
                   "text detector: `mser` (MSER in the band, fast: the paper's) or `db` (the learned PP-OCRv4 DB "
                   "detector, text/db_text_detector.h: text of any size and polarity in clutter, ~0.5 s a frame on "
                   "one core; for still images and slow cameras)"),
      EnumParam<O>("recognizer_type", DOORPLATE_PARAM_FIELD(extractor.recognizer_type),
                   {{"tesseract", TextRecognizerType::kTesseract}, {"ppocr", TextRecognizerType::kPpOcr}},
                   "recogniser: `tesseract` (Debian's LSTM model) or `ppocr` (the learned PP-OCRv4 recogniser, "
                   "ppocr_recognizer.h: reads real signs far better, ~20-100 ms a crop). The learned models come "
                   "from `scripts/fetch_ocr_models.sh`; choosing one that is not installed stops the nodelet, "
                   "naming the missing file. Side by side: docs/results/real-photos.md"),
      ConvertedParam<O, std::string>(
          "model_dir", "extractor.db_detector.model_dir, extractor.ppocr.model_dir",
          [](const O& o) { return o.extractor.db_detector.model_dir; },
          [](O& o, const std::string& dir) { o.extractor.db_detector.model_dir = o.extractor.ppocr.model_dir = dir; },
          "folder of the learned models; empty: `$DOORPLATE_OCR_MODEL_DIR`, else "
          "/usr/local/share/doorplate_localization/ocr_models"),
      Param<O>("db/target_short_side_px", DOORPLATE_PARAM_FIELD(extractor.db_detector.target_short_side_px),
               "the searched rows are scaled so their short side is this, then padded to multiples of 32",
               r::AtLeast(32)),
      Param<O>("db/max_input_side_px", DOORPLATE_PARAM_FIELD(extractor.db_detector.max_input_side_px),
               "... and their long side at most this; >= target_short_side_px", r::AtLeast(32)),
      Param<O>("db/binary_threshold", DOORPLATE_PARAM_FIELD(extractor.db_detector.binary_threshold),
               "DB: text-probability threshold of the mask", OpenUnit()),
      Param<O>("db/box_threshold", DOORPLATE_PARAM_FIELD(extractor.db_detector.box_threshold),
               "DB: mean probability a box needs", OpenUnit()),
      Param<O>("db/unclip_ratio", DOORPLATE_PARAM_FIELD(extractor.db_detector.unclip_ratio),
               "DB: box growth around the shrunk text kernel", r::Positive()),
      Param<O>("db/min_box_side_px", DOORPLATE_PARAM_FIELD(extractor.db_detector.min_box_side_px),
               "DB: smallest box side (image px)", r::AtLeast(1)),
      Param<O>("ppocr/allowed_characters", DOORPLATE_PARAM_FIELD(extractor.ppocr.allowed_characters),
               "characters the learned recogniser may output (lower case is folded to upper case; `·` comes out "
               "as `.`); empty: any of its dictionary"),
      Param<O>("ppocr/min_confidence", DOORPLATE_PARAM_FIELD(extractor.ppocr.min_confidence),
               "readings with a lower mean character probability are not validated (a pictogram read as a digit "
               "scores ~0.3-0.4)",
               r::Probability()),
      Param<O>("ocr/min_confidence", DOORPLATE_PARAM_FIELD(extractor.ocr.min_confidence),
               "the same for Tesseract (its confidence is poorly calibrated on single lines: 0 lets the validator "
               "and the vote decide)",
               r::Probability()),
      Param<O>("ocr/tessdata_dir", DOORPLATE_PARAM_FIELD(extractor.ocr.tessdata_dir),
               "folder of `<language>.traineddata`; empty: `$TESSDATA_PREFIX`, else Debian's "
               "/usr/share/tesseract-ocr/5/tessdata. A missing model stops the nodelet, naming the path"),
      Param<O>("ocr/language", DOORPLATE_PARAM_FIELD(extractor.ocr.language), "Tesseract model",
               {"a Tesseract language name such as eng",
                [](const ParamValue& v) { return !std::get<std::string>(v).empty(); }}),
      EnumParam<O>("ocr/line_mode", DOORPLATE_PARAM_FIELD(extractor.ocr.line_mode),
                   {{"single_line", OcrLineMode::kSingleLine}, {"single_word", OcrLineMode::kSingleWord}},
                   "Tesseract page segmentation"),
      Param<O>("ocr/whitelist", DOORPLATE_PARAM_FIELD(extractor.ocr.whitelist),
               "characters Tesseract may output; \"\" = any"),
      Param<O>("ocr/preprocess/target_text_height_px",
               DOORPLATE_PARAM_FIELD(extractor.ocr.preprocess.target_text_height_px),
               "glyph height the crop is scaled to", r::AtLeast(8)),
      Param<O>("ocr/preprocess/border_px", DOORPLATE_PARAM_FIELD(extractor.ocr.preprocess.border_px),
               "white margin around the binarized crop", r::AtLeast(0)),
      Param<O>("ocr/preprocess/min_text_height_px", DOORPLATE_PARAM_FIELD(extractor.ocr.preprocess.min_text_height_px),
               "shorter glyphs are not read", r::AtLeast(1)),
      Param<O>("ocr/preprocess/ink_thinning_px", DOORPLATE_PARAM_FIELD(extractor.ocr.preprocess.ink_thinning_px),
               "ink eroded by this many pixels after the rescale (Otsu makes blurred strokes bold: a \"3\" reads as "
               "\"5\"); 0: none",
               r::AtLeast(0)),
  };
}

ParamTable<O> ValidatorAndTrackerRows() {
  namespace r = param_rules;
  return {
      Param<O>("room_pattern", DOORPLATE_PARAM_FIELD(extractor.validator.pattern),
               "the building's room identifier format: ECMAScript regex the canonical form of a reading must match "
               "(separators `-` `.` `·` `/` and spaces removed, letters upper-cased; docs/text-map-format.md). The "
               "default accepts `16-186`, `E14-295`, `32-069T`, `B/1404`, `39.A`, `3.21`, `B2.114`, `76·100SC`, "
               "`21/52`, `5`, `5D`, `102A` and refuses words without digits. Set it to the building's format, the "
               "`room_pattern` of its text map")
          .Deprecated("validator/pattern"),
      Param<O>("validator/max_edit_distance", DOORPLATE_PARAM_FIELD(extractor.validator.max_edit_distance),
               "a reading this close (Levenshtein) to exactly one of `~validator/known_rooms` becomes that room",
               r::AtLeast(0)),
      Param<O>("tracker/max_center_jump_px", DOORPLATE_PARAM_FIELD(extractor.tracker.max_center_jump_px),
               "a box joins a track if its centre is this close to the predicted one", r::Positive()),
      Param<O>("tracker/max_vertical_offset_to_height",
               DOORPLATE_PARAM_FIELD(extractor.tracker.max_vertical_offset_to_height),
               "... and its vertical offset / height is below this", r::NonNegative()),
      Param<O>("tracker/max_height_ratio", DOORPLATE_PARAM_FIELD(extractor.tracker.max_height_ratio),
               "... and taller / shorter height is below this", r::Holds(">= 1", [](double v) { return v >= 1.0; })),
      Param<O>("tracker/max_missed_frames", DOORPLATE_PARAM_FIELD(extractor.tracker.max_missed_frames),
               "a track unseen for more processed frames is dropped", r::AtLeast(0)),
      Param<O>("tracker/min_voted_frames", DOORPLATE_PARAM_FIELD(extractor.tracker.min_voted_frames),
               "a plate is reported only with this many frames of valid readings", r::AtLeast(1)),
      Param<O>("tracker/min_reread_gap_s", DOORPLATE_PARAM_FIELD(extractor.tracker.min_reread_gap_s),
               "a room reported is not reported again until no reported track of it was seen for this long "
               "(a robot standing before a plate reads it once; 0: off)",
               r::NonNegative()),
      Param<O>("tracker/read_every_n_frames", DOORPLATE_PARAM_FIELD(extractor.tracker.read_every_n_frames),
               "reading schedule (`PlateTracker::PlanReadings`): a track is read every n-th frame. Unset, the "
               "schedule follows `~recognizer_type` (`UseReadingScheduleFor`): the slow learned recogniser pays "
               "its cost a few times per plate instead of every frame",
               r::AtLeast(1))
          .DefaultText("1 (ppocr: 3)"),
      Param<O>("tracker/max_readings_per_track", DOORPLATE_PARAM_FIELD(extractor.tracker.max_readings_per_track),
               "reading schedule: at most this many reads of a track (0: no limit); unset: by `~recognizer_type`",
               r::AtLeast(0))
          .DefaultText("0 (ppocr: 8)"),
      Param<O>("tracker/enough_votes", DOORPLATE_PARAM_FIELD(extractor.tracker.enough_votes),
               "reading schedule: a track whose leading room has this many valid readings is not read again (0: "
               "never enough); unset: by `~recognizer_type`",
               r::AtLeast(0))
          .DefaultText("0 (ppocr: 3)"),
  };
}

// The Tesseract model always (the extractor falls back to it), the learned ones when chosen.
void RequireModels(const O& o, const ParamSource& source) {
  const TextExtractorOptions& e = o.extractor;
  const std::string model = ResolveTessdataDir(e.ocr) + "/" + e.ocr.language + ".traineddata";
  if (!std::ifstream(model).good()) {
    throw ParameterError(source.Resolve("ocr/tessdata_dir") + " = '" + e.ocr.tessdata_dir + "' and " +
                         source.Resolve("ocr/language") + " = '" + e.ocr.language + "': Tesseract model " + model +
                         " not found (empty tessdata_dir: $TESSDATA_PREFIX, else Debian's tesseract-ocr-" +
                         e.ocr.language + " folder)");
  }
  const bool ppocr = e.recognizer_type == TextRecognizerType::kPpOcr;
  if (e.detector_type != TextDetectorType::kDb && !ppocr) return;
  const std::string probe = ResolveOcrModelDir(e.ppocr.model_dir) + (ppocr ? "/ppocrv4_rec_dict.txt" : "/ppocrv4_det.onnx");
  if (!std::ifstream(probe).good()) {
    throw ParameterError(source.Resolve("detector_type") + " = '" + ToString(e.detector_type) + "', " +
                         source.Resolve("recognizer_type") + " = '" + ToString(e.recognizer_type) +
                         "' need the learned models, but " + probe + " is not there (" + source.Resolve("model_dir") +
                         " = '" + e.ppocr.model_dir + "'; install them with scripts/fetch_ocr_models.sh)");
  }
}

}  // namespace

const ParamTable<TextExtractorNodeOptions>& TextExtractorParamTable() {
  static const ParamTable<O> table = [] {
    ParamTable<O> t = ModelRows();
    for (ParamTable<O> part : {DetectorRows(), ValidatorAndTrackerRows()}) t.insert(t.end(), part.begin(), part.end());
    return t;
  }();
  return table;
}

TextExtractorNodeOptions TextExtractorOptionsFrom(const ParamSource& source) {
  const ParamTable<O>& table = TextExtractorParamTable();
  O o;
  ApplyParamTable(table, source, &o);
  if (std::optional<std::vector<std::string>> rooms = source.GetStringList("validator/known_rooms")) {
    o.extractor.validator.known_rooms = std::move(*rooms);
  }
  // The recogniser's reading schedule, for the fields the parameters leave unset.
  PlateTrackerOptions schedule = o.extractor.tracker;
  UseReadingScheduleFor(o.extractor.recognizer_type, &schedule);
  PlateTrackerOptions& t = o.extractor.tracker;
  if (!source.Has("tracker/read_every_n_frames")) t.read_every_n_frames = schedule.read_every_n_frames;
  if (!source.Has("tracker/max_readings_per_track")) t.max_readings_per_track = schedule.max_readings_per_track;
  if (!source.Has("tracker/enough_votes")) t.enough_votes = schedule.enough_votes;
  CheckWithCore(table, o, source, [&o] {
    (void)MserBandDetector(o.extractor.detector);
    (void)PlateTracker(o.extractor.tracker);
    ValidateOcrPreprocessOptions(o.extractor.ocr.preprocess);
    if (o.extractor.db_detector.max_input_side_px < o.extractor.db_detector.target_short_side_px) {
      throw std::invalid_argument("DbTextDetectorOptions.max_input_side_px must be >= target_short_side_px");
    }
    if (o.band_from_geometry) ValidateBandGeometryOptions(o.band_geometry);
  });
  try {  // the pattern is a regex and every known room must match it
    PlateReadingValidator check(o.extractor.validator);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    const bool rooms = what.find("known_rooms") != std::string::npos;
    throw ParameterError((rooms ? source.Resolve("validator/known_rooms")
                                : source.Resolve(source.Has("validator/pattern") ? "validator/pattern" : "room_pattern")) +
                         ": " + what);
  }
  RequireModels(o, source);
  return o;
}

TextExtractorNodeOptions LoadTextExtractorOptions(const ros::NodeHandle& nh) {
  return TextExtractorOptionsFrom(RosParamSource(nh));
}

}  // namespace doorplate_localization
