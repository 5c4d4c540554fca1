#include "doorplate_localization/mcl/floor_belief.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("FloorBeliefOptions.") + field + ": " + rule);
}

}  // namespace

void ValidateFloorBeliefOptions(const FloorBeliefOptions& o) {
  Require(o.misread_probability > 0.0 && o.misread_probability < 0.5, "misread_probability", "must be in (0, 0.5)");
  Require(o.floor_change_probability >= 0.0 && o.floor_change_probability < 1.0, "floor_change_probability",
          "must be in [0, 1)");
  Require(o.certain_probability > 0.5 && o.certain_probability < 1.0, "certain_probability", "must be in (0.5, 1)");
}

FloorBelief::FloorBelief(const FloorBeliefOptions& options, int floors, int known_floor) : options_(options) {
  ValidateFloorBeliefOptions(options_);
  if (floors < 1) throw std::invalid_argument("FloorBelief: floors must be >= 1, got " + std::to_string(floors));
  probabilities_.assign(static_cast<size_t>(floors), 0.0);
  Reset(known_floor);
}

void FloorBelief::Reset(int known_floor) {
  const int n = floors();
  if (known_floor < -1 || known_floor >= n) {
    throw std::invalid_argument("FloorBelief: floor " + std::to_string(known_floor) + " out of range (" +
                                std::to_string(n) + " floors)");
  }
  if (known_floor < 0) {
    std::fill(probabilities_.begin(), probabilities_.end(), 1.0 / n);
  } else {
    std::fill(probabilities_.begin(), probabilities_.end(), 0.0);
    probabilities_[static_cast<size_t>(known_floor)] = 1.0;
  }
}

bool FloorBelief::Update(const std::vector<bool>& has_room) {
  const int n = floors();
  if (static_cast<int>(has_room.size()) != n) {
    throw std::invalid_argument("FloorBelief::Update: " + std::to_string(has_room.size()) + " flags for " +
                                std::to_string(n) + " floors");
  }
  const long known = std::count(has_room.begin(), has_room.end(), true);
  if (known == 0 || known == n) return false;
  // Prediction: the robot may have changed floors since the last informative reading.
  const double p = options_.floor_change_probability;
  std::vector<double> predicted(probabilities_.size());
  for (int f = 0; f < n; ++f) {
    const double elsewhere = 1.0 - probabilities_[static_cast<size_t>(f)];
    predicted[static_cast<size_t>(f)] = (1.0 - p) * probabilities_[static_cast<size_t>(f)] + p / (n - 1) * elsewhere;
  }
  // Correction by the reading.
  const double eps = options_.misread_probability;
  double total = 0.0;
  for (int f = 0; f < n; ++f) {
    predicted[static_cast<size_t>(f)] *= has_room[static_cast<size_t>(f)] ? 1.0 - eps : eps;
    total += predicted[static_cast<size_t>(f)];
  }
  for (int f = 0; f < n; ++f) probabilities_[static_cast<size_t>(f)] = predicted[static_cast<size_t>(f)] / total;
  return true;
}

int FloorBelief::MostLikely() const {
  return static_cast<int>(std::max_element(probabilities_.begin(), probabilities_.end()) - probabilities_.begin());
}

int FloorBelief::CertainFloor() const {
  const int best = MostLikely();
  return probabilities_[static_cast<size_t>(best)] >= options_.certain_probability ? best : -1;
}

}  // namespace doorplate_localization
