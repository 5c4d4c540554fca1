// Ground truth for the text-reading experiment (paper Table I): which doorplate a reported box shows, and
// which plates the robot passed. Truth comes from the world and the TRUE robot pose of each camera frame:
// a plate is visible when its centre projects into the image (CameraRenderer::Project), it faces the
// camera and no wall hides it; it is passed when its projection crosses the image's centre column while
// the robot is on a leg of its sweep (not while turning). A report belongs to the visible plate whose
// projection lies in the reported box (the one nearest the box centre), else to the nearest one within
// half a box width of the box centre, else to no plate (spurious).
// Frames: world frame (metres) for plates and poses, image pixels for boxes.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "doorplate_localization/sim/camera_renderer.h"
#include "doorplate_localization/sim/world.h"
#include "doorplate_localization/text/plate_tracker.h"

namespace doorplate_localization {

struct PlateTruth {
  std::string text;
  std::string label;   // door id, or "plate<k>" for a plate without a door
  Vec2 position;       // sign centre on its wall, world frame
  double height_m = 0.0;
  Vec2 facing;         // unit normal of the sign's face
};

// One pass's record of one plate.
struct PlatePassRecord {
  bool passed = false;
  int correct_reports = 0;
  std::vector<std::string> reported_texts;  // every report attributed to this plate, in order
};

enum class ReportKind { kCorrect, kFalseRead, kSpurious };

struct ReportVerdict {
  ReportKind kind = ReportKind::kSpurious;
  int plate = -1;          // index into plates(), -1 for spurious
  bool duplicate = false;  // the plate had already been reported in this pass
};

struct PassScore {
  int plates_passed = 0;
  int plates_correct = 0;   // passed and reported with the right text at least once
  int false_reads = 0;      // reports naming a wrong text for a real plate
  int spurious = 0;         // reports where no plate was
  int duplicates = 0;       // reports of a plate beyond its first in the pass
  int reports = 0;
  std::vector<PlatePassRecord> plates;  // per plates() entry
};

class PlateScorer {
 public:
  // `world` and `camera` must outlive the scorer.
  PlateScorer(const World& world, const CameraRenderer& camera);

  const std::vector<PlateTruth>& plates() const { return plates_; }

  void BeginPass();
  // Feeds one camera frame's true pose. `on_leg`: the robot is following a wall (crossings count).
  // Returns the plates that were passed in this frame.
  std::vector<int> ObserveFrame(const Pose2D& true_pose, bool on_leg);
  // Scores one report of a frame taken at `true_pose` and records it in the pass.
  ReportVerdict ScoreReport(const PlateReport& report, const Pose2D& true_pose);
  const PassScore& pass() const { return pass_; }

  // The plate a box at `true_pose` shows (index into plates()), or -1: the visible plate whose centre
  // pixel is inside the box (the nearest), else the nearest within half the box width plus the box
  // height of the box centre (a fragment of the plate's text line).
  int MatchBox(const cv::Rect& box_px, const Pose2D& true_pose) const;
  // Whether plate `index` is visible at `true_pose`; `pixel` (optional) receives its projection.
  bool Visible(int index, const Pose2D& true_pose, cv::Point2d* pixel) const;
  // Number of plates visible at `true_pose`.
  int CountVisible(const Pose2D& true_pose) const;

 private:
  const World& world_;
  const CameraRenderer& camera_;
  std::vector<PlateTruth> plates_;
  PassScore pass_;
  std::vector<double> last_offset_px_;  // per plate: u − cx in the previous frame, NaN if not visible then
};

}  // namespace doorplate_localization
