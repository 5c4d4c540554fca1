// How far apart a real and a simulated distribution are (issue 20): Jensen-Shannon divergence of two
// histograms and the 1-D Wasserstein (earth mover's) distance of two samples.
#pragma once

#include <vector>

namespace doorplate_localization {

// Counts of `values` in `bins` equal bins over [lo, hi); values outside are dropped. Requires lo < hi.
std::vector<double> Histogram(const std::vector<float>& values, double lo, double hi, int bins);

// Jensen-Shannon divergence (base 2, in [0, 1]: 0 identical, 1 disjoint) of two histograms over the same
// bins, each normalised to sum 1. Throws std::invalid_argument for different sizes, negative counts or an
// empty histogram.
double JensenShannonDivergence(const std::vector<double>& p, const std::vector<double>& q);

// 1-D Wasserstein-1 distance of two samples' empirical distributions: the area between their CDFs (in the
// samples' unit). Throws std::invalid_argument if either is empty.
double Wasserstein1(std::vector<float> a, std::vector<float> b);

}  // namespace doorplate_localization
