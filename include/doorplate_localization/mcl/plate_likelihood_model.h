// The doorplate measurement model: a reading of text T at bearing β (and maybe range r) is likely
// from a pose that sees a plate with a text compatible with T at that bearing and range, facing it.
//   p(reading | x) = floor_probability
//                    + Σ_j P(T | text_j) · N(β - β̂_j(x); σ_β) · N(r - r̂_j(x); σ_r) · V_j(x)
// with unnormalized Gaussians (peak 1); V_j(x) = 1 if plate j is in view from x — its facing direction
// within max_view_angle_rad of the direction to the robot, its distance in [min, max]_view_distance_m
// and (if a grid is given) a clear line of sight — else 0. Repeated texts add their terms, so two
// plates with the same number keep two hypotheses; the floor keeps a wrong reading from zeroing every
// particle.
#pragma once

#include <memory>
#include <vector>

#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/mcl/localization_grid.h"
#include "doorplate_localization/mcl/text_match.h"
#include "doorplate_localization/mcl/text_observation_model.h"

namespace doorplate_localization {

struct PlateLikelihoodModelOptions {
  double bearing_stddev_rad = 0.1;     // bearing error (camera calibration, plate box centre, robot yaw)
  double range_stddev_m = 0.3;         // range error when the reading has one
  double min_view_distance_m = 0.3;    // plates are read between these distances
  double max_view_distance_m = 6.0;
  double max_view_angle_rad = 1.22;    // 70°: beyond this off the plate's normal the text is unreadable
  double floor_probability = 0.02;     // p(reading | no compatible plate in view): false readings
  bool check_line_of_sight = true;     // ray-cast the grid robot -> plate (needs a grid)
  double line_of_sight_tolerance_m = 0.15;  // the ray may stop this short of the plate (wall cells)
  TextMatchOptions text_match;
};

class PlateLikelihoodModel : public TextObservationModel {
 public:
  // `grid` may be null (then no line-of-sight check). Throws std::invalid_argument naming the field of
  // a bad option or a null map.
  PlateLikelihoodModel(std::shared_ptr<const TextMap> text_map, std::shared_ptr<const LocalizationGrid> grid,
                       const PlateLikelihoodModelOptions& options);

  void LogLikelihoods(const PlateReading& reading, const std::vector<Particle>& particles,
                      std::vector<double>* log_likelihoods) const override;
  double UnexplainedLogLikelihood(const PlateReading& reading) const override;

  // p(reading | pose) (not the log), for one pose.
  double Likelihood(const PlateReading& reading, const Pose2D& pose) const;
  // Whether landmark `index` is in view (V_j above) from a robot at `position`.
  bool InView(int landmark_index, Vec2 position) const;

  const TextMatcher& matcher() const { return matcher_; }

 private:
  double LikelihoodGiven(const PlateReading& reading, const std::vector<LandmarkMatch>& matches,
                         const Pose2D& pose) const;

  const std::shared_ptr<const TextMap> text_map_;
  const std::shared_ptr<const LocalizationGrid> grid_;
  const PlateLikelihoodModelOptions options_;
  const TextMatcher matcher_;
};

}  // namespace doorplate_localization
