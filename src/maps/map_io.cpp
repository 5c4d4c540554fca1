#include "doorplate_localization/maps/map_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "doorplate_localization/common/yaml_reader.h"
#include "doorplate_localization/maps/map_image.h"
#include "format_number.h"

namespace doorplate_localization {
namespace {

namespace fs = std::filesystem;

enum class MapMode { kTrinary, kScale, kRaw };

// What the YAML says about its image.
struct MapMetadata {
  std::string image_path;  // resolved: `~` expanded, relative to the YAML's folder
  double resolution_m = 0.0;
  Pose2D origin;
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  MapMode mode = MapMode::kTrinary;
};

// The thresholds SaveOccupancyMap writes: 205 (unknown) reads back as neither free nor occupied.
constexpr double kSaveOccupiedThresh = 0.65;
constexpr double kSaveFreeThresh = 0.196;

std::string ReadTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MapFileError(path + ": cannot open the map file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string ResolveImagePath(const std::string& image, const std::string& yaml_path) {
  if (image.rfind("~/", 0) == 0 || image == "~") {
    const char* home = std::getenv("HOME");
    return std::string(home ? home : "") + image.substr(1);
  }
  const fs::path p(image);
  if (p.is_absolute()) return image;
  return (fs::path(yaml_path).parent_path() / p).lexically_normal().string();
}

// map_server writes `negate: 0`; a YAML boolean is accepted too.
bool ReadNegate(const YamlField& field) {
  const std::string text = field.AsString();
  if (text == "0") return false;
  if (text == "1") return true;
  try {
    return field.AsBool();
  } catch (const YamlFieldError&) {
    field.Fail("must be 0 or 1, got '" + text + "'");
  }
}

double ReadProbability(const YamlField& root, const std::string& key) {
  const YamlField field = root.Child(key);
  const double v = field.AsDouble();
  if (v < 0.0 || v > 1.0) field.Fail("must be within [0, 1], got " + FormatNumber(v));
  return v;
}

MapMetadata ReadMetadata(const std::string& yaml_path) {
  const YamlField root = YamlField::Parse(ReadTextFile(yaml_path), yaml_path);
  root.RequireOnlyKeys({"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode"});
  MapMetadata meta;
  const YamlField image = root.Child("image");
  if (image.AsString().empty()) image.Fail("must name the image file");
  meta.image_path = ResolveImagePath(image.AsString(), yaml_path);
  const YamlField resolution = root.Child("resolution");
  meta.resolution_m = resolution.AsDouble();
  if (meta.resolution_m <= 0.0) resolution.Fail("must be > 0, got " + FormatNumber(meta.resolution_m));
  const std::vector<double> origin = root.Child("origin").AsDoubles(3);
  meta.origin = {origin[0], origin[1], origin[2]};
  meta.negate = ReadNegate(root.Child("negate"));
  meta.occupied_thresh = ReadProbability(root, "occupied_thresh");
  meta.free_thresh = ReadProbability(root, "free_thresh");
  if (meta.free_thresh >= meta.occupied_thresh) {
    root.Child("free_thresh").Fail("must be < occupied_thresh (" + FormatNumber(meta.occupied_thresh) +
                                   "), got " + FormatNumber(meta.free_thresh));
  }
  if (root.Has("mode")) {
    const YamlField mode = root.Child("mode");
    const std::string m = mode.AsString();
    if (m == "trinary") meta.mode = MapMode::kTrinary;
    else if (m == "scale") meta.mode = MapMode::kScale;
    else if (m == "raw") meta.mode = MapMode::kRaw;
    else mode.Fail("must be trinary, scale or raw, got '" + m + "'");
  }
  if (!fs::is_regular_file(meta.image_path)) {
    image.Fail("image file '" + meta.image_path + "' not found");
  }
  return meta;
}

// map_server's interpretation of one pixel (grey level after averaging the colour channels).
std::int8_t CellValue(int gray, int alpha, const MapMetadata& meta) {
  const int value = meta.negate ? 255 - gray : gray;
  if (meta.mode == MapMode::kRaw) return static_cast<std::int8_t>(value);  // 0..255 as int8, like map_server
  const double occupancy = (255 - value) / 255.0;
  if (occupancy > meta.occupied_thresh) return OccupancyGrid::kOccupied;
  if (occupancy < meta.free_thresh) return OccupancyGrid::kFree;
  if (meta.mode == MapMode::kTrinary || alpha < 255) return OccupancyGrid::kUnknown;
  const double ratio = (occupancy - meta.free_thresh) / (meta.occupied_thresh - meta.free_thresh);
  return static_cast<std::int8_t>(1 + 98 * ratio);
}

// Saved pixel of a cell: its occupancy probability against the thresholds written beside it.
std::uint8_t PixelValue(std::int8_t cell) {
  if (cell < 0 || cell > 100) return 205;
  const double p = cell / 100.0;
  if (p > kSaveOccupiedThresh) return 0;
  if (p < kSaveFreeThresh) return 254;
  return 205;
}

}  // namespace

OccupancyGrid LoadOccupancyMap(const std::string& yaml_path) {
  MapMetadata meta;
  try {
    meta = ReadMetadata(yaml_path);
  } catch (const YamlFieldError& e) {
    throw MapFileError(e.what());
  }
  const MapImage image = ReadMapImage(meta.image_path);
  OccupancyGrid grid(image.width, image.height, meta.resolution_m, meta.origin);
  for (int row = 0; row < image.height; ++row) {
    for (int x = 0; x < image.width; ++x) {
      const size_t i = static_cast<size_t>(row) * image.width + x;
      const int alpha = image.alpha.empty() ? 255 : image.alpha[i];
      grid.At(x, image.height - 1 - row) = CellValue(image.gray[i], alpha, meta);  // row 0 = top = highest y
    }
  }
  return grid;
}

void SaveOccupancyMap(const OccupancyGrid& grid, const std::string& base_path) {
  if (grid.width <= 0 || grid.height <= 0 ||
      grid.cells.size() != static_cast<size_t>(grid.width) * static_cast<size_t>(grid.height)) {
    throw MapFileError(base_path + ".yaml: cannot save a grid of " + std::to_string(grid.width) + " x " +
                       std::to_string(grid.height) + " cells holding " + std::to_string(grid.cells.size()));
  }
  MapImage image;
  image.width = grid.width;
  image.height = grid.height;
  image.gray.resize(grid.cells.size());
  for (int row = 0; row < grid.height; ++row) {
    for (int x = 0; x < grid.width; ++x) {
      image.gray[static_cast<size_t>(row) * grid.width + x] = PixelValue(grid.At(x, grid.height - 1 - row));
    }
  }
  const std::string image_path = base_path + ".pgm";
  std::ostringstream yaml;
  yaml << "image: " << fs::path(image_path).filename().string() << "\n"
       << "resolution: " << FormatNumber(grid.resolution_m) << "\n"
       << "origin: [" << FormatNumber(grid.origin.x_m) << ", " << FormatNumber(grid.origin.y_m) << ", "
       << FormatNumber(grid.origin.theta_rad) << "]\n"
       << "negate: 0\n"
       << "occupied_thresh: " << FormatNumber(kSaveOccupiedThresh) << "\n"
       << "free_thresh: " << FormatNumber(kSaveFreeThresh) << "\n"
       << "mode: trinary\n";
  try {
    WriteFileAtomically(image_path, EncodePgm(image));  // the image first: the YAML never names a missing one
    WriteFileAtomically(base_path + ".yaml", yaml.str());
  } catch (const std::runtime_error& e) {
    throw MapFileError(e.what());
  }
}

void WriteFileAtomically(const std::string& path, const std::string& text) {
  const std::string temp = path + ".tmp." + std::to_string(::getpid());
  const auto fail = [&](const std::string& what) {
    const std::string reason = std::strerror(errno);
    ::unlink(temp.c_str());
    throw std::runtime_error(path + ": " + what + ": " + reason);
  };
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    const std::string reason = std::strerror(errno);  // nothing of ours to remove: `temp` may be someone's
    throw std::runtime_error(path + ": cannot create the temporary file '" + temp + "': " + reason);
  }
  size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      ::close(fd);
      fail("cannot write '" + temp + "'");
    }
    written += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) {
    ::close(fd);
    fail("cannot flush '" + temp + "' to disk");
  }
  if (::close(fd) != 0) fail("cannot close '" + temp + "'");
  if (::rename(temp.c_str(), path.c_str()) != 0) fail("cannot rename '" + temp + "' over it");
  // Make the rename itself durable; a folder that cannot be opened only loses that guarantee.
  const std::string folder = fs::path(path).parent_path().empty() ? "." : fs::path(path).parent_path().string();
  const int dir_fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

}  // namespace doorplate_localization
