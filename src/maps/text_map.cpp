#include "doorplate_localization/maps/text_map.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>

#include <yaml-cpp/yaml.h>

#include "doorplate_localization/common/yaml_reader.h"
#include "doorplate_localization/maps/map_io.h"
#include "format_number.h"

namespace doorplate_localization {
namespace {

const char kHeaderComment[] = "# Text-landmark map (doorplates), format: docs/text-map-format.md\n";

TextLandmark ReadLandmark(const YamlField& item, const RoomIdGrammar& grammar) {
  item.RequireOnlyKeys({"index", "text", "x_m", "y_m", "yaw_rad", "height_m", "wall", "observations",
                        "position_stddev_m"});
  TextLandmark landmark;
  const YamlField text = item.Child("text");
  landmark.text = text.AsString();
  if (landmark.text.empty()) text.Fail("must not be empty");
  if (!grammar.Accepts(landmark.text)) {
    text.Fail("'" + landmark.text + "' (canonical '" + CanonicalRoomId(landmark.text) +
              "') does not fit room_pattern '" + grammar.pattern() + "'");
  }
  landmark.pose = {item.Child("x_m").AsDouble(), item.Child("y_m").AsDouble(), item.Child("yaw_rad").AsDouble()};
  landmark.height_m = item.NonNegative("height_m", landmark.height_m);
  item.Get("wall", &landmark.wall);
  item.Get("observations", &landmark.observations);
  if (landmark.observations < 0) item.Child("observations").Fail("must be >= 0");
  landmark.position_stddev_m = item.NonNegative("position_stddev_m", 0.0);
  return landmark;
}

// Landmarks in index order; every index 0..n-1 exactly once.
std::vector<TextLandmark> ReadLandmarks(const YamlField& list, const RoomIdGrammar& grammar) {
  const std::vector<YamlField> items = list.Items();
  std::vector<TextLandmark> landmarks(items.size());
  std::vector<int> seen_at(items.size(), -1);
  for (size_t k = 0; k < items.size(); ++k) {
    TextLandmark landmark = ReadLandmark(items[k], grammar);
    const YamlField index_field = items[k].Child("index");
    const int index = index_field.AsInt();
    if (index < 0 || index >= static_cast<int>(items.size())) {
      index_field.Fail("must be within 0.." + std::to_string(static_cast<int>(items.size()) - 1) +
                       " (indexes number the landmarks 0..n-1), got " + std::to_string(index));
    }
    if (seen_at[index] >= 0) {
      index_field.Fail("duplicate index " + std::to_string(index) + " (also landmarks[" +
                       std::to_string(seen_at[index]) + "])");
    }
    seen_at[index] = static_cast<int>(k);
    landmarks[index] = std::move(landmark);
  }
  return landmarks;
}

int ReadEndpoint(const YamlField& item, const std::string& key, size_t landmark_count) {
  const YamlField field = item.Child(key);
  const int index = field.AsInt();
  if (index < 0 || index >= static_cast<int>(landmark_count)) {
    field.Fail("no landmark with index " + std::to_string(index) + " (the map has " +
               std::to_string(landmark_count) + ")");
  }
  return index;
}

std::vector<AdjacentDistance> ReadAdjacent(const YamlField& list, size_t landmark_count) {
  std::vector<AdjacentDistance> adjacent;
  std::set<std::tuple<int, int, std::string>> seen;
  for (const YamlField& item : list.Items()) {
    item.RequireOnlyKeys({"from", "to", "distance_m", "source"});
    AdjacentDistance d;
    d.from = ReadEndpoint(item, "from", landmark_count);
    d.to = ReadEndpoint(item, "to", landmark_count);
    if (d.from == d.to) item.Child("to").Fail("must differ from 'from' (" + std::to_string(d.from) + ")");
    const YamlField distance = item.Child("distance_m");
    d.distance_m = distance.AsDouble();
    if (d.distance_m < 0.0) distance.Fail("must be >= 0, got " + FormatNumber(d.distance_m));
    item.Get("source", &d.source);
    if (d.source != "map" && d.source != "odometry") {
      item.Child("source").Fail("must be 'map' or 'odometry', got '" + d.source + "'");
    }
    if (!seen.insert({d.from, d.to, d.source}).second) {
      item.Fail("duplicate entry for " + std::to_string(d.from) + " -> " + std::to_string(d.to) + " (" +
                d.source + ")");
    }
    adjacent.push_back(d);
  }
  return adjacent;
}

// Unit direction of the principal axis of the points, pointing towards +x (or +y when vertical).
Vec2 PrincipalAxis(const std::vector<Vec2>& points) {
  Vec2 mean;
  for (const Vec2& p : points) mean = mean + p;
  mean = (1.0 / points.size()) * mean;
  double sxx = 0, syy = 0, sxy = 0;
  for (const Vec2& p : points) {
    const Vec2 d = p - mean;
    sxx += d.x * d.x;
    syy += d.y * d.y;
    sxy += d.x * d.y;
  }
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  Vec2 axis{std::cos(angle), std::sin(angle)};
  if (axis.x < -1e-9 || (std::abs(axis.x) <= 1e-9 && axis.y < 0)) axis = -1.0 * axis;
  return axis;
}

}  // namespace

std::vector<int> TextMap::Find(const std::string& text) const {
  std::vector<int> found;
  for (size_t i = 0; i < landmarks.size(); ++i) {
    if (SameRoom(landmarks[i].text, text)) found.push_back(static_cast<int>(i));
  }
  return found;
}

std::vector<std::string> TextMap::Texts() const {
  std::map<std::string, std::string> first_text;  // canonical form -> first printed text
  for (const TextLandmark& l : landmarks) first_text.emplace(CanonicalRoomId(l.text), l.text);
  std::vector<std::string> texts;
  for (const auto& [canonical, text] : first_text) texts.push_back(text);
  std::sort(texts.begin(), texts.end());
  return texts;
}

TextMap ParseTextMap(const std::string& yaml_text, const std::string& source_name) {
  try {
    const YamlField root = YamlField::Parse(yaml_text, source_name);
    root.RequireOnlyKeys({"format_version", "frame_id", "occupancy_map", "room_pattern", "landmarks", "adjacent"});
    TextMap map;
    const YamlField version = root.Child("format_version");
    if (version.AsInt() != 1) version.Fail("unsupported version " + version.AsString() + " (this reader knows 1)");
    root.Get("frame_id", &map.frame_id);
    if (map.frame_id.empty()) root.Child("frame_id").Fail("must not be empty");
    root.Get("occupancy_map", &map.occupancy_map);
    root.Get("room_pattern", &map.room_pattern);
    std::optional<RoomIdGrammar> grammar;
    try {
      grammar.emplace(map.room_pattern);
    } catch (const std::invalid_argument& e) {
      root.Child("room_pattern").Fail(e.what());  // only a pattern read from the file can be bad here
    }
    map.landmarks = ReadLandmarks(root.Child("landmarks"), *grammar);
    if (root.Has("adjacent")) map.adjacent = ReadAdjacent(root.Child("adjacent"), map.landmarks.size());
    return map;
  } catch (const YamlFieldError& e) {
    throw TextMapError(e.what());
  }
}

TextMap LoadTextMap(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TextMapError(path + ": cannot open the text map");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return ParseTextMap(buffer.str(), path);
}

std::string TextMapToYaml(const TextMap& map) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "format_version" << YAML::Value << map.format_version;
  out << YAML::Key << "frame_id" << YAML::Value << YAML::DoubleQuoted << map.frame_id;
  out << YAML::Key << "occupancy_map" << YAML::Value << YAML::DoubleQuoted << map.occupancy_map;
  out << YAML::Key << "room_pattern" << YAML::Value << YAML::DoubleQuoted << map.room_pattern;
  out << YAML::Key << "landmarks" << YAML::Value << YAML::BeginSeq;
  for (size_t i = 0; i < map.landmarks.size(); ++i) {
    const TextLandmark& l = map.landmarks[i];
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "index" << YAML::Value << i;
    out << YAML::Key << "text" << YAML::Value << YAML::DoubleQuoted << l.text;
    out << YAML::Key << "x_m" << YAML::Value << FormatNumber(l.pose.x_m);
    out << YAML::Key << "y_m" << YAML::Value << FormatNumber(l.pose.y_m);
    out << YAML::Key << "yaw_rad" << YAML::Value << FormatNumber(l.pose.theta_rad);
    out << YAML::Key << "height_m" << YAML::Value << FormatNumber(l.height_m);
    out << YAML::Key << "wall" << YAML::Value << YAML::DoubleQuoted << l.wall;
    out << YAML::Key << "observations" << YAML::Value << l.observations;
    out << YAML::Key << "position_stddev_m" << YAML::Value << FormatNumber(l.position_stddev_m);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "adjacent" << YAML::Value << YAML::BeginSeq;
  for (const AdjacentDistance& d : map.adjacent) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "from" << YAML::Value << d.from;
    out << YAML::Key << "to" << YAML::Value << d.to;
    out << YAML::Key << "distance_m" << YAML::Value << FormatNumber(d.distance_m);
    out << YAML::Key << "source" << YAML::Value << d.source << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  return kHeaderComment + std::string(out.c_str()) + "\n";
}

void SaveTextMap(const TextMap& map, const std::string& path) {
  const std::string yaml = TextMapToYaml(map);
  ParseTextMap(yaml, path);  // never write a file that would not load: throws naming path and field
  try {
    WriteFileAtomically(path, yaml);
  } catch (const std::runtime_error& e) {
    throw TextMapError(e.what());
  }
}

void ComputeAdjacentDistances(TextMap* map) {
  std::vector<AdjacentDistance>& adjacent = map->adjacent;
  adjacent.erase(std::remove_if(adjacent.begin(), adjacent.end(),
                                [](const AdjacentDistance& d) { return d.source == "map"; }),
                 adjacent.end());
  std::map<std::string, std::vector<int>> by_wall;  // plates without a wall label have no neighbours
  for (size_t i = 0; i < map->landmarks.size(); ++i) {
    if (!map->landmarks[i].wall.empty()) by_wall[map->landmarks[i].wall].push_back(static_cast<int>(i));
  }
  for (auto& [wall, indexes] : by_wall) {
    if (indexes.size() < 2) continue;
    std::vector<Vec2> points;
    for (int i : indexes) points.push_back(map->landmarks[i].pose.Position());
    const Vec2 axis = PrincipalAxis(points);
    const auto along = [&](int i) { return Dot(map->landmarks[i].pose.Position(), axis); };
    std::stable_sort(indexes.begin(), indexes.end(), [&](int a, int b) { return along(a) < along(b); });
    for (size_t k = 0; k + 1 < indexes.size(); ++k) {
      adjacent.push_back({indexes[k], indexes[k + 1], along(indexes[k + 1]) - along(indexes[k]), "map"});
    }
  }
}

}  // namespace doorplate_localization
