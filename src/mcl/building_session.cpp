#include "doorplate_localization/mcl/building_session.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {
namespace {

int StartFloor(const BuildingSessionOptions& options, const BuildingMaps& maps) {
  if (maps.floors.empty()) throw std::invalid_argument("BuildingSession: the building has no floor");
  if (options.start_floor.empty()) return maps.floors.size() == 1 ? 0 : -1;
  for (size_t f = 0; f < maps.floors.size(); ++f) {
    if (maps.floors[f].id == options.start_floor) return static_cast<int>(f);
  }
  std::string ids;
  for (const FloorMaps& floor : maps.floors) ids += (ids.empty() ? "" : ", ") + floor.id;
  throw std::invalid_argument("BuildingSessionOptions.start_floor: no floor '" + options.start_floor +
                              "' (floors: " + ids + ")");
}

void Append(const SessionUpdate& from, SessionUpdate* to) {
  to->plates.insert(to->plates.end(), from.plates.begin(), from.plates.end());
  to->laser_used = to->laser_used || from.laser_used;
  to->estimate_changed = to->estimate_changed || from.estimate_changed;
  to->plates_pending = from.plates_pending;
}

}  // namespace

BuildingSession::BuildingSession(const BuildingSessionOptions& options, std::shared_ptr<const BuildingMaps> maps)
    : options_(options),
      maps_(maps ? std::move(maps) : throw std::invalid_argument("BuildingSession: no building maps")),
      belief_(options.floor_belief, std::max<int>(1, static_cast<int>(maps_->floors.size())), StartFloor(options, *maps_)) {
  rooms_.resize(maps_->floors.size());
  for (size_t f = 0; f < maps_->floors.size(); ++f) {
    if (!maps_->floors[f].text_map) continue;
    for (const TextLandmark& plate : maps_->floors[f].text_map->landmarks) rooms_[f].insert(CanonicalRoomId(plate.text));
  }
  sessions_.resize(maps_->floors.size());
  current_ = std::max(0, StartFloor(options_, *maps_));
  Session(current_);
  // Every other floor's filter now, so that a map the session refuses is refused here, naming the floor,
  // and not at the moment of a switch (each floor's filter has its own random stream: the start floor's
  // run is the same either way).
  for (int floor = 0; floor < static_cast<int>(sessions_.size()); ++floor) Session(floor);
}

namespace {
BuildingSessionOptions WithSession(BuildingSessionOptions options, const TextAmclSessionOptions& session) {
  options.session = session;
  return options;
}
}  // namespace

BuildingSession::BuildingSession(const BuildingSession& previous, const TextAmclSessionOptions& session)
    : options_(WithSession(previous.options_, session)),
      maps_(previous.maps_),
      rooms_(previous.rooms_),
      belief_(previous.belief_),
      current_(previous.current_),
      floor_switches_(previous.floor_switches_),
      events_(previous.events_),
      readings_(previous.readings_) {
  for (size_t floor = 0; floor < previous.sessions_.size(); ++floor) {
    const FloorMaps& maps = maps_->floors[floor];
    TextAmclSessionOptions o = options_.session;
    o.setup.filter.random_seed += static_cast<unsigned>(floor);  // as Session(): the stream itself carries over
    try {
      sessions_.push_back(std::make_unique<TextAmclSession>(o, maps.grid, *previous.sessions_[floor]));
    } catch (const std::exception& e) {
      throw std::invalid_argument("floor '" + maps.id + "': " + e.what());
    }
  }
}

TextAmclSession& BuildingSession::Session(int floor) {
  std::unique_ptr<TextAmclSession>& slot = sessions_[static_cast<size_t>(floor)];
  if (slot) return *slot;
  const FloorMaps& maps = maps_->floors[static_cast<size_t>(floor)];
  TextAmclSessionOptions o = options_.session;
  o.setup.filter.random_seed += static_cast<unsigned>(floor);
  // The start floor's session starts as configured; a floor switched to later, with global localization.
  const bool first = std::none_of(sessions_.begin(), sessions_.end(), [](const auto& s) { return s != nullptr; });
  if (!first) o.start_with_global_localization = true;
  try {
    slot = std::make_unique<TextAmclSession>(o, maps.grid, maps.text_map);
  } catch (const std::exception& e) {
    throw std::invalid_argument("floor '" + maps.id + "': " + e.what());
  }
  return *slot;
}

const std::string& BuildingSession::floor_id() const { return maps_->floors[static_cast<size_t>(current_)].id; }

TextAmclStatus BuildingSession::Status() const {
  TextAmclStatus status = session().Status();
  if (status.state == LocalizationState::kConverged && !floor_certain()) status.state = LocalizationState::kTracking;
  return status;
}

void BuildingSession::Initialize(int floor, const Pose2D& mean, const Eigen::Matrix3d& covariance) {
  if (floor < 0 || floor >= static_cast<int>(sessions_.size())) {
    throw std::invalid_argument("BuildingSession::Initialize: no floor index " + std::to_string(floor));
  }
  Session(floor).Initialize(mean, covariance);
  floor_changed_ = floor != current_;
  current_ = floor;
  belief_.Reset(floor);
}

void BuildingSession::GlobalLocalization() {
  Current().GlobalLocalization();  // first: if it threw, the belief would be left as it was
  belief_.Reset(sessions_.size() == 1 ? 0 : -1);
}

void BuildingSession::Forget(double now_s) {
  const double oldest = now_s - options_.session.odometry_history_s;
  while (!events_.empty() && events_.front().stamp_s < oldest) events_.pop_front();
  while (!readings_.empty() && readings_.front().stamp_s < oldest) readings_.pop_front();
}

void BuildingSession::Remember(double stamp_s, const Pose2D& base_in_odom, const LaserScan* scan) {
  if (!events_.empty() && stamp_s < events_.back().stamp_s) return;
  if (scan) {
    // Keep the scans of the last two scan events only (what a session's plate range rule looks at).
    int scans = 0;
    for (auto it = events_.rbegin(); it != events_.rend(); ++it) {
      if (it->scan && ++scans >= 2) it->scan.reset();
    }
  }
  events_.push_back({stamp_s, base_in_odom, scan ? std::optional<LaserScan>(*scan) : std::nullopt});
  Forget(stamp_s);
}

SessionUpdate BuildingSession::AddOdometry(double stamp_s, const Pose2D& base_in_odom) {
  floor_changed_ = false;
  const SessionUpdate update = Current().AddOdometry(stamp_s, base_in_odom);
  Remember(stamp_s, base_in_odom, nullptr);
  return update;
}

SessionUpdate BuildingSession::AddScan(double stamp_s, const Pose2D& base_in_odom, const LaserScan& scan) {
  floor_changed_ = false;
  const SessionUpdate update = Current().AddScan(stamp_s, base_in_odom, scan);  // throws for a bad scan
  Remember(stamp_s, base_in_odom, &scan);
  return update;
}

std::vector<bool> BuildingSession::FloorsWithRoom(const std::string& text) const {
  const std::string room = CanonicalRoomId(text);
  std::vector<bool> has(rooms_.size());
  for (size_t f = 0; f < rooms_.size(); ++f) has[f] = rooms_[f].count(room) > 0;
  return has;
}

SessionUpdate BuildingSession::AddPlates(double stamp_s, const std::vector<PlateReading>& readings) {
  floor_changed_ = false;
  for (const PlateReading& reading : readings) {
    if (!ValidatePlateReading(reading).empty()) continue;  // the session reports it
    belief_.Update(FloorsWithRoom(reading.text));
    TimedReading timed{stamp_s, reading};
    const auto at = std::upper_bound(readings_.begin(), readings_.end(), stamp_s,
                                     [](double s, const TimedReading& r) { return s < r.stamp_s; });
    readings_.insert(at, std::move(timed));
  }
  const int certain = belief_.CertainFloor();
  if (certain >= 0 && certain != current_) return SwitchTo(certain);  // the replay includes these readings
  return Current().AddPlates(stamp_s, readings);
}

SessionUpdate BuildingSession::SwitchTo(int floor) {
  TextAmclSession& session = Session(floor);
  session.GlobalLocalization();
  current_ = floor;
  floor_changed_ = true;
  ++floor_switches_;
  SessionUpdate total;
  for (const Event& event : events_) {
    Append(event.scan ? session.AddScan(event.stamp_s, event.base_in_odom, *event.scan)
                      : session.AddOdometry(event.stamp_s, event.base_in_odom),
           &total);
  }
  for (const TimedReading& timed : readings_) Append(session.AddPlates(timed.stamp_s, {timed.reading}), &total);
  total.estimate_changed = true;
  return total;
}

}  // namespace doorplate_localization
