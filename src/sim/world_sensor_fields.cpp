#include "world_sensor_fields.h"

#include <cmath>
#include <string>

namespace doorplate_localization {
namespace {

double Probability(const YamlField& f, const std::string& key, double fallback) {
  const double p = f.NonNegative(key, fallback);
  if (p > 1.0) f.Child(key).Fail("must be in [0, 1]");
  return p;
}

void ParseFittedLaserErrors(const YamlField& f, FittedLaserErrorOptions* o) {
  f.RequireOnlyKeys({"noise_base_m", "noise_fraction", "noise_grazing_gain", "dropout_probability", "dropout_per_m",
                     "dropout_near_probability", "dropout_near_range_m", "dropout_grazing_probability",
                     "dropout_grazing_from_deg", "depth_edge_m", "mixed_pixel_probability", "short_probability",
                     "short_mean_m", "detection_range_m", "detection_edge_fraction"});
  o->noise_base_m = f.NonNegative("noise_base_m", o->noise_base_m);
  o->noise_fraction = f.NonNegative("noise_fraction", o->noise_fraction);
  o->noise_grazing_gain = f.NonNegative("noise_grazing_gain", o->noise_grazing_gain);
  o->dropout_probability = Probability(f, "dropout_probability", o->dropout_probability);
  o->dropout_per_m = Probability(f, "dropout_per_m", o->dropout_per_m);
  o->dropout_near_probability = Probability(f, "dropout_near_probability", o->dropout_near_probability);
  o->dropout_near_range_m = f.NonNegative("dropout_near_range_m", o->dropout_near_range_m);
  o->dropout_grazing_probability = Probability(f, "dropout_grazing_probability", o->dropout_grazing_probability);
  o->dropout_grazing_from_deg = f.NonNegative("dropout_grazing_from_deg", o->dropout_grazing_from_deg);
  if (o->dropout_grazing_from_deg >= 90.0) f.Child("dropout_grazing_from_deg").Fail("must be in [0, 90)");
  o->depth_edge_m = f.Positive("depth_edge_m", o->depth_edge_m);
  o->mixed_pixel_probability = Probability(f, "mixed_pixel_probability", o->mixed_pixel_probability);
  o->short_probability = Probability(f, "short_probability", o->short_probability);
  o->short_mean_m = f.Positive("short_mean_m", o->short_mean_m);
  o->detection_range_m = f.NonNegative("detection_range_m", o->detection_range_m);
  o->detection_edge_fraction = f.Positive("detection_edge_fraction", o->detection_edge_fraction);
  if (o->detection_edge_fraction > 1.0) f.Child("detection_edge_fraction").Fail("must be in (0, 1]");
}

void ParseLaser(const YamlField& f, LaserOptions* o) {
  f.RequireOnlyKeys({"num_beams", "angle_min_rad", "min_range_m", "max_range_m", "error_model", "range_noise_stddev_m",
                     "dropout_probability", "fitted", "rate_hz", "mount_x_m", "mount_y_m", "mount_yaw_rad",
                     "mount_height_m"});
  f.Get("num_beams", &o->num_beams);
  if (o->num_beams < 3 || o->num_beams > 100000) f.Child("num_beams").Fail("must be in 3..100000");
  f.Get("angle_min_rad", &o->angle_min_rad);
  o->min_range_m = f.NonNegative("min_range_m", o->min_range_m);
  o->max_range_m = f.Positive("max_range_m", o->max_range_m);
  if (o->min_range_m >= o->max_range_m) f.Fail("min_range_m must be < max_range_m");
  f.Get("error_model", &o->error_model);
  if (o->error_model != "gaussian" && o->error_model != "fitted") {
    f.Child("error_model").Fail("must be 'gaussian' or 'fitted', got '" + o->error_model + "'");
  }
  // A parameter of the model not in use would be ignored silently: refuse it.
  const bool fitted = o->error_model == "fitted";
  for (const char* key : {"range_noise_stddev_m", "dropout_probability"}) {
    if (fitted && f.Has(key)) f.Child(key).Fail("is a parameter of error_model 'gaussian'; set fitted.* instead");
  }
  if (!fitted && f.Has("fitted")) f.Child("fitted").Fail("is only used with error_model: fitted");
  o->range_noise_stddev_m = f.NonNegative("range_noise_stddev_m", o->range_noise_stddev_m);
  o->dropout_probability = f.NonNegative("dropout_probability", o->dropout_probability);
  if (o->dropout_probability > 1.0) f.Child("dropout_probability").Fail("must be in [0, 1]");
  if (f.Has("fitted")) ParseFittedLaserErrors(f.Child("fitted"), &o->fitted);
  o->rate_hz = f.Positive("rate_hz", o->rate_hz);
  f.Get("mount_x_m", &o->mount_x_m);
  f.Get("mount_y_m", &o->mount_y_m);
  f.Get("mount_yaw_rad", &o->mount_yaw_rad);
  o->mount_height_m = f.NonNegative("mount_height_m", o->mount_height_m);
}

void ParseOdometrySlip(const YamlField& f, OdometrySlipOptions* o) {
  f.RequireOnlyKeys({"scale_stddev", "scale_correlation_length_m", "turn_scale_error_m_per_rad",
                     "turn_rotation_error_rad_per_rad"});
  o->scale_stddev = f.NonNegative("scale_stddev", o->scale_stddev);
  if (o->scale_stddev >= 0.2) f.Child("scale_stddev").Fail("must be in [0, 0.2)");
  o->scale_correlation_length_m = f.Positive("scale_correlation_length_m", o->scale_correlation_length_m);
  f.Get("turn_scale_error_m_per_rad", &o->turn_scale_error_m_per_rad);
  if (std::fabs(o->turn_scale_error_m_per_rad) >= 1.0) f.Child("turn_scale_error_m_per_rad").Fail("must be in (-1, 1)");
  f.Get("turn_rotation_error_rad_per_rad", &o->turn_rotation_error_rad_per_rad);
  if (std::fabs(o->turn_rotation_error_rad_per_rad) >= 0.5) {
    f.Child("turn_rotation_error_rad_per_rad").Fail("must be in (-0.5, 0.5)");
  }
}

void ParseOdometry(const YamlField& f, OdometryNoiseOptions* o) {
  f.RequireOnlyKeys({"alpha1_rad2_per_rad", "alpha2_rad2_per_m", "alpha3_m2_per_m", "alpha4_m2_per_rad",
                     "scale_error", "heading_drift_rad_per_m", "rate_hz", "slip"});
  o->alpha1_rad2_per_rad = f.NonNegative("alpha1_rad2_per_rad", o->alpha1_rad2_per_rad);
  o->alpha2_rad2_per_m = f.NonNegative("alpha2_rad2_per_m", o->alpha2_rad2_per_m);
  o->alpha3_m2_per_m = f.NonNegative("alpha3_m2_per_m", o->alpha3_m2_per_m);
  o->alpha4_m2_per_rad = f.NonNegative("alpha4_m2_per_rad", o->alpha4_m2_per_rad);
  f.Get("scale_error", &o->scale_error);
  if (std::fabs(o->scale_error) >= 0.5) f.Child("scale_error").Fail("must be in (-0.5, 0.5)");
  f.Get("heading_drift_rad_per_m", &o->heading_drift_rad_per_m);
  o->rate_hz = f.Positive("rate_hz", o->rate_hz);
  if (f.Has("slip")) ParseOdometrySlip(f.Child("slip"), &o->slip);
}

void ParseCamera(const YamlField& f, CameraOptions* o) {
  f.RequireOnlyKeys({"width_px", "height_px", "horizontal_fov_deg", "fx_px", "fy_px", "cx_px", "cy_px", "side",
                     "mount_x_m", "mount_y_m",
                     "mount_height_m", "pitch_deg", "rate_hz", "lens_blur_sigma_px", "exposure_s",
                     "pixel_noise_stddev", "lighting_gain_stddev", "lighting_gradient"});
  f.Get("width_px", &o->width_px);
  f.Get("height_px", &o->height_px);
  if (o->width_px < 16 || o->height_px < 16 || o->width_px > 8192 || o->height_px > 8192) {
    f.Fail("width_px and height_px must be in 16..8192");
  }
  o->horizontal_fov_deg = f.Positive("horizontal_fov_deg", o->horizontal_fov_deg);
  if (o->horizontal_fov_deg >= 170) f.Child("horizontal_fov_deg").Fail("must be < 170");
  o->fx_px = f.Positive("fx_px", o->fx_px);
  o->fy_px = f.Positive("fy_px", o->fy_px);
  o->cx_px = f.NonNegative("cx_px", o->cx_px);
  o->cy_px = f.NonNegative("cy_px", o->cy_px);
  if (o->cx_px > o->width_px - 1) f.Fail("cx_px must be in [0, width_px - 1]");
  if (o->cy_px > o->height_px - 1) f.Fail("cy_px must be in [0, height_px - 1]");
  if (f.Has("fx_px") && f.Has("horizontal_fov_deg")) f.Fail("give horizontal_fov_deg or fx_px, not both");
  f.Get("side", &o->side);
  if (o->side != "left" && o->side != "right") f.Child("side").Fail("must be 'left' or 'right'");
  f.Get("mount_x_m", &o->mount_x_m);
  f.Get("mount_y_m", &o->mount_y_m);
  o->mount_height_m = f.Positive("mount_height_m", o->mount_height_m);
  f.Get("pitch_deg", &o->pitch_deg);
  if (std::fabs(o->pitch_deg) > 45) f.Child("pitch_deg").Fail("must be within ±45°");
  o->rate_hz = f.Positive("rate_hz", o->rate_hz);
  o->lens_blur_sigma_px = f.NonNegative("lens_blur_sigma_px", o->lens_blur_sigma_px);
  o->exposure_s = f.NonNegative("exposure_s", o->exposure_s);
  o->pixel_noise_stddev = f.NonNegative("pixel_noise_stddev", o->pixel_noise_stddev);
  o->lighting_gain_stddev = f.NonNegative("lighting_gain_stddev", o->lighting_gain_stddev);
  o->lighting_gradient = f.NonNegative("lighting_gradient", o->lighting_gradient);
}

}  // namespace

void ParseSensorOptions(const YamlField& sensors, SensorOptions* options) {
  sensors.RequireOnlyKeys({"laser", "odometry", "camera"});
  if (sensors.Has("laser")) ParseLaser(sensors.Child("laser"), &options->laser);
  if (sensors.Has("odometry")) ParseOdometry(sensors.Child("odometry"), &options->odometry);
  if (sensors.Has("camera")) ParseCamera(sensors.Child("camera"), &options->camera);
}

}  // namespace doorplate_localization
