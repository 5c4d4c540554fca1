// What the offline tools check before they write anything (issue 18): an output never replaces one of the
// run's inputs, and a run that produced nothing usable writes nothing (a good result from an earlier run
// in the same folder stays). ROS-free, header-only.
#pragma once

#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "usage_error.h"
#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"

namespace doorplate_localization::tools {

// A path and the option (or argument) that named it, for messages: {"--world", "worlds/x.yaml"}.
struct NamedPath {
  std::string option;
  std::string path;
};

// Whether `a` and `b` are the same file: when both exist, the same file system object (so hard and
// symbolic links and other spellings count); else the same absolute, normalized path.
inline bool SameFile(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) {
    const bool same = fs::equivalent(a, b, error);
    if (!error) return same;
  }
  const fs::path pa = fs::weakly_canonical(fs::absolute(a), error);
  const fs::path pb = fs::weakly_canonical(fs::absolute(b), error);
  return pa.lexically_normal() == pb.lexically_normal();
}

// Throws UsageError naming both when an output is an input: "--out maps/x: would write worlds/x.yaml, the
// input given to --world; nothing was written".
inline void RefuseOverwritingInputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (const NamedPath& out : outputs) {
    for (const NamedPath& in : inputs) {
      if (!in.path.empty() && !out.path.empty() && SameFile(in.path, out.path)) {
        throw UsageError(out.option + ": would write " + out.path + ", the input given to " + in.option +
                         "; nothing was written");
      }
    }
  }
}

// Throws std::runtime_error "<source>: the run produced no usable map (...): nothing was written" unless the
// grid has a finite origin and resolution and at least one free and one occupied cell.
inline void RequireUsableMap(const OccupancyGrid& grid, const std::string& source) {
  long free_cells = 0, occupied_cells = 0;
  for (const std::int8_t v : grid.cells) {
    if (v == OccupancyGrid::kFree) ++free_cells;
    if (v == OccupancyGrid::kOccupied) ++occupied_cells;
  }
  const bool finite = std::isfinite(grid.origin.x_m) && std::isfinite(grid.origin.y_m) &&
                      std::isfinite(grid.resolution_m) && grid.resolution_m > 0.0;
  if (!finite || free_cells == 0 || occupied_cells == 0) {
    throw std::runtime_error(source + ": the run produced no usable map (" + std::to_string(grid.width) + " x " +
                             std::to_string(grid.height) + " cells, " + std::to_string(free_cells) + " free, " +
                             std::to_string(occupied_cells) + " occupied" + (finite ? "" : ", non-finite origin") +
                             "): nothing was written");
  }
}

// Throws std::runtime_error "<source>: the trajectory is empty / pose k is not finite: nothing was written".
template <class Point>
void RequireFiniteTrajectory(const std::vector<Point>& trajectory, const std::string& source) {
  if (trajectory.empty()) throw std::runtime_error(source + ": the trajectory is empty: nothing was written");
  for (size_t i = 0; i < trajectory.size(); ++i) {
    const Pose2D& p = trajectory[i].pose;
    if (!std::isfinite(p.x_m) || !std::isfinite(p.y_m) || !std::isfinite(p.theta_rad)) {
      throw std::runtime_error(source + ": pose " + std::to_string(i) + " of the trajectory is not finite: " +
                               "nothing was written");
    }
  }
}

}  // namespace doorplate_localization::tools
