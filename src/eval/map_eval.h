// `doorplate_eval map` (paper Table II): one drive in the simulator, every laser scan fed to the mapping
// session (slam/mapping_session.h, the loop the nodelet runs) with the odometry pose, and for method
// rbpf_text every rendered camera frame through the real text extractor, its reports fed to
// MappingSession::AddPlates (stamped now, with the odometry now); MappingSession::Solve() once at the end.
// The drive is a corridor sweep (out along one wall, turn, back along the other; CorridorSweep) or, for a
// whole floor, FloorExplorer's passes (issue 17), which end on re-read plates: the extractor then runs for
// both methods, so both drive the same way. The result is measured on the output maps (map_measure.h).
// ROS-free, in-process, deterministic for a seed.
#pragma once

#include <cstdint>
#include <string>

#include "doorplate_localization/behaviour/corridor_sweep.h"
#include "doorplate_localization/behaviour/floor_explorer.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/sim/world.h"
#include "doorplate_localization/slam/text_slam.h"
#include "doorplate_localization/text/text_extractor.h"
#include "floor_measure.h"
#include "map_measure.h"
#include "plate_alignment.h"

namespace doorplate_localization {

enum class MapMethod { kRbpf, kRbpfText };
// "rbpf" / "rbpf_text"; ParseMapMethod throws std::invalid_argument for anything else.
const char* MapMethodName(MapMethod method);
MapMethod ParseMapMethod(const std::string& name);

// kSweep: one corridor out and back, then the run ends; kPatrol: the same again and again until max_time_s
// (the wall follower's ~mode patrol: a long run over mapped ground); kExplore: FloorExplorer's passes.
enum class MapDrive { kSweep, kPatrol, kExplore };
// "sweep" / "patrol" / "explore"; ParseMapDrive throws std::invalid_argument for anything else.
const char* MapDriveName(MapDrive drive);
MapDrive ParseMapDrive(const std::string& name);

struct MapEvalOptions {
  MapMethod method = MapMethod::kRbpfText;
  std::uint64_t seed = 1;            // simulator seed; the filter's seed is derived from it
  double speed_mps = 0.4;            // cruise speed of the sweep
  double max_time_s = 1800.0;        // simulated seconds after which an unfinished sweep stops
  // slam.num_particles etc.; slam.seed is overwritten from `seed`. The command starts method rbpf from
  // RbpfSlamOptions' defaults and rbpf_text from TextSlamOptions' (DefaultTextSlamLaserOptions).
  TextSlamOptions slam;
  TextExtractorOptions extractor;    // fx/cx are set from the simulated camera
  double progress_every_s = 0.0;     // > 0: a progress line on stderr every this many simulated seconds
  MapDrive drive = MapDrive::kSweep;
  CorridorSweepOptions sweep;        // drive kSweep (cruise speed from speed_mps)
  FloorExplorerOptions explore;      // drive kExplore (cruise speed from speed_mps)
  // > 0: the session also solves the back end every this many simulated seconds (MappingSessionOptions::
  // map_update_interval_s, the nodelet's ~map_update_interval); each solve is recorded in `solves`.
  double map_update_interval_s = 0.0;
};

// One back-end solve of the run (the periodic ones and the final one).
struct MapEvalSolve {
  double sim_time_s = 0.0;
  double wall_s = 0.0;               // wall clock of MappingSession::Solve (solve + maps rebuilt)
  int nodes = 0;                     // back-end nodes (0: back end off)
  int nodes_on_mapped_ground = 0;    // of them, kept without their scan
  int loop_closures = 0;             // in the solved graph
  int loop_alignments_computed = 0;  // loop-closure alignments run (SlamBackEndResult)
  int loop_alignments_reused = 0;    // ... taken from the previous solve (same nodes and guess)
};

struct MapEvalResult {
  std::string world_name;
  bool sweep_done = false;           // the drive ended by itself (sweep: done; explore: every pass ended;
                                     // patrol: at least one sweep done)
  int sweeps_done = 0;               // sweep / patrol: out-and-back sweeps completed
  std::vector<int> pass_end_scans;   // explore: processed-scan index at which each pass ended
  std::vector<std::string> pass_ends;  // explore: why each pass ended (PassEndName)
  // explore: position error of the mapped trajectory at each pass end (the start aligned): where a
  // pass closes its loop, this is the loop's closing error.
  std::vector<double> pass_end_errors_m;
  double distance_m = 0.0;           // driven (true path length)
  double sim_seconds = 0.0;          // simulated duration of the sweep
  double seconds = 0.0;              // wall clock of the whole run (simulation, rendering, OCR, SLAM)
  double slam_seconds = 0.0;         // thread CPU time inside the SLAM calls (AddScan + AddPlate)
  double map_build_seconds = 0.0;    // thread CPU time of building the final maps (back end solve + render)
  int scans = 0;                     // scans fed
  int scans_processed = 0;
  int degenerate_scans = 0;          // processed scans the degeneracy-aware proposal found degenerate
  long peak_rss_kb = 0;              // of the process, at the end of the run (VmHWM)
  CorridorExtent truth;              // from the world's walls
  CorridorExtent estimate;           // from the SLAM grid
  double length_accuracy = 0.0;
  double width_accuracy = 0.0;
  int plate_reports = 0;             // extractor reports fed to AddPlate
  int plate_reports_used = 0;
  int plate_ranges_from_wall = 0;    // MappingSession: ranges from the wall line (something before the plate)
  PlateScore plates;                 // under the start-pose alignment (world_from_map)
  PlateAlignment plate_fit;          // the best rigid fit of the mapped plates onto the true ones
  PlateScore plates_fitted;          // the plates scored under plate_fit.world_from_map (if ok)
  std::vector<CorridorAccuracy> corridors;  // per corridor of the world's `corridors` (start-pose alignment)
  Pose2D world_from_map;             // the map frame in the world: the start pose, odometry at the first scan
  double final_position_error_m = 0.0;  // final estimate (back end, else best particle) vs the truth
  double trajectory_rmse_m = 0.0;    // position error of `trajectory` against the truth, per processed scan
  double trajectory_max_error_m = 0.0;
  OutLeg out_leg;                    // the out leg's length as `trajectory` has it (MeasureOutLeg)
  double odometry_scale = 1.0;       // back end's estimate of true ÷ odometry distance (1 if off)
  double odometry_heading_drift_rad_per_m = 0.0;  // back end's heading drift estimate (0 if off)
  int loop_closures = 0;             // back end's scan-alignment loop closures (in the final graph)
  int loop_closures_dropped = 0;     // ... dropped by its consistency check
  int nodes_on_mapped_ground = 0;    // back-end nodes added without their scan (max_nodes_per_place)
  std::vector<MapEvalSolve> solves;  // every solve, in order (the last: the final maps')
  OccupancyGrid grid;
  TextMap text_map;                  // empty landmarks for method rbpf
  std::vector<Pose2D> trajectory;    // TextSlam::Trajectory(): back end poses (else best particle's), map frame
  std::vector<Pose2D> true_trajectory;  // true pose at each processed scan, map frame (same order)
};

// Throws std::invalid_argument for bad options, whatever the components throw for their options.
MapEvalResult RunMapEval(const World& world, const MapEvalOptions& options);

}  // namespace doorplate_localization
