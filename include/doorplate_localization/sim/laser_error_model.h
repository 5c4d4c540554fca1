// What a laser does to the exact ranges of a scan: noise, dropouts, mixed pixels, spurious returns.
// Swappable: LaserSimulator applies whichever model it holds to CastExact's ranges, and
// doorplate_laser_fit applies the same models to ranges cast on a real log's reference grid.
// Ranges follow REP-117 (metres; +inf: nothing within max range; -inf: closer than min range); NaN marks
// a beam whose exact range is unknown, which a model leaves as it is and does not use as a neighbour.
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "doorplate_localization/sim/sensor_options.h"

namespace doorplate_localization {

class LaserErrorModel {
 public:
  virtual ~LaserErrorModel() = default;
  // Whether Apply reads `incidence_rad` (so the caller can skip computing it).
  virtual bool NeedsIncidence() const = 0;
  // Turns exact ranges into measured ones in place. `incidence_rad[i]`: beam i's angle to the surface
  // normal in [0, pi/2] (NaN or an empty vector: head-on). `wrap_around`: the first and last beams are
  // neighbours (a 360° scanner). Readings stay within [min_range_m, max_range_m] or +inf.
  virtual void Apply(std::vector<float>* ranges_m, const std::vector<float>& incidence_rad, double min_range_m,
                     double max_range_m, bool wrap_around, std::mt19937_64& rng) const = 0;
};

// Gaussian noise on every return and dropouts at a fixed rate (LaserOptions::range_noise_stddev_m,
// dropout_probability): the simulator's model before issue 20, with the same random draws.
class GaussianLaserErrorModel : public LaserErrorModel {
 public:
  // Throws std::invalid_argument naming the field if a value is negative or the probability above 1.
  GaussianLaserErrorModel(double range_noise_stddev_m, double dropout_probability);
  bool NeedsIncidence() const override { return false; }
  void Apply(std::vector<float>* ranges_m, const std::vector<float>& incidence_rad, double min_range_m,
             double max_range_m, bool wrap_around, std::mt19937_64& rng) const override;

 private:
  double stddev_m_;
  double dropout_probability_;
};

// The effects measured on real logs (FittedLaserErrorOptions documents them). Draws the same five numbers
// from `rng` for every beam, so the random stream does not depend on the geometry.
class FittedLaserErrorModel : public LaserErrorModel {
 public:
  // Throws std::invalid_argument naming the field ("FittedLaserErrorOptions.short_mean_m: ...").
  explicit FittedLaserErrorModel(const FittedLaserErrorOptions& options);
  bool NeedsIncidence() const override { return true; }
  void Apply(std::vector<float>* ranges_m, const std::vector<float>& incidence_rad, double min_range_m,
             double max_range_m, bool wrap_around, std::mt19937_64& rng) const override;

  // The model's sigma and dropout probability for a return at `range_m` and `incidence_rad`.
  double NoiseStddev(double range_m, double incidence_rad) const;
  double DropoutProbability(double range_m, double incidence_rad) const;
  const FittedLaserErrorOptions& options() const { return options_; }

 private:
  FittedLaserErrorOptions options_;
};

// The model LaserOptions::error_model names ("gaussian" or "fitted"); throws std::invalid_argument
// naming the field for an unknown name or bad parameters.
std::shared_ptr<const LaserErrorModel> MakeLaserErrorModel(const LaserOptions& options);

}  // namespace doorplate_localization
