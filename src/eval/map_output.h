// Files of a `doorplate_eval map` run (--out-dir): the occupancy map (map_server PGM + YAML), the text map
// YAML naming it, and a PNG of the map with the trajectory, the mapped plates and the true ones. All written
// atomically (the map savers; the PNG through WriteFileAtomically).
#pragma once

#include <string>

#include "doorplate_localization/maps/text_map.h"
#include "map_eval.h"

namespace doorplate_localization {

// Writes DIR/map.pgm, DIR/map.yaml, DIR/text_map.yaml and DIR/map.png (creates DIR). `truth` is the
// world's text map (world frame), drawn in the map frame through result.world_from_map. Throws
// std::runtime_error (or the savers' errors) naming the file.
void WriteMapOutputs(const MapEvalResult& result, const TextMap& truth, const std::string& dir);

}  // namespace doorplate_localization
