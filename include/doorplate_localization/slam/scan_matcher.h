// Scan-to-map matcher of the SLAM proposal. It maximises the posterior of a pose given one particle's
// own map and a Gaussian prior (the odometry prediction, see correlative_search.h):
//   J(x) = κ · Σ_points field(x ⊕ point) − ½ (x − prior)ᵀ Ω (x − prior)   (Huber beyond 2σ),
// field = exp(−d²/2σ²) of the distance d to the nearest obstacle, κ = score_to_log_likelihood, Ω the
// prior's information. First a correlative search (correlative_search.h) over a window around a
// search centre, then a hill climb on the bilinearly interpolated field (sub-cell accuracy). Along an axis the scan does not constrain (a long corridor) the field is flat and the
// prior wins; across it the scan wins: the fallback to odometry is per axis, not all or nothing.
// Where the match is weak (few points near obstacles) or the result left the searched window by more
// than the jump guard's margin (the hill climb ran away), the prior is kept.
#pragma once

#include <array>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/slam/correlative_search.h"
#include "doorplate_localization/sensors/odometry_motion_model.h"
#include "doorplate_localization/slam/tiled_grid.h"

namespace doorplate_localization {

struct ScanMatcherOptions {
  double field_sigma_m = 0.1;           // spread of the likelihood field around obstacles
  double likelihood_floor = 0.05;       // per-point likelihood = field + floor (outliers, unknown cells)
  double search_sigmas = 4.0;           // a wide window spans ± this many step spreads...
  double min_search_linear_m = 0.1;     // ...but at least this (also the narrow window)
  double max_search_linear_m = 0.3;     // ...and at most this
  double min_search_angular_rad = 0.04;
  double max_search_angular_rad = 3.2;
  double search_angular_step_rad = 0.01;
  int refine_halvings = 3;              // hill-climb step halvings after the correlative search
  double matched_distance_m = 0.1;      // a point is "matched" within this of an obstacle
  double min_matched_fraction = 0.3;    // fewer matched points: weak match, keep the prediction
  double jump_guard_margin_m = 0.3;     // jump guard: a result further than this beyond the searched
  double jump_guard_margin_rad = 0.2;   // window (from its centre) is rejected
  double score_to_log_likelihood = 0.2;  // κ: log-likelihood per unit of field score (beams correlate)
  double prior_huber_sigmas = 2.0;      // the prior's penalty grows linearly, not quadratically, beyond
};

struct MatchResult {
  enum class Status { kMatched, kWeak, kRejectedJump };
  Status status = Status::kWeak;
  Pose2D pose;                  // the proposal's pose (map frame)
  double matched_fraction = 0;  // of the points, at `pose`
  double log_likelihood = 0;    // sum over points of log(field + floor) at `pose`
};

class ScanMatcher {
 public:
  ScanMatcher(const ScanMatcherOptions& options, const TiledGridOptions& grid_options);
  ScanMatcher(const ScanMatcher&) = delete;  // search_ refers to field_
  ScanMatcher& operator=(const ScanMatcher&) = delete;

  // ± search_sigmas × spread, clamped to the min/max options.
  SearchWindow WideWindow(const StepSpread& spread) const;
  // The min options: for a search centre that is already close.
  SearchWindow NarrowWindow() const;

  // `points` are the scan's endpoints in base_link. Searches `window` around `search_centre` for the
  // maximum of J with the prior N(`prior`, `prior_spread`²); all poses in the map frame.
  MatchResult Match(const TiledGrid& map, const std::vector<Vec2>& points, const Pose2D& search_centre,
                    const SearchWindow& window, const Pose2D& prior,
                    const StepSpread& prior_spread) const;

  // Sum over points of the interpolated field in [0, 1] at `pose`.
  double Score(const TiledGrid& map, const std::vector<Vec2>& points, const Pose2D& pose) const;
  // Sum over points of log(field + floor) at `pose` (nearest cell), and the matched fraction.
  double LogLikelihood(const TiledGrid& map, const std::vector<Vec2>& points, const Pose2D& pose,
                       double* matched_fraction = nullptr) const;

 private:
  PosePrior MakePrior(const Pose2D& prior, const StepSpread& spread) const;
  Pose2D HillClimb(const TiledGrid& map, const std::vector<Vec2>& points, Pose2D start,
                   const PosePrior& prior) const;

  const ScanMatcherOptions options_;
  const double resolution_m_;
  std::array<float, 256> field_;      // field value by squared cell distance (0 for kFar)
  std::array<float, 256> log_field_;  // log(field + floor)
  int matched_dist2_;                 // squared cells within matched_distance_m
  CorrelativeSearch search_;
};

}  // namespace doorplate_localization
