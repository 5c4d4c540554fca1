#include "doorplate_localization/slam/correlative_search.h"

#include <algorithm>
#include <cmath>

namespace doorplate_localization {

double PosePrior::Penalty(double x_m, double y_m, double theta_rad) const {
  const double dx = x_m - mean.x_m, dy = y_m - mean.y_m, dt = NormalizeAngle(theta_rad - mean.theta_rad);
  const double m2 = inv_var_linear * (dx * dx + dy * dy) + inv_var_angular * dt * dt;
  const double c = huber_sigmas;
  const double cost = m2 <= c * c ? 0.5 * m2 : c * std::sqrt(m2) - 0.5 * c * c;
  return cost * score_per_log_likelihood;
}

CorrelativeSearch::CorrelativeSearch(const std::array<float, 256>& field, double resolution_m,
                                     double angular_step_rad, long exhaustive_budget)
    : field_(field),
      resolution_m_(resolution_m),
      angular_step_rad_(angular_step_rad),
      exhaustive_budget_(exhaustive_budget) {}

void CorrelativeSearch::ScoreHeading(const TiledGrid& map, const std::vector<Vec2>& points,
                                     const Vec2& centre, double theta, int n, int stride,
                                     const PosePrior& prior, std::size_t keep,
                                     std::vector<Candidate>* best) const {
  const int side = 2 * n + 1;
  std::vector<double> scores(static_cast<std::size_t>(side) * side, 0.0);
  const double c = std::cos(theta), s = std::sin(theta);
  constexpr int kMask = TiledGrid::kTileSize - 1;
  for (const Vec2& p : points) {
    const CellIndex base = map.CellOf({centre.x + c * p.x - s * p.y, centre.y + s * p.x + c * p.y});
    for (int ky = -n; ky <= n; ++ky) {
      double* row = &scores[static_cast<std::size_t>(ky + n) * side + n];
      const int y = base.y + ky * stride;
      // Walk the row, looking the tile up only where it enters another one.
      const TiledGrid::Tile* tile = nullptr;
      int tile_x = 0;
      bool have_tile = false;
      for (int kx = -n; kx <= n; ++kx) {
        const int x = base.x + kx * stride;
        if (!have_tile || (x >> TiledGrid::kTileBits) != tile_x) {
          tile_x = x >> TiledGrid::kTileBits;
          tile = map.TileAt(tile_x, y >> TiledGrid::kTileBits);
          have_tile = true;
        }
        if (tile) row[kx] += field_[tile->dist2[((y & kMask) << TiledGrid::kTileBits) | (x & kMask)]];
      }
    }
  }
  const double step = stride * resolution_m_;
  for (int ky = -n; ky <= n; ++ky) {
    for (int kx = -n; kx <= n; ++kx) {
      const Pose2D pose{centre.x + kx * step, centre.y + ky * step, theta};
      const double objective = scores[static_cast<std::size_t>(ky + n) * side + kx + n] -
                               prior.Penalty(pose.x_m, pose.y_m, pose.theta_rad);
      if (best->size() == keep && objective <= best->back().objective) continue;
      // Merge with a neighbour already kept (same peak): keep the better of the two.
      auto near = std::find_if(best->begin(), best->end(), [&](const Candidate& k) {
        return std::abs(k.pose.x_m - pose.x_m) <= 2 * step && std::abs(k.pose.y_m - pose.y_m) <= 2 * step &&
               std::abs(NormalizeAngle(k.pose.theta_rad - theta)) <= 4 * angular_step_rad_ + 1e-9;
      });
      if (near != best->end()) {
        if (near->objective >= objective) continue;
        best->erase(near);
      }
      const Candidate candidate{pose, objective};
      best->insert(std::upper_bound(best->begin(), best->end(), candidate,
                                    [](const Candidate& a, const Candidate& b) { return a.objective > b.objective; }),
                   candidate);
      if (best->size() > keep) best->pop_back();
    }
  }
}

Pose2D CorrelativeSearch::Search(const TiledGrid& map, const std::vector<Vec2>& points, const Pose2D& centre,
                                 const SearchWindow& window, const PosePrior& prior) const {
  const int n_lin = static_cast<int>(std::ceil(window.linear_m / resolution_m_ - 1e-9));
  const int n_ang = static_cast<int>(std::ceil(window.angular_rad / angular_step_rad_ - 1e-9));
  const long cost = (2L * n_ang + 1) * (2L * n_lin + 1) * (2L * n_lin + 1) * static_cast<long>(points.size());
  std::vector<Candidate> best;
  if (cost <= exhaustive_budget_) {
    for (int a = -n_ang; a <= n_ang; ++a) {
      ScoreHeading(map, points, centre.Position(), centre.theta_rad + a * angular_step_rad_, n_lin, 1, prior, 1,
                   &best);
    }
    return best.empty() ? centre : best.front().pose;
  }
  // Coarse: every second cell, 4× the angle step, every second point; keep a few distinct peaks.
  std::vector<Vec2> half;
  for (std::size_t k = 0; k < points.size(); k += 2) half.push_back(points[k]);
  const double coarse_step = 4 * angular_step_rad_;
  const int n_ang_coarse = static_cast<int>(std::ceil(window.angular_rad / coarse_step - 1e-9));
  const int n_lin_coarse = (n_lin + 1) / 2;
  std::vector<Candidate> coarse;
  for (int a = -n_ang_coarse; a <= n_ang_coarse; ++a) {
    ScoreHeading(map, half, centre.Position(), centre.theta_rad + a * coarse_step, n_lin_coarse, 2, prior, 6,
                 &coarse);
  }
  // Fine: around each coarse peak, ±2 fine angle steps and ±2 cells.
  for (const Candidate& c : coarse) {
    for (int a = -2; a <= 2; ++a) {
      ScoreHeading(map, points, c.pose.Position(), c.pose.theta_rad + a * angular_step_rad_, 2, 1, prior, 1,
                   &best);
    }
  }
  return best.empty() ? centre : best.front().pose;
}

}  // namespace doorplate_localization
