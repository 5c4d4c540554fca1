#include "doorplate_localization/ros/slam_conversions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <Eigen/Dense>
#include <tf2/LinearMath/Vector3.h>

#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/ros/diagnostic_values.h"
#include "doorplate_localization/ros/scan_conversions.h"
#include "doorplate_localization/ros/text_detection_conversions.h"

namespace doorplate_localization {
namespace {

// base_link in odom from tf; "" or the problem (a non-finite transform).
std::string OdometryPose(const geometry_msgs::Transform& odom_to_base, Pose2D* pose) {
  try {
    *pose = ToPose2D(odom_to_base);
  } catch (const std::invalid_argument& e) {
    return std::string("odom -> base_link: ") + e.what();
  }
  return "";
}

}  // namespace

std::string ToLaserMounting(const geometry_msgs::Transform& base_to_laser, LaserMounting* mounting) {
  Pose2D pose;
  try {
    pose = ToPose2D(base_to_laser);
  } catch (const std::invalid_argument& e) {
    return std::string("base_link -> laser: ") + e.what();
  }
  const tf2::Vector3 z = ChildAxisInParent(base_to_laser.rotation, tf2::Vector3(0, 0, 1));
  if (std::fabs(z.z()) < std::cos(8.0 * M_PI / 180.0)) {
    std::ostringstream problem;
    problem << "the laser's scan plane is tilted " << std::acos(std::min(1.0, std::fabs(z.z()))) * 180.0 / M_PI
            << " deg from the floor plane (at most 8 deg)";
    return problem.str();
  }
  mounting->upside_down = z.z() < 0.0;
  mounting->pose = pose;
  return "";
}

std::string ToMappingScan(const sensor_msgs::LaserScan& msg, const LaserMounting& mounting, double max_range_m,
                          int min_valid_beams, LaserScan* out) {
  std::string problem = ValidateScan(msg);
  if (!problem.empty()) return problem;
  // Drivers disagree on whether angle_max is the last beam's angle: allow one beam either way.
  const double span_beams = (static_cast<double>(msg.angle_max) - msg.angle_min) / msg.angle_increment + 1.0;
  if (std::isfinite(span_beams) && std::fabs(span_beams - static_cast<double>(msg.ranges.size())) > 1.5) {
    std::ostringstream p;
    p << msg.ranges.size() << " ranges, but angle_min " << msg.angle_min << " .. angle_max " << msg.angle_max
      << " at increment " << msg.angle_increment << " make " << std::lround(span_beams) << " beams";
    return p.str();
  }
  const float no_echo_from = max_range_m > 0.0 ? static_cast<float>(max_range_m) : msg.range_max;
  LaserScan scan;
  scan.ranges_m.resize(msg.ranges.size());
  int valid = 0;
  for (std::size_t i = 0; i < msg.ranges.size(); ++i) {
    const float r = msg.ranges[i];
    float& to = scan.ranges_m[i];
    if (std::isnan(r) || r < msg.range_min) {  // NaN, -inf (too close), below range_min
      to = std::numeric_limits<float>::quiet_NaN();
    } else if (r >= no_echo_from || r > msg.range_max) {  // +inf or beyond what the device measures
      to = std::numeric_limits<float>::infinity();
    } else {
      to = r;
      ++valid;
    }
  }
  if (valid < min_valid_beams) {
    std::ostringstream p;
    p << "only " << valid << " of " << msg.ranges.size() << " beams are finite returns (at least "
      << min_valid_beams << " needed)";
    return p.str();
  }
  const double sign = mounting.upside_down ? -1.0 : 1.0;
  scan.angle_min_rad = sign * msg.angle_min;
  scan.angle_increment_rad = sign * msg.angle_increment;
  scan.min_range_m = msg.range_min;
  scan.laser_pose = mounting.pose;
  *out = std::move(scan);
  return "";
}

std::optional<PlateReading> ToPlateSighting(const TextDetection& msg, const CameraAxis& camera,
                                            std::string* why_not) {
  std::string problem;
  if (!msg.crossed_center) {
    problem = "not at the image-centre crossing";
  } else if (msg.text.empty()) {
    problem = "text is empty";
  } else if (msg.text.size() > limits::kMaxPlateTextBytes) {  // issue 18: a 1 MB text was logged whole
    problem = "text: " + std::to_string(msg.text.size()) + " bytes, more than the limit of " +
              std::to_string(limits::kMaxPlateTextBytes) + " (limits::kMaxPlateTextBytes)";
  } else {
    problem = ValidateTextDetection(msg);
  }
  std::optional<PlateReading> reading;
  if (problem.empty()) {
    reading = PlateReadingFromCamera(msg.text, msg.confidence, camera, msg.bearing_rad);
    problem = ValidatePlateReading(*reading);  // what the mapping session accepts (e.g. a text of separators only)
  }
  if (!problem.empty()) {
    if (why_not != nullptr) *why_not = problem;
    return std::nullopt;
  }
  return reading;
}

std::string PrepareSlamScan(const sensor_msgs::LaserScan& msg, const TransformLookup& lookup,
                            const SlamInputFrames& frames, LaserScan* scan, Pose2D* odometry_pose) {
  std::string problem = ValidateScan(msg);  // before any lookup: an empty frame_id is no tf question
  if (!problem.empty()) return problem;
  const auto base_to_laser = lookup(frames.base_frame, msg.header.frame_id, msg.header.stamp, &problem);
  if (!base_to_laser) return problem;
  LaserMounting mounting;
  problem = ToLaserMounting(*base_to_laser, &mounting);
  if (!problem.empty()) return problem;
  const auto odom_to_base = lookup(frames.odom_frame, frames.base_frame, msg.header.stamp, &problem);
  if (!odom_to_base) return problem;
  Pose2D odom_pose;
  problem = OdometryPose(*odom_to_base, &odom_pose);
  if (!problem.empty()) return problem;
  problem = ToMappingScan(msg, mounting, frames.max_range_m, frames.min_valid_beams, scan);
  if (!problem.empty()) return problem;
  *odometry_pose = odom_pose;
  return "";
}

std::string PrepareSlamSightings(const TextDetectionArray& msg, const TransformLookup& lookup,
                                 const SlamInputFrames& frames, std::vector<PlateReading>* sightings,
                                 Pose2D* odometry_pose, std::vector<std::string>* rejected) {
  sightings->clear();
  if (msg.header.frame_id.empty()) return "header.frame_id is empty";
  std::string problem;
  const auto base_to_camera = lookup(frames.base_frame, msg.header.frame_id, msg.header.stamp, &problem);
  if (!base_to_camera) return problem;
  CameraAxis camera;
  problem = ToCameraAxis(*base_to_camera, &camera);
  if (!problem.empty()) return problem;
  const auto odom_to_base = lookup(frames.odom_frame, frames.base_frame, msg.header.stamp, &problem);
  if (!odom_to_base) return problem;
  problem = OdometryPose(*odom_to_base, odometry_pose);
  if (!problem.empty()) return problem;
  for (const TextDetection& detection : msg.detections) {
    std::string why_not;
    if (auto sighting = ToPlateSighting(detection, camera, &why_not)) {
      sightings->push_back(std::move(*sighting));
    } else if (IsPlateReport(detection) && rejected != nullptr) {
      rejected->push_back("'" + limits::TruncateForLog(detection.text) + "': " + why_not);
    }
  }
  return "";
}

double PoseEntropy(const std::vector<SlamParticle>& particles) {
  if (particles.empty()) return 0.0;
  double max_log = -std::numeric_limits<double>::infinity();
  for (const SlamParticle& p : particles) max_log = std::max(max_log, p.log_weight);
  std::vector<double> w(particles.size());
  double total = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) total += w[i] = std::exp(particles[i].log_weight - max_log);
  if (!(total > 0.0) || !std::isfinite(total)) {  // all log-weights -inf or NaN: equal weights
    std::fill(w.begin(), w.end(), 1.0);
    total = static_cast<double>(w.size());
  }
  // Heading: relative to the first particle's, so the mean does not straddle ±pi.
  const double theta0 = particles.front().pose.theta_rad;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> v(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Pose2D& p = particles[i].pose;
    v[i] = {p.x_m, p.y_m, NormalizeAngle(p.theta_rad - theta0)};
    mean += (w[i] / total) * v[i];
  }
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Eigen::Vector3d d = v[i] - mean;
    cov += (w[i] / total) * d * d.transpose();
  }
  cov += 1e-12 * Eigen::Matrix3d::Identity();  // keeps a single pose finite
  return 0.5 * std::log(std::pow(2.0 * M_PI * M_E, 3) * cov.determinant());
}

std::string MapperStateText(const MapperHealth& h) {
  if (!h.error.empty()) return "error: " + limits::TruncateForLog(h.error, 200);
  if (h.scan_age_s < 0.0 || (h.scan_timeout_s > 0.0 && h.scan_age_s > h.scan_timeout_s)) return "waiting_for_scan";
  return "mapping";
}

diagnostic_msgs::DiagnosticStatus ToMapperDiagnosticStatus(const MapperHealth& h, const std::string& name,
                                                           const std::string& hardware_id) {
  diagnostic_msgs::DiagnosticStatus d;
  d.name = name;
  d.hardware_id = hardware_id;
  const std::string state = MapperStateText(h);
  d.level = state == "mapping"                 ? diagnostic_msgs::DiagnosticStatus::OK
            : state.rfind("error", 0) == 0     ? diagnostic_msgs::DiagnosticStatus::ERROR
                                               : diagnostic_msgs::DiagnosticStatus::WARN;
  d.message = state;
  if (!h.last_drop.empty()) d.message += "; last scan dropped: " + limits::TruncateForLog(h.last_drop, 200);
  const auto add = [&d](const std::string& key, const std::string& value) { AddDiagnosticValue(&d, key, value); };
  const auto number = FixedDecimals;
  add("state", state);
  add("scan rate (Hz)", number(h.scan_rate_hz, 1));
  add("last scan age (s)", h.scan_age_s < 0.0 ? "none yet" : number(h.scan_age_s, 2));
  add("scans processed", std::to_string(h.scans_processed));
  add("scans dropped", std::to_string(h.scans_dropped));
  add("last scan dropped", h.last_drop.empty() ? "none" : limits::TruncateForLog(h.last_drop, 200));
  add("particles", std::to_string(h.particles));
  add("effective particles", number(h.neff, 1));
  add("landmarks", std::to_string(h.landmarks));
  add("plates used", std::to_string(h.plates_used));
  add("plates ignored", std::to_string(h.plates_ignored));
  add("scans waiting for the camera", h.scans_waiting_for_camera < 0 ? "off" : std::to_string(h.scans_waiting_for_camera));
  add("camera waits run out", std::to_string(h.camera_waits_expired));
  add("plates later than the camera wait", std::to_string(h.plates_late));
  add("back-end solves", std::to_string(h.solves));
  add("last solve (s)", number(h.last_solve_s, 2));
  add("solves deferred (solve share)", std::to_string(h.solves_deferred));
  add("back-end nodes", std::to_string(h.back_end_nodes));
  add("nodes on mapped ground (scan not kept)", std::to_string(h.nodes_on_mapped_ground));
  add("map", h.map.empty() ? "none yet" : h.map);
  add("last error", h.error.empty() ? "none" : limits::TruncateForLog(h.error, 200));
  return d;
}

}  // namespace doorplate_localization
