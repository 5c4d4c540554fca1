// The text-reading experiment of the paper's Section 4.2 (Table I, Figure 12) on a simulated world: the
// robot sweeps the corridor (CorridorSweep: one wall out, turn, the other wall back) in the Simulator
// (physics 100 Hz, laser and control at the laser's rate, camera at its rate); every camera image goes to
// a TextExtractor and every PlateReport is scored against ground truth (PlateScorer). For Figure 12 the
// MSER detector alone also runs on the same frames in three modes: full image without NMS, full image
// with NMS, and the fixed band with NMS. Deterministic for a given seed, except the timings (thread CPU
// time for the per-frame costs, wall-clock time for whole passes).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "doorplate_localization/behaviour/corridor_sweep.h"
#include "doorplate_localization/sim/world.h"
#include "doorplate_localization/text/text_extractor.h"
#include "plate_scorer.h"

namespace doorplate_localization {

struct OcrEvalOptions {
  int passes = 3;
  std::uint64_t seed = 1;          // pass i uses PassSeed(seed, i) for the simulator
  double speed_mps = 0.4;          // cruise speed (CorridorSweepOptions::follower.cruise_speed_mps)
  bool band = true;                // the extractor searches the fixed band (false: the full image)
  bool known_rooms = false;        // the validator gets the world's plate texts as known rooms
  int detector_every_n_frames = 1; // Figure 12 detector runs on every n-th frame; 0: not at all
  double max_pass_time_s = 1800.0; // simulated seconds; a sweep not done by then ends the pass
  std::string dump_dir;            // "": no failure images
  CorridorSweepOptions sweep;      // cruise speed overridden by speed_mps
  TextExtractorOptions extractor;  // band, known rooms, tracker intrinsics set from the above / camera
  // > 0: a progress line on stderr (pass, simulated seconds, distance driven, plates passed and read) every
  // this many simulated seconds of the run, rewritten in place on a terminal (progress_line.h).
  double progress_every_s = 0.0;
};

// A reading error or a missed plate, for the JSON detail and the dumps.
struct OcrEvalEvent {
  std::string kind;      // "false_read", "spurious", "duplicate", "missed"
  int pass = 0;
  double stamp_s = 0.0;  // simulated time of the frame (missed: when the plate was passed)
  std::string reported;  // reported text (missed: the wrong texts reported for the plate, comma-separated)
  std::string truth;     // plate text ("" for spurious)
  std::string plate;     // plate label ("" for spurious)
  cv::Rect box_px;
  std::string image;     // dumped image file name, "" if none
};

struct OcrPassResult {
  std::uint64_t seed = 0;
  PassScore score;
  int frames = 0;
  double sim_seconds = 0.0;
  double wall_seconds = 0.0;
  bool sweep_done = false;  // the sweep reached kDone within max_pass_time_s
};

// One Figure 12 detector mode over all frames it ran on.
struct DetectorModeStats {
  std::string name;  // "mser_full", "mser_nms_full", "mser_nms_band"
  bool band = false;
  bool nms = false;
  int frames = 0, frames_plate_in_view = 0;
  long long boxes = 0, boxes_plate_in_view = 0;
  double seconds = 0.0;  // thread CPU time in Detect
};

struct OcrEvalResult {
  std::string world_name;
  std::vector<PlateTruth> plates;
  std::vector<OcrPassResult> passes;
  std::vector<OcrEvalEvent> events;
  std::vector<DetectorModeStats> detectors;
  double extractor_seconds = 0.0;  // TextExtractor::Process thread CPU time over all frames
  int extractor_boxes = 0;         // text boxes the extractor's detector gave, all frames

  int Frames() const;
  int PlatesTotal() const;
  int PlatesCorrect() const;
};

// Runs the experiment. Throws std::invalid_argument / std::runtime_error from the components (bad
// options, missing Tesseract model), naming the field or file.
OcrEvalResult RunOcrEval(const World& world, const OcrEvalOptions& options);

}  // namespace doorplate_localization
