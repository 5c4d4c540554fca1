#include "doorplate_localization/maps/map_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>

#include "doorplate_localization/common/limits.h"
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
  std::string save_id;     // the save marker comment SaveOccupancyMap writes, "" for other YAML files
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

// SaveOccupancyMap marks the YAML and the image header of one save with the same comment line, so that a
// loader can tell whether an image belongs to its YAML (see SaveOccupancyMap).
constexpr char kSaveMarker[] = "# doorplate_localization save ";

// The id of the first save marker line within the first `limit` bytes of `text`, or "".
std::string SaveIdIn(const std::string& text, size_t limit = 4096) {
  const std::string head = text.substr(0, limit);
  size_t at = head.rfind(kSaveMarker, 0) == 0 ? 0 : head.find(std::string("\n") + kSaveMarker);
  if (at == std::string::npos) return "";
  if (head[at] == '\n') ++at;
  const size_t begin = at + sizeof(kSaveMarker) - 1;
  const size_t end = head.find_first_of("\r\n", begin);
  return head.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

// The save marker of an image file's header, "" if none or unreadable.
std::string SaveIdOfFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(256, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(std::max<std::streamsize>(0, in.gcount())));
  return SaveIdIn(head);
}

// The image that belongs to a YAML written by SaveOccupancyMap: its named image, or — when a save was
// killed between renaming the new image and the new YAML — the previous image kept as `<image>.prev`.
std::string PairedImagePath(const std::string& image_path, const std::string& save_id) {
  if (save_id.empty() || SaveIdOfFile(image_path) == save_id) return image_path;
  const std::string previous = image_path + ".prev";
  if (fs::is_regular_file(previous) && SaveIdOfFile(previous) == save_id) return previous;
  return image_path;
}

MapMetadata ReadMetadata(const std::string& yaml_path) {
  const std::string text = ReadTextFile(yaml_path);
  const YamlField root = YamlField::Parse(text, yaml_path);
  root.RequireOnlyKeys({"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode"});
  MapMetadata meta;
  const YamlField image = root.Child("image");
  if (image.AsString().empty()) image.Fail("must name the image file");
  meta.image_path = ResolveImagePath(image.AsString(), yaml_path);
  const YamlField resolution = root.Child("resolution");
  meta.resolution_m = resolution.AsDouble();
  if (meta.resolution_m <= 0.0) resolution.Fail("must be > 0, got " + FormatNumber(meta.resolution_m));
  const std::string bad_resolution = limits::CheckMapResolution(meta.resolution_m);
  if (!bad_resolution.empty()) resolution.Fail(bad_resolution);
  const YamlField origin_field = root.Child("origin");
  const std::vector<double> origin = origin_field.AsDoubles(3);
  for (int i = 0; i < 2; ++i) {
    const std::string bad = limits::CheckCoordinate(origin[static_cast<size_t>(i)]);
    if (!bad.empty()) origin_field.Fail(std::string(i == 0 ? "x" : "y") + " " + bad);
  }
  if (!std::isfinite(origin[2])) origin_field.Fail("yaw must be finite");
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
  meta.save_id = SaveIdIn(text);
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

// Writes `text` to `path`.tmp.<pid> and flushes it to disk; returns that name. Throws std::runtime_error
// naming `path` (and removes the temporary file).
std::string WriteTemporaryFile(const std::string& path, const std::string& text) {
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
  return temp;
}

// Renames the flushed `temp` over `path`. Throws std::runtime_error naming `path` (and removes `temp`).
void RenameOver(const std::string& path, const std::string& temp) {
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(temp.c_str());
    throw std::runtime_error(path + ": cannot rename '" + temp + "' over it: " + reason);
  }
}

// Makes renames in the folder of `path` durable; a folder that cannot be opened only loses that guarantee.
void SyncFolderOf(const std::string& path) {
  const std::string folder = fs::path(path).parent_path().empty() ? "." : fs::path(path).parent_path().string();
  const int dir_fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

}  // namespace

OccupancyGrid LoadOccupancyMap(const std::string& yaml_path) {
  MapMetadata meta;
  try {
    meta = ReadMetadata(yaml_path);
  } catch (const YamlFieldError& e) {
    throw MapFileError(e.what());
  }
  const MapImage image = ReadMapImage(PairedImagePath(meta.image_path, meta.save_id));
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
  const std::string image_path = base_path + ".pgm", yaml_path = base_path + ".yaml";
  std::ostringstream body;
  body << "image: " << fs::path(image_path).filename().string() << "\n"
       << "resolution: " << FormatNumber(grid.resolution_m) << "\n"
       << "origin: [" << FormatNumber(grid.origin.x_m) << ", " << FormatNumber(grid.origin.y_m) << ", "
       << FormatNumber(grid.origin.theta_rad) << "]\n"
       << "negate: 0\n"
       << "occupied_thresh: " << FormatNumber(kSaveOccupiedThresh) << "\n"
       << "free_thresh: " << FormatNumber(kSaveFreeThresh) << "\n"
       << "mode: trinary\n";
  const std::string yaml_body = body.str(), pixels = EncodePgm(image);
  // The save's id: a hash of what it writes, so the same map always gives the same files.
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a, 64 bit
  for (const std::string* part : {&yaml_body, &pixels}) {
    for (const unsigned char c : *part) hash = (hash ^ c) * 1099511628211ull;
  }
  std::ostringstream id;
  id << std::hex << hash;
  const std::string yaml = kSaveMarker + id.str() + "\n" + yaml_body;
  const std::string pgm = "P5\n" + std::string(kSaveMarker) + id.str() + "\n" + pixels.substr(3);
  // Two files cannot be replaced in one step. Both are written and flushed under temporary names, the
  // image the current YAML pairs with is kept as `<base>.pgm.prev` (a hard link), then the image and the
  // YAML are renamed over the old ones and `.prev` is removed. A process killed anywhere in between leaves
  // a YAML whose save marker names its image: `<base>.pgm`, or `<base>.pgm.prev` between the two renames,
  // which LoadOccupancyMap then reads. So the map on disk always loads as the previous or the new one
  // (test/maps/map_io_crash_safety_test.cpp). map_server ignores the marker comments.
  const std::string previous = image_path + ".prev";
  std::string image_temp, yaml_temp;  // set while they exist
  try {
    image_temp = WriteTemporaryFile(image_path, pgm);
    yaml_temp = WriteTemporaryFile(yaml_path, yaml);
    std::ifstream old_yaml(yaml_path, std::ios::binary);
    const std::string old_id = old_yaml ? SaveIdIn(std::string(std::istreambuf_iterator<char>(old_yaml), {})) : "";
    if (fs::is_regular_file(image_path) && (old_id.empty() || SaveIdOfFile(image_path) == old_id)) {
      ::unlink(previous.c_str());  // a `.prev` left by an earlier kill that no YAML needs any more
      if (::link(image_path.c_str(), previous.c_str()) != 0) {
        throw std::runtime_error(previous + ": cannot keep the previous image: " + std::strerror(errno));
      }
    }
    RenameOver(image_path, std::exchange(image_temp, ""));
    RenameOver(yaml_path, std::exchange(yaml_temp, ""));
    ::unlink(previous.c_str());
    SyncFolderOf(image_path);
  } catch (const std::runtime_error& e) {
    for (const std::string& temp : {image_temp, yaml_temp}) {
      if (!temp.empty()) ::unlink(temp.c_str());
    }
    throw MapFileError(e.what());
  }
}

void WriteFileAtomically(const std::string& path, const std::string& text) {
  RenameOver(path, WriteTemporaryFile(path, text));
  SyncFolderOf(path);
}

}  // namespace doorplate_localization
