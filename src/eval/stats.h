// Small statistics shared by the experiments' summaries.
#pragma once

#include <algorithm>
#include <vector>

namespace doorplate_localization {

// The median of `values` (the mean of the two middle ones for an even count); 0 for none.
inline double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace doorplate_localization
