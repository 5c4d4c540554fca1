// How likely it is that a plate showing one text is read as another: an OCR confusion model over room
// numbers. Used by the plate likelihood model and the plate pose sampler. Texts are compared in their
// canonical form (common/room_id.h): separators do not count ("E14-295" read as "E14295" is identical),
// letters and digits do ("312A" read for "312B" is one non-confusable substitution).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "doorplate_localization/maps/text_map.h"

namespace doorplate_localization {

struct TextMatchOptions {
  // Character pairs OCR confuses on doorplates (symmetric), as space-separated two-character tokens:
  // 1↔7, 4↔1, 3↔8, 5↔6, 0↔8 by default. Letters are compared upper-cased.
  std::string confusable_pairs = "17 41 38 56 08";
  double confusable_substitution_probability = 0.3;  // per confused character
  double other_edit_probability = 0.05;  // one other substitution, a dropped or an extra character
  int max_confusable_substitutions = 2;  // more confused characters than this: incompatible
};

// A landmark compatible with a reading.
struct LandmarkMatch {
  int landmark_index = -1;   // into TextMap::landmarks
  double probability = 0.0;  // P(this reading's text | the plate shows the landmark's text), (0, 1]
};

class TextMatcher {
 public:
  // Throws std::invalid_argument naming the field of a probability outside [0, 1] or a malformed pair.
  explicit TextMatcher(const TextMatchOptions& options);

  // How similar a misreading `read` of `truth` is, in [0, 1]: 1 for identical canonical texts; else the
  // product of confusable_substitution_probability per confused character (at most
  // max_confusable_substitutions) and other_edit_probability if one other edit (substitution,
  // insertion or deletion) is needed; 0 if more edits are needed.
  double Similarity(const std::string& read, const std::string& truth) const;

  // P(read | plate shows truth) for a reader with confidence c: c if the same room (SameRoom), else
  // (1 - c) · Similarity(read, truth).
  double MatchProbability(const std::string& read, double confidence, const std::string& truth) const;

  // Every landmark whose text could have produced `read`, with its probability (> 0), in map order.
  std::vector<LandmarkMatch> Compatible(const TextMap& map, const std::string& read, double confidence) const;

 private:
  bool Confusable(char a, char b) const;
  // Similarity of equal-length canonical strings, allowing `other_edits_left` non-confusable substitutions.
  double SameLengthSimilarity(const std::string& a, const std::string& b, int other_edits_left) const;

  const TextMatchOptions options_;
  std::vector<std::pair<char, char>> pairs_;  // parsed confusable_pairs
};

}  // namespace doorplate_localization
