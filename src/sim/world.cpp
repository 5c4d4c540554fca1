#include "doorplate_localization/sim/world.h"

#include <algorithm>
#include <cmath>

#include "world_detail_surfaces.h"

namespace doorplate_localization {
namespace {

Vec2 UnitAlong(const Segment& s) {
  const Vec2 d = s.b - s.a;
  return (1.0 / Norm(d)) * d;
}

Vec2 PointOnWall(const Wall& wall, double offset_m) {
  return wall.segment.a + offset_m * UnitAlong(wall.segment);
}


const ColorRgb kRoomColor{205, 212, 228};

// A closed door `recess_m` behind its wall's line: the leaf (textured as the wall, so the camera draws the
// door and its plates on it) and the two reveals joining it to the wall line.
void AddRecessedLeaf(const World& world, int w, const Door& door, std::vector<Surface>* out) {
  const Wall& wall = world.walls[w];
  const Vec2 back = door.recess_m * world.WallNormal(w, !wall.corridor_side_left);
  const double from_m = door.offset_m - door.width_m / 2.0, to_m = door.offset_m + door.width_m / 2.0;
  const Vec2 a = PointOnWall(wall, from_m), b = PointOnWall(wall, to_m);
  Surface leaf;
  leaf.segment = {a + back, b + back};
  leaf.z_max_m = door.height_m;
  leaf.wall_index = w;
  leaf.wall_offset_at_a_m = from_m;
  leaf.color = wall.color;
  leaf.kind = SurfaceKind::kDoorDetail;
  out->push_back(leaf);
  for (const Segment& s : {Segment{a, a + back}, Segment{b + back, b}}) {
    Surface reveal;
    reveal.segment = s;
    reveal.z_max_m = door.height_m;
    reveal.color = door.frame_color;
    reveal.kind = SurfaceKind::kDoorDetail;
    out->push_back(reveal);
  }
}

// A gap in a wall's line between two offsets and heights: an open door (lintel above, room box behind),
// a recessed closed door (lintel above, leaf and reveals behind) or glass (sill, lintel, pane, room box).
struct WallOpening {
  double from_m = 0.0, to_m = 0.0, z_min_m = 0.0, z_max_m = 0.0;
  const Door* door = nullptr;
  const GlassPanel* glass = nullptr;
};

std::vector<WallOpening> WallOpenings(const World& world, int w) {
  std::vector<WallOpening> openings;
  for (const Door& door : world.doors) {
    if (door.wall_index == w && (door.open || door.recess_m > 0.0)) {
      openings.push_back({door.offset_m - door.width_m / 2.0, door.offset_m + door.width_m / 2.0, 0.0,
                          door.height_m, &door, nullptr});
    }
  }
  for (const GlassPanel& glass : world.glass) {
    if (glass.wall_index != w) continue;
    const double half = glass.segment.Length() / 2.0;
    openings.push_back({glass.offset_m - half, glass.offset_m + half, glass.z_min_m, glass.z_max_m, nullptr, &glass});
  }
  std::sort(openings.begin(), openings.end(),
            [](const WallOpening& a, const WallOpening& b) { return a.from_m < b.from_m; });
  return openings;
}

// The room box behind an opening: two side walls and a back wall, on the side away from the corridor.
void AddRoomBox(const World& world, int wall_index, double offset_m, double room_width_m, double room_depth_m,
                std::vector<Surface>* out) {
  const Wall& wall = world.walls[wall_index];
  const Vec2 into_room = world.WallNormal(wall_index, !wall.corridor_side_left);
  const Vec2 q1 = PointOnWall(wall, offset_m - room_width_m / 2.0);
  const Vec2 q2 = PointOnWall(wall, offset_m + room_width_m / 2.0);
  const Vec2 depth = room_depth_m * into_room;
  for (const Segment& s : {Segment{q1, q1 + depth}, Segment{q1 + depth, q2 + depth}, Segment{q2 + depth, q2}}) {
    Surface surface;
    surface.segment = s;
    surface.z_max_m = world.wall_height_m;
    surface.color = kRoomColor;
    out->push_back(surface);
  }
}

// A glass pane in a wall: the pane and its frame posts (AddGlassPane), and the room box behind it.
void AddWallGlass(const World& world, const GlassPanel& glass, std::vector<Surface>* out) {
  AddGlassPane(glass, out);
  AddRoomBox(world, glass.wall_index, glass.offset_m, glass.room_width_m, glass.room_depth_m, out);
}

// SplitMix64's finaliser: a well-mixed 64-bit value from any 64-bit input.
std::uint64_t Mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint64_t Quantized(double value, double unit) {
  return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::llround(value / unit)));
}

}  // namespace

bool GlassReturnsBeam(const Surface& surface, Vec2 origin, double angle_rad) {
  if (surface.laser_reflect_probability >= 1.0) return true;
  if (surface.laser_reflect_probability <= 0.0) return false;
  std::uint64_t h = Mix(surface.seed + 0x9e3779b97f4a7c15ULL);
  for (const std::uint64_t v :
       {Quantized(surface.segment.a.x, 1e-4), Quantized(surface.segment.a.y, 1e-4),
        Quantized(surface.segment.b.x, 1e-4), Quantized(surface.segment.b.y, 1e-4), Quantized(origin.x, 1e-4),
        Quantized(origin.y, 1e-4), Quantized(NormalizeAngle(angle_rad), 1e-6)}) {
    h = Mix(h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)));
  }
  const double u = static_cast<double>(h >> 11) * 0x1.0p-53;  // uniform in [0, 1)
  return u < surface.laser_reflect_probability;
}

std::vector<const TextSign*> World::Plates() const {
  std::vector<const TextSign*> plates;
  for (const TextSign& sign : signs) {
    if (sign.kind == TextKind::kPlate) plates.push_back(&sign);
  }
  return plates;
}

Vec2 World::SignPosition(const TextSign& sign) const {
  return PointOnWall(walls.at(sign.wall_index), sign.offset_m);
}

Vec2 World::WallNormal(int wall_index, bool left_side) const {
  const Vec2 u = UnitAlong(walls.at(wall_index).segment);
  return left_side ? Vec2{-u.y, u.x} : Vec2{u.y, -u.x};
}

Vec2 World::CorridorNormal(int wall_index) const {
  return WallNormal(wall_index, walls.at(wall_index).corridor_side_left);
}

double World::LightingGain(const Vec2& point) const {
  double gain = 1.0;
  for (const LightZone& zone : lighting) {
    // Distance outside the box (0 inside) and position across it along the zone's axis.
    const double dx = std::max({zone.min.x - point.x, point.x - zone.max.x, 0.0});
    const double dy = std::max({zone.min.y - point.y, point.y - zone.max.y, 0.0});
    const double outside_m = std::hypot(dx, dy);
    if (outside_m > 0.0 && !(outside_m < zone.edge_m)) continue;
    const double lo = zone.axis_x ? zone.min.x : zone.min.y, hi = zone.axis_x ? zone.max.x : zone.max.y;
    const double at = zone.axis_x ? point.x : point.y;
    const double t = hi > lo ? std::clamp((at - lo) / (hi - lo), 0.0, 1.0) : 0.0;
    const double zone_gain = zone.gain + t * (zone.gain_at_max - zone.gain);
    const double weight = outside_m > 0.0 ? 1.0 - outside_m / zone.edge_m : 1.0;
    gain *= 1.0 + weight * (zone_gain - 1.0);
  }
  return gain;
}

void BuildSurfaces(World& world) {
  world.surfaces.clear();
  for (int w = 0; w < static_cast<int>(world.walls.size()); ++w) {
    const Wall& wall = world.walls[w];
    const std::vector<WallOpening> openings = WallOpenings(world, w);
    const double length = wall.segment.Length();
    auto add_piece = [&](double from_m, double to_m, double z_min, double z_max) {
      if (to_m - from_m <= 1e-9) return;
      Surface piece;
      piece.segment = {PointOnWall(wall, from_m), PointOnWall(wall, to_m)};
      piece.z_min_m = z_min;
      piece.z_max_m = z_max;
      piece.wall_index = w;
      piece.wall_offset_at_a_m = from_m;
      piece.color = wall.color;
      world.surfaces.push_back(piece);
    };
    double cursor = 0.0;
    for (const WallOpening& opening : openings) {
      add_piece(cursor, opening.from_m, 0.0, world.wall_height_m);
      if (opening.z_min_m > 0.0) add_piece(opening.from_m, opening.to_m, 0.0, opening.z_min_m);  // sill
      if (opening.door != nullptr || opening.z_max_m < world.wall_height_m) {
        add_piece(opening.from_m, opening.to_m, opening.z_max_m, world.wall_height_m);  // lintel
      }
      if (opening.door != nullptr && opening.door->open) {
        AddRoomBox(world, w, opening.door->offset_m, opening.door->room_width_m, opening.door->room_depth_m,
                   &world.surfaces);
      } else if (opening.door != nullptr) {
        AddRecessedLeaf(world, w, *opening.door, &world.surfaces);
      } else {
        AddWallGlass(world, *opening.glass, &world.surfaces);
      }
      cursor = opening.to_m;
    }
    add_piece(cursor, length, 0.0, world.wall_height_m);
  }
  AddDetailSurfaces(world, &world.surfaces);
  world.num_static_surfaces = world.surfaces.size();
}

}  // namespace doorplate_localization
