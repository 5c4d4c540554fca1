#include "doorplate_localization/mcl/resampler.h"

#include <algorithm>
#include <cmath>

namespace doorplate_localization {
namespace {

// Cumulative weights; uniform if the weights are all 0 (or not finite).
std::vector<double> Cumulative(const std::vector<Particle>& particles) {
  std::vector<double> cumulative(particles.size());
  double total = 0.0;
  for (size_t i = 0; i < particles.size(); ++i) {
    const double w = particles[i].weight;
    total += (w > 0.0 && std::isfinite(w)) ? w : 0.0;
    cumulative[i] = total;
  }
  if (!(total > 0.0) || !std::isfinite(total)) {
    for (size_t i = 0; i < cumulative.size(); ++i) cumulative[i] = static_cast<double>(i + 1);
  }
  return cumulative;
}

}  // namespace

std::vector<int> LowVarianceResampler::Select(const std::vector<Particle>& particles, int count,
                                              std::mt19937_64& rng) const {
  std::vector<int> selected;
  if (count <= 0 || particles.empty()) return selected;
  const std::vector<double> cumulative = Cumulative(particles);
  const double step = cumulative.back() / count;
  double pointer = std::uniform_real_distribution<double>(0.0, step)(rng);
  selected.reserve(count);
  size_t i = 0;
  const size_t last = particles.size() - 1;
  for (int k = 0; k < count; ++k, pointer += step) {
    while (i < last && cumulative[i] <= pointer) ++i;
    selected.push_back(static_cast<int>(i));
  }
  return selected;
}

std::vector<int> MultinomialResampler::Select(const std::vector<Particle>& particles, int count,
                                              std::mt19937_64& rng) const {
  std::vector<int> selected;
  if (count <= 0 || particles.empty()) return selected;
  const std::vector<double> cumulative = Cumulative(particles);
  std::uniform_real_distribution<double> unit(0.0, cumulative.back());
  selected.reserve(count);
  for (int k = 0; k < count; ++k) {
    const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), unit(rng));
    selected.push_back(static_cast<int>(std::min<size_t>(it - cumulative.begin(), particles.size() - 1)));
  }
  return selected;
}

}  // namespace doorplate_localization
