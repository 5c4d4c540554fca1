#include "world_detail_fields.h"

#include "doorplate_localization/common/limits.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "doorplate_localization/sim/clutter_presets.h"

namespace doorplate_localization {

double ParseCoordinateM(const YamlField& f) {
  const double v = f.AsDouble();
  const std::string problem = limits::CheckCoordinate(v);
  if (!problem.empty()) f.Fail(problem);
  return v;
}

Vec2 ParsePointM(const YamlField& f) {
  const std::vector<YamlField> items = f.Items();
  if (items.size() != 2) f.Fail("must be a list of 2 numbers, got " + std::to_string(items.size()));
  return {ParseCoordinateM(items[0]), ParseCoordinateM(items[1])};
}
namespace {

constexpr double kBumperHeightM = 0.3;  // as the simulator's: lower clutter stops the robot

int WallIndex(const YamlField& field, const std::map<std::string, int>& walls) {
  const std::string id = field.AsString();
  const auto it = walls.find(id);
  if (it == walls.end()) field.Fail("no wall with id '" + id + "'");
  return it->second;
}

double InRange(const YamlField& f, const std::string& key, double fallback, double lo, double hi) {
  if (!f.Has(key)) return fallback;
  const double v = f.Child(key).AsDouble();
  if (!(v >= lo && v <= hi)) {
    f.Child(key).Fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + std::to_string(v));
  }
  return v;
}

// Unit normal of wall `w` towards `side` ("left"/"right" of from→to; absent: the corridor side).
Vec2 SideNormal(const YamlField& f, const World& world, int w) {
  bool left = world.walls[w].corridor_side_left;
  if (f.Has("side")) {
    const std::string side = f.Child("side").AsString();
    if (side != "left" && side != "right") f.Child("side").Fail("must be 'left' or 'right' of the wall's from→to");
    left = side == "left";
  }
  return world.WallNormal(w, left);
}

// Intervals of wall `w` (offsets) taken by doors with their frames and by glass: runs break there.
std::vector<std::pair<double, double>> WallGaps(const World& world, int w) {
  std::vector<std::pair<double, double>> gaps;
  for (const Door& d : world.doors) {
    if (d.wall_index == w) gaps.push_back({d.offset_m - d.width_m / 2 - d.frame_width_m, d.offset_m + d.width_m / 2 + d.frame_width_m});
  }
  for (const GlassPanel& g : world.glass) {
    if (g.wall_index == w) gaps.push_back({g.offset_m - g.segment.Length() / 2, g.offset_m + g.segment.Length() / 2});
  }
  std::sort(gaps.begin(), gaps.end());
  return gaps;
}

// Pose of an item whose back is `gap_m` from the wall line at `offset_m`, its +y along `normal`.
Pose2D OnWall(const World& world, int w, double offset_m, Vec2 normal, double gap_m, double depth_m) {
  const Segment& s = world.walls[w].segment;
  const Vec2 p = s.a + (offset_m / s.Length()) * (s.b - s.a) + (gap_m + depth_m / 2) * normal;
  return {p.x, p.y, std::atan2(-normal.x, normal.y)};
}

// A wall-mounted item spanning offsets [from, to] and heights [z0, z1] on one side must not hide a plate.
void CheckPlatesClear(const YamlField& f, const World& world, int w, Vec2 normal, double from_m, double to_m,
                      const std::vector<ClutterBox>& boxes) {
  double z0 = 1e9, z1 = -1e9;
  for (const ClutterBox& b : boxes) z0 = std::min(z0, b.z_min_m), z1 = std::max(z1, b.z_max_m);
  for (const TextSign& sign : world.signs) {
    if (sign.wall_index != w) continue;
    const Vec2 facing = world.WallNormal(w, sign.corridor_side_left);
    if (Dot(facing, normal) <= 0.0) continue;  // the other side of the wall
    const bool along = sign.offset_m + sign.width_m / 2 > from_m && sign.offset_m - sign.width_m / 2 < to_m;
    const bool up = sign.center_height_m + sign.height_m / 2 > z0 && sign.center_height_m - sign.height_m / 2 < z1;
    if (along && up) f.Fail("covers sign '" + sign.text + "' on wall '" + world.walls[w].id + "'");
  }
}

std::vector<ClutterBox> PresetBoxes(const YamlField& f, const ClutterPreset& preset, double length_m) {
  double height_m = 0.0;
  if (f.Has("height_m")) {
    if (!preset.height_adjustable) f.Child("height_m").Fail("type '" + preset.type + "' has a fixed height");
    height_m = f.Positive("height_m", 0.0);
  }
  std::optional<ColorRgb> color;
  if (f.Has("color")) {
    ColorRgb c{};
    f.GetColor("color", &c);
    color = c;
  }
  try {
    return ClutterPresetBoxes(preset, length_m, height_m, color);
  } catch (const std::invalid_argument& e) {
    f.Fail(e.what());
  }
}

std::string ItemId(const YamlField& f, const World& world, const std::string& type) {
  std::string id = type + std::to_string(world.clutter.size() + 1);
  f.Get("id", &id);
  if (id.empty()) f.Child("id").Fail("must not be empty");
  for (const ClutterItem& other : world.clutter) {
    if (other.id == id || other.id.rfind(id + "#", 0) == 0) f.Fail("duplicate clutter id '" + id + "'");
  }
  return id;
}

// `handrail`, `skirting`: one item per stretch of [from_m, to_m] between doors and glass.
void ParseRun(const YamlField& f, const ClutterPreset& preset, const std::map<std::string, int>& walls,
              World* world) {
  f.RequireOnlyKeys({"type", "id", "wall", "from_m", "to_m", "side", "gap_m", "height_m", "color"});
  const std::string id = ItemId(f, *world, preset.type);
  const int w = WallIndex(f.Child("wall"), walls);
  const double length = world->walls[w].segment.Length();
  const double from_m = InRange(f, "from_m", 0.0, 0.0, length), to_m = InRange(f, "to_m", length, 0.0, length);
  if (!(to_m > from_m)) f.Child("to_m").Fail("must be > from_m");
  const Vec2 normal = SideNormal(f, *world, w);
  const double gap_m = InRange(f, "gap_m", preset.wall_gap_m, 0.0, 1.0);
  double cursor = from_m;
  int piece = 0;
  auto add = [&](double a, double b) {
    if (b - a < preset.min_length_m) return;
    const std::vector<ClutterBox> boxes = PresetBoxes(f, preset, b - a);
    CheckPlatesClear(f, *world, w, normal, a, b, boxes);
    world->clutter.push_back({id + "#" + std::to_string(++piece), preset.type,
                              OnWall(*world, w, (a + b) / 2, normal, gap_m, preset.depth_m), boxes});
  };
  for (const auto& [gap_from, gap_to] : WallGaps(*world, w)) {
    if (gap_to <= cursor || gap_from >= to_m) continue;
    add(cursor, std::min(gap_from, to_m));
    cursor = std::max(cursor, gap_to);
  }
  add(cursor, to_m);
  if (piece == 0) f.Fail("the run has no stretch of at least " + std::to_string(preset.min_length_m) + " m between doors");
}

}  // namespace

const std::set<std::string> kDoorDetailKeys = {"recess_m", "frame_width_m", "frame_depth_m", "frame_color"};

void ParseDoorDetail(const YamlField& f, Door* door) {
  door->recess_m = InRange(f, "recess_m", door->recess_m, 0.0, 0.5);
  door->frame_width_m = InRange(f, "frame_width_m", door->frame_width_m, 0.0, 0.3);
  door->frame_depth_m = InRange(f, "frame_depth_m", door->frame_depth_m, 0.0, 0.3);
  f.GetColor("frame_color", &door->frame_color);
}

void CheckDoorDetail(const YamlField& f, const World& world, const Door& door) {
  if (door.open && door.recess_m > 0.0) f.Fail("door '" + door.id + "': recess_m needs a closed door");
  if ((door.frame_width_m > 0.0) != (door.frame_depth_m > 0.0)) {
    f.Fail("door '" + door.id + "': give both frame_width_m and frame_depth_m (> 0), or neither");
  }
  const double half = door.width_m / 2 + door.frame_width_m;
  if (door.offset_m - half < 0 || door.offset_m + half > world.walls[door.wall_index].segment.Length()) {
    f.Fail("door '" + door.id + "' with its frame does not fit on wall '" + world.walls[door.wall_index].id + "'");
  }
  if (door.frame_width_m > 0.0 && door.height_m + door.frame_width_m > world.wall_height_m) {
    f.Fail("door '" + door.id + "': height_m + frame_width_m exceeds wall_height_m");
  }
}

void ParseGlass(const YamlField& f, const std::map<std::string, int>& walls, World* world) {
  f.RequireOnlyKeys({"id", "wall", "offset_m", "width_m", "room_depth_m", "room_width_m", "from", "to", "z_min_m", "z_max_m",
                     "laser_reflect_probability", "camera_opacity", "frame_width_m", "tint", "frame_color", "seed"});
  GlassPanel g;
  g.id = "glass" + std::to_string(world->glass.size() + 1);
  f.Get("id", &g.id);
  for (const GlassPanel& other : world->glass) {
    if (other.id == g.id) f.Fail("duplicate glass id '" + g.id + "'");
  }
  g.z_min_m = InRange(f, "z_min_m", 0.0, 0.0, world->wall_height_m);
  g.z_max_m = InRange(f, "z_max_m", std::min(g.z_max_m, world->wall_height_m), 0.0, world->wall_height_m);
  if (!(g.z_max_m > g.z_min_m)) f.Fail("z_max_m must be > z_min_m");
  g.laser_reflect_probability = InRange(f, "laser_reflect_probability", g.laser_reflect_probability, 0.0, 1.0);
  g.camera_opacity = InRange(f, "camera_opacity", g.camera_opacity, 0.01, 1.0);
  g.frame_width_m = InRange(f, "frame_width_m", g.frame_width_m, 0.0, 0.3);
  f.GetColor("tint", &g.tint);
  f.GetColor("frame_color", &g.frame_color);
  int seed = 0;
  f.Get("seed", &seed);
  if (seed < 0) f.Child("seed").Fail("must be >= 0");
  g.seed = static_cast<std::uint64_t>(seed);
  if (f.Has("wall")) {
    if (f.Has("from") || f.Has("to")) f.Fail("give either 'wall' + 'offset_m' + 'width_m' or 'from' + 'to'");
    g.wall_index = WallIndex(f.Child("wall"), walls);
    const Segment& wall = world->walls[g.wall_index].segment;
    g.offset_m = f.Child("offset_m").AsDouble();
    const double width = f.Child("width_m").AsDouble();
    if (!(width > 0.0)) f.Child("width_m").Fail("must be > 0, got " + std::to_string(width));
    if (g.offset_m - width / 2 < 0 || g.offset_m + width / 2 > wall.Length()) {
      f.Fail("glass '" + g.id + "' does not fit on wall '" + world->walls[g.wall_index].id + "'");
    }
    const Vec2 u = (1.0 / wall.Length()) * (wall.b - wall.a);
    g.segment = {wall.a + (g.offset_m - width / 2) * u, wall.a + (g.offset_m + width / 2) * u};
    g.room_depth_m = f.Positive("room_depth_m", 3.0);
    g.room_width_m = f.Positive("room_width_m", width);
    if (g.room_width_m < width) f.Child("room_width_m").Fail("must be >= width_m");
    for (const auto& [from_m, to_m] : WallGaps(*world, g.wall_index)) {
      if (from_m < g.offset_m + width / 2 && to_m > g.offset_m - width / 2) {
        f.Fail("glass '" + g.id + "' overlaps a door (with its frame) or other glass on wall '" +
               world->walls[g.wall_index].id + "'");
      }
    }
  } else {
    if (f.Has("offset_m") || f.Has("width_m") || f.Has("room_depth_m") || f.Has("room_width_m")) {
      f.Fail("'offset_m', 'width_m', 'room_depth_m' and 'room_width_m' need 'wall'");
    }
    g.segment = {ParsePointM(f.Child("from")), ParsePointM(f.Child("to"))};
  }
  if (!(g.segment.Length() > 2 * g.frame_width_m + 0.01)) f.Fail("glass must be wider than its two frame posts + 1 cm");
  world->glass.push_back(g);
}

void ParseClutter(const YamlField& f, const std::map<std::string, int>& walls, World* world) {
  const std::string type = f.Child("type").AsString();
  const ClutterPreset* preset = FindClutterPreset(type);
  if (preset == nullptr) {
    std::string names;
    for (const ClutterPreset& p : ClutterPresets()) names += (names.empty() ? "" : ", ") + p.type;
    f.Child("type").Fail("unknown clutter type '" + type + "' (one of " + names + ")");
  }
  if (preset->run) return ParseRun(f, *preset, walls, world);
  f.RequireOnlyKeys({"type", "id", "wall", "offset_m", "side", "gap_m", "x_m", "y_m", "yaw_deg", "length_m",
                     "height_m", "color"});
  ClutterItem item;
  item.type = type;
  item.id = ItemId(f, *world, type);
  double length_m = 0.0;
  if (f.Has("length_m")) {
    if (preset->min_length_m == preset->max_length_m) f.Child("length_m").Fail("type '" + type + "' has a fixed size");
    length_m = f.Positive("length_m", 0.0);
  }
  item.boxes = PresetBoxes(f, *preset, length_m);
  const double l = length_m > 0.0 ? length_m : preset->length_m;
  if (f.Has("wall")) {
    for (const char* key : {"x_m", "y_m", "yaw_deg"}) {
      if (f.Has(key)) f.Fail(std::string("give either 'wall' + 'offset_m' or 'x_m' + 'y_m' (+ 'yaw_deg'), not '") +
                             key + "' with 'wall'");
    }
    const int w = WallIndex(f.Child("wall"), walls);
    const double offset_m = f.Child("offset_m").AsDouble();
    if (offset_m - l / 2 < 0 || offset_m + l / 2 > world->walls[w].segment.Length()) {
      f.Fail("clutter '" + item.id + "' does not fit on wall '" + world->walls[w].id + "'");
    }
    const Vec2 normal = SideNormal(f, *world, w);
    item.pose = OnWall(*world, w, offset_m, normal, InRange(f, "gap_m", preset->wall_gap_m, 0.0, 1.0), preset->depth_m);
    CheckPlatesClear(f, *world, w, normal, offset_m - l / 2, offset_m + l / 2, item.boxes);
  } else {
    for (const char* key : {"offset_m", "side", "gap_m"}) {
      if (f.Has(key)) f.Fail(std::string("'") + key + "' needs 'wall'");
    }
    double yaw_deg = 0.0;
    f.Get("yaw_deg", &yaw_deg);
    item.pose = {ParseCoordinateM(f.Child("x_m")), ParseCoordinateM(f.Child("y_m")),
                 NormalizeAngle(yaw_deg * M_PI / 180.0)};
  }
  world->clutter.push_back(item);
}

void ParsePerson(const YamlField& f, World* world) {
  f.RequireOnlyKeys({"id", "waypoints", "speed_mps", "mode", "pause_s", "start_offset_s", "height_m", "top_color",
                     "legs_color"});
  Person p;
  p.id = "person" + std::to_string(world->people.size() + 1);
  f.Get("id", &p.id);
  for (const Person& other : world->people) {
    if (other.id == p.id) f.Fail("duplicate person id '" + p.id + "'");
  }
  const std::vector<YamlField> points = f.Child("waypoints").Items();
  if (points.size() < 2) f.Child("waypoints").Fail("needs at least 2 points");
  for (const YamlField& point : points) {
    p.waypoints.push_back(ParsePointM(point));
    if (p.waypoints.size() > 1 && Norm(p.waypoints.back() - p.waypoints[p.waypoints.size() - 2]) < 0.01) {
      point.Fail("must be at least 1 cm from the previous waypoint");
    }
  }
  std::string mode = "back_and_forth";
  f.Get("mode", &mode);
  if (mode != "back_and_forth" && mode != "loop") f.Child("mode").Fail("must be 'back_and_forth' or 'loop'");
  p.loop = mode == "loop";
  if (p.loop && Norm(p.waypoints.back() - p.waypoints.front()) < 0.01) {
    f.Child("waypoints").Fail("a loop's last waypoint must be at least 1 cm from its first (the loop closes itself)");
  }
  p.speed_mps = InRange(f, "speed_mps", p.speed_mps, 0.1, 3.0);
  p.pause_s = InRange(f, "pause_s", p.pause_s, 0.0, 3600.0);
  p.start_offset_s = InRange(f, "start_offset_s", p.start_offset_s, 0.0, 1e6);
  p.height_m = InRange(f, "height_m", p.height_m, 1.0, 2.2);
  p.hip_height_m = 0.512 * p.height_m;
  f.GetColor("top_color", &p.top_color);
  f.GetColor("legs_color", &p.legs_color);
  world->people.push_back(p);
}

void CheckStartOutsideClutter(const YamlField& robot, const World& world) {
  for (const ClutterItem& item : world.clutter) {
    const Vec2 local = item.pose.Inverse().TransformPoint(world.start_pose.Position());
    for (const ClutterBox& b : item.boxes) {
      if (b.z_min_m > kBumperHeightM) continue;
      if (std::fabs(local.x - b.center.x) < b.size_x_m / 2 + world.robot_radius_m &&
          std::fabs(local.y - b.center.y) < b.size_y_m / 2 + world.robot_radius_m) {
        robot.Child("start").Fail("start pose is inside or touching clutter '" + item.id + "'");
      }
    }
  }
}

}  // namespace doorplate_localization
