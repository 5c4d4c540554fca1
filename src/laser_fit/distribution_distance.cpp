#include "doorplate_localization/laser_fit/distribution_distance.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace doorplate_localization {

std::vector<double> Histogram(const std::vector<float>& values, double lo, double hi, int bins) {
  if (!(lo < hi) || bins < 1) throw std::invalid_argument("Histogram: need lo < hi and bins >= 1");
  std::vector<double> h(bins, 0.0);
  for (const float v : values) {
    if (!(v >= lo && v < hi)) continue;
    h[std::min(bins - 1, static_cast<int>((v - lo) / (hi - lo) * bins))] += 1.0;
  }
  return h;
}

double JensenShannonDivergence(const std::vector<double>& p, const std::vector<double>& q) {
  if (p.size() != q.size()) throw std::invalid_argument("JensenShannonDivergence: histograms of different sizes");
  const double sp = std::accumulate(p.begin(), p.end(), 0.0), sq = std::accumulate(q.begin(), q.end(), 0.0);
  if (!(sp > 0.0 && sq > 0.0)) throw std::invalid_argument("JensenShannonDivergence: an empty histogram");
  double jsd = 0.0;
  for (size_t k = 0; k < p.size(); ++k) {
    if (p[k] < 0.0 || q[k] < 0.0) throw std::invalid_argument("JensenShannonDivergence: a negative count");
    const double a = p[k] / sp, b = q[k] / sq, m = 0.5 * (a + b);
    if (a > 0.0) jsd += 0.5 * a * std::log2(a / m);
    if (b > 0.0) jsd += 0.5 * b * std::log2(b / m);
  }
  return std::clamp(jsd, 0.0, 1.0);
}

double Wasserstein1(std::vector<float> a, std::vector<float> b) {
  if (a.empty() || b.empty()) throw std::invalid_argument("Wasserstein1: an empty sample");
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  // Walk both sorted samples; between consecutive values the CDFs are constant.
  size_t i = 0, j = 0;
  double x = std::min(a[0], b[0]), area = 0.0;
  while (i < a.size() || j < b.size()) {
    const double next = j >= b.size() || (i < a.size() && a[i] <= b[j]) ? a[i] : b[j];
    area += std::fabs(static_cast<double>(i) / a.size() - static_cast<double>(j) / b.size()) * (next - x);
    x = next;
    while (i < a.size() && a[i] == next) ++i;
    while (j < b.size() && b[j] == next) ++j;
  }
  return area;
}

}  // namespace doorplate_localization
