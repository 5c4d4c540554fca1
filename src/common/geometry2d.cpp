#include "doorplate_localization/common/geometry2d.h"

#include <algorithm>

namespace doorplate_localization {

double NormalizeAngle(double angle_rad) {
  double a = std::remainder(angle_rad, 2.0 * M_PI);  // in [-pi, pi]
  if (a <= -M_PI) a += 2.0 * M_PI;
  return a;
}

Pose2D Pose2D::Compose(const Pose2D& other) const {
  const Vec2 p = TransformPoint(other.Position());
  return {p.x, p.y, NormalizeAngle(theta_rad + other.theta_rad)};
}

Vec2 Pose2D::TransformPoint(Vec2 local) const {
  const double c = std::cos(theta_rad), s = std::sin(theta_rad);
  return {x_m + c * local.x - s * local.y, y_m + s * local.x + c * local.y};
}

Pose2D Pose2D::Inverse() const {
  const double c = std::cos(theta_rad), s = std::sin(theta_rad);
  return {-(c * x_m + s * y_m), -(-s * x_m + c * y_m), NormalizeAngle(-theta_rad)};
}

Pose2D Pose2D::Between(const Pose2D& other) const { return Inverse().Compose(other); }

std::optional<double> RaySegmentDistance(Vec2 origin, Vec2 unit_direction, const Segment& segment,
                                         double* t_along_segment) {
  const Vec2 e = segment.b - segment.a;
  const double denom = Cross(unit_direction, e);
  if (std::fabs(denom) < 1e-12) return std::nullopt;  // parallel: grazing rays never hit
  const Vec2 w = segment.a - origin;
  const double t = Cross(w, e) / denom;           // along the ray
  double u = Cross(w, unit_direction) / denom;  // along the segment
  // Segments are closed with a hair of slack (1e-9 of their length): where two walls meet, rounding puts a
  // ray through the shared end point just outside both of them, and the laser saw through the corner.
  constexpr double kSlack = 1e-9;
  if (t < 0.0 || u < -kSlack || u > 1.0 + kSlack) return std::nullopt;
  u = std::clamp(u, 0.0, 1.0);
  if (t_along_segment != nullptr) *t_along_segment = u;
  return t;
}

double PointSegmentDistance(Vec2 p, const Segment& segment) {
  const Vec2 e = segment.b - segment.a;
  const double len2 = Dot(e, e);
  if (len2 <= 0.0) return Norm(p - segment.a);
  const double u = std::clamp(Dot(p - segment.a, e) / len2, 0.0, 1.0);
  return Norm(p - (segment.a + u * e));
}

}  // namespace doorplate_localization
