// MappingSession: the rules are listed in mapping_session.h; each is applied here, in one place.
#include "doorplate_localization/slam/mapping_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "doorplate_localization/common/freed_memory.h"

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
  if (!(o.map_update_max_solve_share >= 0 && o.map_update_max_solve_share < 1)) {
    fail("map_update_max_solve_share: must be in [0, 1) (0: off), got " + std::to_string(o.map_update_max_solve_share));
  }
  if (!(o.camera_wait_s >= 0 && o.camera_wait_s <= 60)) {
    fail("camera_wait_s: must be in [0, 60] seconds (0: scans do not wait for the camera), got " +
         std::to_string(o.camera_wait_s));
  }
}

MappingSession::MappingSession(const MappingSessionOptions& options)
    : options_(Validated(options)), slam_(options.slam), wall_clock_([] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
      }) {}

MappingUpdate MappingSession::AddScan(double stamp_s, const Pose2D& base_in_odom, const LaserScan& scan) {
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
  const std::string refused = Ordering() ? RefuseOrderedScan(stamp_s) : RefuseScan(stamp_s);
  if (!refused.empty()) {
    ++counters_.scans_refused;
    update.scan_refused_reason = refused;
    return update;
  }
  update.scan_taken = true;
  last_scan_stamp_s_ = std::max(stamp_s, last_scan_stamp_s_.value_or(stamp_s));
  const auto later = [stamp_s](const auto& s) { return s.stamp_s > stamp_s; };  // stamp order, also when late
  scans_.insert(std::find_if(scans_.begin(), scans_.end(), later), TimedScan{stamp_s, scan});
  while (scans_.size() > 1 && scans_.front().stamp_s < *last_scan_stamp_s_ - options_.scan_history_s) scans_.pop_front();
  if (Ordering()) {
    waiting_.insert(std::find_if(waiting_.begin(), waiting_.end(), later), WaitingScan{stamp_s, base_in_odom, -1, scan});
    SendWaitingScans(/*flush=*/false, &update);
  } else {
    ProcessScan({stamp_s, base_in_odom, index, scan}, &update);
    // Held sightings this scan decides: a scan at or after their stamp has now arrived.
    ApplyHeldBefore(std::nextafter(stamp_s, HUGE_VAL), &update);
  }
  if (update.scan_processed || !update.plates.empty()) RefreshMapToOdom(&update);
  return update;
}

std::string MappingSession::RefuseScan(double stamp_s) const {
  if (!last_scan_stamp_s_ || stamp_s > *last_scan_stamp_s_) return "";
  return "stamp " + std::to_string(stamp_s) + " s is not after the previous scan's " +
         std::to_string(*last_scan_stamp_s_) + " s (time went backwards?)";
}

std::string MappingSession::RefuseOrderedScan(double stamp_s) const {
  if (last_sent_stamp_s_ && stamp_s <= *last_sent_stamp_s_) {
    return "stamp " + std::to_string(stamp_s) + " s is not after the last scan mapped, " +
           std::to_string(*last_sent_stamp_s_) + " s (more than camera_wait_s late, or time went backwards?)";
  }
  for (const WaitingScan& w : waiting_) {
    if (w.stamp_s == stamp_s) return "stamp " + std::to_string(stamp_s) + " s: a scan of that stamp was given already";
  }
  return "";
}

void MappingSession::ProcessScan(const WaitingScan& taken, MappingUpdate* update) {
  const bool temporal = options_.temporal_update_s > 0 && last_processed_stamp_s_ &&
                        taken.stamp_s - *last_processed_stamp_s_ >= options_.temporal_update_s;
  const bool processed = slam_.AddScan(taken.scan, taken.base_in_odom, taken.index, temporal);
  last_sent_stamp_s_ = taken.stamp_s;
  if (!processed) return;
  update->scan_processed = true;
  ++counters_.scans_processed;
  last_processed_stamp_s_ = taken.stamp_s;
  processed_scan_indices_.push_back(taken.index);
  if (options_.map_update_interval_s > 0 &&
      (!last_solve_stamp_s_ || taken.stamp_s - *last_solve_stamp_s_ >= options_.map_update_interval_s)) {
    if (next_periodic_solve_wall_s_ && wall_clock_() < *next_periodic_solve_wall_s_) {
      ++counters_.solves_deferred;
    } else {
      update->solved = Solve().solved || update->solved;
    }
  }
}

void MappingSession::SendWaitingScans(bool flush, MappingUpdate* update) {
  while (!waiting_.empty()) {
    const WaitingScan& next = waiting_.front();
    const bool reported = camera_stamp_s_ && *camera_stamp_s_ >= next.stamp_s;
    const bool expired = *last_scan_stamp_s_ - next.stamp_s >= options_.camera_wait_s ||
                         waiting_.size() > kMaxWaitingScans;
    if (!flush && !reported && !expired) return;
    if (!reported && expired) ++counters_.scans_camera_wait_expired;
    ApplyHeldBefore(next.stamp_s, update);
    WaitingScan taken = std::move(waiting_.front());
    waiting_.pop_front();
    taken.index = ordered_index_++;
    ProcessScan(taken, update);
  }
}

void MappingSession::ApplyHeldBefore(std::optional<double> stamp_s, MappingUpdate* update) {
  // Stamp order; among equal stamps, the order of arrival.
  std::vector<HeldPlate> due;
  for (auto it = held_.begin(); it != held_.end();) {
    if (!stamp_s || it->stamp_s < *stamp_s) {
      due.push_back(std::move(*it));
      it = held_.erase(it);
    } else {
      ++it;
    }
  }
  std::stable_sort(due.begin(), due.end(), [](const HeldPlate& a, const HeldPlate& b) { return a.stamp_s < b.stamp_s; });
  for (const HeldPlate& h : due) ApplyPlate(h.stamp_s, h.base_in_odom, h.sighting, update);
}

MappingUpdate MappingSession::Flush() {
  MappingUpdate update;
  SendWaitingScans(/*flush=*/true, &update);
  ApplyHeldBefore(std::nullopt, &update);
  slam_.FinishInput();  // the last node's fusion waits for no more scans
  if (update.scan_processed || !update.plates.empty()) RefreshMapToOdom(&update);
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
                                        const std::vector<PlateReading>& sightings) {
  if (!std::isfinite(stamp_s)) throw std::invalid_argument("MappingSession::AddPlates: stamp_s must be finite");
  if (!Finite(base_in_odom)) throw std::invalid_argument("MappingSession::AddPlates: base_in_odom must be finite");
  for (const PlateReading& s : sightings) {  // all or nothing
    if (const std::string bad = ValidatePlateReading(s); !bad.empty()) {
      throw std::invalid_argument("MappingSession::AddPlates: " + bad);
    }
  }
  MappingUpdate update;
  bool used = false;
  if (Ordering()) camera_stamp_s_ = std::max(stamp_s, camera_stamp_s_.value_or(stamp_s));
  for (const PlateReading& given : sightings) {
    ++counters_.plate_sightings;
    const bool late = Ordering() && last_sent_stamp_s_ && stamp_s < *last_sent_stamp_s_;
    if (late) ++counters_.plates_late;
    if (Ordering() ? !late : !given.range_m && ScanMayStillCome(stamp_s)) {
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
  if (Ordering()) SendWaitingScans(/*flush=*/false, &update);
  if (used || update.scan_processed || !update.plates.empty()) RefreshMapToOdom(&update);
  return update;
}

bool MappingSession::ApplyPlate(double stamp_s, const Pose2D& base_in_odom, const PlateReading& given,
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
  const double start_s = wall_clock_();
  slam_.Solve();
  last_solve_stamp_s_ = last_processed_stamp_s_;
  map_ = slam_.BuildOccupancyGrid();
  text_map_ = slam_.BuildTextMap();
  // The solve's temporaries (tens of MB on an hour's graph) would otherwise stay resident: freed_memory.h.
  ReturnFreedMemoryToSystem();
  ++counters_.solves;
  const double end_s = wall_clock_();
  counters_.last_solve_wall_s = end_s - start_s;
  const double share = options_.map_update_max_solve_share;
  if (share > 0) next_periodic_solve_wall_s_ = end_s + counters_.last_solve_wall_s * (1.0 / share - 1.0);
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
