#include "doorplate_localization/maps/building_map.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "doorplate_localization/common/yaml_reader.h"
#include "doorplate_localization/maps/map_io.h"
#include "format_number.h"

namespace doorplate_localization {
namespace {

namespace fs = std::filesystem;

const char kHeaderComment[] = "# Building (floors and lifts), format: docs/building-format.md\n";

[[noreturn]] void Fail(const std::string& source, const std::string& path, const std::string& problem) {
  throw BuildingFileError(source + ": " + path + ": " + problem);
}

std::string Indexed(const std::string& list, size_t i) { return list + "[" + std::to_string(i) + "]"; }

std::string JoinIds(const std::vector<std::string>& ids) {
  std::string text;
  for (const std::string& id : ids) text += (text.empty() ? "" : ", ") + id;
  return text;
}

// The ids of `list` ("floors" or "lifts"): not empty, each once.
void CheckIds(const std::vector<std::string>& ids, const std::string& list, const std::string& kind,
              const std::string& source) {
  std::map<std::string, size_t> seen;
  for (size_t i = 0; i < ids.size(); ++i) {
    if (ids[i].empty()) Fail(source, Indexed(list, i) + ".id", "must not be empty");
    const auto [it, fresh] = seen.emplace(ids[i], i);
    if (!fresh) {
      Fail(source, Indexed(list, i) + ".id",
           "duplicate " + kind + " id '" + ids[i] + "' (also " + Indexed(list, it->second) + ")");
    }
  }
}

void CheckFloorIds(const std::vector<std::string>& ids, const std::string& source) {
  if (ids.empty()) Fail(source, "floors", "must list at least one floor");
  CheckIds(ids, "floors", "floor", source);
}

// Lifts: ids not empty and unique, >= 2 stops, each on a known floor, no floor twice, finite poses.
void CheckLifts(const std::vector<Lift>& lifts, const std::vector<std::string>& floor_ids,
                const std::string& source) {
  std::vector<std::string> lift_ids;
  for (const Lift& lift : lifts) lift_ids.push_back(lift.id);
  CheckIds(lift_ids, "lifts", "lift", source);
  for (size_t l = 0; l < lifts.size(); ++l) {
    const Lift& lift = lifts[l];
    const std::string at = Indexed("lifts", l);
    if (lift.stops.size() < 2) {
      Fail(source, at + ".stops", "a lift needs at least 2 stops, got " + std::to_string(lift.stops.size()));
    }
    std::map<std::string, size_t> floors_served;
    for (size_t s = 0; s < lift.stops.size(); ++s) {
      const LiftStop& stop = lift.stops[s];
      const std::string stop_at = at + Indexed(".stops", s);
      if (std::find(floor_ids.begin(), floor_ids.end(), stop.floor) == floor_ids.end()) {
        Fail(source, stop_at + ".floor", "no floor '" + stop.floor + "' (floors: " + JoinIds(floor_ids) + ")");
      }
      const auto [other, first] = floors_served.emplace(stop.floor, s);
      if (!first) {
        Fail(source, stop_at + ".floor", "lift '" + lift.id + "' stops on floor '" + stop.floor + "' twice (also " +
                                             at + Indexed(".stops", other->second) + ")");
      }
      const std::pair<const char*, double> values[] = {
          {"x_m", stop.pose.x_m}, {"y_m", stop.pose.y_m}, {"yaw_rad", stop.pose.theta_rad}};
      for (const auto& [key, value] : values) {
        if (!std::isfinite(value)) Fail(source, stop_at + "." + key, "must be a finite number");
      }
    }
  }
}

void CheckBuilding(const BuildingFile& building, const std::string& source) {
  if (building.format_version != 1) {
    Fail(source, "format_version", "unsupported version " + std::to_string(building.format_version) +
                                       " (this reader knows 1)");
  }
  if (building.name.empty()) Fail(source, "name", "must not be empty");
  std::vector<std::string> ids;
  for (const BuildingFloor& floor : building.floors) ids.push_back(floor.id);
  CheckFloorIds(ids, source);
  for (size_t i = 0; i < building.floors.size(); ++i) {
    const BuildingFloor& f = building.floors[i];
    if (f.occupancy_map.empty() && f.text_map.empty() && f.world.empty()) {
      Fail(source, Indexed("floors", i), "floor '" + f.id + "' names no file (give occupancy_map, text_map or world)");
    }
  }
  CheckLifts(building.lifts, ids, source);
}

// `path` resolved against `base_dir` when it is relative ("" stays "").
std::string Resolve(const std::string& path, const std::string& base_dir) {
  if (path.empty() || base_dir.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(base_dir) / path).lexically_normal().string();
}

// `path` relative to `base_dir` (both taken from the current folder when relative); absolute when there
// is no relative way (another root).
std::string RelativeTo(const std::string& path, const std::string& base_dir) {
  if (path.empty() || base_dir.empty()) return path;
  const fs::path target = fs::absolute(path).lexically_normal();
  const fs::path relative = target.lexically_relative(fs::absolute(base_dir).lexically_normal());
  return relative.empty() ? target.string() : relative.string();
}

// Index of the floor with `id` in `floors` (BuildingFloor or FloorMaps), -1 if none.
template <typename Floor>
int IndexOfFloor(const std::vector<Floor>& floors, const std::string& id) {
  for (size_t i = 0; i < floors.size(); ++i) {
    if (floors[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

LiftStop ReadStop(const YamlField& item) {
  item.RequireOnlyKeys({"floor", "x_m", "y_m", "yaw_rad"});
  LiftStop stop;
  stop.floor = item.Child("floor").AsString();
  stop.pose = {item.Child("x_m").AsDouble(), item.Child("y_m").AsDouble(), item.Child("yaw_rad").AsDouble()};
  return stop;
}

BuildingFile ReadBuilding(const YamlField& root) {
  root.RequireOnlyKeys({"format_version", "name", "floors", "lifts"});
  BuildingFile building;
  building.format_version = root.Child("format_version").AsInt();
  building.name = root.Child("name").AsString();
  for (const YamlField& item : root.Child("floors").Items()) {
    item.RequireOnlyKeys({"id", "occupancy_map", "text_map", "world"});
    BuildingFloor floor;
    floor.id = item.Child("id").AsString();
    item.Get("occupancy_map", &floor.occupancy_map);
    item.Get("text_map", &floor.text_map);
    item.Get("world", &floor.world);
    building.floors.push_back(floor);
  }
  if (root.Has("lifts")) {
    for (const YamlField& item : root.Child("lifts").Items()) {
      item.RequireOnlyKeys({"id", "stops"});
      Lift lift;
      lift.id = item.Child("id").AsString();
      for (const YamlField& stop : item.Child("stops").Items()) lift.stops.push_back(ReadStop(stop));
      building.lifts.push_back(lift);
    }
  }
  return building;
}

}  // namespace

const LiftStop* Lift::StopOn(const std::string& floor) const {
  for (const LiftStop& stop : stops) {
    if (stop.floor == floor) return &stop;
  }
  return nullptr;
}

int BuildingFile::FloorIndex(const std::string& id) const { return IndexOfFloor(floors, id); }

BuildingFile ParseBuildingFile(const std::string& yaml_text, const std::string& source_name,
                               const std::string& base_dir) {
  BuildingFile building;
  try {
    building = ReadBuilding(YamlField::Parse(yaml_text, source_name));
  } catch (const YamlFieldError& e) {
    throw BuildingFileError(e.what());
  }
  CheckBuilding(building, source_name);
  for (BuildingFloor& floor : building.floors) {
    floor.occupancy_map = Resolve(floor.occupancy_map, base_dir);
    floor.text_map = Resolve(floor.text_map, base_dir);
    floor.world = Resolve(floor.world, base_dir);
  }
  return building;
}

BuildingFile LoadBuildingFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw BuildingFileError(path + ": cannot open the building file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return ParseBuildingFile(buffer.str(), path, fs::path(path).parent_path().string());
}

std::string BuildingFileToYaml(const BuildingFile& building, const std::string& base_dir) {
  CheckBuilding(building, "building '" + building.name + "'");
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "format_version" << YAML::Value << building.format_version;
  out << YAML::Key << "name" << YAML::Value << YAML::DoubleQuoted << building.name;
  out << YAML::Key << "floors" << YAML::Value << YAML::BeginSeq;
  for (const BuildingFloor& floor : building.floors) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "id" << YAML::Value << YAML::DoubleQuoted << floor.id;
    const std::pair<const char*, const std::string*> paths[] = {
        {"occupancy_map", &floor.occupancy_map}, {"text_map", &floor.text_map}, {"world", &floor.world}};
    for (const auto& [key, path] : paths) {
      if (path->empty()) continue;
      out << YAML::Key << key << YAML::Value << YAML::DoubleQuoted << RelativeTo(*path, base_dir);
    }
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "lifts" << YAML::Value << YAML::BeginSeq;
  for (const Lift& lift : building.lifts) {
    out << YAML::BeginMap << YAML::Key << "id" << YAML::Value << YAML::DoubleQuoted << lift.id;
    out << YAML::Key << "stops" << YAML::Value << YAML::BeginSeq;
    for (const LiftStop& stop : lift.stops) {
      out << YAML::Flow << YAML::BeginMap << YAML::Key << "floor" << YAML::Value << YAML::DoubleQuoted << stop.floor;
      out << YAML::Key << "x_m" << YAML::Value << FormatNumber(stop.pose.x_m);
      out << YAML::Key << "y_m" << YAML::Value << FormatNumber(stop.pose.y_m);
      out << YAML::Key << "yaw_rad" << YAML::Value << FormatNumber(stop.pose.theta_rad) << YAML::EndMap;
    }
    out << YAML::EndSeq << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  return kHeaderComment + std::string(out.c_str()) + "\n";
}

void SaveBuildingFile(const BuildingFile& building, const std::string& path) {
  std::string yaml;
  try {
    yaml = BuildingFileToYaml(building, fs::path(path).parent_path().string());
  } catch (const BuildingFileError& e) {
    throw BuildingFileError(path + ": not saved: " + e.what());
  }
  try {
    WriteFileAtomically(path, yaml);
  } catch (const std::runtime_error& e) {
    throw BuildingFileError(e.what());
  }
}

int BuildingMaps::FloorIndex(const std::string& id) const { return IndexOfFloor(floors, id); }

std::vector<int> BuildingMaps::FloorsOfRoom(const std::string& text) const {
  std::vector<int> found;
  for (size_t i = 0; i < floors.size(); ++i) {
    if (floors[i].text_map && !floors[i].text_map->Find(text).empty()) found.push_back(static_cast<int>(i));
  }
  return found;
}

BuildingMaps LoadBuildingMaps(const BuildingFile& building, const std::string& building_path) {
  CheckBuilding(building, building_path);
  BuildingMaps maps;
  maps.name = building.name;
  maps.lifts = building.lifts;
  for (size_t i = 0; i < building.floors.size(); ++i) {
    const BuildingFloor& floor = building.floors[i];
    const std::string at = Indexed("floors", i) + " (id '" + floor.id + "')";
    const std::pair<const char*, const std::string*> required[] = {
        {"occupancy_map", &floor.occupancy_map}, {"text_map", &floor.text_map}};
    for (const auto& [key, path] : required) {
      if (path->empty()) Fail(building_path, at, std::string("no ") + key + " (the maps of every floor need one)");
    }
    FloorMaps loaded;
    loaded.id = floor.id;
    try {
      loaded.grid = LoadOccupancyMap(floor.occupancy_map);
      loaded.text_map = std::make_shared<const TextMap>(LoadTextMap(floor.text_map));
    } catch (const std::runtime_error& e) {  // MapFileError, TextMapError: they name the map file
      Fail(building_path, at, e.what());
    }
    maps.floors.push_back(std::move(loaded));
  }
  ValidateBuildingMaps(maps, building_path);
  return maps;
}

void ValidateBuildingMaps(const BuildingMaps& maps, const std::string& source) {
  std::vector<std::string> ids;
  for (const FloorMaps& floor : maps.floors) ids.push_back(floor.id);
  CheckFloorIds(ids, source);
  for (size_t i = 0; i < maps.floors.size(); ++i) {
    if (!maps.floors[i].text_map) Fail(source, Indexed("floors", i) + " (id '" + ids[i] + "')", "has no text map");
  }
  CheckLifts(maps.lifts, ids, source);
  for (size_t l = 0; l < maps.lifts.size(); ++l) {
    for (size_t s = 0; s < maps.lifts[l].stops.size(); ++s) {
      const LiftStop& stop = maps.lifts[l].stops[s];
      const OccupancyGrid& grid = maps.floors[maps.FloorIndex(stop.floor)].grid;
      const std::string at = Indexed("lifts", l) + Indexed(".stops", s);
      const std::string where = "(" + FormatNumber(stop.pose.x_m) + ", " + FormatNumber(stop.pose.y_m) + ") m";
      int x = 0, y = 0;
      if (!grid.WorldToCell(stop.pose.Position(), &x, &y)) {
        Fail(source, at, where + " is outside the grid of floor '" + stop.floor + "'");
      }
      const std::int8_t value = grid.At(x, y);
      if (value != OccupancyGrid::kFree) {
        const std::string kind =
            value == OccupancyGrid::kUnknown ? "an unknown" : "an occupied (" + std::to_string(value) + ")";
        Fail(source, at, where + " is on " + kind + " cell (" + std::to_string(x) + ", " + std::to_string(y) +
                             ") of floor '" + stop.floor + "'; a stop must be on a free cell");
      }
    }
  }
}

}  // namespace doorplate_localization
