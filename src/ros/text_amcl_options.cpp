// TextAmclNodelet's parameter table and loader: every parameter once (name, field, default, rule, doc);
// rules between fields are the core's (TextAmclSession and the models MakeTextAmcl builds), checked on a
// small synthetic map.
#include "text_amcl_options.h"

#include <cmath>
#include <memory>
#include <string>

#include "doorplate_localization/common/limits.h"
#include "text_amcl_building.h"

namespace doorplate_localization {
namespace {

using O = TextAmclNodeOptions;

// A laser option of both laser models: read from the likelihood field's options, written to both.
template <typename T, typename Access>
ParamSpec<O> BothLaserModels(std::string name, std::string field, Access access, std::string doc, ParamRule rule) {
  return ConvertedParam<O, T>(
      std::move(name), "session.setup.likelihood_field." + field,
      [access](const O& o) { return access(o.session.setup.likelihood_field); },
      [access](O& o, T v) { access(o.session.setup.likelihood_field) = access(o.session.setup.beam) = v; },
      std::move(doc), std::move(rule));
}

// A doorplate option the plate likelihood model and the pose sampler share (same geometry, same confusions).
template <typename T, typename Access>
ParamSpec<O> PlateAndSampler(std::string name, std::string field, Access access, std::string doc, ParamRule rule) {
  return ConvertedParam<O, T>(
      std::move(name), "session.setup.plate." + field, [access](const O& o) { return access(o.session.setup.plate); },
      [access](O& o, T v) { access(o.session.setup.plate) = access(o.session.setup.plate_sampler) = v; },
      std::move(doc), std::move(rule));
}

double& CovarianceDiagonal(O& o, int i) { return o.session.initial_covariance(i, i); }

}  // namespace

TextAmclSessionOptions AmclDefaultSessionOptions() {
  TextAmclSessionOptions s;
  s.setup.likelihood_field.beams.laser_max_beams = s.setup.beam.beams.laser_max_beams = 30;
  s.setup.motion.noise_law = OdometryNoiseLaw::kDiff;
  return s;
}

const ParamTable<O>& TextAmclParamTable() {
  namespace r = param_rules;
  const ParamRule unit_open_low = r::Holds("in (0, 1]", [](double v) { return v > 0.0 && v <= 1.0; });
  // Checked before the filter allocates anything for them (common/limits.h).
  const ParamRule particles = r::Holds("in [1, " + std::to_string(limits::kMaxParticles) + "] (limits::kMaxParticles)",
                                       [](double v) { return v >= 1.0 && v <= limits::kMaxParticles; });
#define F(path) DOORPLATE_PARAM_FIELD(session.setup.path)
  static const ParamTable<O> table = {
      // --- filter (amcl) ---
      Param<O>("min_particles", F(filter.min_particles), "KLD-sampling lower bound", particles),
      Param<O>("max_particles", F(filter.max_particles), "KLD-sampling upper bound; initialization draws this many",
               particles),
      Param<O>("kld_err", F(filter.kld_err), "KLD-sampling error bound (used as given, like amcl)", r::Positive()),
      Param<O>("kld_z", F(filter.kld_z), "KLD-sampling normal quantile", r::Positive()),
      Param<O>("update_min_d", F(filter.update_min_d_m), "travel (m) that triggers a filter update", r::NonNegative()),
      Param<O>("update_min_a", F(filter.update_min_a_rad), "rotation (rad) that triggers a filter update (π/6)",
               r::NonNegative()),
      Param<O>("resample_interval", F(filter.resample_interval), "laser updates per resampling", r::AtLeast(1)),
      Param<O>("recovery_alpha_slow", F(filter.recovery_alpha_slow),
               "Augmented MCL average (**differs**: amcl 0 = off); 0 <= slow <= fast <= 1", r::Probability()),
      Param<O>("recovery_alpha_fast", F(filter.recovery_alpha_fast),
               "Augmented MCL average (**differs**: amcl 0); both 0 disable random injection", r::Probability()),
      // --- laser (amcl) ---
      EnumParam<O>("laser_model_type", F(laser_model_type),
                   {{"likelihood_field", LaserModelType::kLikelihoodField},
                    {"likelihood_field_prob", LaserModelType::kLikelihoodFieldProb}, {"beam", LaserModelType::kBeam}},
                   "`likelihood_field` (amcl's cube-sum), `likelihood_field_prob` (product) or `beam`"),
      BothLaserModels<int>("laser_max_beams", "beams.laser_max_beams",
                           [](auto& m) -> auto& { return m.beams.laser_max_beams; },
                           "beams used per scan, evenly spread (amcl's default; the core's is 60)", r::AtLeast(2))
          .Shipped(60),
      BothLaserModels<double>("laser_min_range", "beams.laser_min_range_m",
                              [](auto& m) -> auto& { return m.beams.laser_min_range_m; },
                              "<= 0: the scan's range_min", r::Finite()),
      BothLaserModels<double>("laser_max_range", "beams.laser_max_range_m",
                              [](auto& m) -> auto& { return m.beams.laser_max_range_m; },
                              "<= 0: the scan's range_max; else > laser_min_range", r::Finite()),
      BothLaserModels<double>("laser_z_hit", "z_hit", [](auto& m) -> auto& { return m.z_hit; },
                              "mixture weight of hits, both models", r::Probability()),
      BothLaserModels<double>("laser_z_rand", "z_rand", [](auto& m) -> auto& { return m.z_rand; },
                              "mixture weight of random readings, both models", r::Probability()),
      Param<O>("laser_z_short", F(beam.z_short), "beam model only", r::Probability()),
      Param<O>("laser_z_max", F(beam.z_max), "beam model only", r::Probability()),
      BothLaserModels<double>("laser_sigma_hit", "sigma_hit_m", [](auto& m) -> auto& { return m.sigma_hit_m; },
                              "std dev of a hit (m)", r::Positive()),
      Param<O>("laser_lambda_short", F(beam.lambda_short_per_m), "beam model only", r::Positive()),
      Param<O>("laser_likelihood_max_dist", F(likelihood_field.laser_likelihood_max_dist_m),
               "likelihood field: distances clamped here (m)", r::Positive()),
      Param<O>("do_beamskip", F(likelihood_field.do_beamskip), "amcl's beam skipping (likelihood field)"),
      Param<O>("beam_skip_distance", F(likelihood_field.beam_skip_distance_m), "beam skipping", r::Positive()),
      Param<O>("beam_skip_threshold", F(likelihood_field.beam_skip_threshold), "beam skipping", r::Probability()),
      Param<O>("beam_skip_error_threshold", F(likelihood_field.beam_skip_error_threshold), "beam skipping",
               r::Probability()),
      Param<O>("selective_resampling", DOORPLATE_PARAM_FIELD(selective_resampling), "true is refused (not provided)",
               {"false (not provided)", [](const ParamValue& v) { return !std::get<bool>(v); }}),
      // --- odometry (amcl) ---
      EnumParam<O>("odom_model_type", F(motion.noise_law),
                   {{"diff", OdometryNoiseLaw::kDiff}, {"diff-corrected", OdometryNoiseLaw::kDiffCorrected}},
                   "`diff` (amcl's, the α·δ² std dev variant; the core's default is `diff-corrected`) or "
                   "`diff-corrected`; `omni`, `omni-corrected` are refused")
          .Shipped(std::string("diff-corrected")),
      Param<O>("odom_alpha1", F(motion.rot_noise_from_rot), "rotation noise from rotation (sensors/odometry_motion_model.h)",
               r::NonNegative()),
      Param<O>("odom_alpha2", F(motion.rot_noise_from_trans), "rotation noise from translation", r::NonNegative()),
      Param<O>("odom_alpha3", F(motion.trans_noise_from_trans), "translation noise from translation",
               r::NonNegative()),
      Param<O>("odom_alpha4", F(motion.trans_noise_from_rot), "translation noise from rotation", r::NonNegative()),
      Param<O>("odom_alpha5", DOORPLATE_PARAM_FIELD(odom_alpha5), "amcl's omni alpha: validated, unused",
               r::NonNegative()),
      // --- frames, start and map (amcl) ---
      Param<O>("base_frame_id", DOORPLATE_PARAM_FIELD(base_frame_id), "the robot's frame", r::FrameId()),
      Param<O>("odom_frame_id", DOORPLATE_PARAM_FIELD(odom_frame_id),
               "odometry frame; differs from base_frame_id and global_frame_id", r::FrameId()),
      Param<O>("global_frame_id", DOORPLATE_PARAM_FIELD(global_frame_id), "the map frame", r::FrameId()),
      Param<O>("tf_broadcast", DOORPLATE_PARAM_FIELD(tf_broadcast), "publish global_frame -> odom_frame"),
      Param<O>("transform_tolerance", DOORPLATE_PARAM_FIELD(transform_tolerance_s),
               "s: the transform is stamped scan stamp + this", r::NonNegative()),
      Param<O>("initial_pose_x", DOORPLATE_PARAM_FIELD(session.initial_pose.x_m), "start pose on a new map (m)",
               r::Finite()),
      Param<O>("initial_pose_y", DOORPLATE_PARAM_FIELD(session.initial_pose.y_m), "start pose (m)", r::Finite()),
      ConvertedParam<O, double>(
          "initial_pose_a", "session.initial_pose.theta_rad",
          [](const O& o) { return o.session.initial_pose.theta_rad; },
          [](O& o, double a) { o.session.initial_pose.theta_rad = NormalizeAngle(a); }, "start heading (rad)",
          r::Finite()),
      ConvertedParam<O, double>(
          "initial_cov_xx", "session.initial_covariance(0,0)",
          [](const O& o) { return o.session.initial_covariance(0, 0); },
          [](O& o, double v) { CovarianceDiagonal(o, 0) = v; }, "start variance of x (m²)", r::NonNegative()),
      ConvertedParam<O, double>(
          "initial_cov_yy", "session.initial_covariance(1,1)",
          [](const O& o) { return o.session.initial_covariance(1, 1); },
          [](O& o, double v) { CovarianceDiagonal(o, 1) = v; }, "start variance of y (m²)", r::NonNegative()),
      ConvertedParam<O, double>(
          "initial_cov_aa", "session.initial_covariance(2,2)",
          [](const O& o) { return o.session.initial_covariance(2, 2); },
          [](O& o, double v) { CovarianceDiagonal(o, 2) = v; }, "start variance of the heading (rad², (π/12)²)",
          r::NonNegative()),
      Param<O>("gui_publish_rate", DOORPLATE_PARAM_FIELD(gui_publish_rate_hz),
               "particlecloud at most this often (Hz); <= 0: after every update", r::Finite())
          .Shipped(5.0),
      Param<O>("save_pose_rate", DOORPLATE_PARAM_FIELD(save_pose_rate_hz),
               "Hz: the estimate is written to `~initial_pose_*`, `~initial_cov_*`; <= 0: never", r::Finite()),
      Param<O>("use_map_topic", DOORPLATE_PARAM_FIELD(use_map_topic),
               "subscribe `map` instead of calling `static_map`"),
      Param<O>("first_map_only", DOORPLATE_PARAM_FIELD(first_map_only), "keep the first map"),
      // --- ours ---
      Param<O>("map_file", DOORPLATE_PARAM_FIELD(map_file),
               "(ours) a map_server YAML loaded directly (before `use_map_topic` / `static_map`), republished "
               "latched on `map`; unusable: the nodelet does not start, naming the file"),
      Param<O>("start_with_global_localization", DOORPLATE_PARAM_FIELD(session.start_with_global_localization),
               "(ours) on a new map, spread the particles over the free space instead of `~initial_pose_*`"),
      Param<O>("tf_timeout_s", DOORPLATE_PARAM_FIELD(tf_timeout_s),
               "(ours) how long a text_detections callback waits for a transform (scans wait in a tf filter instead)",
               r::NonNegative())
          .Deprecated("tf_timeout"),
      Param<O>("scan_timeout_s", DOORPLATE_PARAM_FIELD(scan_timeout_s),
               "(ours) no scan taken for this long (s, ROS time): `~state` says waiting_for_scan and the "
               "diagnostic warns (no estimate is being published); <= 0: never",
               r::Finite()),
      ConvertedParam<O, int>(
          "seed", "session.setup.filter.random_seed",
          [](const O& o) { return static_cast<int>(o.session.setup.filter.random_seed); },
          [](O& o, int seed) { o.session.setup.filter.random_seed = static_cast<std::uint64_t>(seed); },
          "(ours) the filter's random seed (runs are repeatable for a given input)", r::AtLeast(0)),
      Param<O>("use_text", F(use_text), "(ours) false: plain amcl, doorplate readings ignored"),
      Param<O>("text_map_file", DOORPLATE_PARAM_FIELD(text_map_file),
               "(ours) the doorplate map (docs/text-map-format.md); \"\", missing or broken: an error naming the "
               "file, and localization with the laser alone"),
      Param<O>("building_file", DOORPLATE_PARAM_FIELD(building_file),
               "(ours) a building of several floors (docs/building-format.md, a maps building file: each floor's "
               "`occupancy_map` and `text_map`, the lifts); set: the floors' maps come from it (not `map_file`, "
               "`text_map_file`, `map`, `static_map`; `set_map` is refused), the current floor's grid is latched on "
               "`map`, its plates on `text_landmarks`, its id on `~floor`; unusable: the nodelet does not start, "
               "naming the file"),
      Param<O>("start_floor", DOORPLATE_PARAM_FIELD(start_floor),
               "(ours) the id of the floor the robot starts on; \"\": unknown (the plates decide; the first floor's "
               "map until then); without `building_file` the id of the one map's floor"),
      Param<O>("floor_misread_probability", DOORPLATE_PARAM_FIELD(floor_belief.misread_probability),
               "(ours) the chance that a reading names a room of another floor (mcl/floor_belief.h: ε)",
               r::Holds("in (0, 0.5)", [](double v) { return v > 0.0 && v < 0.5; })),
      Param<O>("floor_change_probability", DOORPLATE_PARAM_FIELD(floor_belief.floor_change_probability),
               "(ours) the chance that the robot changed floors unseen between two informative readings",
               r::Holds("in [0, 1)", [](double v) { return v >= 0.0 && v < 1.0; })),
      Param<O>("floor_certain_probability", DOORPLATE_PARAM_FIELD(floor_belief.certain_probability),
               "(ours) a floor is certain (and its map current) at this belief; `~state` is converged only on a "
               "certain floor",
               r::Holds("in (0.5, 1)", [](double v) { return v > 0.5 && v < 1.0; })),
      Param<O>("text_min_confidence", F(filter.text_min_confidence), "readings below are ignored", r::Probability()),
      Param<O>("text_reseed_fraction", F(filter.text_reseed_fraction),
               "share of particles reseeded at the compatible plates while not converged or when a reading "
               "contradicts the estimate",
               r::Probability()),
      Param<O>("text_explained_ratio", F(filter.text_explained_ratio),
               "the converged estimate explains a reading when its plate likelihood is this many times the "
               "unexplained one (below: kidnap)",
               r::Holds("finite and >= 1", [](double v) { return std::isfinite(v) && v >= 1.0; })),
      Param<O>("text_bearing_stddev_rad", F(plate.bearing_stddev_rad), "plate likelihood: bearing error",
               r::Positive()),
      Param<O>("text_range_stddev_m", F(plate.range_stddev_m), "plate likelihood: range error", r::Positive()),
      PlateAndSampler<double>("text_min_view_distance_m", "min_view_distance_m",
                              [](auto& m) -> auto& { return m.min_view_distance_m; },
                              "a plate can be read from this far", r::NonNegative()),
      Param<O>("text_max_view_distance_m", F(plate.max_view_distance_m),
               "... up to this far; > text_min_view_distance_m", r::Positive()),
      PlateAndSampler<double>("text_max_view_angle_rad", "max_view_angle_rad",
                              [](auto& m) -> auto& { return m.max_view_angle_rad; },
                              "... and at most this far off its normal",
                              r::Holds("in (0, pi/2]", [](double v) { return v > 0.0 && v <= M_PI / 2; })),
      Param<O>("text_floor_probability", F(plate.floor_probability),
               "likelihood of a reading no plate in view explains", unit_open_low),
      Param<O>("text_check_line_of_sight", F(plate.check_line_of_sight), "ray-cast the map robot -> plate"),
      PlateAndSampler<std::string>("text_confusable_pairs", "text_match.confusable_pairs",
                                   [](auto& m) -> auto& { return m.text_match.confusable_pairs; },
                                   "OCR confusion model (mcl/text_match.h): character pairs", {}),
      PlateAndSampler<double>("text_confusable_substitution_probability",
                              "text_match.confusable_substitution_probability",
                              [](auto& m) -> auto& { return m.text_match.confusable_substitution_probability; },
                              "OCR confusion model", r::Probability()),
      PlateAndSampler<double>("text_other_edit_probability", "text_match.other_edit_probability",
                              [](auto& m) -> auto& { return m.text_match.other_edit_probability; },
                              "OCR confusion model", r::Probability()),
      Param<O>("text_reseed_range_stddev_m", F(plate_sampler.range_stddev_m),
               "plate pose sampler (mcl/plate_pose_sampler.h)", r::Positive()),
      Param<O>("text_reseed_wall_distance_min_m", F(plate_sampler.typical_view_distance_min_m), "plate pose sampler",
               r::Positive()),
      Param<O>("text_reseed_wall_distance_max_m", F(plate_sampler.typical_view_distance_max_m),
               "plate pose sampler; >= text_reseed_wall_distance_min_m", r::Positive()),
      Param<O>("text_use_laser_range", DOORPLATE_PARAM_FIELD(session.text_use_laser_range),
               "the reading's range is the laser's along its bearing in the scan nearest in time to the reading "
               "(`PlateRangeAlongBearing`, sensors/plate_range.h: the mapping's rule too)"),
      Param<O>("text_range_max_bearing_error_rad", DOORPLATE_PARAM_FIELD(session.plate_range.beam_window_rad),
               "the range is the median of the echoes within this of the bearing", r::Positive()),
      Param<O>("text_range_occluded_margin_m", DOORPLATE_PARAM_FIELD(session.plate_range.occluded_margin_m),
               "when that median is this much shorter than the wall line around the bearing, someone stood "
               "before the plate and the wall's range is taken; 0: off",
               r::NonNegative()),
      Param<O>("text_range_max_scan_age_s", DOORPLATE_PARAM_FIELD(session.text_range_max_scan_age_s),
               "and that scan must be this close in time to the reading (a laser outage gives no range)",
               r::Positive()),
      Param<O>("converged_cluster_weight", F(filter.converged_cluster_weight),
               "`~state` converged: the heaviest cluster's weight share", unit_open_low),
      Param<O>("converged_stddev_m", F(filter.converged_stddev_m), "... and its position spread", r::Positive()),
      Param<O>("converged_heading_stddev_rad", F(filter.converged_heading_stddev_rad), "... and its heading spread",
               r::Positive()),
      Param<O>("converge_after_plate", F(filter.converge_after_plate),
               "after global localization with text, `~state` converged also waits for a used plate reading "
               "(scans alone cannot tell a symmetric floor's twin places apart)"),
      Param<O>("lost_likelihood_ratio", F(filter.lost_likelihood_ratio),
               "`~state` lost below this w_fast / w_slow; random injection starts below it", unit_open_low),
  };
#undef F
  return table;
}

TextAmclNodeOptions TextAmclOptionsFrom(const ParamSource& source) {
  O o;
  ApplyParamTable(TextAmclParamTable(), source, &o);
  CheckTextAmclOptions(o, source);
  o.building = LoadLocalizerBuilding(o, source);
  return o;
}

void CheckTextAmclOptions(const TextAmclNodeOptions& o, const ParamSource& source) {
  const ParamTable<O>& table = TextAmclParamTable();
  // Node-level rules (the core takes one beam selection and one frame-free session).
  const BeamSelectionOptions& beams = o.session.setup.likelihood_field.beams;
  if (beams.laser_min_range_m > 0.0 && beams.laser_max_range_m > 0.0 &&
      !(beams.laser_max_range_m > beams.laser_min_range_m)) {
    throw ParameterError(source.Resolve("laser_max_range") + " must be > laser_min_range, got " +
                         FormatParamValue(beams.laser_max_range_m));
  }
  if (o.odom_frame_id == o.base_frame_id || o.odom_frame_id == o.global_frame_id) {
    throw ParameterError(source.Resolve("odom_frame_id") + " must be different from base_frame_id and " +
                         "global_frame_id, got " + o.odom_frame_id);
  }
  // The whole set against the core: a session on a small closed room with one plate.
  CheckWithCore(table, o, source, [&o] {
    OccupancyGrid room(20, 20, 0.1, Pose2D{}, OccupancyGrid::kFree);
    for (int i = 0; i < 20; ++i) {
      room.At(i, 0) = room.At(i, 19) = room.At(0, i) = room.At(19, i) = OccupancyGrid::kOccupied;
    }
    auto plates = std::make_shared<TextMap>();
    plates->landmarks.push_back({"101", Pose2D{1.0, 0.1, M_PI / 2}, 1.5, "south", 0, 0.0});
    TextAmclSessionOptions session = o.session;
    session.start_with_global_localization = false;
    session.initial_pose = Pose2D{1.0, 1.0, 0.0};  // inside the room, whatever the map the user's pose is for
    (void)TextAmclSession(session, room, plates);
    ValidateFloorBeliefOptions(o.floor_belief);
  });
}

TextAmclNodeOptions LoadTextAmclOptions(const ros::NodeHandle& nh) { return TextAmclOptionsFrom(RosParamSource(nh)); }

}  // namespace doorplate_localization
