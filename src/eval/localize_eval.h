// The global-localization experiment of the paper's Section 4.2 (Table III) and kidnapped-robot trials on
// a simulated world. Each trial puts the robot at a random pose in the main corridor, or anywhere on a floor
// whose world lists its corridors (StartPoseSampler: heading along the corridor ± heading noise), starts
// the filter with global localization (max_particles uniform over the free cells) and lets the robot
// search in the Simulator (physics 100 Hz, laser and control at the laser's rate) with one of two drives:
// kPatrol, the paper's strategy (Sec. 3.4: follow a wall along the corridor, turn around at the end —
// CorridorSweep, restarted whenever a sweep ends), or kContour, for floors of several corridors
// (ContourSteering: follow one wall wherever it leads, round corners, into side corridors and out of dead
// ends; it never ends). The drive only moves the robot: the filter's loop is the same for both. The filter runs in a TextAmclSession
// (mcl/text_amcl_session.h), the loop the Text AMCL nodelet runs: scans with their odometry, plate readings
// with the odometry of their moment, its ordering, range and unknown-room rules. With text_amcl every camera
// image goes to the real TextExtractor and each plate report becomes a PlateReading for the session; amcl
// ignores readings, so its trials do not render the camera (the robot's motion is the same either way).
// A trial ends when the filter first reports kConverged (paper: "when the particles were converged to one
// cluster, the localization process ended"): success if the estimate — the session's map→odom composed
// with the current odometry (the heaviest cluster's mean carried to now) — is within
// success_distance_m and success_angle_rad of the true pose, else a wrong convergence; or, unconverged,
// after max_travel_m of driving (failure).
// Kidnap trials (kidnap = true): after a successful convergence the robot is teleported to another random
// corridor pose (odometry does not see it), the filter is left alone and the robot keeps searching; it
// recovers when the filter is kConverged with the estimate within the success tolerance of the truth before
// it has driven max_travel_m more.
// Buildings of several floors (issue 17 item 5; LocalizeBuilding): each trial starts on a floor drawn
// uniformly (then a pose on it as above), the filter is a BuildingSession (mcl/building_session.h) that
// does not know the floor: the plates pick it. A kidnap is a lift ride: a floor drawn uniformly (the same
// one again or another; the simulator's ChangeWorld), a pose on it. A fix is within tolerance only on the
// right floor. With one floor (every Table III world) nothing is drawn for the floor and the
// BuildingSession is its TextAmclSession: the trials are those of before, draw for draw.
// Deterministic for a given seed (trial i uses PassSeed(seed, i) for the simulator, the poses and the
// filter), except the timings.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "doorplate_localization/behaviour/contour_steering.h"
#include "doorplate_localization/behaviour/corridor_sweep.h"
#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/mcl/particle.h"
#include "doorplate_localization/mcl/text_amcl_setup.h"
#include "doorplate_localization/sim/world.h"
#include "doorplate_localization/text/text_extractor.h"
#include "localize_start_poses.h"

namespace doorplate_localization {

enum class LocalizeMethod { kAmcl, kTextAmcl };
// "amcl", "text_amcl".
const char* ToString(LocalizeMethod method);

// How the robot searches: kPatrol = CorridorSweep out and back (one corridor), kContour = ContourSteering
// along one wall wherever it leads (a floor).
enum class LocalizeDrive { kPatrol, kContour };
// "patrol", "contour"; ParseLocalizeDrive throws std::invalid_argument naming anything else.
const char* ToString(LocalizeDrive drive);
LocalizeDrive ParseLocalizeDrive(const std::string& name);

struct LocalizeEvalOptions {
  LocalizeMethod method = LocalizeMethod::kTextAmcl;
  int trials = 30;
  std::uint64_t seed = 1;
  bool kidnap = false;
  double max_travel_m = 120.0;          // per search (and again after a kidnap)
  double speed_mps = 0.4;               // cruise speed (of sweep.follower and of contour)
  LocalizeDrive drive = LocalizeDrive::kPatrol;
  double success_distance_m = 0.3;
  double success_angle_rad = 10.0 * M_PI / 180.0;
  double camera_rate_hz = 0.0;          // 0: the world's camera rate
  bool known_rooms = false;             // give the text validator the text map's room list
  TextAmclSetupOptions filter;          // use_text and the random seed are set per trial
  CorridorSweepOptions sweep;           // drive kPatrol
  ContourSteeringOptions contour;       // drive kContour (cruise_speed_mps is set from speed_mps)
  TextExtractorOptions extractor;       // known rooms and the tracker intrinsics are set from the run
  StartPoseSamplerOptions poses;
  // > 0: a progress line on stderr (trial, simulated seconds, distance driven, the particles' spread, plates
  // used, filter state) every this many simulated seconds of the run, rewritten in place on a terminal
  // (progress_line.h).
  double progress_every_s = 0.0;
};

// The filter's estimate compared with the truth at one moment.
struct LocalizeFix {
  double travel_m = 0.0;       // driven since the search started (start or kidnap)
  double sim_time_s = 0.0;
  Pose2D estimate;             // map frame, carried to this moment by odometry
  Pose2D truth;
  std::string floor;           // the filter's current floor (BuildingFloor id)
  std::string true_floor;
  double error_m = 0.0;
  double error_deg = 0.0;      // |heading error|
  bool within_tolerance = false;  // the right floor, and the pose within the success tolerance
};

struct LocalizeTrial {
  int index = 0;
  std::uint64_t seed = 0;
  Pose2D start_pose;
  std::string start_floor;
  // Travel until the filter was first certain of the true floor (FloorBelief), −1 if never; buildings of
  // several floors only (after a kidnap: kidnap_floor_travel_m).
  double floor_travel_m = -1.0;
  bool converged = false;      // reached kConverged within max_travel_m
  LocalizeFix fix;             // at convergence, or at the end of the search if it never converged
  int plate_reports = 0;       // reports of the text extractor during the whole trial (search and recovery)
  int plate_updates = 0;       // of them, used by the filter (PlateUpdateResult::used)
  int laser_updates = 0;
  // Kidnap (only when kidnap = true and the first convergence succeeded).
  bool kidnapped = false;
  Pose2D kidnap_pose;
  std::string kidnap_floor;
  double kidnap_floor_travel_m = -1.0;
  bool lost_detected = false;  // the filter entered kLost after the kidnap
  double lost_detected_travel_m = 0.0;
  std::string lost_reason;     // LostReason of the first kLost after the kidnap
  bool recovered = false;
  LocalizeFix recovery;        // at recovery, or at the end of the kidnap search
  double sim_seconds = 0.0;
  double wall_seconds = 0.0;

  bool Success() const { return converged && fix.within_tolerance; }
  bool WrongConvergence() const { return converged && !fix.within_tolerance; }
};

struct LocalizeEvalResult {
  std::string world_name;
  LocalizeMethod method = LocalizeMethod::kTextAmcl;
  bool kidnap = false;
  bool floor_start_poses = false;  // poses drawn over the world's corridors (else the main corridor band)
  std::vector<std::string> floors; // the building's floor ids (one for a world)
  std::vector<LocalizeTrial> trials;
  double seconds = 0.0;  // wall clock, whole run
};

// Totals over the trials. Medians of the travel and errors are over the converged trials (successes and
// wrong convergences), recovery travel over the recovered trials; 0 when there are none.
struct LocalizeSummary {
  int trials = 0, successes = 0, wrong_convergences = 0, not_converged = 0;
  int wrong_floor = 0;  // converged on another floor than the robot's (counted in wrong_convergences)
  double median_floor_travel_m = 0.0;  // over trials whose floor became certain (buildings only)
  // Of the not converged trials, those whose heaviest cluster was nevertheless within the tolerance at the
  // end of the search (a laser-only filter in a symmetric corridor: a coin toss between mirror images).
  int not_converged_estimate_right = 0;
  double success_rate = 0.0;
  double median_travel_m = 0.0, median_final_error_m = 0.0, median_final_error_deg = 0.0;
  double longest_travel_m = 0.0;  // of the converged trials
  int kidnaps = 0, recoveries = 0, kidnap_lost_detected = 0;
  double recovery_rate = 0.0;  // recoveries / kidnaps
  double median_recovery_travel_m = 0.0;
};

LocalizeSummary Summarize(const LocalizeEvalResult& result);

// The spread of a particle set: RMS distance of the particles' positions from their mean, metres (0 for
// fewer than two); the measure of scripts/mission_progress.py on particlecloud.
double ParticleSpreadM(const std::vector<Particle>& particles);

// Runs the experiment on `world` with the map the filter knows: `grid` (occupancy) and `text_map` (may be
// null for amcl; required for text_amcl). `ground_truth_grid` rejects start poses near obstacles (usually
// the same grid). Throws std::invalid_argument / std::runtime_error naming the field or file.
LocalizeEvalResult RunLocalizeEval(const World& world, const OccupancyGrid& grid,
                                   std::shared_ptr<const TextMap> text_map, const OccupancyGrid& ground_truth_grid,
                                   const LocalizeEvalOptions& options);

// A building to run the trials in: one simulator world per floor, index-aligned with maps->floors (the
// maps the filter knows; text maps required for text_amcl), and per floor the ground-truth grid that
// rejects start poses near obstacles.
struct LocalizeBuilding {
  std::string name;
  std::vector<World> worlds;
  std::shared_ptr<const BuildingMaps> maps;
  std::vector<OccupancyGrid> ground_truth_grids;
};
LocalizeEvalResult RunLocalizeEval(const LocalizeBuilding& building, const LocalizeEvalOptions& options);

// The maps a localization session gets: `maps` with use_text, else a copy without its text maps (amcl).
std::shared_ptr<const BuildingMaps> SessionMaps(std::shared_ptr<const BuildingMaps> maps, bool use_text);

// A world as a one-floor building (floor id = the world's name) with the maps the robot knows.
LocalizeBuilding OneFloorBuilding(World world, OccupancyGrid grid, std::shared_ptr<const TextMap> text_map,
                                  OccupancyGrid ground_truth_grid);

}  // namespace doorplate_localization
