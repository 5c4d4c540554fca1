// FloorBelief: which floor of a building the robot is on, as a discrete Bayes filter (a hidden Markov
// model over the floors) driven by the rooms the robot reads (issue 17 item 5). The laser cannot tell
// floors of the same layout apart; a plate can: a reading of room 305 is evidence for every floor whose
// text map has a room 305 and against the others.
//
// One Update per plate reading that some floors know and others do not:
//   prediction  b'(f) = (1 − p) b(f) + p / (F − 1) · Σ_{g≠f} b(g)     p = floor_change_probability
//   correction  b(f) ∝ b'(f) · L(f),  L(f) = 1 − ε when floor f has the room, ε otherwise
// where ε = misread_probability is the chance that a reading names a room of another floor (a misread
// digit, a sign from elsewhere) and p the chance that the robot changed floors since the previous
// informative reading (a lift ride it was not told of). With the defaults (ε = p = 0.05, switch at 0.99)
// two consecutive readings of another floor decide the floor from an unknown start (0.5 → 0.95 → 0.995 with
// two floors) and three overturn a certain floor after a lift ride. Readings that every floor or no floor
// knows carry no information about the floor and change nothing. ROS-free; no units.
#pragma once

#include <vector>

namespace doorplate_localization {

struct FloorBeliefOptions {
  double misread_probability = 0.05;       // ε, in (0, 0.5)
  double floor_change_probability = 0.05;  // p, in [0, 1)
  double certain_probability = 0.99;       // a floor is certain (and becomes the current one) at this, in (0.5, 1)
};

// Throws std::invalid_argument naming the field ("FloorBeliefOptions.misread_probability: ...").
void ValidateFloorBeliefOptions(const FloorBeliefOptions& options);

class FloorBelief {
 public:
  // `floors` >= 1; `known_floor` in [0, floors) starts certain of that floor, −1 starts uniform.
  // Throws std::invalid_argument for bad options or counts.
  FloorBelief(const FloorBeliefOptions& options, int floors, int known_floor);

  // Restarts: certain of `known_floor`, or uniform for −1.
  void Reset(int known_floor);
  // One reading: `has_room[f]` says whether floor f's map has the room read. Returns false (nothing
  // changed) when every floor or no floor has it. Size must equal floors().
  bool Update(const std::vector<bool>& has_room);

  int floors() const { return static_cast<int>(probabilities_.size()); }
  const std::vector<double>& probabilities() const { return probabilities_; }
  int MostLikely() const;  // the lowest index among the most probable floors
  // The most likely floor when its probability reaches certain_probability, else −1.
  int CertainFloor() const;
  const FloorBeliefOptions& options() const { return options_; }

 private:
  const FloorBeliefOptions options_;
  std::vector<double> probabilities_;
};

}  // namespace doorplate_localization
