#include "doorplate_localization/slam/scan_matcher.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace doorplate_localization {
namespace {

struct PoseDelta {  // (b - a) with the angle wrapped
  double dx, dy, dt;
};
PoseDelta Difference(const Pose2D& b, const Pose2D& a) {
  return {b.x_m - a.x_m, b.y_m - a.y_m, NormalizeAngle(b.theta_rad - a.theta_rad)};
}

}  // namespace

ScanMatcher::ScanMatcher(const ScanMatcherOptions& options, const TiledGridOptions& grid_options)
    : options_(options),
      resolution_m_(grid_options.resolution_m),
      search_(field_, grid_options.resolution_m, options.search_angular_step_rad) {
  if (!(options.field_sigma_m > 0) || !(options.likelihood_floor > 0) ||
      !(options.search_angular_step_rad > 0) || !(options.score_to_log_likelihood > 0)) {
    throw std::invalid_argument(
        "ScanMatcherOptions: field_sigma_m, likelihood_floor, search_angular_step_rad and "
        "score_to_log_likelihood must be > 0");
  }
  for (int d2 = 0; d2 < 256; ++d2) {
    const double d_m2 = d2 * resolution_m_ * resolution_m_;
    const double f = d2 == TiledGrid::kFar
                         ? 0.0
                         : std::exp(-0.5 * d_m2 / (options.field_sigma_m * options.field_sigma_m));
    field_[d2] = static_cast<float>(f);
    log_field_[d2] = static_cast<float>(std::log(f + options.likelihood_floor));
  }
  const double cells = options.matched_distance_m / resolution_m_;
  matched_dist2_ = static_cast<int>(std::floor(cells * cells));
}

SearchWindow ScanMatcher::WideWindow(const StepSpread& spread) const {
  return {std::clamp(options_.search_sigmas * spread.linear_m, options_.min_search_linear_m,
                     options_.max_search_linear_m),
          std::clamp(options_.search_sigmas * spread.angular_rad, options_.min_search_angular_rad,
                     options_.max_search_angular_rad)};
}

SearchWindow ScanMatcher::NarrowWindow() const {
  return {options_.min_search_linear_m, options_.min_search_angular_rad};
}

double ScanMatcher::Score(const TiledGrid& map, const std::vector<Vec2>& points,
                          const Pose2D& pose) const {
  constexpr int kMask = TiledGrid::kTileSize - 1;
  const double c = std::cos(pose.theta_rad), s = std::sin(pose.theta_rad);
  const double inv = 1.0 / resolution_m_;
  double sum = 0.0;
  for (const Vec2& p : points) {
    const double u = (pose.x_m + c * p.x - s * p.y) * inv - 0.5;
    const double v = (pose.y_m + s * p.x + c * p.y) * inv - 0.5;
    const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
    const double fx = u - i, fy = v - j;
    double f00, f10, f01, f11;
    if ((i & kMask) != kMask && (j & kMask) != kMask) {  // the 2×2 block lies in one tile
      const TiledGrid::Tile* tile = map.TileAt(i >> TiledGrid::kTileBits, j >> TiledGrid::kTileBits);
      if (!tile) continue;
      const int k = TiledGrid::CellInTile({i, j});
      f00 = field_[tile->dist2[k]], f10 = field_[tile->dist2[k + 1]];
      f01 = field_[tile->dist2[k + TiledGrid::kTileSize]], f11 = field_[tile->dist2[k + TiledGrid::kTileSize + 1]];
    } else {
      f00 = field_[map.Dist2Cells({i, j})], f10 = field_[map.Dist2Cells({i + 1, j})];
      f01 = field_[map.Dist2Cells({i, j + 1})], f11 = field_[map.Dist2Cells({i + 1, j + 1})];
    }
    sum += (1 - fy) * ((1 - fx) * f00 + fx * f10) + fy * ((1 - fx) * f01 + fx * f11);
  }
  return sum;
}

double ScanMatcher::LogLikelihood(const TiledGrid& map, const std::vector<Vec2>& points,
                                  const Pose2D& pose, double* matched_fraction) const {
  const double c = std::cos(pose.theta_rad), s = std::sin(pose.theta_rad);
  double sum = 0.0;
  int matched = 0;
  for (const Vec2& p : points) {
    const CellIndex cell =
        map.CellOf({pose.x_m + c * p.x - s * p.y, pose.y_m + s * p.x + c * p.y});
    const std::uint8_t d2 = map.Dist2Cells(cell);
    sum += log_field_[d2];
    if (d2 <= matched_dist2_) ++matched;
  }
  if (matched_fraction) *matched_fraction = points.empty() ? 0.0 : double(matched) / points.size();
  return sum;
}

PosePrior ScanMatcher::MakePrior(const Pose2D& prior, const StepSpread& spread) const {
  const double sl = std::max(spread.linear_m, 1e-3), sa = std::max(spread.angular_rad, 1e-4);
  return {prior, 1.0 / (sl * sl), 1.0 / (sa * sa), options_.prior_huber_sigmas,
          1.0 / options_.score_to_log_likelihood};
}

Pose2D ScanMatcher::HillClimb(const TiledGrid& map, const std::vector<Vec2>& points, Pose2D pose,
                              const PosePrior& prior) const {
  const auto objective = [&](const Pose2D& x) {
    return Score(map, points, x) - prior.Penalty(x.x_m, x.y_m, x.theta_rad);
  };
  double step_lin = 0.5 * resolution_m_, step_ang = 0.5 * options_.search_angular_step_rad;
  double best = objective(pose);
  for (int h = 0; h <= options_.refine_halvings; ++h) {
    for (int moves = 0; moves < 16; ++moves) {
      const Pose2D candidates[6] = {
          {pose.x_m + step_lin, pose.y_m, pose.theta_rad}, {pose.x_m - step_lin, pose.y_m, pose.theta_rad},
          {pose.x_m, pose.y_m + step_lin, pose.theta_rad}, {pose.x_m, pose.y_m - step_lin, pose.theta_rad},
          {pose.x_m, pose.y_m, pose.theta_rad + step_ang}, {pose.x_m, pose.y_m, pose.theta_rad - step_ang}};
      int chosen = -1;
      for (int k = 0; k < 6; ++k) {
        const double value = objective(candidates[k]);
        if (value > best) best = value, chosen = k;
      }
      if (chosen < 0) break;
      pose = candidates[chosen];
    }
    step_lin *= 0.5, step_ang *= 0.5;
  }
  pose.theta_rad = NormalizeAngle(pose.theta_rad);
  return pose;
}

MatchResult ScanMatcher::Match(const TiledGrid& map, const std::vector<Vec2>& points,
                               const Pose2D& search_centre, const SearchWindow& window,
                               const Pose2D& prior, const StepSpread& prior_spread) const {
  MatchResult result;
  const PosePrior pose_prior = MakePrior(prior, prior_spread);
  const Pose2D coarse = search_.Search(map, points, search_centre, window, pose_prior);
  const Pose2D refined = HillClimb(map, points, coarse, pose_prior);
  double matched = 0.0;
  LogLikelihood(map, points, refined, &matched);
  if (matched < options_.min_matched_fraction) {
    result.status = MatchResult::Status::kWeak;
    result.pose = prior;
  } else {
    result.pose = refined;
    const PoseDelta d = Difference(result.pose, search_centre);
    if (std::hypot(d.dx, d.dy) > std::sqrt(2.0) * window.linear_m + options_.jump_guard_margin_m ||
        std::abs(d.dt) > window.angular_rad + options_.jump_guard_margin_rad) {
      result.status = MatchResult::Status::kRejectedJump;
      result.pose = prior;
    } else {
      result.status = MatchResult::Status::kMatched;
    }
  }
  result.log_likelihood = LogLikelihood(map, points, result.pose, &result.matched_fraction);
  return result;
}

}  // namespace doorplate_localization
