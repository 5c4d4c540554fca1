#include "image_noise.h"

#include <algorithm>
#include <cmath>

namespace doorplate_localization {

std::vector<std::int16_t> GaussianQuantiles(int n, double stddev) {
  const auto cdf = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  const double step = 1e-3;
  std::vector<std::int16_t> table(n);
  double x0 = -8.0, f0 = cdf(x0);
  for (int i = 0; i < n; ++i) {
    const double p = (i + 0.5) / n;
    double x1 = x0 + step, f1 = cdf(x1);
    while (f1 < p) {
      x0 = x1;
      f0 = f1;
      x1 += step;
      f1 = cdf(x1);
    }
    const double value = 16.0 * stddev * (x0 + (p - f0) / (f1 - f0) * step);
    table[i] = static_cast<std::int16_t>(std::lround(std::clamp(value, -32000.0, 32000.0)));
  }
  return table;
}

cv::Mat BlurKernel(double sigma_px, double box_px) {
  std::vector<double> gauss{1.0}, box{1.0};
  if (sigma_px > 0.05) {
    const int r = static_cast<int>(std::ceil(3.0 * sigma_px));
    gauss.assign(2 * r + 1, 0.0);
    for (int t = -r; t <= r; ++t) gauss[t + r] = std::exp(-0.5 * t * t / (sigma_px * sigma_px));
  }
  if (box_px > 1.0) {  // tap t covers [t - 0.5, t + 0.5]; its weight is the overlap with the box
    const int r = static_cast<int>(std::ceil(box_px / 2.0 - 0.5));
    box.assign(2 * r + 1, 0.0);
    for (int t = -r; t <= r; ++t) {
      box[t + r] = std::max(0.0, std::min(t + 0.5, box_px / 2) - std::max(t - 0.5, -box_px / 2));
    }
  }
  cv::Mat kernel = cv::Mat::zeros(1, static_cast<int>(gauss.size() + box.size() - 1), CV_32F);
  for (std::size_t i = 0; i < gauss.size(); ++i) {
    for (std::size_t j = 0; j < box.size(); ++j) kernel.at<float>(0, i + j) += gauss[i] * box[j];
  }
  return kernel / cv::sum(kernel)[0];
}

void ApplyGainAndNoise(double gain, double gradient, const std::vector<std::int16_t>& noise_table,
                       std::uint64_t seed, cv::Mat* image) {
  const int width = image->cols, row_values = 3 * width;
  std::vector<std::int32_t> channel_gain(row_values);
  for (int u = 0; u < width; ++u) {
    const double g = gain * (1.0 + gradient * ((u + 0.5) / width - 0.5));
    channel_gain[3 * u] = channel_gain[3 * u + 1] = channel_gain[3 * u + 2] =
        static_cast<std::int32_t>(std::lround(std::clamp(g, 0.0, 8.0) * 4096.0));
  }
  SplitMix64 fast_rng{seed};
  const std::size_t table_mask = noise_table.empty() ? 0 : noise_table.size() - 1;
  std::vector<std::uint64_t> words((row_values + 3) / 4);
  const auto* index = reinterpret_cast<const std::uint16_t*>(words.data());
  for (int r = 0; r < image->rows; ++r) {
    uchar* p = image->ptr<uchar>(r);
    if (noise_table.empty()) {
      for (int i = 0; i < row_values; ++i) {
        p[i] = cv::saturate_cast<uchar>((p[i] * channel_gain[i] + 2048) >> 12);
      }
      continue;
    }
    for (std::uint64_t& w : words) w = fast_rng();
    for (int i = 0; i < row_values; ++i) {
      const int noise = noise_table[index[i] & table_mask];
      p[i] = cv::saturate_cast<uchar>((p[i] * channel_gain[i] + noise * 256 + 2048) >> 12);
    }
  }
}

}  // namespace doorplate_localization
