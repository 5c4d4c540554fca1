#include "doorplate_localization/mcl/text_amcl_session.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {
namespace {

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("TextAmclSessionOptions.") + field + ": " + rule);
}

void Validate(const TextAmclSessionOptions& o) {
  try {
    ValidatePlateRangeOptions(o.plate_range);
  } catch (const std::invalid_argument& e) {
    Require(false, "plate_range", e.what());
  }
  Require(std::isfinite(o.text_range_max_scan_age_s) && o.text_range_max_scan_age_s >= 0.0,
          "text_range_max_scan_age_s", "must be finite and >= 0");
  Require(std::isfinite(o.odometry_history_s) && o.odometry_history_s > 0.0, "odometry_history_s",
          "must be finite and > 0");
  Require(o.max_pending_plate_readings >= 1, "max_pending_plate_readings", "must be >= 1");
}

// Linear interpolation of x, y and the shorter way round for the heading; `t` in [0, 1].
Pose2D Interpolate(const Pose2D& a, const Pose2D& b, double t) {
  return {a.x_m + t * (b.x_m - a.x_m), a.y_m + t * (b.y_m - a.y_m),
          NormalizeAngle(a.theta_rad + t * NormalizeAngle(b.theta_rad - a.theta_rad))};
}

}  // namespace

const char* ToString(PlateDisposition disposition) {
  switch (disposition) {
    case PlateDisposition::kWeighed: return "weighed";
    case PlateDisposition::kUnknownRoomFirst: return "unknown_room_first";
    case PlateDisposition::kUnknownRoom: return "unknown_room";
    case PlateDisposition::kNoTextMap: return "no_text_map";
    case PlateDisposition::kStale: return "stale";
    case PlateDisposition::kInvalid: return "invalid";
  }
  return "?";
}

TextAmclSession::TextAmclSession(const TextAmclSessionOptions& options, const OccupancyGrid& map,
                                 std::shared_ptr<const TextMap> text_map)
    : options_(options), text_map_(std::move(text_map)) {
  Validate(options_);
  filter_ = MakeTextAmcl(options_.setup, map, text_map_);
  if (options_.setup.use_text && text_map_) {
    matcher_ = std::make_unique<TextMatcher>(options_.setup.plate.text_match);
  }
  if (options_.start_with_global_localization) {
    GlobalLocalization();
  } else {
    Initialize(options_.initial_pose, options_.initial_covariance);
  }
}

TextAmclSession::TextAmclSession(const TextAmclSessionOptions& options, const OccupancyGrid& map,
                                 const TextAmclSession& previous)
    : options_(options),
      text_map_(previous.text_map_),
      odometry_(previous.odometry_),
      pending_(previous.pending_),
      scans_(previous.scans_),
      filter_odom_(previous.filter_odom_),
      move_at_next_scan_(previous.move_at_next_scan_),
      unknown_rooms_(previous.unknown_rooms_),
      estimate_(previous.estimate_),
      map_to_odom_(previous.map_to_odom_),
      counters_(previous.counters_) {
  Validate(options_);
  filter_ = MakeTextAmcl(options_.setup, map, text_map_);
  filter_->ContinueFrom(*previous.filter_);
  if (options_.setup.use_text && text_map_) {
    matcher_ = std::make_unique<TextMatcher>(options_.setup.plate.text_match);
  }
  status_ = filter_->Status();
}

void TextAmclSession::Initialize(const Pose2D& mean, const Eigen::Matrix3d& covariance) {
  filter_->Initialize(mean, covariance);
  Restarted();
}

void TextAmclSession::GlobalLocalization() {
  filter_->GlobalLocalization();
  Restarted();
}

void TextAmclSession::Restarted() {
  filter_odom_.reset();  // the filter takes the next odometry as its reference
  move_at_next_scan_ = false;
  map_to_odom_.reset();
  estimate_ = filter_->Estimate();
  status_ = filter_->Status();
}

void TextAmclSession::RequestNoMotionUpdate() { filter_->ForceUpdate(); }

void TextAmclSession::RecordOdometry(double stamp_s, const Pose2D& base_in_odom) {
  auto it = odometry_.end();
  while (it != odometry_.begin() && std::prev(it)->stamp_s > stamp_s) --it;
  if (it != odometry_.begin() && std::prev(it)->stamp_s == stamp_s) {
    std::prev(it)->pose = base_in_odom;
  } else {
    odometry_.insert(it, {stamp_s, base_in_odom});
  }
  while (odometry_.front().stamp_s < odometry_.back().stamp_s - options_.odometry_history_s) odometry_.pop_front();
}

std::optional<Pose2D> TextAmclSession::OdometryAt(double stamp_s) const {
  if (odometry_.empty() || stamp_s < odometry_.front().stamp_s || stamp_s > odometry_.back().stamp_s) {
    return std::nullopt;
  }
  const auto after = std::lower_bound(odometry_.begin(), odometry_.end(), stamp_s,
                                      [](const TimedPose& p, double t) { return p.stamp_s < t; });
  if (after->stamp_s == stamp_s || after == odometry_.begin()) return after->pose;
  const auto before = std::prev(after);
  const double t = (stamp_s - before->stamp_s) / (after->stamp_s - before->stamp_s);
  return Interpolate(before->pose, after->pose, t);
}

bool TextAmclSession::MoveFilter(const Pose2D& base_in_odom, bool forced) {
  const bool first = !filter_odom_.has_value();
  if (forced) filter_->ForceUpdate();
  const bool moved = filter_->UpdateOdometry(base_in_odom);
  if (moved || first) filter_odom_ = base_in_odom;
  return moved;
}

void TextAmclSession::Refresh(SessionUpdate* update) {
  estimate_ = filter_->Estimate();
  status_ = filter_->Status();
  if (filter_odom_) map_to_odom_ = estimate_.pose.Compose(filter_odom_->Inverse());
  update->estimate_changed = true;
}

Pose2D TextAmclSession::PoseAtOdometry(const Pose2D& base_in_odom) const {
  return map_to_odom_ ? map_to_odom_->Compose(base_in_odom) : estimate_.pose;
}

SessionUpdate TextAmclSession::AddOdometry(double stamp_s, const Pose2D& base_in_odom) {
  SessionUpdate update;
  if (!odometry_.empty() && stamp_s < odometry_.back().stamp_s) {
    update.plates_pending = static_cast<int>(pending_.size());
    return update;
  }
  RecordOdometry(stamp_s, base_in_odom);
  ApplyPending(&update);
  return update;
}

SessionUpdate TextAmclSession::AddScan(double stamp_s, const Pose2D& base_in_odom, const LaserScan& scan) {
  const std::string problem = ValidateLocalizationScan(scan);
  if (!problem.empty()) throw std::invalid_argument(problem);
  SessionUpdate update;
  if (!scans_.empty() && stamp_s < scans_.back().stamp_s) {
    update.scan_ignored_reason = "time went backwards (stamp " + std::to_string(stamp_s) + " s after " +
                                 std::to_string(scans_.back().stamp_s) + " s)";
    // A restarted clock (a bag played again, a simulator reset): forget the old timeline, continue from it.
    scans_.clear();
    scans_.push_back({stamp_s, scan});
    odometry_.clear();
    for (const PendingReading& p : pending_) {
      update.plates.push_back({p.stamp_s, p.reading, PlateDisposition::kStale, {}, "time went backwards"});
      ++counters_.stale_readings;
    }
    pending_.clear();
    return update;
  }
  ++counters_.scans;
  RecordOdometry(stamp_s, base_in_odom);
  scans_.push_back({stamp_s, scan});
  if (scans_.size() > 2) scans_.pop_front();
  ApplyPending(&update);  // readings up to this scan's stamp come first
  MoveFilter(base_in_odom, move_at_next_scan_);
  move_at_next_scan_ = false;
  update.laser_used = filter_->UpdateLaser(scan);
  if (update.laser_used) {
    ++counters_.laser_updates;
    Refresh(&update);
  }
  return update;
}

SessionUpdate TextAmclSession::AddPlates(double stamp_s, const std::vector<PlateReading>& readings) {
  SessionUpdate update;
  for (PlateReading reading : readings) {
    ++counters_.plate_readings;
    reading.range_m.reset();
    const std::string problem = ValidatePlateReading(reading);
    if (!problem.empty() || !std::isfinite(stamp_s)) {
      ++counters_.invalid_readings;
      update.plates.push_back({stamp_s, reading, PlateDisposition::kInvalid, {},
                               problem.empty() ? "stamp must be finite" : problem});
      continue;
    }
    if (!matcher_) {
      update.plates.push_back({stamp_s, reading, PlateDisposition::kNoTextMap, {}, ""});
      continue;
    }
    if (matcher_->Compatible(*text_map_, reading.text, reading.confidence).empty()) {
      ++counters_.unknown_room_readings;
      // One warning per room; past limits::kMaxRememberedUnknownRooms rooms (OCR garbage over a long run)
      // they are counted but no longer remembered, so the set cannot grow without bound.
      const bool first = unknown_rooms_.size() < limits::kMaxRememberedUnknownRooms &&
                         unknown_rooms_.insert(CanonicalRoomId(reading.text)).second;
      update.plates.push_back(
          {stamp_s, reading, first ? PlateDisposition::kUnknownRoomFirst : PlateDisposition::kUnknownRoom, {}, ""});
      continue;
    }
    auto it = pending_.end();
    while (it != pending_.begin() && std::prev(it)->stamp_s > stamp_s) --it;
    pending_.insert(it, {stamp_s, reading});
    if (static_cast<int>(pending_.size()) > options_.max_pending_plate_readings) {
      ++counters_.stale_readings;
      update.plates.push_back({pending_.front().stamp_s, pending_.front().reading, PlateDisposition::kStale, {},
                               "no odometry reached its stamp"});
      pending_.pop_front();
    }
  }
  ApplyPending(&update);
  return update;
}

void TextAmclSession::ApplyPending(SessionUpdate* update) {
  while (!pending_.empty() && !odometry_.empty() && pending_.front().stamp_s <= odometry_.back().stamp_s) {
    const PendingReading pending = pending_.front();
    pending_.pop_front();
    ApplyReading(pending, update);
  }
  update->plates_pending = static_cast<int>(pending_.size());
}

std::optional<double> TextAmclSession::RangeFor(double stamp_s, double bearing_rad) const {
  if (!options_.text_use_laser_range || scans_.empty()) return std::nullopt;
  const TimedScan* nearest = &scans_.front();
  for (const TimedScan& s : scans_) {
    if (std::fabs(s.stamp_s - stamp_s) < std::fabs(nearest->stamp_s - stamp_s)) nearest = &s;
  }
  if (std::fabs(nearest->stamp_s - stamp_s) > options_.text_range_max_scan_age_s) return std::nullopt;
  const std::optional<PlateRange> range =
      PlateRangeAlongBearing(nearest->scan.ranges_m, BeamGeometryOf(nearest->scan), bearing_rad, options_.plate_range);
  if (!range) return std::nullopt;
  return range->range_m;
}

void TextAmclSession::ApplyReading(const PendingReading& pending, SessionUpdate* update) {
  PlateReadingOutcome outcome;
  outcome.stamp_s = pending.stamp_s;
  outcome.reading = pending.reading;
  const std::optional<Pose2D> odom = OdometryAt(pending.stamp_s);
  if (!odom) {
    ++counters_.stale_readings;
    outcome.disposition = PlateDisposition::kStale;
    outcome.detail = "older than the odometry kept";
  } else {
    outcome.reading.range_m = RangeFor(pending.stamp_s, pending.reading.bearing_rad);
    MoveFilter(*odom, /*forced=*/true);  // to the reading's stamp, forwards or back
    move_at_next_scan_ = true;            // and the next scan to its own
    outcome.result = filter_->UpdatePlate(outcome.reading);
    ++counters_.plates_weighed;
    if (outcome.result.used) ++counters_.plates_used;
    Refresh(update);
  }
  update->plates.push_back(outcome);
}

}  // namespace doorplate_localization
