#include "world_detail_surfaces.h"

#include <cmath>

namespace doorplate_localization {
namespace {

// A frame round a door: two jambs beside the opening and a head over it, `frame_depth_m` out of the wall
// into the corridor. Only the three faces off the wall line are surfaces (the back lies on the wall).
void AddDoorFrame(const World& world, const Door& door, std::vector<Surface>* out) {
  const Wall& wall = world.walls[door.wall_index];
  const Vec2 u = (1.0 / wall.segment.Length()) * (wall.segment.b - wall.segment.a);
  const Vec2 n = world.CorridorNormal(door.wall_index);
  const auto at = [&](double offset_m, double out_m) { return wall.segment.a + offset_m * u + out_m * n; };
  const double half = door.width_m / 2.0, fw = door.frame_width_m, fd = door.frame_depth_m;
  struct Part {
    double from_m, to_m, z_min_m, z_max_m;
  };
  for (const Part& p : {Part{door.offset_m - half - fw, door.offset_m - half, 0.0, door.height_m + fw},
                        Part{door.offset_m + half, door.offset_m + half + fw, 0.0, door.height_m + fw},
                        Part{door.offset_m - half, door.offset_m + half, door.height_m, door.height_m + fw}}) {
    for (const Segment& s : {Segment{at(p.from_m, 0.0), at(p.from_m, fd)}, Segment{at(p.from_m, fd), at(p.to_m, fd)},
                             Segment{at(p.to_m, fd), at(p.to_m, 0.0)}}) {
      Surface face;
      face.segment = s;
      face.z_min_m = p.z_min_m;
      face.z_max_m = p.z_max_m;
      face.color = door.frame_color;
      face.kind = SurfaceKind::kDoorDetail;
      out->push_back(face);
    }
  }
}

}  // namespace

void AddBoxFaces(const Pose2D& item_pose, const ClutterBox& box, SurfaceKind kind, std::vector<Surface>* out) {
  const double hx = box.size_x_m / 2.0, hy = box.size_y_m / 2.0;
  const Vec2 corners[4] = {item_pose.TransformPoint({box.center.x - hx, box.center.y - hy}),
                           item_pose.TransformPoint({box.center.x + hx, box.center.y - hy}),
                           item_pose.TransformPoint({box.center.x + hx, box.center.y + hy}),
                           item_pose.TransformPoint({box.center.x - hx, box.center.y + hy})};
  for (int i = 0; i < 4; ++i) {
    Surface face;
    face.segment = {corners[i], corners[(i + 1) % 4]};
    face.z_min_m = box.z_min_m;
    face.z_max_m = box.z_max_m;
    face.color = box.color;
    face.kind = kind;
    out->push_back(face);
  }
}

void AddGlassPane(const GlassPanel& glass, std::vector<Surface>* out) {
  const double length = glass.segment.Length(), fw = glass.frame_width_m;
  const Vec2 u = (1.0 / length) * (glass.segment.b - glass.segment.a);
  Surface pane;
  pane.segment = {glass.segment.a + fw * u, glass.segment.b - fw * u};
  pane.z_min_m = glass.z_min_m;
  pane.z_max_m = glass.z_max_m;
  pane.color = glass.tint;
  pane.kind = SurfaceKind::kGlass;
  pane.laser_reflect_probability = glass.laser_reflect_probability;
  pane.camera_opacity = glass.camera_opacity;
  pane.seed = glass.seed;
  out->push_back(pane);
  if (!(fw > 0.0)) return;
  const double yaw = std::atan2(u.y, u.x);
  for (const Vec2& end : {glass.segment.a + (fw / 2) * u, glass.segment.b - (fw / 2) * u}) {
    ClutterBox post;
    post.size_x_m = post.size_y_m = fw;
    post.z_min_m = glass.z_min_m;
    post.z_max_m = glass.z_max_m;
    post.color = glass.frame_color;
    AddBoxFaces({end.x, end.y, yaw}, post, SurfaceKind::kStructure, out);
  }
}

void AddDetailSurfaces(const World& world, std::vector<Surface>* out) {
  for (const Door& door : world.doors) {
    if (door.frame_width_m > 0.0 && door.frame_depth_m > 0.0) AddDoorFrame(world, door, out);
  }
  for (const GlassPanel& glass : world.glass) {
    if (glass.wall_index < 0) AddGlassPane(glass, out);
  }
  for (const ClutterItem& item : world.clutter) {
    for (const ClutterBox& box : item.boxes) AddBoxFaces(item.pose, box, SurfaceKind::kClutter, out);
  }
}

}  // namespace doorplate_localization
