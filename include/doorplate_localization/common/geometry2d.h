// 2D geometry shared by the simulator and the filters: poses, segments, ray casting.
// Frames: all poses are of a child frame expressed in a parent frame; x forward, y left, theta
// counter-clockwise (REP-103). Units: metres and radians.
#pragma once

#include <cmath>
#include <optional>

namespace doorplate_localization {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline double Dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double Cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double Norm(Vec2 a) { return std::hypot(a.x, a.y); }

// Wraps an angle to (-pi, pi].
double NormalizeAngle(double angle_rad);

struct Pose2D {
  double x_m = 0.0;
  double y_m = 0.0;
  double theta_rad = 0.0;

  Vec2 Position() const { return {x_m, y_m}; }
  // Composition this ⊕ other: `other` is expressed in this pose's frame.
  Pose2D Compose(const Pose2D& other) const;
  // Maps a point from this pose's frame into the parent frame.
  Vec2 TransformPoint(Vec2 local) const;
  // Inverse pose: the parent frame expressed in this pose's frame.
  Pose2D Inverse() const;
  // Relative pose: `other` expressed in this pose's frame (this⁻¹ ⊕ other).
  Pose2D Between(const Pose2D& other) const;
};

struct Segment {
  Vec2 a;
  Vec2 b;
  double Length() const { return Norm(b - a); }
};

// Distance along a ray (origin + t * unit_direction, t >= 0) to a segment; nullopt when it misses.
// `t_along_segment` (optional out) receives the hit's position along the segment in [0, 1].
std::optional<double> RaySegmentDistance(Vec2 origin, Vec2 unit_direction, const Segment& segment,
                                         double* t_along_segment = nullptr);

// Shortest distance from a point to a segment, metres.
double PointSegmentDistance(Vec2 p, const Segment& segment);

}  // namespace doorplate_localization
