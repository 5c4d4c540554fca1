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

}  // namespace doorplate_localization
