#include "map_output.h"

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

#include "doorplate_localization/maps/map_io.h"
#include "map_overlay.h"

namespace doorplate_localization {
namespace {

// The map with the trajectory, the mapped plates (red circles) and the true ones (green crosses).
cv::Mat DrawMap(const MapEvalResult& r, const TextMap& truth) {
  MapOverlay overlay;
  OverlayPath path;
  for (const Pose2D& p : r.trajectory) path.points.push_back(p.Position());
  path.color = {200, 120, 0};
  path.thickness_px = 1;
  overlay.paths.push_back(path);
  const Pose2D map_from_world = r.world_from_map.Inverse();
  for (const TextLandmark& l : truth.landmarks) {
    overlay.marks.push_back({map_from_world.TransformPoint(l.pose.Position()), "", {0, 170, 0}, true, false});
  }
  for (const TextLandmark& l : r.text_map.landmarks) {
    overlay.marks.push_back({l.pose.Position(), l.text, {0, 0, 220}, false, l.pose.theta_rad < 0});
  }
  overlay.legend = "blue: trajectory  red: mapped plates  green: true plates";
  return DrawMapOverlay(r.grid, overlay);
}

}  // namespace

void WriteMapOutputs(const MapEvalResult& result, const TextMap& truth, const std::string& dir) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path base = std::filesystem::path(dir);
  SaveOccupancyMap(result.grid, (base / "map").string());
  TextMap text_map = result.text_map;
  text_map.occupancy_map = "map.yaml";
  SaveTextMap(text_map, (base / "text_map.yaml").string());
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", DrawMap(result, truth), png)) {
    throw std::runtime_error((base / "map.png").string() + ": PNG encoding failed");
  }
  WriteFileAtomically((base / "map.png").string(), std::string(png.begin(), png.end()));
  // One line per processed scan: the best particle's pose and the true pose, both in the map frame.
  std::ostringstream traj;
  traj << "# processed_scan est_x_m est_y_m est_theta_rad true_x_m true_y_m true_theta_rad (map frame)\n";
  const std::size_t n = std::min(result.trajectory.size(), result.true_trajectory.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Pose2D& e = result.trajectory[i];
    const Pose2D& t = result.true_trajectory[i];
    traj << i << ' ' << e.x_m << ' ' << e.y_m << ' ' << e.theta_rad << ' ' << t.x_m << ' ' << t.y_m << ' '
         << t.theta_rad << '\n';
  }
  WriteFileAtomically((base / "trajectory.txt").string(), traj.str());
}

}  // namespace doorplate_localization
