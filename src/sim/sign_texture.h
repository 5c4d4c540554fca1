// Doorplate and sign textures for the camera renderer (private to the sim library): drawn once with
// OpenCV's anti-aliased Hershey fonts as mip pyramids, and sampled per image column.
#pragma once

#include <cstddef>
#include <vector>

#include <opencv2/core.hpp>

#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

// Draws a sign flat (filled background, thin border, text lines centred; or its image_path photo stretched
// to its size) at up to 1500 px/m and returns its mip pyramid (level 0 full size, each next level half).
// Throws std::invalid_argument naming signs[index] (and the image file if it cannot be read).
std::vector<cv::Mat> MakeSignPyramid(const TextSign& sign, std::size_t index);

// Draws a sign into column rows [first, last), seen at `u_m` metres from its left edge (as read). Row r
// sees `(r - top_row) / rows_per_m` metres below the sign's top. The mip level matches the vertical
// pixel footprint; `footprint_u_m` wider than that is averaged with extra samples (anisotropy). Edge
// pixels are blended with what is behind by their coverage (`coverage_u` across, computed here along).
void SampleSignColumn(const std::vector<cv::Mat>& levels, const TextSign& sign, double u_m,
                      double footprint_u_m, double coverage_u, double top_row, double rows_per_m,
                      double shade, int first, int last, cv::Vec3b* column);

}  // namespace doorplate_localization
