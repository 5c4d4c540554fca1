#include "doorplate_localization/sim/people.h"

#include <cmath>

#include "world_detail_surfaces.h"

namespace doorplate_localization {
namespace {

constexpr double kLegSpacingM = 0.09;   // leg centre from the walking line
constexpr double kLegSwingM = 0.18;     // fore-aft swing of a leg at the laser's height, amplitude
constexpr int kLegSides = 8;
const ColorRgb kSkin{222, 186, 158};

// The visiting order of the waypoints in one cycle: back and forth (0..n-1..0) or a loop (0..n-1, 0).
std::vector<Vec2> CyclePoints(const Person& person) {
  std::vector<Vec2> points = person.waypoints;
  if (person.loop) {
    points.push_back(person.waypoints.front());
  } else {
    for (int i = static_cast<int>(person.waypoints.size()) - 2; i >= 0; --i) points.push_back(person.waypoints[i]);
  }
  return points;
}

}  // namespace

PersonState PersonAt(const Person& person, double time_s) {
  const std::vector<Vec2> points = CyclePoints(person);
  double cycle_length_m = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) cycle_length_m += Norm(points[i] - points[i - 1]);
  const double legs = static_cast<double>(points.size() - 1);
  const double cycle_s = cycle_length_m / person.speed_mps + legs * person.pause_s;
  const double t = time_s + person.start_offset_s;
  const double cycles = std::floor(t / cycle_s);
  double in_cycle = t - cycles * cycle_s;
  PersonState state;
  state.walked_m = cycles * cycle_length_m;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Vec2 a = points[i - 1], b = points[i];
    const double length = Norm(b - a), walk_s = length / person.speed_mps;
    state.heading_rad = std::atan2(b.y - a.y, b.x - a.x);
    if (in_cycle < walk_s) {
      const double along = in_cycle * person.speed_mps;
      state.position = a + (along / length) * (b - a);
      state.walked_m += along;
      return state;
    }
    state.walked_m += length;
    state.position = b;
    if (in_cycle < walk_s + person.pause_s) {
      state.standing = true;
      return state;
    }
    in_cycle -= walk_s + person.pause_s;
  }
  state.standing = true;  // only by rounding at the very end of a cycle
  return state;
}

void AppendPersonSurfaces(const Person& person, const PersonState& state, std::vector<Surface>* out) {
  const Pose2D body{state.position.x, state.position.y, state.heading_rad};
  const double swing = state.standing ? 0.0 : kLegSwingM * std::sin(2.0 * M_PI * state.walked_m / person.stride_m);
  const double radius = person.leg_diameter_m / 2.0;
  for (const double side : {-1.0, 1.0}) {
    const Vec2 centre = body.TransformPoint({side * swing, side * kLegSpacingM});
    for (int k = 0; k < kLegSides; ++k) {
      const double a0 = 2.0 * M_PI * k / kLegSides, a1 = 2.0 * M_PI * (k + 1) / kLegSides;
      Surface face;
      face.segment = {centre + radius * Vec2{std::cos(a0), std::sin(a0)},
                      centre + radius * Vec2{std::cos(a1), std::sin(a1)}};
      face.z_max_m = person.hip_height_m;
      face.color = person.legs_color;
      face.kind = SurfaceKind::kPerson;
      out->push_back(face);
    }
  }
  ClutterBox torso;
  torso.size_x_m = 0.24;
  torso.size_y_m = 0.42;
  torso.z_min_m = person.hip_height_m;
  torso.z_max_m = person.height_m - 0.25;
  torso.color = person.top_color;
  AddBoxFaces(body, torso, SurfaceKind::kPerson, out);
  ClutterBox head;
  head.size_x_m = 0.20;
  head.size_y_m = 0.18;
  head.z_min_m = person.height_m - 0.25;
  head.z_max_m = person.height_m;
  head.color = kSkin;
  AddBoxFaces(body, head, SurfaceKind::kPerson, out);
}

void PlacePeople(World& world, double time_s) {
  if (world.people.empty()) return;
  world.surfaces.resize(world.num_static_surfaces);
  for (const Person& person : world.people) AppendPersonSurfaces(person, PersonAt(person, time_s), &world.surfaces);
}

}  // namespace doorplate_localization
