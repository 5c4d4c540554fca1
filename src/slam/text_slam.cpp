#include "doorplate_localization/slam/text_slam.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

constexpr double kPi = 3.14159265358979323846;

const TextSlamOptions& Validated(const TextSlamOptions& o) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("TextSlamOptions." + what); };
  if (!(o.min_confidence >= 0 && o.min_confidence <= 1)) fail("min_confidence: must be in [0, 1]");
  if (!(o.min_plate_range_m >= 0) || !(o.max_plate_range_m > o.min_plate_range_m)) {
    fail("min_plate_range_m/max_plate_range_m: need 0 <= min < max");
  }
  try {
    ValidatePlateRangeOptions(o.plate_range);
  } catch (const std::invalid_argument& e) {
    fail(std::string("plate_range: ") + e.what());
  }
  if (!(o.plate_sigma_m > 0)) fail("plate_sigma_m: must be > 0");
  if (!(o.association_radius_m > 0)) fail("association_radius_m: must be > 0");
  if (!(o.text_likelihood_gain >= 0)) fail("text_likelihood_gain: must be >= 0");
  if (!(o.max_odometry_gap_m > 0)) fail("max_odometry_gap_m: must be > 0");
  try {
    RoomIdGrammar check(o.room_pattern);
  } catch (const std::invalid_argument& e) {
    fail(std::string("room_pattern: ") + e.what());
  }
  return o;
}

// `caller` names the method in the message ("TextSlam::AddScan").
void ValidatePose(const Pose2D& p, const char* caller) {
  if (!std::isfinite(p.x_m) || !std::isfinite(p.y_m) || !std::isfinite(p.theta_rad)) {
    throw std::invalid_argument(std::string(caller) + ": odometry_pose must be finite");
  }
}

// The back end's options with the plate noise of the text options (one value for both).
SlamBackEndOptions BackEndOptions(const TextSlamOptions& o) {
  SlamBackEndOptions b = o.back_end;
  b.plate_sigma_m = o.plate_sigma_m;
  return b;
}

}  // namespace

RbpfSlamOptions DefaultTextSlamLaserOptions() {
  RbpfSlamOptions options;
  options.degenerate_min_points = 10.0;
  return options;
}


TextSlam::TextSlam(const TextSlamOptions& options)
    : options_(Validated(options)),
      room_grammar_(options.room_pattern),
      slam_(options.slam),
      back_end_(BackEndOptions(options)),
      node_fusion_(options.back_end.node_fusion) {}

bool TextSlam::AddScan(const LaserScan& scan, const Pose2D& odometry_pose, int scan_index, bool force_update) {
  ValidatePose(odometry_pose, "TextSlam::AddScan");
  const int degenerate_before = slam_.stats().degenerate_scans;
  const bool processed = slam_.AddScan(scan, odometry_pose, scan_index, force_update);
  // Node points fused over neighbouring scans (back_end.node_fusion): every scan is remembered; a node takes
  // its points fused with the scans before it, and again, once the scans after it are in (or the next node
  // or a solve comes first), fused with those too.
  const bool fuse = options_.back_end.enabled && node_fusion_.enabled();
  const long scan_id = fuse ? node_fusion_.Add(slam_.MatchPoints(scan), odometry_pose) : -1;
  if (node_awaiting_scans_ && node_fusion_.Complete(node_awaiting_scans_->second)) FinishNodeAwaitingScans();
  if (processed && options_.back_end.enabled) {
    FinishNodeAwaitingScans();  // before the new node: AddNode may align with it
    const bool pinned = slam_.stats().degenerate_scans == degenerate_before;
    std::vector<Vec2> points = fuse ? node_fusion_.Fuse(scan_id) : slam_.MatchPoints(scan);
    if (back_end_.AddNode(std::move(points), odometry_pose, slam_.BestParticle().pose, pinned)) {
      node_scans_.emplace_back(back_end_.num_nodes() - 1, scan);
      if (fuse && !node_fusion_.Complete(scan_id)) node_awaiting_scans_.emplace(back_end_.num_nodes() - 1, scan_id);
    }
  }
  return processed;
}

void TextSlam::FinishNodeAwaitingScans() {
  if (!node_awaiting_scans_) return;
  const auto [node, scan_id] = *node_awaiting_scans_;
  node_awaiting_scans_.reset();
  // (Always remembered: AddScan finishes the node as soon as its scans_after are in, before it is forgotten.)
  if (node_fusion_.Remembered(scan_id)) back_end_.ReplaceNodePoints(node, node_fusion_.Fuse(scan_id));
}

void TextSlam::FinishInput() { FinishNodeAwaitingScans(); }

void TextSlam::Solve() {
  if (!options_.back_end.enabled || back_end_.num_nodes() == 0) return;
  std::vector<Pose2D> history;
  if (options_.back_end.front_end_history_sigma_m > 0) {
    for (const TrajectoryPoint& p : slam_.MeanTrajectory()) history.push_back(p.pose);
  }
  solved_ = back_end_.Optimize(history, node_awaiting_scans_ ? node_awaiting_scans_->first : -1);
}

int TextSlam::nodes_since_solve() const {
  if (!options_.back_end.enabled) return 0;
  return back_end_.num_nodes() - (solved_ ? static_cast<int>(solved_->poses.size()) : 0);
}

std::vector<Pose2D> TextSlam::Trajectory() const {
  std::vector<Pose2D> poses;
  if (solved_ && !solved_->poses.empty()) {
    poses = solved_->poses;
    const int last = static_cast<int>(poses.size()) - 1;
    for (int node = last + 1; node < back_end_.num_nodes(); ++node) {
      poses.push_back(solved_->poses.back().Compose(back_end_.NodeOdometry(last).Between(back_end_.NodeOdometry(node))));
    }
    return poses;
  }
  if (!slam_.started()) return poses;
  for (const TrajectoryPoint& p : slam_.BestTrajectory()) poses.push_back(p.pose);
  return poses;
}

TextSlamPlateResult TextSlam::AddPlate(const PlateReading& sighting, const Pose2D& odometry_pose) {
  if (const std::string bad = ValidatePlateReading(sighting); !bad.empty()) {
    throw std::invalid_argument("TextSlam::AddPlate: " + bad);
  }
  ValidatePose(odometry_pose, "TextSlam::AddPlate");
  TextSlamPlateResult result;
  if (!room_grammar_.Accepts(sighting.text)) {
    result.outcome = PlateOutcome::kNotARoomId;
    result.reason = "'" + sighting.text + "' does not fit room_pattern '" + options_.room_pattern + "'";
    return result;
  }
  if (!slam_.started()) {
    result.outcome = PlateOutcome::kNoScanYet;
    result.reason = "no scan processed yet";
    return result;
  }
  if (sighting.confidence < options_.min_confidence) {
    result.outcome = PlateOutcome::kLowConfidence;
    result.reason = "confidence " + std::to_string(sighting.confidence) + " < min_confidence";
    return result;
  }
  const Pose2D since_scan = slam_.LastProcessedOdometry().Between(odometry_pose);
  if (std::hypot(since_scan.x_m, since_scan.y_m) > options_.max_odometry_gap_m) {
    result.outcome = PlateOutcome::kTooFarFromLastScan;
    result.reason = "odometry moved too far since the last processed scan";
    return result;
  }
  const std::optional<double> range = sighting.range_m;
  if (!range) {
    result.outcome = PlateOutcome::kNoRange;
    result.reason = "no range (none given, no usable beam along the bearing)";
    return result;
  }
  result.range_m = *range;
  if (*range < options_.min_plate_range_m || *range > options_.max_plate_range_m) {
    result.outcome = PlateOutcome::kRangeOutOfBounds;
    result.reason = "range " + std::to_string(*range) + " m outside [min_plate_range_m, max_plate_range_m]";
    return result;
  }
  // The plate in base_link at the reading, and the wall normal it faces (towards the robot's side).
  const int side = sighting.bearing_rad >= 0 ? 1 : -1;
  const Vec2 local{*range * std::cos(sighting.bearing_rad), *range * std::sin(sighting.bearing_rad)};
  const double local_yaw = side > 0 ? -kPi / 2 : kPi / 2;
  const auto measure = [&](const SlamParticle& p, double* yaw) {
    const Pose2D at_reading = p.pose.Compose(since_scan);
    *yaw = NormalizeAngle(at_reading.theta_rad + local_yaw);
    return at_reading.TransformPoint(local);
  };
  const auto associate = [&](const SlamLandmarks* list, Vec2 z, double yaw) {
    int found = -1;
    double best = options_.association_radius_m;
    if (!list) return found;
    for (int i = 0; i < static_cast<int>(list->size()); ++i) {
      const SlamLandmark& l = (*list)[i];
      if (!SameRoom(l.text, sighting.text) || std::cos(l.yaw_rad - yaw) < 0.5) continue;
      const double d = Norm(l.position - z);
      if (d < best) best = d, found = i;
    }
    return found;
  };
  // Association on the best particle decides which landmark id this reading is, for every particle.
  const SlamParticle& best = slam_.BestParticle();
  double best_yaw = 0.0;
  const Vec2 best_z = measure(best, &best_yaw);
  const int best_slot = associate(best.landmarks.get(), best_z, best_yaw);
  const int id = best_slot >= 0 ? (*best.landmarks)[best_slot].id : next_landmark_id_;
  const bool is_new = best_slot < 0;
  if (is_new) {
    ++next_landmark_id_;
    first_reading_in_odom_.push_back(odometry_pose.TransformPoint(local));
  }
  const double sigma2 = options_.plate_sigma_m * options_.plate_sigma_m;
  const double cap2 = options_.association_radius_m * options_.association_radius_m;
  slam_.UpdateLandmarksAndReweight([&](const SlamParticle& p, SlamLandmarksHandle* handle) {
    double yaw = 0.0;
    const Vec2 z = measure(p, &yaw);
    auto next = std::make_shared<SlamLandmarks>(*handle ? **handle : SlamLandmarks{});
    auto it = std::find_if(next->begin(), next->end(), [&](const SlamLandmark& l) { return l.id == id; });
    double log_likelihood = 0.0;
    if (it == next->end()) {
      next->push_back({id, sighting.text, z, yaw, side, 1});
    } else {
      const double n = it->observations;
      const double d2 = std::min(std::pow(Norm(it->position - z), 2), cap2);
      log_likelihood = -options_.text_likelihood_gain * d2 / (2.0 * sigma2 * (1.0 + 1.0 / n));
      it->position = (1.0 / (n + 1)) * (n * it->position + z);
      it->observations += 1;
    }
    *handle = std::move(next);
    return log_likelihood;
  });
  if (options_.back_end.enabled && back_end_.num_nodes() > 0) {
    back_end_.AddPlateReading(id, back_end_.num_nodes() - 1, since_scan.TransformPoint(local));
  }
  result.outcome = is_new ? PlateOutcome::kNewLandmark : PlateOutcome::kReobserved;
  result.landmark_index = id;
  result.reason = is_new ? "new landmark" : "re-observed landmark";
  return result;
}

Pose2D TextSlam::BestPose() const { return slam_.BestParticle().pose; }

Pose2D TextSlam::EstimatedPose(const Pose2D& odometry_pose) const {
  if (solved_ && !solved_->poses.empty()) {
    const int node = static_cast<int>(solved_->poses.size()) - 1;
    return solved_->poses.back().Compose(back_end_.NodeOdometry(node).Between(odometry_pose));
  }
  return BestPose().Compose(slam_.LastProcessedOdometry().Between(odometry_pose));
}

std::vector<SlamLandmark> TextSlam::BestLandmarks() const {
  if (!slam_.started()) return {};
  const SlamLandmarksHandle& h = slam_.BestParticle().landmarks;
  std::vector<SlamLandmark> list = h ? *h : SlamLandmarks{};
  if (solved_) {
    for (SlamLandmark& l : list) {
      if (l.id < static_cast<int>(solved_->plates.size()) && solved_->plates[l.id]) l.position = *solved_->plates[l.id];
    }
  }
  std::sort(list.begin(), list.end(), [](const SlamLandmark& a, const SlamLandmark& b) { return a.id < b.id; });
  return list;
}

OccupancyGrid TextSlam::BuildOccupancyGrid() const {
  if (!slam_.started()) throw std::logic_error("TextSlam::BuildOccupancyGrid: no scan was added yet");
  if (!solved_) return slam_.BestParticle().map.ToOccupancyGrid();
  const std::vector<Pose2D> poses = Trajectory();
  TiledGrid grid(options_.slam.grid);
  for (const auto& [node, scan] : node_scans_) {
    if (node < static_cast<int>(poses.size())) slam_.IntegrateScanInto(&grid, scan, poses[node]);
  }
  return grid.ToOccupancyGrid();
}

}  // namespace doorplate_localization
