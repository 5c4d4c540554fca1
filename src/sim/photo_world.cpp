#include "doorplate_localization/sim/photo_world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

namespace doorplate_localization {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> SplitTabs(const std::string& line) {
  std::vector<std::string> columns(1);
  for (char c : line) {
    if (c == '\t') columns.emplace_back(); else columns.back() += c;
  }
  return columns;
}

int ParseInt(const std::string& text, const std::string& where, const char* column, int min_value) {
  std::size_t used = 0;
  long value = 0;
  try {
    value = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || value < min_value || value > 1000000) {
    throw std::invalid_argument(where + ": " + column + " must be a whole number >= " + std::to_string(min_value) +
                                ", got '" + text + "'");
  }
  return static_cast<int>(value);
}

// A YAML double-quoted scalar.
std::string Quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string Num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.4g", v);
  return buffer;
}

}  // namespace

std::vector<PlateCrop> ParsePlateCropTsv(const std::string& tsv_text, const std::string& source_name,
                                         const std::string& base_dir) {
  std::vector<PlateCrop> crops;
  std::istringstream in(tsv_text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::string where = source_name + ":" + std::to_string(number);
    const std::vector<std::string> c = SplitTabs(line);
    if (c.size() != 6) {
      throw std::invalid_argument(where + ": expected 6 tab-separated columns (image_path, x, y, w, h, text), got " +
                                  std::to_string(c.size()));
    }
    PlateCrop crop;
    crop.where = where;
    if (c[0].empty()) throw std::invalid_argument(where + ": image_path is empty");
    const fs::path path(c[0]);
    crop.image_path = (path.is_absolute() || base_dir.empty() ? path : fs::path(base_dir) / path).string();
    crop.x_px = ParseInt(c[1], where, "x", 0);
    crop.y_px = ParseInt(c[2], where, "y", 0);
    crop.width_px = ParseInt(c[3], where, "w", 1);
    crop.height_px = ParseInt(c[4], where, "h", 1);
    crop.text = c[5];
    if (crop.text.empty()) throw std::invalid_argument(where + ": text is empty");
    crops.push_back(crop);
  }
  return crops;
}

void PlateSizeForCrop(const PhotoWorldOptions& o, int width_px, int height_px, double* width_m, double* height_m) {
  const double aspect = static_cast<double>(height_px) / std::max(width_px, 1);  // height / width
  *width_m = o.plate_width_m;
  *height_m = o.plate_width_m * aspect;
  if (*height_m > o.max_plate_height_m) {
    *height_m = o.max_plate_height_m;
    *width_m = o.max_plate_height_m / aspect;
  }
}

PhotoWorld WritePhotoWorld(const std::vector<PlateCrop>& crops, const PhotoWorldOptions& o,
                           const std::string& out_dir) {
  if (crops.empty()) throw std::runtime_error("WritePhotoWorld: no plate crops");
  if (!(o.plate_width_m > 0.0 && o.max_plate_height_m > 0.0 && o.door_spacing_m > 1.0 && o.first_offset_m >= 0.6 &&
        o.corridor_width_m > 0.8 && o.wall_height_m > o.plate_center_height_m + o.max_plate_height_m / 2)) {
    throw std::runtime_error("WritePhotoWorld: unusable options (plate sizes > 0, door_spacing_m > 1, "
                             "first_offset_m >= 0.6, corridor_width_m > 0.8, plates below the ceiling)");
  }
  if (o.name.empty() || o.name.find('/') != std::string::npos) {
    throw std::runtime_error("WritePhotoWorld: name must be a non-empty file stem, got '" + o.name + "'");
  }
  const fs::path dir = fs::path(out_dir) / "worlds";
  fs::create_directories(dir / "faces");
  PhotoWorld world;
  world.world_path = (dir / (o.name + ".yaml")).string();
  const double step = o.door_spacing_m / 2.0;
  world.length_m = 2.0 * o.first_offset_m + step * static_cast<double>(crops.size() - 1);

  std::ostringstream doors, plates;
  for (std::size_t i = 0; i < crops.size(); ++i) {
    const PlateCrop& crop = crops[i];
    const cv::Mat photo = cv::imread(crop.image_path, cv::IMREAD_COLOR);
    if (photo.empty()) throw std::runtime_error(crop.where + ": cannot read image '" + crop.image_path + "'");
    if (crop.width_px < o.min_crop_px || crop.height_px < o.min_crop_px) {
      throw std::runtime_error(crop.where + ": box " + std::to_string(crop.width_px) + "x" +
                               std::to_string(crop.height_px) + " is smaller than " + std::to_string(o.min_crop_px) +
                               " px");
    }
    const cv::Rect box(crop.x_px, crop.y_px, crop.width_px, crop.height_px);
    if ((box & cv::Rect(0, 0, photo.cols, photo.rows)) != box) {
      throw std::runtime_error(crop.where + ": box (" + std::to_string(box.x) + ", " + std::to_string(box.y) + ", " +
                               std::to_string(box.width) + ", " + std::to_string(box.height) + ") leaves the " +
                               std::to_string(photo.cols) + "x" + std::to_string(photo.rows) + " image '" +
                               crop.image_path + "'");
    }
    char name[32];
    std::snprintf(name, sizeof(name), "plate_%02zu.png", i + 1);
    const fs::path face = dir / "faces" / name;
    if (!cv::imwrite(face.string(), photo(box))) throw std::runtime_error(face.string() + ": cannot write");
    world.face_paths.push_back(face.string());

    double width_m = 0.0, height_m = 0.0;
    PlateSizeForCrop(o, crop.width_px, crop.height_px, &width_m, &height_m);
    const std::string id = "d" + std::to_string(i + 1);
    doors << "  - {id: " << id << ", wall: " << (i % 2 == 0 ? "north" : "south")
          << ", offset_m: " << Num(o.first_offset_m + step * static_cast<double>(i)) << "}\n";
    plates << "  - {text: " << Quoted(crop.text) << ", door: " << id << ", center_height_m: "
           << Num(o.plate_center_height_m) << ", size_m: [" << Num(width_m) << ", " << Num(height_m)
           << "], image: faces/" << name << "}  # " << crop.where << "\n";
  }

  const std::string length = Num(world.length_m), width = Num(o.corridor_width_m);
  std::ostringstream yaml;
  yaml << "# Written by doorplate_photo_world: " << crops.size() << " real plate crops as image plates on the\n"
       << "# closed doors of a " << length << " m x " << width << " m corridor (docs/world-format.md).\n"
       << "format_version: 1\n"
       << "name: " << o.name << "\n"
       << "description: " << Quoted(std::to_string(crops.size()) + " photographed plates, alternating walls") << "\n"
       << "wall_height_m: " << Num(o.wall_height_m) << "\n"
       << "walls:\n"
       << "  - {id: south, from: [0, 0], to: [" << length << ", 0], corridor_side: left}\n"
       << "  - {id: north, from: [0, " << width << "], to: [" << length << ", " << width << "], corridor_side: right}\n"
       << "  - {id: west, from: [0, 0], to: [0, " << width << "], corridor_side: right}\n"
       << "  - {id: east, from: [" << length << ", 0], to: [" << length << ", " << width << "], corridor_side: left}\n"
       << "doors:\n" << doors.str() << "plates:\n" << plates.str()
       << "robot:\n  start: {x_m: 0.6, y_m: " << Num(o.corridor_width_m * 0.3) << ", theta_deg: 0}\n";
  const fs::path tmp = world.world_path + ".tmp";
  {
    std::ofstream out(tmp);
    out << yaml.str();
    if (!out) throw std::runtime_error(tmp.string() + ": cannot write");
  }
  fs::rename(tmp, world.world_path);
  return world;
}

}  // namespace doorplate_localization
