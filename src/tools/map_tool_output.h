// Outputs shared by the offline mapping tools (doorplate_map_log, doorplate_map_rawlog, doorplate_map_bag)
// and doorplate_world_maps: the trajectory file, the occupancy + text map pair, and the wall-time / peak-RSS
// figures of their progress and summary lines. ROS-free, header-only (the tools link doorplate_maps).
#pragma once

#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/slam/trajectory_tree.h"

namespace doorplate_localization::tools {

// Writes `scan_index x y theta` (metres, radians, map frame; 6 decimals) per point, atomically.
inline void WriteTrajectory(const std::vector<TrajectoryPoint>& trajectory, const std::string& path) {
  std::ostringstream text;
  text.precision(6);
  text << std::fixed;
  for (const TrajectoryPoint& p : trajectory) {
    text << p.scan_index << ' ' << p.pose.x_m << ' ' << p.pose.y_m << ' ' << p.pose.theta_rad << '\n';
  }
  WriteFileAtomically(path, text.str());
}

// Writes BASE.pgm + BASE.yaml (map_server format) and BASE.text_map.yaml, whose occupancy_map names
// BASE.yaml relative to it (its file name). Both atomically; throws naming the file on failure.
inline void SaveMapPair(const OccupancyGrid& grid, TextMap text_map, const std::string& base) {
  SaveOccupancyMap(grid, base);
  text_map.occupancy_map = std::filesystem::path(base + ".yaml").filename().string();
  SaveTextMap(text_map, base + ".text_map.yaml");
}

// The process's peak resident set size so far, in MB (getrusage ru_maxrss, KiB on Linux).
inline double PeakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

// Wall time since construction (steady clock), for the tools' progress and summary lines.
class Stopwatch {
 public:
  double Seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_ = Clock::now();
};

}  // namespace doorplate_localization::tools
