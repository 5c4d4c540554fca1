// map_server-compatible occupancy map files: a YAML file (image, resolution, origin, negate,
// occupied_thresh, free_thresh, mode) beside a PGM (or PNG) image. Writes are atomic (temp file + rename),
// so a crash never leaves a half-written map next to the last good one.
#pragma once

#include <stdexcept>
#include <string>

#include "doorplate_localization/maps/occupancy_grid.h"

namespace doorplate_localization {

// An unusable map file; what() names the file and the field ("maps/x.yaml: resolution: must be > 0, got 0",
// "maps/x.pgm: not a PGM image (bad magic 'P3')").
class MapFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Loads a map_server YAML and its image (path relative to the YAML's folder, `~` expanded) with map_server's
// trinary interpretation (and `scale`/`raw` modes). Throws MapFileError.
OccupancyGrid LoadOccupancyMap(const std::string& yaml_path);

// Writes `<base>.pgm` and `<base>.yaml` (trinary: 254 free, 0 occupied, 205 unknown; thresholds 0.65/0.196)
// atomically; the YAML names the image by its file name. Both carry a "# doorplate_localization save <id>"
// comment (id: a hash of the content); while the two renames happen the previous image is kept as `<base>.pgm.prev`, so a process
// killed mid-save leaves the previous or the new map, as LoadOccupancyMap reads them (it picks `.prev`
// when the image's id differs from the YAML's). Throws MapFileError naming the file on failure.
void SaveOccupancyMap(const OccupancyGrid& grid, const std::string& base_path);

// Writes `text` to `path` atomically (write `path`.tmp.<pid>, fsync, rename). Throws std::runtime_error naming
// the path. Shared by every writer of maps and results.
void WriteFileAtomically(const std::string& path, const std::string& text);

}  // namespace doorplate_localization
