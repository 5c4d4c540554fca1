// In-memory corridor world: walls, doors, doorplates, distractor text, robot start and sensor settings.
// Frame: the world frame is the ground-truth map frame, x along the main corridor, z up from the floor.
// Units: metres, radians; colours are RGB 0..255. The file format is docs/world-format.md.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sim/sensor_options.h"

namespace doorplate_localization {

using ColorRgb = std::array<std::uint8_t, 3>;

// A straight wall from `segment.a` to `segment.b`, floor to ceiling. Positions on it ("offset") are
// metres from `segment.a` towards `segment.b`.
struct Wall {
  std::string id;
  Segment segment;
  bool corridor_side_left = true;  // the corridor lies left of a→b; rooms behind open doors lie right
  ColorRgb color{225, 222, 210};
};

struct Door {
  std::string id;
  int wall_index = -1;          // into World::walls
  double offset_m = 0.0;        // door centre along the wall
  double width_m = 0.9;
  double height_m = 2.1;
  bool open = false;            // open: a gap in the wall showing a room behind it
  double room_depth_m = 3.0;    // room box generated behind an open door
  double room_width_m = 3.0;
  ColorRgb color{140, 95, 60};
  // Detail (docs/world-format.md, "Recessed doors and frames"); all 0 = flush with the wall, no frame.
  double recess_m = 0.0;         // closed doors: the leaf sits this far behind the wall line
  double frame_width_m = 0.0;    // jamb face width along the wall, each side (and the head's height)
  double frame_depth_m = 0.0;    // how far the frame stands out of the wall into the corridor
  ColorRgb frame_color{235, 235, 230};
};

enum class TextKind { kPlate, kDistractor };

// Hershey fonts of OpenCV, by name in world files.
enum class SignFont { kSimplex, kDuplex, kComplex, kTriplex, kPlain, kComplexSmall, kScriptSimplex, kScriptComplex };

// A flat rectangle with text on a wall: a doorplate (room number) or distractor text (poster, sign).
struct TextSign {
  TextKind kind = TextKind::kPlate;
  std::string text;
  int wall_index = -1;
  int door_index = -1;          // plates: the door they label, -1 if none
  double offset_m = 0.0;        // sign centre along the wall
  double center_height_m = 1.6;
  double width_m = 0.24;
  double height_m = 0.12;
  ColorRgb background{245, 245, 240};
  ColorRgb foreground{20, 20, 20};
  SignFont font = SignFont::kSimplex;
  bool italic = false;
  double text_height_m = 0.0;          // cap height of the text; 0: a third of height_m (one line)
  double stroke_to_cap_height = 0.13;  // stroke thickness as a fraction of the cap height
  // Non-empty: the sign's face is this image (PNG/JPG, absolute or relative to the working directory),
  // stretched to width_m × height_m; text, colours and font are then not drawn (text stays the truth).
  std::string image_path;
  bool corridor_side_left = true;  // side of its wall's a→b the sign faces (copied from the wall)
};

// A region of the world lit brighter or darker than the rest: an axis-aligned box on the floor plan.
// Walls, doors and signs seen inside it are multiplied by a gain that goes linearly from `gain` at the
// box's low edge to `gain_at_max` at its high edge along `axis_x` (true: x, false: y). Within `edge_m`
// outside the box the effect fades out linearly. Zones multiply where they overlap; outside every zone
// the gain is 1. Floor and ceiling are not affected.
struct LightZone {
  Vec2 min{0.0, 0.0};
  Vec2 max{0.0, 0.0};
  double gain = 1.0;
  double gain_at_max = 1.0;
  bool axis_x = true;
  double edge_m = 0.0;
};

// What a surface belongs to. Glass is drawn translucent by the camera and returns a laser beam only
// with its `laser_reflect_probability`; people's surfaces are dynamic (moved by PlacePeople, left out of
// ground-truth maps and of the robot's bumper).
enum class SurfaceKind { kStructure, kDoorDetail, kClutter, kGlass, kPerson };

// A vertical rectangle the sensors can see: a wall piece, a lintel over an open door, a generated room
// wall, a door reveal or frame, a face of a clutter box, a glass pane or a person's part.
// `wall_index` >= 0 means its texture comes from that wall's doors and signs, with `wall_offset_at_a_m`
// the wall offset of `segment.a`.
struct Surface {
  Segment segment;
  double z_min_m = 0.0;
  double z_max_m = 2.6;
  int wall_index = -1;
  double wall_offset_at_a_m = 0.0;
  ColorRgb color{225, 222, 210};
  SurfaceKind kind = SurfaceKind::kStructure;
  double laser_reflect_probability = 1.0;  // < 1 only for glass: the chance a beam returns from it
  double camera_opacity = 1.0;             // < 1 only for glass: weight of its colour over what lies behind
  std::uint64_t seed = 0;                  // glass: seeds its deterministic per-beam returns
};

// A box of a clutter item in the item's frame: x along its length (along the wall when wall-mounted),
// y across (away from the wall), z up from the floor. `center` is the box centre on the floor plan.
struct ClutterBox {
  Vec2 center;
  double size_x_m = 0.0;
  double size_y_m = 0.0;
  double z_min_m = 0.0;
  double z_max_m = 0.0;
  ColorRgb color{128, 128, 128};
};

// Static clutter (world file `clutter[]`): a preset type (src/sim/clutter_presets.cpp) made of boxes,
// placed by `pose` (item frame in the world frame; for wall-mounted items x runs along the wall).
struct ClutterItem {
  std::string id;
  std::string type;
  Pose2D pose;
  std::vector<ClutterBox> boxes;
};

// A glass pane (world file `glass[]`): a vertical rectangle from `segment.a` to `segment.b` between
// z_min_m and z_max_m. In a wall (`wall_index` >= 0) it replaces that wall between the offsets
// `offset_m` ± width/2 and heights z_min_m..z_max_m, with a room box behind it (`room_depth_m` > 0).
struct GlassPanel {
  std::string id;
  Segment segment;
  int wall_index = -1;
  double offset_m = 0.0;
  double z_min_m = 0.0;
  double z_max_m = 2.1;
  double laser_reflect_probability = 0.1;
  double camera_opacity = 0.3;
  double frame_width_m = 0.05;     // opaque posts at both ends, full pane height
  double room_depth_m = 0.0;
  double room_width_m = 0.0;       // room box width behind glass in a wall (>= the pane's width)
  ColorRgb tint{170, 205, 215};
  ColorRgb frame_color{90, 90, 95};
  std::uint64_t seed = 0;
};

// A person walking (world file `people[]`) along `waypoints` at `speed_mps`: back and forth, or round a
// loop (`loop`), stopping `pause_s` at every waypoint; `start_offset_s` shifts the walk in time. Seen as
// two legs (`leg_diameter_m`) swinging with a gait below `hip_height_m`, a torso and a head above.
// Where it is depends only on the simulated time (PersonAt, include/doorplate_localization/sim/people.h).
struct Person {
  std::string id;
  std::vector<Vec2> waypoints;
  double speed_mps = 1.1;
  bool loop = false;
  double pause_s = 0.0;
  double start_offset_s = 0.0;
  double height_m = 1.72;
  double hip_height_m = 0.88;
  double leg_diameter_m = 0.12;
  double stride_m = 1.4;           // two steps
  ColorRgb top_color{70, 110, 160};
  ColorRgb legs_color{50, 50, 60};
};

// Ground truth of one corridor (world file `corridors[]`): its centreline from `centreline.a` to
// `centreline.b` (world frame, metres) and its nominal width, wall to wall (metres). Not used by the
// simulator; for per-corridor map measures (src/eval/floor_measure.h).
struct CorridorSpec {
  std::string id;
  Segment centreline;
  double width_m = 0.0;
};

struct World {
  int format_version = 1;
  std::string name;
  std::string description;
  std::string source_file;      // where it was loaded from ("" if built in code)
  double wall_height_m = 2.6;
  ColorRgb floor_color{150, 150, 145};
  ColorRgb ceiling_color{235, 235, 235};
  std::vector<Wall> walls;
  std::vector<Door> doors;
  std::vector<TextSign> signs;
  Pose2D start_pose;
  double robot_radius_m = 0.2;
  SensorOptions sensors;
  std::vector<LightZone> lighting;
  std::vector<CorridorSpec> corridors;  // optional ground truth, empty if the file gives none
  std::vector<ClutterItem> clutter;      // optional detail (docs/world-format.md)
  std::vector<GlassPanel> glass;
  std::vector<Person> people;

  // Derived by BuildSurfaces(): what the laser and the camera see. The first `num_static_surfaces` are
  // static; PlacePeople (people.h) replaces the rest with the people's surfaces at a time.
  std::vector<Surface> surfaces;
  std::size_t num_static_surfaces = 0;

  // Ground truth for experiments: the plates (kind == kPlate).
  std::vector<const TextSign*> Plates() const;
  // World position (z ignored) of a sign's centre on its wall.
  Vec2 SignPosition(const TextSign& sign) const;
  // Unit normal of a wall pointing to its left (left_side) or right side of a→b.
  Vec2 WallNormal(int wall_index, bool left_side) const;
  // Unit normal of a wall pointing into the corridor.
  Vec2 CorridorNormal(int wall_index) const;
  // Brightness gain of the lighting zones at a floor-plan point (1 outside every zone).
  double LightingGain(const Vec2& point) const;
};

// Splits walls at open doors, recessed doors and glass in walls, adds lintels, room boxes, door
// reveals and frames, clutter boxes and glass panes; fills `world.surfaces` with the static surfaces
// (no people: see PlacePeople) and sets `num_static_surfaces`. Idempotent. A world without detail gets
// exactly the surfaces, in the same order, as before the detail existed.
void BuildSurfaces(World& world);

// Whether a laser beam from `origin` along `angle_rad` that meets glass `surface` returns from it:
// a deterministic draw with probability surface.laser_reflect_probability, from the surface's seed, the
// origin (to 0.1 mm) and the angle (to 1 µrad). Always true for surfaces with probability >= 1.
bool GlassReturnsBeam(const Surface& surface, Vec2 origin, double angle_rad);

}  // namespace doorplate_localization
