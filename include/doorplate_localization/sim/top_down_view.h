// A top-down picture of a world (x to the right, y up) to draw poses, scans and trajectories on: for the
// snapshot tool, run reports and docs. Colours are OpenCV BGR.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "doorplate_localization/sim/camera_renderer.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

class TopDownView {
 public:
  // Sizes the picture to the world's surfaces plus `margin_m`, at most `max_side_px` pixels a side and
  // between 5 and 80 px per metre; draws walls, doors and labelled signs, and the detail: door frames
  // (grey), clutter (orange), glass (light blue), people (purple), thick where the laser sees them.
  explicit TopDownView(const World& world, double margin_m = 1.0, int max_side_px = 4000);

  cv::Point ToPixel(Vec2 world_point) const;
  double px_per_m() const { return px_per_m_; }
  cv::Mat& image() { return image_; }

  // Laser hits of `scan` taken from `laser_pose` (laser frame in the world), as dots.
  void DrawScan(const LaserScan& scan, const Pose2D& laser_pose, const cv::Scalar& bgr = {0, 0, 230});
  // The camera's horizontal field of view from the robot at `robot_pose`, 3 m long.
  void DrawCameraFov(const CameraRenderer& camera, const Pose2D& robot_pose);
  // The robot's outline and heading.
  void DrawRobot(const Pose2D& robot_pose, const cv::Scalar& bgr = {30, 30, 30});
  // A polyline through the poses' positions.
  void DrawTrajectory(const std::vector<Pose2D>& poses, const cv::Scalar& bgr, int thickness = 2);
  // A small legend line at the top left (row 0, 1, ...).
  void DrawLegend(int row, const std::string& text, const cv::Scalar& bgr);

 private:
  void DrawWorld();

  const World& world_;
  double x0_ = 0, y1_ = 0, px_per_m_ = 20;
  cv::Mat image_;
};

}  // namespace doorplate_localization
