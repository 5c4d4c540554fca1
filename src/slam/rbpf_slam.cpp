#include "doorplate_localization/slam/rbpf_slam.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/slam/minor_axis.h"

namespace doorplate_localization {
namespace {

const RbpfSlamOptions& Validated(const RbpfSlamOptions& o) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("RbpfSlamOptions." + what); };
  if (o.num_particles < 1 || o.num_particles > limits::kMaxParticles) {  // 1e9 was std::bad_alloc (issue 18)
    fail("num_particles: must be in [1, " + std::to_string(limits::kMaxParticles) + "] (limits::kMaxParticles), got " +
         std::to_string(o.num_particles));
  }
  if (!(o.linear_update_m >= 0) || !(o.angular_update_rad >= 0)) fail("linear/angular_update: must be >= 0");
  if (!(o.resample_neff_ratio >= 0 && o.resample_neff_ratio <= 1)) fail("resample_neff_ratio: must be in [0, 1]");
  if (!(o.likelihood_gain > 0)) fail("likelihood_gain: must be > 0");
  if (!(o.max_usable_range_m > 0)) fail("max_usable_range_m: must be > 0");
  if (!(o.no_return_clear_range_m >= 0)) fail("no_return_clear_range_m: must be >= 0");
  if (o.max_match_points < 3) fail("max_match_points: must be >= 3");
  if (!(o.mean_trajectory_radius_m >= 0)) fail("mean_trajectory_radius_m: must be >= 0");
  if (!(o.degenerate_min_points >= 0)) fail("degenerate_min_points: must be >= 0");
  if (!(o.max_match_range_m >= 0)) fail("max_match_range_m: must be >= 0");
  return o;
}

void ValidateScan(const LaserScan& scan) {
  if (scan.ranges_m.empty() || !std::isfinite(scan.angle_increment_rad) || scan.angle_increment_rad == 0.0 ||
      !std::isfinite(scan.angle_min_rad)) {
    throw std::invalid_argument(
        "RbpfSlam: a scan needs ranges, a finite angle_min_rad and a finite, non-zero angle_increment_rad");
  }
}

// The scan's positional information Σ n nᵀ: its weakest direction (base_link) and eigenvalue (points). n: unit normal of the chord between the echoes 0.1-0.4 m before and after each
// echo along the scan (a shorter chord would turn 1 cm of range noise into a tilted normal).
double FindDegenerateAxis(const std::vector<Vec2>& ordered_hits, Vec2* axis) {
  constexpr double kMinChord = 0.1, kMaxChord = 0.4;
  const int n = static_cast<int>(ordered_hits.size());
  double sxx = 0, sxy = 0, syy = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2 p = ordered_hits[i];
    int lo = i - 1, hi = i + 1;
    while (lo >= 0 && Norm(ordered_hits[lo] - p) < kMinChord && Norm(ordered_hits[lo + 1] - ordered_hits[lo]) < kMinChord) --lo;
    while (hi < n && Norm(ordered_hits[hi] - p) < kMinChord && Norm(ordered_hits[hi - 1] - ordered_hits[hi]) < kMinChord) ++hi;
    if (lo < 0 || hi >= n) continue;
    const Vec2 a = ordered_hits[lo], b = ordered_hits[hi];
    if (Norm(a - p) < kMinChord || Norm(b - p) < kMinChord || Norm(a - p) > kMaxChord || Norm(b - p) > kMaxChord) continue;
    // Both halves must lie on one line (a corner is not a surface).
    const Vec2 u = (1.0 / Norm(b - a)) * (b - a);
    if (std::abs(Cross(u, p - a)) > 0.03) continue;
    sxx += u.y * u.y, sxy -= u.x * u.y, syy += u.x * u.x;  // n = (-u.y, u.x)
  }
  const MinorAxis weakest = MinorAxisOf(sxx, sxy, syy);
  *axis = weakest.axis;
  return weakest.eigenvalue;
}

}  // namespace

RbpfSlam::RbpfSlam(const RbpfSlamOptions& options)
    : options_(Validated(options)),
      motion_(options.motion),
      matcher_(options.matcher, options.grid),
      rng_(options.seed) {}

RbpfSlam::ScanPoints RbpfSlam::PrepareScan(const LaserScan& scan, bool match_only) const {
  ScanPoints points;
  points.origin = scan.laser_pose.Position();
  std::vector<Vec2> hits;
  const double usable = options_.max_usable_range_m;
  for (int i = 0; i < static_cast<int>(scan.ranges_m.size()); ++i) {
    const double r = scan.ranges_m[i];
    if (std::isnan(r) || r < scan.min_range_m) continue;
    const double a = scan.BeamAngle(i);
    const bool hit = r <= usable;
    const double d = hit ? r : std::isinf(r) ? std::min(usable, options_.no_return_clear_range_m) : usable;
    if (d <= 0.0 || (match_only && !hit)) continue;
    const Vec2 end = scan.laser_pose.TransformPoint({d * std::cos(a), d * std::sin(a)});
    if (!match_only) {
      const auto kind = hit             ? ScanPoints::BeamEnd::kHit
                        : std::isinf(r) ? ScanPoints::BeamEnd::kNoReturn
                                        : ScanPoints::BeamEnd::kCut;
      points.integrate.emplace_back(end, kind);
    }
    if (hit && (options_.max_match_range_m <= 0 || r <= options_.max_match_range_m)) hits.push_back(end);
  }
  if (options_.degenerate_min_points > 0 && !match_only) {
    const double weakest = FindDegenerateAxis(hits, &points.degenerate_axis);
    points.degenerate = weakest < options_.degenerate_min_points;
    // 0 below k = degenerate_min_points (odometry only along the axis), 1 above 2k (the whole correction:
    // an end wall in range constrains the match), linear in between.
    const double k = options_.degenerate_min_points;
    points.along_axis_gain = std::clamp((weakest - k) / k, 0.0, 1.0);
  }
  const std::size_t stride = (hits.size() + options_.max_match_points - 1) / options_.max_match_points;
  for (std::size_t k = 0; k < hits.size(); k += std::max<std::size_t>(stride, 1)) points.match.push_back(hits[k]);
  return points;
}

void RbpfSlam::Integrate(TiledGrid& map, const Pose2D& pose, const ScanPoints& points) const {
  const Vec2 origin = pose.TransformPoint(points.origin);
  // Beams with an echo first, so that a dropout between echoes of a wall not yet in the map stops at
  // the wall this very scan puts there.
  for (const auto& [end, kind] : points.integrate) {
    if (kind == ScanPoints::BeamEnd::kNoReturn) continue;
    map.IntegrateBeam(origin, pose.TransformPoint(end), kind == ScanPoints::BeamEnd::kHit);
  }
  for (const auto& [end, kind] : points.integrate) {
    if (kind == ScanPoints::BeamEnd::kNoReturn) map.IntegrateNoReturnBeam(origin, pose.TransformPoint(end));
  }
}

void RbpfSlam::IntegrateScanInto(TiledGrid* map, const LaserScan& scan, const Pose2D& pose) const {
  ValidateScan(scan);
  Integrate(*map, pose, PrepareScan(scan));
}

bool RbpfSlam::AddScan(const LaserScan& scan, const Pose2D& odometry_pose, int scan_index, bool force_update) {
  ValidateScan(scan);
  ++stats_.scans_seen;
  if (!started_) {
    const ScanPoints points = PrepareScan(scan);
    SlamParticle first{odometry_pose, 0.0, 0.0, TiledGrid(options_.grid), nullptr, nullptr};
    Integrate(first.map, first.pose, points);
    first.trajectory = ExtendTrajectory(nullptr, {scan_index, odometry_pose});
    particles_.assign(options_.num_particles, first);
    started_ = true;
    last_odometry_ = last_received_odometry_ = odometry_pose;
    ++stats_.scans_processed;
    return true;
  }
  // The spread grows with every odometry increment, processed or not: several short moves are
  // noisier than one long move of the same length.
  pending_spread_ = OdometryMotionModel::Accumulate(
      pending_spread_, motion_.Spread(last_received_odometry_, odometry_pose));
  last_received_odometry_ = odometry_pose;
  const Pose2D delta = last_odometry_.Between(odometry_pose);
  if (!force_update && std::hypot(delta.x_m, delta.y_m) < options_.linear_update_m &&
      std::abs(NormalizeAngle(delta.theta_rad)) < options_.angular_update_rad) {
    return false;
  }
  const ScanPoints points = PrepareScan(scan);
  const StepSpread spread = pending_spread_;
  pending_spread_ = StepSpread{};

  // Front end: one wide search on the best particle's map turns the odometry step into a scan-
  // corrected step; every particle then searches a narrow window around its own corrected step.
  const SlamParticle& best = particles_[BestIndex()];
  const Pose2D best_prediction = best.pose.Compose(delta);
  const MatchResult wide = matcher_.Match(best.map, points.match, best_prediction,
                                          matcher_.WideWindow(spread), best_prediction, spread);
  const Pose2D step = wide.status == MatchResult::Status::kMatched ? best.pose.Between(wide.pose) : delta;

  for (SlamParticle& p : particles_) {
    const Pose2D prior = OdometryMotionModel::SampleIsotropic(p.pose, delta, spread, rng_);
    const MatchResult r =
        matcher_.Match(p.map, points.match, p.pose.Compose(step), matcher_.NarrowWindow(), prior, spread);
    p.pose = r.pose;
    double log_likelihood = r.log_likelihood;
    if (options_.degenerate_min_points > 0 && r.status == MatchResult::Status::kMatched &&
        points.along_axis_gain < 1.0) {
      // Along the scan's weakest axis, move from this particle's odometry sample only by the share
      // along_axis_gain of the match's correction (0 when the scan does not fix that axis, 1 when it does).
      const double c = std::cos(p.pose.theta_rad), s = std::sin(p.pose.theta_rad);
      const Vec2 axis{c * points.degenerate_axis.x - s * points.degenerate_axis.y,
                      s * points.degenerate_axis.x + c * points.degenerate_axis.y};
      const double along = (1.0 - points.along_axis_gain) * Dot(p.pose.Position() - prior.Position(), axis);
      p.pose.x_m -= along * axis.x;
      p.pose.y_m -= along * axis.y;
      log_likelihood = matcher_.LogLikelihood(p.map, points.match, p.pose);
    }
    const double l = options_.likelihood_gain * log_likelihood;
    p.log_weight += l;
    p.log_score += l;
    switch (r.status) {
      case MatchResult::Status::kMatched: ++stats_.matches; break;
      case MatchResult::Status::kWeak: ++stats_.weak_matches; break;
      case MatchResult::Status::kRejectedJump: ++stats_.rejected_jumps; break;
    }
  }
  if (points.degenerate) ++stats_.degenerate_scans;
  FinishStep(&points, scan_index);
  last_odometry_ = odometry_pose;
  ++stats_.scans_processed;
  return true;
}

void RbpfSlam::ReweightParticles(const std::function<double(const SlamParticle&)>& log_likelihood) {
  for (SlamParticle& p : particles_) {
    const double l = log_likelihood(p);
    p.log_weight += l;
    p.log_score += l;
  }
  FinishStep(nullptr, 0);
}

void RbpfSlam::UpdateLandmarksAndReweight(
    const std::function<double(const SlamParticle&, SlamLandmarksHandle*)>& update) {
  for (SlamParticle& p : particles_) {
    SlamLandmarksHandle handle = p.landmarks;
    const double l = update(p, &handle);
    p.landmarks = std::move(handle);
    p.log_weight += l;
    p.log_score += l;
  }
  FinishStep(nullptr, 0);
}

double RbpfSlam::Neff() const {
  if (particles_.empty()) return 0.0;
  double max_lw = -std::numeric_limits<double>::infinity();
  for (const SlamParticle& p : particles_) max_lw = std::max(max_lw, p.log_weight);
  double sum = 0.0, sum2 = 0.0;
  for (const SlamParticle& p : particles_) {
    const double w = std::exp(p.log_weight - max_lw);
    sum += w, sum2 += w * w;
  }
  return sum * sum / sum2;
}

int RbpfSlam::BestIndex() const {
  int best = 0;
  for (int i = 1; i < static_cast<int>(particles_.size()); ++i) {
    const SlamParticle& p = particles_[i];
    const SlamParticle& b = particles_[best];
    if (p.log_weight > b.log_weight || (p.log_weight == b.log_weight && p.log_score > b.log_score)) best = i;
  }
  return best;
}

std::size_t RbpfSlam::MapMemoryBytes() const {
  std::unordered_set<const TiledGrid::Tile*> tiles;
  for (const SlamParticle& p : particles_) p.map.CollectTiles(&tiles);
  return tiles.size() * sizeof(TiledGrid::Tile);
}

std::vector<TrajectoryPoint> RbpfSlam::MeanTrajectory() const {
  const std::vector<TrajectoryPoint> best = BestTrajectory();
  double max_lw = -std::numeric_limits<double>::infinity();
  for (const SlamParticle& p : particles_) max_lw = std::max(max_lw, p.log_weight);
  std::vector<double> sx(best.size(), 0.0), sy(best.size(), 0.0), sc(best.size(), 0.0), ss(best.size(), 0.0);
  double total = 0.0;
  const double radius2 = options_.mean_trajectory_radius_m * options_.mean_trajectory_radius_m;
  for (const SlamParticle& p : particles_) {
    const std::vector<TrajectoryPoint> history = UnrollTrajectory(p.trajectory);
    if (history.size() != best.size()) continue;
    double d2 = 0.0;
    for (std::size_t i = 0; i < best.size(); ++i) {
      d2 += std::pow(history[i].pose.x_m - best[i].pose.x_m, 2) + std::pow(history[i].pose.y_m - best[i].pose.y_m, 2);
    }
    if (d2 > radius2 * best.size()) continue;  // another mode
    const double w = std::exp(p.log_weight - max_lw);
    total += w;
    for (std::size_t i = 0; i < best.size(); ++i) {
      sx[i] += w * history[i].pose.x_m, sy[i] += w * history[i].pose.y_m;
      sc[i] += w * std::cos(history[i].pose.theta_rad), ss[i] += w * std::sin(history[i].pose.theta_rad);
    }
  }
  std::vector<TrajectoryPoint> mean = best;  // the best particle is always in its own mode: total > 0
  for (std::size_t i = 0; i < mean.size(); ++i) {
    mean[i].pose = {sx[i] / total, sy[i] / total, std::atan2(ss[i], sc[i])};
  }
  return mean;
}

const SlamParticle& RbpfSlam::BestParticle() const {
  if (particles_.empty()) throw std::logic_error("RbpfSlam::BestParticle: no scan was added yet");
  return particles_[BestIndex()];
}

void RbpfSlam::FinishStep(const ScanPoints* scan, int scan_index) {
  const int n = static_cast<int>(particles_.size());
  stats_.last_neff = Neff();
  std::vector<int> parents(n);
  for (int i = 0; i < n; ++i) parents[i] = i;
  const bool resample = stats_.last_neff < options_.resample_neff_ratio * n;
  if (resample) {
    // Systematic (low-variance) resampling.
    double max_lw = -std::numeric_limits<double>::infinity();
    for (const SlamParticle& p : particles_) max_lw = std::max(max_lw, p.log_weight);
    std::vector<double> cumulative(n);
    double total = 0.0;
    for (int i = 0; i < n; ++i) cumulative[i] = total += std::exp(particles_[i].log_weight - max_lw);
    std::uniform_real_distribution<double> start(0.0, total / n);
    double u = start(rng_);
    int i = 0;
    for (int k = 0; k < n; ++k, u += total / n) {
      while (i < n - 1 && cumulative[i] < u) ++i;
      parents[k] = i;
    }
    ++stats_.resamplings;
  }
  // The scan goes into each surviving parent's map once, before children share its tiles.
  if (scan) {
    std::vector<bool> done(n, false);
    for (int parent : parents) {
      if (done[parent]) continue;
      done[parent] = true;
      SlamParticle& p = particles_[parent];
      Integrate(p.map, p.pose, *scan);
      p.trajectory = ExtendTrajectory(p.trajectory, {scan_index, p.pose});
    }
  }
  if (resample) {
    std::vector<SlamParticle> next;
    next.reserve(n);
    for (int parent : parents) {
      next.push_back(particles_[parent]);
      next.back().log_weight = 0.0;
    }
    particles_ = std::move(next);
  }
}

}  // namespace doorplate_localization
