// Options of the simulated sensors. Defaults model the paper's robot: RPLIDAR A2 (360°, 16 m), wheel
// odometry, a 640×480 camera aimed sideways at the opposite wall. A world file may override any field
// (see docs/world-format.md); units are in the field names.
#pragma once

#include <cstdint>
#include <string>

namespace doorplate_localization {

// 2D laser scanner in the base_link frame. Beams are spread evenly over [angle_min_rad,
// angle_min_rad + (num_beams - 1) * 2*pi/num_beams] for a 360° device.
struct LaserOptions {
  int num_beams = 360;
  double angle_min_rad = -3.14159265358979323846;
  double min_range_m = 0.15;
  double max_range_m = 16.0;
  double range_noise_stddev_m = 0.01;   // Gaussian noise on every return
  double dropout_probability = 0.01;    // a beam returns no echo (+inf, REP-117) with this probability
  double rate_hz = 10.0;
  double mount_x_m = 0.0;               // laser frame origin in base_link
  double mount_y_m = 0.0;
  double mount_yaw_rad = 0.0;
  double mount_height_m = 0.25;         // only surfaces spanning this height are seen
};

// Differential-drive odometry error, independent of the simulation step: every random term is a random
// walk whose variance grows linearly with the motion (AMCL's alpha roles, per unit of motion).
struct OdometryNoiseOptions {
  double alpha1_rad2_per_rad = 0.001;   // rotation variance per radian turned
  double alpha2_rad2_per_m = 0.00002;   // rotation variance per metre driven
  double alpha3_m2_per_m = 0.0004;      // translation variance per metre driven
  double alpha4_m2_per_rad = 0.0001;    // translation variance per radian turned
  double scale_error = 0.02;            // systematic: odometry distance = (1 + scale_error) * true
  double heading_drift_rad_per_m = 0.002;  // systematic yaw drift per metre driven (unequal wheels)
  double rate_hz = 50.0;
};

// Pinhole camera on the robot, looking sideways. Optical frame: z forward, x right, y down.
struct CameraOptions {
  int width_px = 640;
  int height_px = 480;
  double horizontal_fov_deg = 60.0;     // gives fx_px when fx_px is 0
  // Pinhole intrinsics in pixels (pixel centres at integers). 0 = derived: fx from horizontal_fov_deg,
  // fy = fx (square pixels), cx = (width_px - 1) / 2, cy = (height_px - 1) / 2.
  double fx_px = 0.0;
  double fy_px = 0.0;
  double cx_px = 0.0;
  double cy_px = 0.0;
  std::string side = "left";            // "left" (yaw +90°) or "right" (yaw -90°) of base_link
  double mount_x_m = 0.0;               // optical centre in base_link
  double mount_y_m = 0.0;
  double mount_height_m = 1.2;
  double pitch_deg = 10.0;              // positive: tilted up
  double rate_hz = 30.0;
  double lens_blur_sigma_px = 0.6;
  double exposure_s = 0.008;            // motion blur = image speed × exposure
  double pixel_noise_stddev = 3.0;      // grey levels, 0..255
  double lighting_gain_stddev = 0.08;   // per-frame brightness gain ~ N(1, σ)
  double lighting_gradient = 0.15;      // left-to-right brightness change across the image (fraction)
};

struct SensorOptions {
  LaserOptions laser;
  OdometryNoiseOptions odometry;
  CameraOptions camera;
};

}  // namespace doorplate_localization
