// Options of the simulated sensors. Defaults model the paper's robot: RPLIDAR A2 (360°, 16 m), wheel
// odometry, a 640×480 camera aimed sideways at the opposite wall. A world file may override any field
// (see docs/world-format.md); units are in the field names.
#pragma once

#include <cstdint>
#include <string>

namespace doorplate_localization {

// The "fitted" laser error model (LaserErrorModel, sim/laser_error_model.h): what a real laser does beyond
// Gaussian noise, measured on the CARMEN logs by doorplate_laser_fit (docs/results/laser-model.md, which
// also says which values are scaled for the RPLIDAR A2). r: the exact range, metres; i: the incidence
// angle between the beam and the surface normal. Events, per beam, in this order:
//  1. at a depth edge (a neighbouring beam's exact range differs by more than depth_edge_m), a mixed
//     pixel with mixed_pixel_probability: a range uniform between the near and the far surface;
//  2. with short_probability, something (a person, clutter) stands min range + an exponential with mean
//     short_mean_m away; if that is before the surface (or within max range on a beam that hits
//     nothing) the beam returns there: a spurious short return;
//  3. a dropout (no return, +inf) with probability dropout_probability + dropout_per_m * r +
//     dropout_near_probability * [r < dropout_near_range_m] +
//     dropout_grazing_probability * max(0, (i - dropout_grazing_from_deg) / (90° - dropout_grazing_from_deg));
//     and, with detection_range_m > 0, a dropout whenever the echo is too weak (the lidar equation: the
//     returned power falls as cos(i) / r², so the farthest detected range is r_max = detection_range_m ·
//     sqrt(cos i)): with probability clamp((r / r_max − 1) / detection_edge_fraction + 1/2, 0, 1), combined
//     with the above as independent events;
//  4. otherwise Gaussian noise with sigma sqrt(noise_base_m² + (noise_fraction * r)²) *
//     (1 + noise_grazing_gain * (1 / cos(min(i, 80°)) - 1)).
// The defaults are doorplate_laser_fit's fit to the four CARMEN logs (SICK LMS; 2026-12-02, seed 1), rounded,
// with noise_fraction raised to the RPLIDAR A2's datasheet figure (docs/results/laser-model.md).
struct FittedLaserErrorOptions {
  double noise_base_m = 0.022;
  double noise_fraction = 0.005;             // fitted 0.0025 on the SICK; RPLIDAR: its datasheet's <1 % as 2 sigma
  double noise_grazing_gain = 0.77;
  double dropout_probability = 0.0059;
  double dropout_per_m = 0.0;
  double dropout_near_probability = 0.040;
  double dropout_near_range_m = 1.0;
  double dropout_grazing_probability = 0.020;
  double dropout_grazing_from_deg = 30.0;
  double depth_edge_m = 0.3;
  double mixed_pixel_probability = 0.115;
  double short_probability = 0.090;
  double short_mean_m = 5.96;
  // Head-on detection range of the world's surfaces (0: no limit). The SICK LMS of the logs (80 m, time of
  // flight) shows none within them; a triangulation scanner such as the RPLIDAR A2 does: 16 m on white
  // targets by its datasheet, less on painted walls and much less at grazing incidence (docs/world-format.md).
  double detection_range_m = 0.0;
  double detection_edge_fraction = 0.2;
};

// 2D laser scanner in the base_link frame. Beams are spread evenly over [angle_min_rad,
// angle_min_rad + (num_beams - 1) * 2*pi/num_beams] for a 360° device.
struct LaserOptions {
  int num_beams = 360;
  double angle_min_rad = -3.14159265358979323846;
  double min_range_m = 0.15;
  double max_range_m = 16.0;
  // "gaussian": range_noise_stddev_m and dropout_probability below on every beam (the default; its random
  // draws are those of every earlier version). "fitted": FittedLaserErrorOptions `fitted`.
  std::string error_model = "gaussian";
  double range_noise_stddev_m = 0.01;   // gaussian: noise on every return
  double dropout_probability = 0.01;    // gaussian: a beam returns no echo (+inf, REP-117) with this probability
  FittedLaserErrorOptions fitted;       // fitted: its parameters
  double rate_hz = 10.0;
  double mount_x_m = 0.0;               // laser frame origin in base_link
  double mount_y_m = 0.0;
  double mount_yaw_rad = 0.0;
  double mount_height_m = 0.25;         // only surfaces spanning this height are seen
};

// Differential-drive odometry error, independent of the simulation step: every random term is a random
// walk whose variance grows linearly with the motion (AMCL's alpha roles, per unit of motion).
// Odometry that slips (issue 20, item 3; fitted in docs/results/odometry-model.md). All zero = off: the
// odometry then draws exactly the random numbers it drew before this existed.
struct OdometrySlipOptions {
  // A scale error that varies slowly along the path (floor surfaces, load): an Ornstein–Uhlenbeck process
  // over the distance driven, stationary standard deviation `scale_stddev` (a fraction, like
  // scale_error) and correlation length `scale_correlation_length_m`; added to scale_error.
  double scale_stddev = 0.0;
  double scale_correlation_length_m = 10.0;
  // Slip on turns: extra scale error per rad/m of turn rate (a step's translation grows by
  // turn_scale_error_m_per_rad × |rotation|), and rotation over-read by this fraction of the rotation.
  double turn_scale_error_m_per_rad = 0.0;
  double turn_rotation_error_rad_per_rad = 0.0;

  bool Enabled() const {
    return scale_stddev != 0.0 || turn_scale_error_m_per_rad != 0.0 || turn_rotation_error_rad_per_rad != 0.0;
  }
};

struct OdometryNoiseOptions {
  double alpha1_rad2_per_rad = 0.001;   // rotation variance per radian turned
  double alpha2_rad2_per_m = 0.00002;   // rotation variance per metre driven
  double alpha3_m2_per_m = 0.0004;      // translation variance per metre driven
  double alpha4_m2_per_rad = 0.0001;    // translation variance per radian turned
  double scale_error = 0.02;            // systematic: odometry distance = (1 + scale_error) * true
  double heading_drift_rad_per_m = 0.002;  // systematic yaw drift per metre driven (unequal wheels)
  double rate_hz = 50.0;
  OdometrySlipOptions slip;             // off by default (last: positional initializers keep their meaning)
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
