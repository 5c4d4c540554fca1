#include "doorplate_localization/sim/top_down_view.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {

TopDownView::TopDownView(const World& world, double margin_m, int max_side_px) : world_(world) {
  double x0 = world.start_pose.x_m, x1 = x0, y0 = world.start_pose.y_m, y1 = y0;
  for (const Surface& s : world.surfaces) {
    for (const Vec2& p : {s.segment.a, s.segment.b}) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
  }
  x0 -= margin_m, y0 -= margin_m, x1 += margin_m, y1 += margin_m;
  px_per_m_ = std::clamp(std::min(max_side_px / (x1 - x0), max_side_px / (y1 - y0)), 5.0, 80.0);
  x0_ = x0;
  y1_ = y1;
  image_ = cv::Mat(static_cast<int>((y1 - y0) * px_per_m_), static_cast<int>((x1 - x0) * px_per_m_), CV_8UC3,
                   cv::Scalar(255, 255, 255));
  DrawWorld();
}

cv::Point TopDownView::ToPixel(Vec2 p) const {
  return cv::Point(static_cast<int>(std::lround((p.x - x0_) * px_per_m_)),
                   static_cast<int>(std::lround((y1_ - p.y) * px_per_m_)));
}

void TopDownView::DrawWorld() {
  const auto on_wall = [&](int wall, double offset_m) {
    const Segment& s = world_.walls[wall].segment;
    return s.a + (offset_m / s.Length()) * (s.b - s.a);
  };
  const double laser_z = world_.sensors.laser.mount_height_m;
  for (const Surface& s : world_.surfaces) {
    const bool wall_piece = s.wall_index >= 0 && s.z_min_m <= 0.0;
    cv::Scalar colour = wall_piece ? cv::Scalar(60, 60, 60) : cv::Scalar(200, 170, 150);
    int thickness = wall_piece ? 3 : 1;
    if (s.kind != SurfaceKind::kStructure) {  // detail: thick where the laser sees it
      static const cv::Scalar kColours[] = {{60, 60, 60}, {90, 90, 90}, {30, 120, 210}, {230, 190, 90}, {170, 0, 170}};
      colour = kColours[static_cast<int>(s.kind)];
      thickness = s.z_min_m <= laser_z && laser_z <= s.z_max_m ? 2 : 1;
    }
    cv::line(image_, ToPixel(s.segment.a), ToPixel(s.segment.b), colour, thickness, cv::LINE_AA);
  }
  for (const Door& door : world_.doors) {
    const Vec2 a = on_wall(door.wall_index, door.offset_m - door.width_m / 2);
    const Vec2 b = on_wall(door.wall_index, door.offset_m + door.width_m / 2);
    cv::line(image_, ToPixel(a), ToPixel(b), cv::Scalar(door.color[2], door.color[1], door.color[0]),
             door.open ? 1 : 5);
  }
  for (const TextSign& sign : world_.signs) {
    const Vec2 normal = world_.WallNormal(sign.wall_index, sign.corridor_side_left);
    const Vec2 centre = world_.SignPosition(sign) + 0.08 * normal;
    const bool plate = sign.kind == TextKind::kPlate;
    const cv::Scalar colour = plate ? cv::Scalar(200, 90, 20) : cv::Scalar(0, 140, 255);
    cv::circle(image_, ToPixel(centre), 4, colour, cv::FILLED, cv::LINE_AA);
    cv::putText(image_, sign.text, ToPixel(world_.SignPosition(sign) + 0.45 * normal) + cv::Point(-12, 5),
                cv::FONT_HERSHEY_SIMPLEX, 0.45, colour, 1, cv::LINE_AA);
  }
}

void TopDownView::DrawScan(const LaserScan& scan, const Pose2D& laser_pose, const cv::Scalar& bgr) {
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double r = scan.ranges_m[i];
    if (!std::isfinite(r)) continue;
    const double angle = scan.angle_min_rad + i * scan.angle_increment_rad;
    cv::circle(image_, ToPixel(laser_pose.TransformPoint({r * std::cos(angle), r * std::sin(angle)})), 2, bgr,
               cv::FILLED);
  }
}

void TopDownView::DrawCameraFov(const CameraRenderer& camera, const Pose2D& pose) {
  const CameraIntrinsics& k = camera.intrinsics();
  double mx, my, mz, yaw, pitch;
  camera.MountPose(&mx, &my, &mz, &yaw, &pitch);
  const Vec2 eye = pose.TransformPoint({mx, my});
  const double half_fov = std::atan2(0.5 * k.width_px, k.fx_px);
  for (double side : {-1.0, 1.0}) {
    const double a = pose.theta_rad + yaw + side * half_fov;
    cv::line(image_, ToPixel(eye), ToPixel(eye + 3.0 * Vec2{std::cos(a), std::sin(a)}), cv::Scalar(40, 170, 40), 1,
             cv::LINE_AA);
  }
}

void TopDownView::DrawRobot(const Pose2D& pose, const cv::Scalar& bgr) {
  const Vec2 nose = pose.TransformPoint({world_.robot_radius_m, 0.0});
  cv::circle(image_, ToPixel(pose.Position()), static_cast<int>(world_.robot_radius_m * px_per_m_), bgr, 2,
             cv::LINE_AA);
  cv::line(image_, ToPixel(pose.Position()), ToPixel(nose), bgr, 2, cv::LINE_AA);
}

void TopDownView::DrawTrajectory(const std::vector<Pose2D>& poses, const cv::Scalar& bgr, int thickness) {
  std::vector<cv::Point> points;
  points.reserve(poses.size());
  for (const Pose2D& p : poses) points.push_back(ToPixel(p.Position()));
  if (points.size() >= 2) cv::polylines(image_, points, /*isClosed=*/false, bgr, thickness, cv::LINE_AA);
}

void TopDownView::DrawLegend(int row, const std::string& text, const cv::Scalar& bgr) {
  cv::putText(image_, text, cv::Point(10, 22 + 22 * row), cv::FONT_HERSHEY_SIMPLEX, 0.6, bgr, 1, cv::LINE_AA);
}

}  // namespace doorplate_localization
