// MappingSession: the rules are listed in mapping_session.h; each is applied here, in one place.
#include "doorplate_localization/slam/mapping_session.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

const MappingSessionOptions& Validated(const MappingSessionOptions& o) {
  ValidateMappingSessionOptions(o);
  return o;
}

bool Finite(const Pose2D& p) { return std::isfinite(p.x_m) && std::isfinite(p.y_m) && std::isfinite(p.theta_rad); }

}  // namespace

void ValidateMappingSessionOptions(const MappingSessionOptions& o) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("MappingSessionOptions." + what); };
  if (o.throttle_scans < 1) fail("throttle_scans: must be >= 1, got " + std::to_string(o.throttle_scans));
  if (!std::isfinite(o.temporal_update_s)) fail("temporal_update_s: must be finite (<= 0: off)");
  if (!(o.map_update_interval_s >= 0) || !std::isfinite(o.map_update_interval_s)) {
    fail("map_update_interval_s: must be finite and >= 0 (0: only on Solve())");
  }
  if (!(o.plate_range_max_scan_age_s >= 0) || !std::isfinite(o.plate_range_max_scan_age_s)) {
    fail("plate_range_max_scan_age_s: must be finite and >= 0");
  }
  if (!(o.scan_history_s >= 0) || !std::isfinite(o.scan_history_s)) fail("scan_history_s: must be finite and >= 0");
}

MappingSession::MappingSession(const MappingSessionOptions& options)
    : options_(Validated(options)), slam_(options.slam) {}

MappingUpdate MappingSession::AddScan(double stamp_s, const Pose2D& base_in_odom, const RangeScan& scan) {
  if (!std::isfinite(stamp_s)) throw std::invalid_argument("MappingSession::AddScan: stamp_s must be finite");
  if (!Finite(base_in_odom)) throw std::invalid_argument("MappingSession::AddScan: base_in_odom must be finite");
  if (scan.ranges_m.empty() || !std::isfinite(scan.angle_min_rad) || !std::isfinite(scan.angle_increment_rad) ||
      scan.angle_increment_rad == 0.0 || !Finite(scan.laser_pose)) {
    throw std::invalid_argument("MappingSession::AddScan: the scan needs ranges, finite angle_min_rad and "
                                "laser_pose, and a finite, non-zero angle_increment_rad");
  }
  MappingUpdate update;
  ++counters_.scans;
  const int index = scan_calls_++;
  if (index % options_.throttle_scans != 0) return update;  // gmapping's throttle_scans: every call counts
  if (last_scan_stamp_s_ && stamp_s <= *last_scan_stamp_s_) {
    ++counters_.scans_refused;
    update.scan_refused_reason = "stamp " + std::to_string(stamp_s) + " s is not after the previous scan's " +
                                 std::to_string(*last_scan_stamp_s_) + " s (time went backwards?)";
    return update;
  }
  const bool temporal = options_.temporal_update_s > 0 && last_processed_stamp_s_ &&
                        stamp_s - *last_processed_stamp_s_ >= options_.temporal_update_s;
  update.scan_processed = slam_.AddScan(scan, base_in_odom, index, temporal);
  update.scan_taken = true;
  last_scan_stamp_s_ = stamp_s;
  scans_.push_back({stamp_s, scan});
  while (scans_.size() > 1 && scans_.front().stamp_s < stamp_s - options_.scan_history_s) scans_.pop_front();
  if (update.scan_processed) {
    ++counters_.scans_processed;
    last_processed_stamp_s_ = stamp_s;
    processed_scan_indices_.push_back(index);
    if (options_.map_update_interval_s > 0 &&
        (!last_solve_stamp_s_ || stamp_s - *last_solve_stamp_s_ >= options_.map_update_interval_s)) {
      const MappingUpdate solved = Solve();
      update.solved = solved.solved;
    }
  }
  // Held sightings this scan decides: a scan at or after their stamp has now arrived. Applied in stamp order
  // (their arrival order is kept among equal stamps).
  std::vector<HeldPlate> due;
  for (auto it = held_.begin(); it != held_.end();) {
    if (it->stamp_s <= stamp_s) {
      due.push_back(std::move(*it));
      it = held_.erase(it);
    } else {
      ++it;
    }
  }
  std::stable_sort(due.begin(), due.end(), [](const HeldPlate& a, const HeldPlate& b) { return a.stamp_s < b.stamp_s; });
  for (const HeldPlate& h : due) ApplyPlate(h.stamp_s, h.base_in_odom, h.sighting, &update);
  if (update.scan_processed || !due.empty()) RefreshMapToOdom(&update);
  return update;
}

bool MappingSession::ScanMayStillCome(double stamp_s) const {
  if (scans_.empty()) return true;
  if (scans_.back().stamp_s >= stamp_s) return false;  // received scans are in stamp order: none newer to come
  return stamp_s - scans_.back().stamp_s > options_.plate_range_max_scan_age_s;
}

std::optional<double> MappingSession::RangeFor(double stamp_s, double bearing_rad, std::string* why) {
  const TimedScan* nearest = nullptr;
  for (const TimedScan& s : scans_) {  // oldest first: `<=` keeps the newer on ties
    if (!nearest || std::abs(s.stamp_s - stamp_s) <= std::abs(nearest->stamp_s - stamp_s)) nearest = &s;
  }
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(2);
  if (!nearest || std::abs(nearest->stamp_s - stamp_s) > options_.plate_range_max_scan_age_s) {
    out << "no scan within " << options_.plate_range_max_scan_age_s << " s of the reading's stamp " << stamp_s << " s";
    if (nearest) out << " (nearest " << nearest->stamp_s << " s, newest " << scans_.back().stamp_s << " s)";
    *why = out.str();
    return std::nullopt;
  }
  const std::optional<PlateRange> range = PlateRangeAlongBearing(
      nearest->scan.ranges_m, BeamGeometryOf(nearest->scan), bearing_rad, options_.slam.plate_range);
  if (!range) {
    out << "no echo within " << options_.slam.plate_range.beam_window_rad << " rad of the bearing " << bearing_rad
        << " rad in the scan at " << nearest->stamp_s << " s";
    *why = out.str();
    return std::nullopt;
  }
  if (range->from_wall) ++counters_.plate_ranges_from_wall;
  return range->range_m;
}

MappingUpdate MappingSession::AddPlates(double stamp_s, const Pose2D& base_in_odom,
                                        const std::vector<PlateSighting>& sightings) {
  if (!std::isfinite(stamp_s)) throw std::invalid_argument("MappingSession::AddPlates: stamp_s must be finite");
  if (!Finite(base_in_odom)) throw std::invalid_argument("MappingSession::AddPlates: base_in_odom must be finite");
  for (const PlateSighting& s : sightings) ValidatePlateSighting(s);  // all or nothing
  MappingUpdate update;
  bool used = false;
  for (const PlateSighting& given : sightings) {
    ++counters_.plate_sightings;
    if (!given.range_m && ScanMayStillCome(stamp_s)) {
      if (held_.size() >= kMaxHeldPlates) {  // bounded: the oldest waits no longer
        const HeldPlate oldest = held_.front();
        held_.pop_front();
        used = ApplyPlate(oldest.stamp_s, oldest.base_in_odom, oldest.sighting, &update) || used;
      }
      held_.push_back({stamp_s, base_in_odom, given});
      ++counters_.plates_held;
      ++update.plates_held;
      continue;
    }
    used = ApplyPlate(stamp_s, base_in_odom, given, &update) || used;
  }
  if (used) RefreshMapToOdom(&update);
  return update;
}

bool MappingSession::ApplyPlate(double stamp_s, const Pose2D& base_in_odom, const PlateSighting& given,
                                MappingUpdate* update) {
  MappingPlateOutcome outcome;
  outcome.stamp_s = stamp_s;
  outcome.sighting = given;
  std::string no_range_why;
  if (!given.range_m) outcome.sighting.range_m = RangeFor(stamp_s, given.bearing_rad, &no_range_why);
  outcome.result = slam_.AddPlate(outcome.sighting, base_in_odom);
  if (outcome.result.outcome == PlateOutcome::kNoRange && !no_range_why.empty()) {
    outcome.result.reason = "no range: " + no_range_why;
  }
  const bool used = outcome.result.used();
  if (used) ++counters_.plates_used;
  update->plates.push_back(std::move(outcome));
  return used;
}

MappingUpdate MappingSession::Solve() {
  MappingUpdate update;
  if (!started()) return update;
  slam_.Solve();
  last_solve_stamp_s_ = last_processed_stamp_s_;
  map_ = slam_.BuildOccupancyGrid();
  text_map_ = slam_.BuildTextMap();
  ++counters_.solves;
  update.solved = true;
  RefreshMapToOdom(&update);
  return update;
}

void MappingSession::RefreshMapToOdom(MappingUpdate* update) {
  if (!started()) return;
  const Pose2D& odom = slam_.slam().LastProcessedOdometry();
  map_to_odom_ = slam_.EstimatedPose(odom).Compose(odom.Inverse());
  update->map_to_odom_changed = true;
}

}  // namespace doorplate_localization
