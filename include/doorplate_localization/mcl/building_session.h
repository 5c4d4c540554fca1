// BuildingSession: Text AMCL on a building of several floors (issue 17 item 5). One TextAmclSession per
// floor (all made at construction, the start floor's first), one of them current; a FloorBelief (floor_belief.h) over the
// floors, updated by every plate reading. The current session gets the odometry, scans and readings; when
// the belief becomes certain of another floor (a plate of floor 3 while on floor 2's map: after a lift ride,
// or from an unknown start) the building switches maps without a restart: the new floor's session starts
// global localization, gets the recent odometry and scans again (the last odometry_history_s) and the
// recent readings, so the plates that decided the floor also place the robot on it.
//
// Reported state: the current session's, except that kConverged is reported only while the current floor
// is certain (FloorBelief::CertainFloor): a pose on a floor the plates have not confirmed is not a fix.
// A one-floor building behaves exactly as its TextAmclSession (the belief is certain and never changes):
// `doorplate_eval localize` runs every world through this class.
//
// Frames: each floor's map frame; odom and base_link as in text_amcl_session.h (odometry continues across
// floors: a lift ride moves the robot without odometry seeing it). Units: metres, radians, seconds.
// Deterministic for a given random_seed and input sequence (floor f's filter uses random_seed + f).
#pragma once

#include <deque>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/mcl/floor_belief.h"
#include "doorplate_localization/mcl/text_amcl_session.h"

namespace doorplate_localization {

struct BuildingSessionOptions {
  // Every floor's session (start_with_global_localization and initial_pose apply to the start floor; a
  // floor switched to later always starts with global localization). Its odometry_history_s is also how
  // far back a switch replays.
  TextAmclSessionOptions session;
  FloorBeliefOptions floor_belief;
  // The floor the robot starts on (a BuildingFloor id), or "" when unknown: the belief starts uniform and
  // the first floor's map is current until the plates decide. With one floor "" means that floor.
  std::string start_floor;
};

class BuildingSession {
 public:
  // `maps` must have >= 1 floor, each with a text map (may be null only with use_text false, then there
  // is nothing to tell floors apart). Throws std::invalid_argument naming the field of a bad option, an
  // unknown start_floor, or a floor whose map the session refuses ("floor '3': ...").
  BuildingSession(const BuildingSessionOptions& options, std::shared_ptr<const BuildingMaps> maps);

  // Goes on from `previous` with new session options (dynamic_reconfigure): every floor's session continues
  // from its previous one (TextAmclSession's continuing constructor: the particles are kept); the floor
  // belief, current floor and replay window carry over. Throws std::invalid_argument ("floor '3': ...")
  // as the other constructor; `previous` is never changed.
  BuildingSession(const BuildingSession& previous, const TextAmclSessionOptions& session);

  // amcl's initialpose on a floor (`floor` index): that floor becomes current and certain.
  void Initialize(int floor, const Pose2D& mean, const Eigen::Matrix3d& covariance);
  // amcl's global_localization: the floor is unknown again (uniform belief), the current floor's session
  // restarts global localization; the plates will pick the floor.
  void GlobalLocalization();
  void RequestNoMotionUpdate() { Current().RequestNoMotionUpdate(); }

  // As TextAmclSession's; the readings also update the floor belief (before they reach a session), and
  // may switch the floor (floor_changed() says so; the switch's replayed readings are in the update).
  SessionUpdate AddOdometry(double stamp_s, const Pose2D& base_in_odom);
  SessionUpdate AddScan(double stamp_s, const Pose2D& base_in_odom, const LaserScan& scan);
  SessionUpdate AddPlates(double stamp_s, const std::vector<PlateReading>& readings);

  // --- state (as left by the last call) ---
  int floor() const { return current_; }  // index into maps().floors
  const std::string& floor_id() const;
  bool floor_certain() const { return belief_.CertainFloor() == current_; }
  const FloorBelief& belief() const { return belief_; }
  bool floor_changed() const { return floor_changed_; }  // by the last call
  int floor_switches() const { return floor_switches_; }
  const TextAmclSession& session() const { return *sessions_[static_cast<size_t>(current_)]; }
  const PoseEstimate& Estimate() const { return session().Estimate(); }
  // The current session's status with kConverged demoted to kTracking while the floor is not certain.
  TextAmclStatus Status() const;
  const std::optional<Pose2D>& MapToOdom() const { return session().MapToOdom(); }
  Pose2D PoseAtOdometry(const Pose2D& base_in_odom) const { return session().PoseAtOdometry(base_in_odom); }
  const BuildingMaps& maps() const { return *maps_; }

 private:
  struct Event {  // an input of the current session, kept for a switch's replay
    double stamp_s;
    Pose2D base_in_odom;
    std::optional<LaserScan> scan;
  };
  struct TimedReading {
    double stamp_s;
    PlateReading reading;
  };

  TextAmclSession& Current() { return *sessions_[static_cast<size_t>(current_)]; }
  TextAmclSession& Session(int floor);  // made on first use (the constructor uses every floor)
  void Remember(double stamp_s, const Pose2D& base_in_odom, const LaserScan* scan);
  void Forget(double now_s);
  std::vector<bool> FloorsWithRoom(const std::string& text) const;
  // Makes `floor` current with global localization and replays the recent inputs into it.
  SessionUpdate SwitchTo(int floor);

  const BuildingSessionOptions options_;
  const std::shared_ptr<const BuildingMaps> maps_;
  std::vector<std::set<std::string>> rooms_;  // per floor: canonical room ids of its text map
  std::vector<std::unique_ptr<TextAmclSession>> sessions_;
  FloorBelief belief_;
  int current_ = 0;
  bool floor_changed_ = false;
  int floor_switches_ = 0;
  std::deque<Event> events_;          // stamp order, within odometry_history_s of the newest
  std::deque<TimedReading> readings_; // stamp order, the same window
};

}  // namespace doorplate_localization
