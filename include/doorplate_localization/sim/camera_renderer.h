// Renders what the sideways pinhole camera sees: walls, doors, open rooms, doorplates and distractor
// text, clutter, people and translucent glass, with perspective, lens and motion blur, lighting changes
// and pixel noise.
// Frames: camera optical frame (z forward, x right, y down) mounted per CameraOptions on base_link.
#pragma once

#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

// Pinhole intrinsics from CameraOptions: its fx/fy/cx/cy where given, else square pixels with fx from the
// horizontal field of view and the principal point at the image centre.
struct CameraIntrinsics {
  double fx_px = 0.0, fy_px = 0.0, cx_px = 0.0, cy_px = 0.0;
  int width_px = 0, height_px = 0;
};
CameraIntrinsics IntrinsicsFromOptions(const CameraOptions& options);

struct Point3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

class CameraRenderer {
 public:
  // Builds sign textures once; `world` must outlive the renderer and have its surfaces built
  // (BuildSurfaces). Throws std::invalid_argument naming the field for unusable options or signs.
  CameraRenderer(const World& world, const CameraOptions& options);

  // Renders a BGR8 image of size width_px × height_px: RenderClean plus lens blur, horizontal motion
  // blur of |image speed| × exposure_s (image speed from `speed_mps` (base_link forward) at the depth
  // seen on the optical axis and from `yaw_rate_rps`), a per-frame lighting gain, the left-to-right
  // lighting gradient and Gaussian pixel noise, all drawn from `rng` (deterministic per seed).
  // Render, RenderClean and Project only read the renderer: safe to call from several threads.
  cv::Mat Render(const Pose2D& robot_pose, double speed_mps, double yaw_rate_rps, std::mt19937_64& rng) const;
  // Noise-free, blur-free render with the same geometry (for tests and ground truth).
  cv::Mat RenderClean(const Pose2D& robot_pose) const;

  // Projects a world point (x, y, z up) to pixel coordinates (pixel centres at integers, the same
  // model as the rendered images, pitch included); false if behind the camera. The pixel may lie
  // outside the image.
  bool Project(const Pose2D& robot_pose, const Point3& world_point, cv::Point2d* pixel) const;

  const CameraIntrinsics& intrinsics() const { return intrinsics_; }
  // Optical frame pose relative to base_link as (x, y, z, roll, pitch, yaw) of the camera body
  // (x forward along the optical axis, REP-103 body convention) – what the tf publisher needs.
  // Metres and radians; pitch_rad follows REP-103 (positive = nose down), so a camera tilted up by
  // CameraOptions::pitch_deg > 0 has pitch_rad < 0. Roll is zero.
  void MountPose(double* x, double* y, double* z, double* yaw_rad, double* pitch_rad) const;

 private:
  // A sign's texture as a mip pyramid (level 0 high resolution, each next level half size), BGR.
  struct SignTexture {
    std::vector<cv::Mat> levels;
  };
  struct Hit;

  // Ray-casts the unpitched image (optical axis horizontal) into `transposed` (one row per image
  // column) and returns the depth of the nearest surface on the optical axis (+inf if none).
  double RenderUnpitchedTransposed(const Pose2D& robot_pose, cv::Mat* transposed) const;
  void PaintHit(const Hit& hit, double depth_scale, const Vec2& camera_xy, int row_begin, int row_end,
                cv::Vec3b* column) const;
  void Degrade(double center_depth_m, double speed_mps, double yaw_rate_rps, std::mt19937_64& rng,
               cv::Mat* image) const;

  const World& world_;
  const CameraOptions options_;
  CameraIntrinsics intrinsics_;
  double pitch_rad_ = 0.0;
  // The unpitched image: columns × rows with principal point (unpitched_cx_px_, unpitched_cy_px_),
  // large enough that every output pixel maps inside it; remap maps from the output to it.
  int unpitched_cols_ = 0, unpitched_rows_ = 0;
  double unpitched_cx_px_ = 0.0, unpitched_cy_px_ = 0.0;
  cv::Mat pitch_map1_, pitch_map2_;
  cv::Mat background_column_;                 // 1 × unpitched_rows_ floor/ceiling colours, BGR
  std::vector<std::vector<int>> wall_doors_;  // closed doors per wall index
  std::vector<std::vector<int>> wall_signs_;  // signs per wall index
  std::vector<SignTexture> sign_textures_;    // per World::signs entry
  std::vector<std::int16_t> noise_table_;     // quantiles of N(0, pixel_noise_stddev), 1/16 levels
  int max_hits_ = 12;                         // nearest surfaces kept per column (more in detailed worlds)
};

}  // namespace doorplate_localization
