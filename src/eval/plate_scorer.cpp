#include "plate_scorer.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

std::string Label(const World& world, const TextSign& sign) {
  if (sign.door_index >= 0) return world.doors.at(sign.door_index).id;
  char offset[32];
  std::snprintf(offset, sizeof(offset), "%.2f", sign.offset_m);
  return world.walls.at(sign.wall_index).id + "@" + offset;
}

}  // namespace

PlateScorer::PlateScorer(const World& world, const CameraRenderer& camera) : world_(world), camera_(camera) {
  for (const TextSign* sign : world.Plates()) {
    PlateTruth plate;
    plate.text = sign->text;
    plate.label = Label(world, *sign);
    plate.position = world.SignPosition(*sign);
    plate.height_m = sign->center_height_m;
    plate.facing = world.WallNormal(sign->wall_index, sign->corridor_side_left);
    plates_.push_back(plate);
  }
  BeginPass();
}

void PlateScorer::BeginPass() {
  pass_ = PassScore{};
  pass_.plates.assign(plates_.size(), PlatePassRecord{});
  last_offset_px_.assign(plates_.size(), kNan);
}

bool PlateScorer::Visible(int index, const Pose2D& true_pose, cv::Point2d* pixel) const {
  const PlateTruth& plate = plates_.at(index);
  cv::Point2d px;
  if (!camera_.Project(true_pose, {plate.position.x, plate.position.y, plate.height_m}, &px)) return false;
  const CameraIntrinsics& k = camera_.intrinsics();
  if (px.x < 0 || px.y < 0 || px.x > k.width_px - 1 || px.y > k.height_px - 1) return false;
  double mx, my, mz, yaw, pitch;
  camera_.MountPose(&mx, &my, &mz, &yaw, &pitch);
  const Vec2 camera = true_pose.TransformPoint({mx, my});
  const Vec2 to_plate = plate.position - camera;
  const double distance = Norm(to_plate);
  if (distance < 1e-6 || Dot(plate.facing, to_plate) >= 0.0) return false;  // seen from behind
  const Vec2 direction = (1.0 / distance) * to_plate;
  for (const Surface& surface : world_.surfaces) {
    if (plate.height_m < surface.z_min_m || plate.height_m > surface.z_max_m) continue;
    const auto hit = RaySegmentDistance(camera, direction, surface.segment);
    if (hit && *hit < distance - 0.02) return false;  // hidden behind another surface
  }
  if (pixel != nullptr) *pixel = px;
  return true;
}

int PlateScorer::CountVisible(const Pose2D& true_pose) const {
  int count = 0;
  for (size_t i = 0; i < plates_.size(); ++i) count += Visible(static_cast<int>(i), true_pose, nullptr) ? 1 : 0;
  return count;
}

std::vector<int> PlateScorer::ObserveFrame(const Pose2D& true_pose, bool on_leg) {
  std::vector<int> passed_now;
  const double cx = camera_.intrinsics().cx_px;
  for (size_t i = 0; i < plates_.size(); ++i) {
    cv::Point2d px;
    if (!on_leg || !Visible(static_cast<int>(i), true_pose, &px)) {
      last_offset_px_[i] = kNan;
      continue;
    }
    const double offset = px.x - cx;
    const double previous = last_offset_px_[i];
    last_offset_px_[i] = offset;
    if (std::isnan(previous) || (previous > 0.0) == (offset > 0.0)) continue;
    if (!pass_.plates[i].passed) {
      pass_.plates[i].passed = true;
      ++pass_.plates_passed;
      if (pass_.plates[i].correct_reports > 0) ++pass_.plates_correct;
      passed_now.push_back(static_cast<int>(i));
    }
  }
  return passed_now;
}

int PlateScorer::MatchBox(const cv::Rect& box_px, const Pose2D& true_pose) const {
  const cv::Point2d centre(box_px.x + 0.5 * box_px.width, box_px.y + 0.5 * box_px.height);
  int inside = -1, near = -1;
  // Near: within half the box width plus one text height of its centre. A separator can split a plate's
  // line in one frame ("E14" + "295"), and the report then carries the fragment's box.
  double inside_distance = std::numeric_limits<double>::infinity(),
         near_distance = 0.5 * box_px.width + box_px.height;
  for (size_t i = 0; i < plates_.size(); ++i) {
    cv::Point2d px;
    if (!Visible(static_cast<int>(i), true_pose, &px)) continue;
    const double distance = std::hypot(px.x - centre.x, px.y - centre.y);
    const bool in_box = px.x >= box_px.x && px.x <= box_px.x + box_px.width && px.y >= box_px.y &&
                        px.y <= box_px.y + box_px.height;
    if (in_box && distance < inside_distance) {
      inside = static_cast<int>(i);
      inside_distance = distance;
    } else if (!in_box && distance <= near_distance) {
      near = static_cast<int>(i);
      near_distance = distance;
    }
  }
  return inside >= 0 ? inside : near;
}

ReportVerdict PlateScorer::ScoreReport(const PlateReport& report, const Pose2D& true_pose) {
  ReportVerdict verdict;
  ++pass_.reports;
  verdict.plate = MatchBox(report.box_px, true_pose);
  if (verdict.plate < 0) {
    ++pass_.spurious;
    return verdict;
  }
  PlatePassRecord& record = pass_.plates[verdict.plate];
  verdict.duplicate = !record.reported_texts.empty();
  if (verdict.duplicate) ++pass_.duplicates;
  record.reported_texts.push_back(report.text);
  if (!SameRoom(report.text, plates_[verdict.plate].text)) {
    verdict.kind = ReportKind::kFalseRead;
    ++pass_.false_reads;
    return verdict;
  }
  verdict.kind = ReportKind::kCorrect;
  if (record.correct_reports++ == 0 && record.passed) ++pass_.plates_correct;
  return verdict;
}

}  // namespace doorplate_localization
