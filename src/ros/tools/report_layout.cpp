#include "report_layout.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {

MapWindow KnownExtent(const OccupancyGrid& grid) {
  if (grid.width <= 0 || grid.height <= 0) throw std::invalid_argument("KnownExtent: empty grid");
  int x_min = grid.width, y_min = grid.height, x_max = -1, y_max = -1;
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      if (grid.At(x, y) == OccupancyGrid::kUnknown) continue;
      x_min = std::min(x_min, x), x_max = std::max(x_max, x);
      y_min = std::min(y_min, y), y_max = std::max(y_max, y);
    }
  }
  if (x_max < 0) x_min = 0, y_min = 0, x_max = grid.width - 1, y_max = grid.height - 1;
  // The cells' corners, taken into the map frame (the grid's origin may be rotated).
  MapWindow w{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
              std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  for (const int cx : {x_min, x_max + 1}) {
    for (const int cy : {y_min, y_max + 1}) {
      const Vec2 p = grid.origin.TransformPoint({cx * grid.resolution_m, cy * grid.resolution_m});
      w.x0_m = std::min(w.x0_m, p.x), w.x1_m = std::max(w.x1_m, p.x);
      w.y0_m = std::min(w.y0_m, p.y), w.y1_m = std::max(w.y1_m, p.y);
    }
  }
  return w;
}

FoldedLayout FoldExtent(const MapWindow& extent, const FoldOptions& options) {
  if (!(extent.WidthM() > 0.0 && extent.HeightM() > 0.0)) throw std::invalid_argument("FoldExtent: empty extent");
  if (!(options.width_px >= 100.0)) throw std::invalid_argument("FoldOptions.width_px must be >= 100");
  if (!(options.margin_m >= 0.0)) throw std::invalid_argument("FoldOptions.margin_m must be >= 0");
  if (!(options.overlap_m >= 0.0)) throw std::invalid_argument("FoldOptions.overlap_m must be >= 0");
  if (!(options.target_aspect > 0.0)) throw std::invalid_argument("FoldOptions.target_aspect must be > 0");
  if (options.max_segments < 1) throw std::invalid_argument("FoldOptions.max_segments must be >= 1");
  if (!(options.max_px_per_m > 0.0)) throw std::invalid_argument("FoldOptions.max_px_per_m must be > 0");
  const double width = extent.WidthM() + 2.0 * options.margin_m;
  const double height = extent.HeightM() + 2.0 * options.margin_m;
  int best = 1;
  double best_miss = std::numeric_limits<double>::max();
  for (int k = 1; k <= options.max_segments; ++k) {
    const double segment = (width + (k - 1) * options.overlap_m) / k;
    if (k > 1 && segment < height) break;  // folding further would make segments taller than wide
    const double miss = std::fabs(std::log(segment / (k * height) / options.target_aspect));
    if (miss < best_miss) best_miss = miss, best = k;
  }
  FoldedLayout layout;
  const double segment = (width + (best - 1) * options.overlap_m) / best;
  layout.px_per_m = std::min(options.width_px / segment, options.max_px_per_m);
  const double x0 = extent.x0_m - options.margin_m, y0 = extent.y0_m - options.margin_m;
  for (int k = 0; k < best; ++k) {
    const double left = x0 + k * (segment - options.overlap_m);
    layout.windows.push_back({left, y0, left + segment, y0 + height});
  }
  return layout;
}

std::vector<double> NiceTicks(double lo, double hi, int max_count) {
  if (!(hi > lo) || max_count < 2) return {};
  const double raw = (hi - lo) / (max_count - 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10.0 * power;
  for (const double m : {1.0, 2.0, 5.0}) {
    if (m * power >= raw) {
      step = m * power;
      break;
    }
  }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) {
    ticks.push_back(std::fabs(t) < 1e-12 * step ? 0.0 : t);
  }
  return ticks;
}

double ArrowMagnification(double max_error_m, double target_length_m) {
  if (!(max_error_m > 0.0)) return 1.0;
  double best = 1.0;
  for (double power = 1.0; power <= 1000.0; power *= 10.0) {
    for (const double m : {1.0, 2.0, 5.0}) {
      if (m * power <= 1000.0 && m * power * max_error_m <= target_length_m) best = m * power;
    }
  }
  return best;
}

std::vector<PlateErrorRow> PairPlates(const TextMap& mapped, const TextMap& truth, const Pose2D& map_from_world,
                                      double match_radius_m) {
  std::vector<PlateErrorRow> rows;
  for (const TextLandmark& t : truth.landmarks) {
    PlateErrorRow row;
    row.text = t.text;
    row.truth = map_from_world.TransformPoint(t.pose.Position());
    rows.push_back(row);
  }
  std::vector<std::tuple<double, int, int>> pairs;  // distance, mapped, true
  for (std::size_t i = 0; i < mapped.landmarks.size(); ++i) {
    for (std::size_t j = 0; j < rows.size(); ++j) {
      if (!SameRoom(truth.landmarks[j].text, mapped.landmarks[i].text)) continue;
      const double d = Norm(mapped.landmarks[i].pose.Position() - rows[j].truth);
      if (d <= match_radius_m) pairs.emplace_back(d, static_cast<int>(i), static_cast<int>(j));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> used(mapped.landmarks.size(), false);
  for (const auto& [d, i, j] : pairs) {
    if (used[i] || rows[j].mapped) continue;
    used[i] = true;
    rows[j].mapped = true;
    rows[j].estimate = mapped.landmarks[i].pose.Position();
    rows[j].error_m = d;
  }
  return rows;
}

std::vector<SpreadSample> ReadSpreadLog(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the particle spread log");
  std::string line;
  const std::string header = "sim_time_s,driven_m,spread_m,particles,plates_read";
  if (!std::getline(in, line) || line != header) {
    throw std::runtime_error(path + ": line 1: expected the header '" + header + "'");
  }
  std::vector<SpreadSample> samples;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::istringstream row(line);
    SpreadSample s;
    char c1 = 0, c2 = 0, c3 = 0, c4 = 0;
    row >> s.sim_time_s >> c1 >> s.driven_m >> c2 >> s.spread_m >> c3 >> s.particles >> c4 >> s.plates_read;
    if (!row || c1 != ',' || c2 != ',' || c3 != ',' || c4 != ',' || !(row >> std::ws).eof() ||
        !std::isfinite(s.sim_time_s) || !(s.spread_m >= 0.0) || s.particles < 0) {
      throw std::runtime_error(path + ": line " + std::to_string(number) + ": expected 5 numbers (" + header +
                               "), got '" + line + "'");
    }
    samples.push_back(s);
  }
  std::stable_sort(samples.begin(), samples.end(),
                   [](const SpreadSample& a, const SpreadSample& b) { return a.sim_time_s < b.sim_time_s; });
  return samples;
}

double DrivenAt(const std::vector<SpreadSample>& samples, double sim_time_s) {
  if (sim_time_s <= samples.front().sim_time_s) return samples.front().driven_m;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const SpreadSample &a = samples[i - 1], &b = samples[i];
    if (sim_time_s <= b.sim_time_s) {
      const double span = b.sim_time_s - a.sim_time_s;
      return span <= 0.0 ? b.driven_m : a.driven_m + (b.driven_m - a.driven_m) * (sim_time_s - a.sim_time_s) / span;
    }
  }
  return samples.back().driven_m;
}

}  // namespace doorplate_localization
