// World file reader: YAML (docs/world-format.md) → World, validating every field.
#include "doorplate_localization/sim/world_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <iomanip>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "doorplate_localization/common/yaml_reader.h"
#include "world_detail_fields.h"
#include "world_sensor_fields.h"

namespace doorplate_localization {
namespace {

constexpr int kFormatVersion = 1;

struct Indexes {
  std::map<std::string, int> walls;
  std::map<std::string, int> doors;
};

int LookUp(const std::map<std::string, int>& index, const YamlField& field, const char* what) {
  const std::string id = field.AsString();
  const auto it = index.find(id);
  if (it == index.end()) field.Fail(std::string("no ") + what + " with id '" + id + "'");
  return it->second;
}

SignFont ParseFont(const YamlField& field) {
  static const std::map<std::string, SignFont> kFonts = {
      {"simplex", SignFont::kSimplex},          {"duplex", SignFont::kDuplex},
      {"complex", SignFont::kComplex},          {"triplex", SignFont::kTriplex},
      {"plain", SignFont::kPlain},              {"complex_small", SignFont::kComplexSmall},
      {"script_simplex", SignFont::kScriptSimplex}, {"script_complex", SignFont::kScriptComplex}};
  const auto it = kFonts.find(field.AsString());
  if (it == kFonts.end()) {
    field.Fail("font must be one of simplex, duplex, complex, triplex, plain, complex_small, script_simplex, "
               "script_complex");
  }
  return it->second;
}

// `image`: a path relative to the world file's folder; the file must decode (PNG, JPG, ... via OpenCV).
std::string ParseImagePath(const YamlField& field, const std::string& source_name) {
  const std::filesystem::path given(field.AsString());
  if (given.empty()) field.Fail("image path must not be empty");
  const std::filesystem::path path =
      given.is_absolute() ? given : std::filesystem::path(source_name).parent_path() / given;
  if (cv::imread(path.string(), cv::IMREAD_COLOR).empty()) {
    field.Fail("cannot read image '" + path.string() + "' (missing, or not an image OpenCV decodes)");
  }
  return path.string();
}

void ParseLightZone(const YamlField& f, World* world) {
  f.RequireOnlyKeys({"min", "max", "gain", "gain_at_max", "axis", "edge_m"});
  LightZone zone;
  zone.min = ParsePointM(f.Child("min"));
  zone.max = ParsePointM(f.Child("max"));
  if (!(zone.max.x >= zone.min.x && zone.max.y >= zone.min.y)) f.Child("max").Fail("must be >= min in x and y");
  zone.gain = f.NonNegative("gain", zone.gain);
  zone.gain_at_max = f.NonNegative("gain_at_max", zone.gain);
  if (zone.gain > 10.0 || zone.gain_at_max > 10.0) f.Fail("gain and gain_at_max must be in [0, 10]");
  std::string axis = "x";
  f.Get("axis", &axis);
  if (axis != "x" && axis != "y") f.Child("axis").Fail("must be 'x' or 'y'");
  zone.axis_x = axis == "x";
  zone.edge_m = f.NonNegative("edge_m", zone.edge_m);
  world->lighting.push_back(zone);
}

// `corridors[]`: ground-truth centrelines and widths; ids unique, from != to, width > 0 (finite: AsDouble).
void ParseCorridor(const YamlField& f, World* world) {
  f.RequireOnlyKeys({"id", "from", "to", "width_m"});
  CorridorSpec corridor;
  corridor.id = f.Child("id").AsString();
  if (corridor.id.empty()) f.Child("id").Fail("must not be empty");
  for (const CorridorSpec& other : world->corridors) {
    if (other.id == corridor.id) f.Child("id").Fail("duplicate corridor id '" + corridor.id + "'");
  }
  corridor.centreline = {ParsePointM(f.Child("from")), ParsePointM(f.Child("to"))};
  if (corridor.centreline.Length() < 1e-3) f.Child("to").Fail("must be at least 1 mm from 'from'");
  corridor.width_m = f.Child("width_m").AsDouble();
  if (!(corridor.width_m > 0.0)) f.Child("width_m").Fail("must be > 0, got " + std::to_string(corridor.width_m));
  world->corridors.push_back(corridor);
}

void ParseWall(const YamlField& f, World* world, Indexes* idx) {
  f.RequireOnlyKeys({"id", "from", "to", "corridor_side", "color"});
  Wall wall;
  wall.id = f.Child("id").AsString();
  if (idx->walls.count(wall.id)) f.Child("id").Fail("duplicate wall id '" + wall.id + "'");
  wall.segment = {ParsePointM(f.Child("from")), ParsePointM(f.Child("to"))};
  if (wall.segment.Length() < 1e-3) f.Fail("wall 'from' and 'to' must be at least 1 mm apart");
  const std::string side = f.Child("corridor_side").AsString();
  if (side != "left" && side != "right") f.Child("corridor_side").Fail("must be 'left' or 'right' of from→to");
  wall.corridor_side_left = side == "left";
  f.GetColor("color", &wall.color);
  idx->walls[wall.id] = static_cast<int>(world->walls.size());
  world->walls.push_back(wall);
}

// Walls may meet (at corners, T-junctions: an end on the other wall) but not cross or lie on one another: a
// crossing or a duplicated wall is an authoring mistake the maps and the laser would silently carry. Fails on
// the later wall's entry, naming both ids and where.
void CheckWallsDoNotCross(const std::vector<YamlField>& items, const World& world) {
  constexpr double kToleranceM = 1e-3;
  for (size_t j = 1; j < world.walls.size(); ++j) {
    const Segment& b = world.walls[j].segment;
    const Vec2 db = b.b - b.a;
    for (size_t i = 0; i < j; ++i) {
      const Segment& a = world.walls[i].segment;
      const Vec2 da = a.b - a.a;
      const double la = Norm(da), lb = Norm(db), denom = Cross(da, db);
      std::ostringstream why;
      why << std::fixed << std::setprecision(3);
      if (std::fabs(denom) > 1e-9 * la * lb) {
        const double t = Cross(b.a - a.a, db) / denom, u = Cross(b.a - a.a, da) / denom;  // along a, along b
        const double ta = kToleranceM / la, tb = kToleranceM / lb;
        if (t > ta && t < 1.0 - ta && u > tb && u < 1.0 - tb) {
          const Vec2 p = a.a + t * da;
          why << "crosses wall '" << world.walls[i].id << "' at (" << p.x << ", " << p.y
              << "); walls may meet at their ends, not cross";
        }
      } else if (std::fabs(Cross(b.a - a.a, da)) / la < kToleranceM) {  // on one line: do they overlap?
        const Vec2 unit = (1.0 / la) * da;
        const double s0 = Dot(b.a - a.a, unit), s1 = Dot(b.b - a.a, unit);
        const double overlap = std::min(la, std::max(s0, s1)) - std::max(0.0, std::min(s0, s1));
        if (overlap > kToleranceM) {
          why << "lies on wall '" << world.walls[i].id << "' for " << overlap << " m; walls may meet at their ends, "
              << "not overlap";
        }
      }
      if (!why.str().empty()) items[j].Fail(why.str());
    }
  }
}

// Door fields shared by `doors` entries and `door_rows` entries.
void ParseDoorFields(const YamlField& f, Door* door) {
  door->width_m = f.Positive("width_m", door->width_m);
  door->height_m = f.Positive("height_m", door->height_m);
  f.Get("open", &door->open);
  door->room_depth_m = f.Positive("room_depth_m", door->room_depth_m);
  door->room_width_m = f.Positive("room_width_m", door->room_width_m);
  f.GetColor("color", &door->color);
  ParseDoorDetail(f, door);
}

const std::set<std::string> kDoorFieldKeys = {"width_m",      "height_m", "open",          "room_depth_m",
                                              "room_width_m", "color",    "recess_m",      "frame_width_m",
                                              "frame_depth_m", "frame_color"};

void CheckDoor(const YamlField& f, const World& world, const Door& door) {
  const Wall& wall = world.walls[door.wall_index];
  if (door.offset_m - door.width_m / 2 < 0 || door.offset_m + door.width_m / 2 > wall.segment.Length()) {
    f.Fail("door '" + door.id + "' does not fit on wall '" + wall.id + "' (length " +
           std::to_string(wall.segment.Length()) + " m)");
  }
  if (door.height_m > world.wall_height_m) f.Fail("door height exceeds wall_height_m");
  if (door.room_width_m < door.width_m) f.Fail("room_width_m must be >= width_m");
  CheckDoorDetail(f, world, door);
  for (const Door& other : world.doors) {
    if (other.wall_index == door.wall_index &&
        std::abs(other.offset_m - door.offset_m) <
            (other.width_m + door.width_m) / 2 + other.frame_width_m + door.frame_width_m) {
      f.Fail("door '" + door.id + "' overlaps door '" + other.id + "'");
    }
  }
}

void AddDoor(const YamlField& f, Door door, World* world, Indexes* idx) {
  if (idx->doors.count(door.id)) f.Fail("duplicate door id '" + door.id + "'");
  CheckDoor(f, *world, door);
  idx->doors[door.id] = static_cast<int>(world->doors.size());
  world->doors.push_back(door);
}

void ParseDoor(const YamlField& f, World* world, Indexes* idx) {
  std::set<std::string> keys = kDoorFieldKeys;
  keys.insert({"id", "wall", "offset_m"});
  f.RequireOnlyKeys(keys);
  Door door;
  door.id = f.Child("id").AsString();
  door.wall_index = LookUp(idx->walls, f.Child("wall"), "wall");
  door.offset_m = f.Child("offset_m").AsDouble();
  ParseDoorFields(f, &door);
  AddDoor(f, door, world, idx);
}

// Sign appearance fields shared by plates, distractors and door_rows' `plate`.
void ParseSignLook(const YamlField& f, const std::string& source_name, TextSign* sign) {
  sign->center_height_m = f.Positive("center_height_m", sign->center_height_m);
  if (f.Has("size_m")) {
    const auto size = f.Child("size_m").AsDoubles(2);
    if (size[0] <= 0 || size[1] <= 0) f.Child("size_m").Fail("width and height must be > 0");
    sign->width_m = size[0];
    sign->height_m = size[1];
  }
  f.GetColor("background", &sign->background);
  f.GetColor("foreground", &sign->foreground);
  if (f.Has("font")) sign->font = ParseFont(f.Child("font"));
  f.Get("italic", &sign->italic);
  sign->text_height_m = f.Positive("text_height_m", sign->text_height_m);
  if (sign->text_height_m > sign->height_m) f.Fail("text_height_m must be <= the sign height (size_m[1])");
  sign->stroke_to_cap_height = f.Positive("stroke_to_cap_height", sign->stroke_to_cap_height);
  if (sign->stroke_to_cap_height > 0.5) f.Child("stroke_to_cap_height").Fail("must be in (0, 0.5]");
  if (f.Has("image")) sign->image_path = ParseImagePath(f.Child("image"), source_name);
}

const std::set<std::string> kSignLookKeys = {"center_height_m", "size_m", "background", "foreground", "font",
                                             "italic", "text_height_m", "stroke_to_cap_height", "image"};

void AddSign(const YamlField& f, TextSign sign, World* world) {
  if (sign.text.empty()) f.Fail("text must not be empty");
  const Wall& wall = world->walls[sign.wall_index];
  sign.corridor_side_left = wall.corridor_side_left;
  if (sign.offset_m - sign.width_m / 2 < 0 || sign.offset_m + sign.width_m / 2 > wall.segment.Length()) {
    f.Fail("sign '" + sign.text + "' does not fit on wall '" + wall.id + "'");
  }
  if (sign.center_height_m + sign.height_m / 2 > world->wall_height_m) f.Fail("sign reaches above the wall");
  world->signs.push_back(sign);
}

// A plate or distractor: placed either on a door (`door`, `along_door_m`) or on a wall (`wall`, `offset_m`).
void ParseSign(const YamlField& f, TextKind kind, World* world, const Indexes& idx) {
  std::set<std::string> keys = kSignLookKeys;
  keys.insert({"text", "door", "along_door_m", "wall", "offset_m"});
  f.RequireOnlyKeys(keys);
  TextSign sign;
  sign.kind = kind;
  sign.text = f.Child("text").AsString();
  if (kind == TextKind::kDistractor) sign.center_height_m = 2.2;
  if (f.Has("door")) {
    if (f.Has("wall") || f.Has("offset_m")) f.Fail("give either 'door' (+ along_door_m) or 'wall' + 'offset_m'");
    sign.door_index = LookUp(idx.doors, f.Child("door"), "door");
    const Door& door = world->doors[sign.door_index];
    sign.wall_index = door.wall_index;
    double along = 0.0;
    f.Get("along_door_m", &along);
    sign.offset_m = door.offset_m + along;
  } else {
    if (f.Has("along_door_m")) f.Fail("'along_door_m' needs 'door'");
    sign.wall_index = LookUp(idx.walls, f.Child("wall"), "wall");
    sign.offset_m = f.Child("offset_m").AsDouble();
  }
  ParseSignLook(f, world->source_file, &sign);
  AddSign(f, sign, world);
}

// A row of equally spaced doors, each with a plate: the compact way to write a corridor by hand.
void ParseDoorRow(const YamlField& f, World* world, Indexes* idx) {
  std::set<std::string> keys = kDoorFieldKeys;
  keys.insert({"wall", "first_offset_m", "spacing_m", "texts", "id_prefix", "plate"});
  f.RequireOnlyKeys(keys);
  Door templ;
  templ.wall_index = LookUp(idx->walls, f.Child("wall"), "wall");
  ParseDoorFields(f, &templ);
  const double first = f.Child("first_offset_m").AsDouble();
  const double spacing = f.Positive("spacing_m", 3.0);
  std::string prefix = world->walls[templ.wall_index].id + "_door";
  f.Get("id_prefix", &prefix);
  TextSign plate_look;
  double along = 0.0;
  if (f.Has("plate")) {
    const YamlField p = f.Child("plate");
    std::set<std::string> pkeys = kSignLookKeys;
    pkeys.insert("along_door_m");
    p.RequireOnlyKeys(pkeys);
    ParseSignLook(p, world->source_file, &plate_look);
    p.Get("along_door_m", &along);
  }
  const std::vector<YamlField> texts = f.Child("texts").Items();
  for (size_t i = 0; i < texts.size(); ++i) {
    Door door = templ;
    door.id = prefix + std::to_string(i + 1);
    door.offset_m = first + spacing * static_cast<double>(i);
    AddDoor(texts[i], door, world, idx);
    const std::string text = texts[i].AsString();
    if (text.empty()) continue;  // "" = a door without a plate
    TextSign plate = plate_look;
    plate.text = text;
    plate.door_index = idx->doors.at(door.id);
    plate.wall_index = door.wall_index;
    plate.offset_m = door.offset_m + along;
    AddSign(texts[i], plate, world);
  }
}

void ParseRobot(const YamlField& f, World* world) {
  f.RequireOnlyKeys({"start", "radius_m"});
  const YamlField start = f.Child("start");
  start.RequireOnlyKeys({"x_m", "y_m", "theta_deg"});
  world->start_pose.x_m = ParseCoordinateM(start.Child("x_m"));
  world->start_pose.y_m = ParseCoordinateM(start.Child("y_m"));
  double theta_deg = 0.0;
  start.Get("theta_deg", &theta_deg);
  world->start_pose.theta_rad = NormalizeAngle(theta_deg * M_PI / 180.0);
  world->robot_radius_m = f.Positive("radius_m", world->robot_radius_m);
}

void CheckStartIsFree(const YamlField& root, const World& world) {
  for (const Surface& s : world.surfaces) {
    if (s.z_min_m > 0.3) continue;
    if (PointSegmentDistance(world.start_pose.Position(), s.segment) < world.robot_radius_m) {
      root.Child("robot").Fail("start pose is inside or touching a wall");
    }
  }
}

}  // namespace

World ParseWorldYaml(const std::string& yaml_text, const std::string& source_name) {
  try {
    const YamlField root = YamlField::Parse(yaml_text, source_name);
    root.RequireOnlyKeys({"format_version", "name", "description", "wall_height_m", "floor_color", "ceiling_color",
                          "robot", "walls", "doors", "door_rows", "plates", "distractors", "sensors",
                          "lighting", "corridors", "glass", "clutter", "people"});
    World world;
    world.source_file = source_name;
    world.format_version = root.Child("format_version").AsInt();
    if (world.format_version != kFormatVersion) {
      root.Child("format_version").Fail("unsupported version " + std::to_string(world.format_version) +
                                        " (this build reads version " + std::to_string(kFormatVersion) + ")");
    }
    world.name = root.Child("name").AsString();
    root.Get("description", &world.description);
    world.wall_height_m = root.Positive("wall_height_m", world.wall_height_m);
    root.GetColor("floor_color", &world.floor_color);
    root.GetColor("ceiling_color", &world.ceiling_color);
    Indexes idx;
    const std::vector<YamlField> wall_items = root.Child("walls").Items();
    for (const YamlField& f : wall_items) ParseWall(f, &world, &idx);
    CheckWallsDoNotCross(wall_items, world);
    if (root.Has("doors")) for (const YamlField& f : root.Child("doors").Items()) ParseDoor(f, &world, &idx);
    if (root.Has("door_rows")) for (const YamlField& f : root.Child("door_rows").Items()) ParseDoorRow(f, &world, &idx);
    if (root.Has("plates")) {
      for (const YamlField& f : root.Child("plates").Items()) ParseSign(f, TextKind::kPlate, &world, idx);
    }
    if (root.Has("distractors")) {
      for (const YamlField& f : root.Child("distractors").Items()) ParseSign(f, TextKind::kDistractor, &world, idx);
    }
    if (root.Has("lighting")) for (const YamlField& f : root.Child("lighting").Items()) ParseLightZone(f, &world);
    if (root.Has("corridors")) for (const YamlField& f : root.Child("corridors").Items()) ParseCorridor(f, &world);
    if (root.Has("glass")) for (const YamlField& f : root.Child("glass").Items()) ParseGlass(f, idx.walls, &world);
    if (root.Has("clutter")) {
      for (const YamlField& f : root.Child("clutter").Items()) ParseClutter(f, idx.walls, &world);
    }
    if (root.Has("people")) for (const YamlField& f : root.Child("people").Items()) ParsePerson(f, &world);
    ParseRobot(root.Child("robot"), &world);
    CheckStartOutsideClutter(root.Child("robot"), world);
    if (root.Has("sensors")) ParseSensorOptions(root.Child("sensors"), &world.sensors);
    BuildSurfaces(world);
    CheckStartIsFree(root, world);
    return world;
  } catch (const YamlFieldError& e) {
    throw WorldFileError(e.what());
  }
}

World LoadWorldFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw WorldFileError(path + ": cannot open world file");
  std::stringstream text;
  text << in.rdbuf();
  return ParseWorldYaml(text.str(), path);
}

}  // namespace doorplate_localization
