#include "doorplate_localization/sim/world.h"

#include <algorithm>
#include <cmath>

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

// The room box behind an open door: two side walls and a back wall, on the side away from the corridor.
void AddRoomBox(const World& world, int wall_index, const Door& door, std::vector<Surface>* out) {
  const Wall& wall = world.walls[wall_index];
  const Vec2 into_room = world.WallNormal(wall_index, !wall.corridor_side_left);
  const Vec2 q1 = PointOnWall(wall, door.offset_m - door.room_width_m / 2.0);
  const Vec2 q2 = PointOnWall(wall, door.offset_m + door.room_width_m / 2.0);
  const Vec2 depth = door.room_depth_m * into_room;
  for (const Segment& s : {Segment{q1, q1 + depth}, Segment{q1 + depth, q2 + depth}, Segment{q2 + depth, q2}}) {
    Surface surface;
    surface.segment = s;
    surface.z_max_m = world.wall_height_m;
    surface.color = kRoomColor;
    out->push_back(surface);
  }
}

}  // namespace

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
    std::vector<const Door*> open_doors;
    for (const Door& door : world.doors) {
      if (door.wall_index == w && door.open) open_doors.push_back(&door);
    }
    std::sort(open_doors.begin(), open_doors.end(),
              [](const Door* a, const Door* b) { return a->offset_m < b->offset_m; });
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
    for (const Door* door : open_doors) {
      const double gap_from = door->offset_m - door->width_m / 2.0;
      const double gap_to = door->offset_m + door->width_m / 2.0;
      add_piece(cursor, gap_from, 0.0, world.wall_height_m);
      add_piece(gap_from, gap_to, door->height_m, world.wall_height_m);  // lintel
      AddRoomBox(world, w, *door, &world.surfaces);
      cursor = gap_to;
    }
    add_piece(cursor, length, 0.0, world.wall_height_m);
  }
}

}  // namespace doorplate_localization
