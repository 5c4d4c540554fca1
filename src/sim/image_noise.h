// Pixel noise and blur helpers for the camera renderer (private to the sim library).
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace doorplate_localization {

// table[i] = 16 · stddev · Φ⁻¹((i + 0.5) / n): uniform random indices into it draw N(0, stddev²) in
// 1/16 grey levels, quantised to n levels (tails cut at ±3.5σ for n = 4096).
std::vector<std::int16_t> GaussianQuantiles(int n, double stddev);

// SplitMix64 (Steele, Lea, Flood 2014): a fast 64-bit generator for per-pixel noise, seeded per frame.
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t operator()() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
};

// 1-D kernel: a Gaussian (lens blur, sigma_px) convolved with a box of `box_px` pixels (motion during
// exposure), normalised to sum 1.
cv::Mat BlurKernel(double sigma_px, double box_px);

// Scales a CV_8UC3 image by `gain`, tilted across it (column u of width w gets
// gain · (1 + gradient · ((u + 0.5) / w − 0.5)), clamped to [0, 8]), and adds noise drawn from
// `noise_table` (GaussianQuantiles, 1/16 grey levels; empty: no noise) with a SplitMix64 seeded by `seed`.
// Fixed point: out = (in · G + noise · 256 + 2048) >> 12 with G = gain · 4096. `noise_table.size()` must be
// a power of two ≤ 65536.
void ApplyGainAndNoise(double gain, double gradient, const std::vector<std::int16_t>& noise_table,
                       std::uint64_t seed, cv::Mat* image);

}  // namespace doorplate_localization
