#include "text_amcl_options.h"

#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace doorplate_localization {
namespace {

// Reads a number (or `fallback`) that must be finite and satisfy `ok`, described by `rule` in the error.
template <typename T>
T ReadChecked(const ros::NodeHandle& nh, const std::string& name, T fallback, const std::function<bool(double)>& ok,
              const std::string& rule) {
  const T value = ReadParam(nh, name, fallback);
  RequireParam(std::isfinite(static_cast<double>(value)) && ok(static_cast<double>(value)), nh, name, rule, value);
  return value;
}
double ReadPositive(const ros::NodeHandle& nh, const std::string& name, double fallback) {
  return ReadChecked(nh, name, fallback, [](double v) { return v > 0.0; }, "finite and > 0");
}
double ReadNonNegative(const ros::NodeHandle& nh, const std::string& name, double fallback) {
  return ReadChecked(nh, name, fallback, [](double v) { return v >= 0.0; }, "finite and >= 0");
}
double ReadProbability(const ros::NodeHandle& nh, const std::string& name, double fallback) {
  return ReadChecked(nh, name, fallback, [](double v) { return v >= 0.0 && v <= 1.0; }, "in [0, 1]");
}
double ReadFinite(const ros::NodeHandle& nh, const std::string& name, double fallback) {
  return ReadChecked(nh, name, fallback, [](double) { return true; }, "finite");
}

void ReadFilter(const ros::NodeHandle& nh, TextAmclOptions& f) {
  f.min_particles = ReadChecked(nh, "min_particles", f.min_particles, [](double v) { return v >= 1; }, ">= 1");
  f.max_particles = ReadChecked(nh, "max_particles", f.max_particles,
                                [&](double v) { return v >= f.min_particles; }, ">= min_particles");
  f.kld_err = ReadPositive(nh, "kld_err", f.kld_err);
  f.kld_z = ReadPositive(nh, "kld_z", f.kld_z);
  f.update_min_d_m = ReadNonNegative(nh, "update_min_d", f.update_min_d_m);
  f.update_min_a_rad = ReadNonNegative(nh, "update_min_a", f.update_min_a_rad);
  f.resample_interval = ReadChecked(nh, "resample_interval", f.resample_interval, [](double v) { return v >= 1; },
                                    ">= 1");
  f.recovery_alpha_slow = ReadProbability(nh, "recovery_alpha_slow", f.recovery_alpha_slow);
  f.recovery_alpha_fast = ReadChecked(nh, "recovery_alpha_fast", f.recovery_alpha_fast,
                                      [&](double v) { return v >= f.recovery_alpha_slow && v <= 1.0; },
                                      "in [recovery_alpha_slow, 1]");
  f.text_min_confidence = ReadProbability(nh, "text_min_confidence", f.text_min_confidence);
  f.text_reseed_fraction = ReadProbability(nh, "text_reseed_fraction", f.text_reseed_fraction);
  f.text_explained_ratio = ReadChecked(nh, "text_explained_ratio", f.text_explained_ratio,
                                       [](double v) { return v >= 1.0; }, "finite and >= 1");
  f.converged_cluster_weight = ReadChecked(nh, "converged_cluster_weight", f.converged_cluster_weight,
                                           [](double v) { return v > 0.0 && v <= 1.0; }, "in (0, 1]");
  f.converged_stddev_m = ReadPositive(nh, "converged_stddev_m", f.converged_stddev_m);
  f.converged_heading_stddev_rad = ReadPositive(nh, "converged_heading_stddev_rad", f.converged_heading_stddev_rad);
  f.lost_likelihood_ratio = ReadChecked(nh, "lost_likelihood_ratio", f.lost_likelihood_ratio,
                                        [](double v) { return v > 0.0 && v <= 1.0; }, "in (0, 1]");
  const int seed = ReadChecked(nh, "seed", 1, [](double v) { return v >= 0; }, ">= 0");
  f.random_seed = static_cast<std::uint64_t>(seed);
}

void ReadLaser(const ros::NodeHandle& nh, TextAmclSetupOptions& s) {
  const std::string type = ReadParam<std::string>(nh, "laser_model_type", "likelihood_field");
  try {
    s.laser_model_type = ParseLaserModelType(type);
  } catch (const std::invalid_argument&) {
    RequireParam(false, nh, "laser_model_type", "'likelihood_field', 'likelihood_field_prob' or 'beam'", type);
  }
  BeamSelectionOptions beams;
  beams.laser_max_beams = ReadChecked(nh, "laser_max_beams", 30, [](double v) { return v >= 2; }, ">= 2");
  beams.laser_min_range_m = ReadFinite(nh, "laser_min_range", -1.0);  // <= 0: the scan's range_min
  beams.laser_max_range_m = ReadFinite(nh, "laser_max_range", -1.0);  // <= 0: the scan's range_max
  if (beams.laser_min_range_m > 0.0 && beams.laser_max_range_m > 0.0) {
    RequireParam(beams.laser_max_range_m > beams.laser_min_range_m, nh, "laser_max_range", "> laser_min_range",
                 beams.laser_max_range_m);
  }
  LikelihoodFieldModelOptions& lf = s.likelihood_field;
  BeamModelOptions& b = s.beam;
  lf.beams = b.beams = beams;
  lf.z_hit = b.z_hit = ReadProbability(nh, "laser_z_hit", 0.95);
  lf.z_rand = b.z_rand = ReadProbability(nh, "laser_z_rand", 0.05);
  b.z_short = ReadProbability(nh, "laser_z_short", 0.1);
  b.z_max = ReadProbability(nh, "laser_z_max", 0.05);
  lf.sigma_hit_m = b.sigma_hit_m = ReadPositive(nh, "laser_sigma_hit", 0.2);
  b.lambda_short_per_m = ReadPositive(nh, "laser_lambda_short", 0.1);
  lf.laser_likelihood_max_dist_m = ReadPositive(nh, "laser_likelihood_max_dist", 2.0);
  lf.do_beamskip = ReadParam(nh, "do_beamskip", false);
  lf.beam_skip_distance_m = ReadPositive(nh, "beam_skip_distance", 0.5);
  lf.beam_skip_threshold = ReadProbability(nh, "beam_skip_threshold", 0.3);
  lf.beam_skip_error_threshold = ReadProbability(nh, "beam_skip_error_threshold", 0.9);
  const bool selective = ReadParam(nh, "selective_resampling", false);
  RequireParam(!selective, nh, "selective_resampling", "false (not provided)", selective);
}

void ReadMotion(const ros::NodeHandle& nh, DiffDriveMotionModelOptions& m) {
  const std::string type = ReadParam<std::string>(nh, "odom_model_type", "diff");  // amcl's default
  try {
    m.odom_model_type = ParseOdomModelType(type);
  } catch (const std::invalid_argument&) {
    RequireParam(false, nh, "odom_model_type", "'diff' or 'diff-corrected'", type);
  }
  m.odom_alpha1 = ReadNonNegative(nh, "odom_alpha1", 0.2);
  m.odom_alpha2 = ReadNonNegative(nh, "odom_alpha2", 0.2);
  m.odom_alpha3 = ReadNonNegative(nh, "odom_alpha3", 0.2);
  m.odom_alpha4 = ReadNonNegative(nh, "odom_alpha4", 0.2);
  ReadNonNegative(nh, "odom_alpha5", 0.2);  // amcl's omni-only alpha: validated, unused by the diff models
}

void ReadText(const ros::NodeHandle& nh, TextAmclNodeOptions& o) {
  TextAmclSetupOptions& s = o.setup;
  s.use_text = ReadParam(nh, "use_text", s.use_text);
  o.text_map_file = ReadParam(nh, "text_map_file", o.text_map_file);
  PlateLikelihoodModelOptions& p = s.plate;
  p.bearing_stddev_rad = ReadPositive(nh, "text_bearing_stddev_rad", p.bearing_stddev_rad);
  p.range_stddev_m = ReadPositive(nh, "text_range_stddev_m", p.range_stddev_m);
  p.min_view_distance_m = ReadNonNegative(nh, "text_min_view_distance_m", p.min_view_distance_m);
  p.max_view_distance_m = ReadChecked(nh, "text_max_view_distance_m", p.max_view_distance_m,
                                      [&](double v) { return v > p.min_view_distance_m; },
                                      "finite and > text_min_view_distance_m");
  p.max_view_angle_rad = ReadChecked(nh, "text_max_view_angle_rad", p.max_view_angle_rad,
                                     [](double v) { return v > 0.0 && v <= M_PI / 2; }, "in (0, pi/2]");
  p.floor_probability = ReadChecked(nh, "text_floor_probability", p.floor_probability,
                                    [](double v) { return v > 0.0 && v <= 1.0; }, "in (0, 1]");
  p.check_line_of_sight = ReadParam(nh, "text_check_line_of_sight", p.check_line_of_sight);
  TextMatchOptions& m = p.text_match;
  m.confusable_pairs = ReadParam(nh, "text_confusable_pairs", m.confusable_pairs);
  m.confusable_substitution_probability =
      ReadProbability(nh, "text_confusable_substitution_probability", m.confusable_substitution_probability);
  m.other_edit_probability = ReadProbability(nh, "text_other_edit_probability", m.other_edit_probability);
  // The pose sampler sees plates under the same geometry and confusions as the likelihood model.
  PlatePoseSamplerOptions& ps = s.plate_sampler;
  ps.min_view_distance_m = p.min_view_distance_m;
  ps.max_view_angle_rad = p.max_view_angle_rad;
  ps.text_match = m;
  ps.range_stddev_m = ReadPositive(nh, "text_reseed_range_stddev_m", ps.range_stddev_m);
  ps.typical_view_distance_min_m = ReadPositive(nh, "text_reseed_wall_distance_min_m", ps.typical_view_distance_min_m);
  ps.typical_view_distance_max_m =
      ReadChecked(nh, "text_reseed_wall_distance_max_m", ps.typical_view_distance_max_m,
                  [&](double v) { return v >= ps.typical_view_distance_min_m; },
                  "finite and >= text_reseed_wall_distance_min_m");
  o.text_use_laser_range = ReadParam(nh, "text_use_laser_range", o.text_use_laser_range);
  o.text_range_max_bearing_error_rad =
      ReadPositive(nh, "text_range_max_bearing_error_rad", o.text_range_max_bearing_error_rad);
  o.text_range_max_scan_age_s = ReadPositive(nh, "text_range_max_scan_age_s", o.text_range_max_scan_age_s);
}

// The whole set against the core: the filter built on a small closed room. Names the core's field.
void CheckAgainstCore(const ros::NodeHandle& nh, const TextAmclNodeOptions& o) {
  OccupancyGrid room(20, 20, 0.1, Pose2D{}, OccupancyGrid::kFree);
  for (int i = 0; i < 20; ++i) room.At(i, 0) = room.At(i, 19) = room.At(0, i) = room.At(19, i) = OccupancyGrid::kOccupied;
  auto plates = std::make_shared<TextMap>();
  plates->landmarks.push_back({"101", Pose2D{1.0, 0.1, M_PI / 2}, 1.5, "south", 0, 0.0});
  try {
    MakeTextAmcl(o.setup, room, plates);
  } catch (const std::exception& e) {
    throw ParameterError(nh.resolveName("") + ": the parameters do not make a filter: " + e.what());
  }
}

}  // namespace

TextAmclNodeOptions LoadTextAmclOptions(const ros::NodeHandle& nh) {
  TextAmclNodeOptions o;
  TextAmclOptions& f = o.setup.filter;
  f.recovery_alpha_slow = 0.001;  // amcl: 0 (off); ours on by default (docs/parameters.md)
  f.recovery_alpha_fast = 0.1;
  ReadFilter(nh, f);
  ReadLaser(nh, o.setup);
  ReadMotion(nh, o.setup.motion);
  ReadText(nh, o);

  o.base_frame_id = ReadFrameParam(nh, "base_frame_id", o.base_frame_id);
  o.odom_frame_id = ReadFrameParam(nh, "odom_frame_id", o.odom_frame_id);
  o.global_frame_id = ReadFrameParam(nh, "global_frame_id", o.global_frame_id);
  RequireParam(o.odom_frame_id != o.base_frame_id && o.odom_frame_id != o.global_frame_id, nh, "odom_frame_id",
               "different from base_frame_id and global_frame_id", o.odom_frame_id);
  o.tf_broadcast = ReadParam(nh, "tf_broadcast", o.tf_broadcast);
  o.transform_tolerance_s = ReadNonNegative(nh, "transform_tolerance", o.transform_tolerance_s);
  o.tf_timeout_s = ReadNonNegative(nh, "tf_timeout", o.tf_timeout_s);

  o.initial_pose.x_m = ReadFinite(nh, "initial_pose_x", 0.0);
  o.initial_pose.y_m = ReadFinite(nh, "initial_pose_y", 0.0);
  o.initial_pose.theta_rad = NormalizeAngle(ReadFinite(nh, "initial_pose_a", 0.0));
  o.initial_covariance.setZero();
  o.initial_covariance(0, 0) = ReadNonNegative(nh, "initial_cov_xx", 0.25);
  o.initial_covariance(1, 1) = ReadNonNegative(nh, "initial_cov_yy", 0.25);
  o.initial_covariance(2, 2) = ReadNonNegative(nh, "initial_cov_aa", (M_PI / 12.0) * (M_PI / 12.0));
  o.start_with_global_localization = ReadParam(nh, "start_with_global_localization", o.start_with_global_localization);
  o.gui_publish_rate_hz = ReadFinite(nh, "gui_publish_rate", o.gui_publish_rate_hz);
  o.save_pose_rate_hz = ReadFinite(nh, "save_pose_rate", o.save_pose_rate_hz);

  o.map_file = ReadParam(nh, "map_file", o.map_file);
  o.use_map_topic = ReadParam(nh, "use_map_topic", o.use_map_topic);
  o.first_map_only = ReadParam(nh, "first_map_only", o.first_map_only);
  CheckAgainstCore(nh, o);
  return o;
}

TextAmclSessionOptions ToSessionOptions(const TextAmclNodeOptions& options) {
  TextAmclSessionOptions o;
  o.setup = options.setup;
  o.start_with_global_localization = options.start_with_global_localization;
  o.initial_pose = options.initial_pose;
  o.initial_covariance = options.initial_covariance;
  o.text_use_laser_range = options.text_use_laser_range;
  o.text_range_max_bearing_error_rad = options.text_range_max_bearing_error_rad;
  o.text_range_max_scan_age_s = options.text_range_max_scan_age_s;
  return o;
}

}  // namespace doorplate_localization
