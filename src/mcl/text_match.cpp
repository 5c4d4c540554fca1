#include "doorplate_localization/mcl/text_match.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {

TextMatcher::TextMatcher(const TextMatchOptions& options) : options_(options) {
  const auto probability = [](double p, const char* field) {
    if (!(p >= 0.0 && p <= 1.0)) {
      throw std::invalid_argument(std::string("TextMatcher: ") + field + ": must be in [0, 1], got " +
                                  std::to_string(p));
    }
  };
  probability(options.confusable_substitution_probability, "confusable_substitution_probability");
  probability(options.other_edit_probability, "other_edit_probability");
  if (options.max_confusable_substitutions < 0) {
    throw std::invalid_argument("TextMatcher: max_confusable_substitutions: must be >= 0");
  }
  std::istringstream tokens(options.confusable_pairs);
  std::string token;
  while (tokens >> token) {
    const std::string pair = CanonicalRoomId(token);
    if (pair.size() != 2) {
      throw std::invalid_argument("TextMatcher: confusable_pairs: expected two-character tokens like \"17\", got \"" +
                                  token + "\"");
    }
    pairs_.emplace_back(pair[0], pair[1]);
  }
}

bool TextMatcher::Confusable(char a, char b) const {
  for (const auto& [x, y] : pairs_) {
    if ((a == x && b == y) || (a == y && b == x)) return true;
  }
  return false;
}

double TextMatcher::SameLengthSimilarity(const std::string& a, const std::string& b, int other_edits_left) const {
  double similarity = 1.0;
  int confused = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i] == b[i]) continue;
    if (Confusable(a[i], b[i]) && confused < options_.max_confusable_substitutions) {
      ++confused;
      similarity *= options_.confusable_substitution_probability;
    } else if (other_edits_left > 0) {
      --other_edits_left;
      similarity *= options_.other_edit_probability;
    } else {
      return 0.0;
    }
  }
  return similarity;
}

double TextMatcher::Similarity(const std::string& read, const std::string& truth) const {
  const std::string a = CanonicalRoomId(read), b = CanonicalRoomId(truth);
  if (a.empty() || b.empty()) return 0.0;
  if (a == b) return 1.0;
  if (a.size() == b.size()) return SameLengthSimilarity(a, b, 1);
  if (std::abs(static_cast<int>(a.size()) - static_cast<int>(b.size())) != 1) return 0.0;
  // One character dropped or added: the best alignment deleting one character from the longer text.
  const std::string& longer = a.size() > b.size() ? a : b;
  const std::string& shorter = a.size() > b.size() ? b : a;
  double best = 0.0;
  for (size_t k = 0; k < longer.size(); ++k) {
    const std::string without = longer.substr(0, k) + longer.substr(k + 1);
    best = std::max(best, SameLengthSimilarity(without, shorter, 0));
  }
  return options_.other_edit_probability * best;
}

double TextMatcher::MatchProbability(const std::string& read, double confidence, const std::string& truth) const {
  const double c = std::clamp(confidence, 0.0, 1.0);
  if (SameRoom(read, truth)) return c;
  return (1.0 - c) * Similarity(read, truth);
}

std::vector<LandmarkMatch> TextMatcher::Compatible(const TextMap& map, const std::string& read,
                                                   double confidence) const {
  std::vector<LandmarkMatch> matches;
  const std::string canonical_read = CanonicalRoomId(read);  // compared once per landmark below
  for (size_t i = 0; i < map.landmarks.size(); ++i) {
    const double p = MatchProbability(canonical_read, confidence, map.landmarks[i].text);
    if (p > 0.0) matches.push_back({static_cast<int>(i), p});
  }
  return matches;
}

}  // namespace doorplate_localization
