// The picture of a map_server map, decoded: 8-bit grey (colour channels averaged, as map_server does) with
// an optional alpha channel. Row 0 is the TOP of the picture, i.e. the highest y of the map.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace doorplate_localization {

struct MapImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> gray;   // row-major, width * height, 0 black .. 255 white
  std::vector<std::uint8_t> alpha;  // same layout, or empty when the picture has no alpha channel
};

// Reads a binary (P5) or ASCII (P2) PGM with maxval 1..255 (values rescaled to 0..255), or an 8-bit
// image OpenCV decodes (PNG, ...). Throws MapFileError (map_io.h) naming the file and what is wrong; a PGM
// or PNG whose header states more than limits::kMaxMapCells pixels is refused before the file is read whole.
MapImage ReadMapImage(const std::string& path);

// Decodes PGM bytes; `source` names the data in errors. Throws MapFileError.
MapImage ParsePgm(const std::string& bytes, const std::string& source);

// Encodes a binary P5 PGM (maxval 255).
std::string EncodePgm(const MapImage& image);

}  // namespace doorplate_localization
