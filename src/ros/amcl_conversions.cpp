#include "doorplate_localization/ros/amcl_conversions.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>

#include <Eigen/Eigenvalues>

#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/ros/diagnostic_values.h"
#include "doorplate_localization/ros/text_detection_conversions.h"

namespace doorplate_localization {

LaserScan ToLocalizationScan(const sensor_msgs::LaserScan& msg, const Pose2D& laser_in_base) {
  LaserScan scan;
  scan.angle_min_rad = msg.angle_min;
  scan.angle_increment_rad = msg.angle_increment;
  scan.min_range_m = msg.range_min;
  scan.max_range_m = msg.range_max;
  scan.ranges_m = msg.ranges;
  scan.laser_pose = laser_in_base;
  return scan;
}

std::vector<PlateReading> ToPlateReadings(const TextDetectionArray& msg, const CameraAxis& camera,
                                          std::vector<std::string>* problems) {
  std::vector<PlateReading> readings;
  for (const TextDetection& d : msg.detections) {
    if (!IsPlateReport(d)) continue;
    const PlateReading r = PlateReadingFromCamera(d.text, d.confidence, camera, d.bearing_rad);
    const std::string problem = ValidatePlateReading(r);
    if (!problem.empty()) {
      if (problems != nullptr) problems->push_back("detection '" + limits::TruncateForLog(d.text) + "': " + problem);
      continue;
    }
    readings.push_back(r);
  }
  return readings;
}

std::string FromInitialPoseMsg(const geometry_msgs::PoseWithCovarianceStamped& msg, const std::string& global_frame,
                               Pose2D* mean, Eigen::Matrix3d* covariance) {
  if (!msg.header.frame_id.empty() && msg.header.frame_id != global_frame) {
    return "header.frame_id is '" + msg.header.frame_id + "', expected '" + global_frame + "'";
  }
  const geometry_msgs::Pose& p = msg.pose.pose;
  if (!IsFinitePose(p)) return "pose must be finite";
  // An initial pose 3e38 m away is refused as a map origin there would be (limits.h; a fuzzing find).
  for (const auto& [field, value] : {std::pair{"x", p.position.x}, std::pair{"y", p.position.y}}) {
    const std::string bad = limits::CheckCoordinate(value);
    if (!bad.empty()) return std::string("pose.position.") + field + ": " + bad;
  }
  const double norm = QuaternionNorm(p.orientation);
  if (std::fabs(norm - 1.0) > 0.01) {
    std::ostringstream out;
    out << "pose.orientation must be a unit quaternion, got norm " << norm;
    return out.str();
  }
  static constexpr int kIndex[3] = {0, 1, 5};  // x, y, yaw in the 6x6 row-major covariance
  Eigen::Matrix3d c;
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) c(r, k) = msg.pose.covariance[kIndex[r] * 6 + kIndex[k]];
  }
  if (!c.allFinite()) return "pose.covariance must be finite";
  if ((c - c.transpose()).cwiseAbs().maxCoeff() > 1e-9 * std::max(1.0, c.cwiseAbs().maxCoeff())) {
    return "pose.covariance of x, y, yaw must be symmetric";
  }
  const double min_eigenvalue = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(c).eigenvalues().minCoeff();
  if (min_eigenvalue < -1e-9) {
    std::ostringstream out;
    out << "pose.covariance of x, y, yaw must be positive semi-definite, smallest eigenvalue " << min_eigenvalue;
    return out.str();
  }
  *mean = ToPose2D(p);
  // Symmetric within the tolerance above, handed on exactly symmetric: TextAmcl::Initialize's own check is
  // relative to the matrix's norm and refused 2e-26 off the diagonal of an otherwise zero matrix (a
  // fuzzing find: the nodelet accepted an initial pose its filter then refused).
  *covariance = 0.5 * c + 0.5 * c.transpose();  // (c + cᵀ) / 2 would overflow for entries near 1e308
  return "";
}

geometry_msgs::PoseWithCovarianceStamped ToAmclPoseMsg(const PoseEstimate& estimate, const std::string& frame_id,
                                                       const ros::Time& stamp) {
  geometry_msgs::PoseWithCovarianceStamped msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.pose.pose = ToPoseMsg(estimate.pose);
  static constexpr int kIndex[3] = {0, 1, 5};
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) msg.pose.covariance[kIndex[r] * 6 + kIndex[k]] = estimate.covariance(r, k);
  }
  return msg;
}

geometry_msgs::PoseArray ToParticleCloudMsg(const std::vector<Particle>& particles, const std::string& frame_id,
                                            const ros::Time& stamp) {
  geometry_msgs::PoseArray msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.poses.reserve(particles.size());
  for (const Particle& p : particles) msg.poses.push_back(ToPoseMsg(p.pose));
  return msg;
}

std::string StateText(LocalizationState state, LostReason reason) {
  if (state != LocalizationState::kLost) return ToString(state);
  return std::string(ToString(state)) + ": " + ToString(reason);
}

std::string NodeStateText(const LocalizerHealth& h) {
  if (!h.map_in_force) return "waiting_for_map";
  if (!h.error.empty()) return "error: " + limits::TruncateForLog(h.error, 200);
  if (h.scan_age_s < 0.0 || (h.scan_timeout_s > 0.0 && h.scan_age_s > h.scan_timeout_s)) return "waiting_for_scan";
  return StateText(h.status.state, h.status.lost_reason);
}

diagnostic_msgs::DiagnosticStatus ToDiagnosticStatus(const LocalizerHealth& h, const std::string& name,
                                                     const std::string& hardware_id) {
  diagnostic_msgs::DiagnosticStatus d;
  d.name = name;
  d.hardware_id = hardware_id;
  const std::string state = NodeStateText(h);
  if (state.rfind("error", 0) == 0) {
    d.level = diagnostic_msgs::DiagnosticStatus::ERROR;
  } else if (state == "converged" || state == "tracking") {
    d.level = diagnostic_msgs::DiagnosticStatus::OK;
  } else {
    d.level = diagnostic_msgs::DiagnosticStatus::WARN;  // waiting_for_map, waiting_for_scan, lost
  }
  d.message = state;
  if (h.global_localization_queued) d.message += " (global_localization queued until a map is in force)";
  const auto add = [&d](const std::string& key, const std::string& value) { AddDiagnosticValue(&d, key, value); };
  const auto number = FixedDecimals;
  add("state", state);
  add("map in force", h.map_in_force ? h.map : "none");
  add("global localization queued", h.global_localization_queued ? "yes" : "no");
  add("scan rate (Hz)", number(h.scan_rate_hz, 1));
  add("last scan age (s)", h.scan_age_s < 0.0 ? "none since the (re)start" : number(h.scan_age_s, 2));
  add("scans dropped", std::to_string(h.scans_dropped));
  add("last scan dropped", h.last_scan_dropped.empty() ? "none" : limits::TruncateForLog(h.last_scan_dropped, 200));
  add("odometry tf age (s)", h.tf_age_s < 0.0 ? "no transform" : number(h.tf_age_s, 2));
  add("particles", std::to_string(h.status.particle_count));
  add("best cluster weight", number(h.status.best_cluster_weight, 3));
  add("position stddev (m)", number(h.status.position_stddev_m, 3));
  add("plates weighed", std::to_string(h.plates_weighed));
  add("plates used", std::to_string(h.plates_used));
  add("unknown room readings", std::to_string(h.unknown_room_readings));
  add("last error", h.error.empty() ? "none" : limits::TruncateForLog(h.error, 200));
  return d;
}

std::string DescribePlateOutcome(const PlateReadingOutcome& outcome) {
  const PlateReading& r = outcome.reading;
  const std::string text = limits::TruncateForLog(r.text);
  std::ostringstream out;
  out.setf(std::ios::fixed);
  switch (outcome.disposition) {
    case PlateDisposition::kWeighed: {
      const PlateUpdateResult& u = outcome.result;
      if (!u.used) {
        out << "plate '" << text << "' not used: " << u.ignored_reason;
        break;
      }
      out.precision(3);
      out << "plate '" << text << "' at " << r.bearing_rad << " rad, range ";
      if (r.range_m) out << std::setprecision(2) << *r.range_m << " m"; else out << "none";
      out << std::setprecision(2) << ": explained " << u.explained_ratio << " (best cluster "
          << u.best_cluster_explained_ratio << ")" << (u.contradicted_estimate ? ", CONTRADICTS the estimate" : "")
          << ", " << u.reseeded_particles << " reseeded";
      break;
    }
    case PlateDisposition::kUnknownRoomFirst:
    case PlateDisposition::kUnknownRoom:
      out << "room '" << text << "' is not in the text map";
      break;
    default:
      out.precision(3);
      out << "plate '" << text << "' at " << outcome.stamp_s << " s ignored (" << ToString(outcome.disposition)
          << ")" << (outcome.detail.empty() ? "" : ": ") << outcome.detail;
  }
  return out.str();
}

}  // namespace doorplate_localization
