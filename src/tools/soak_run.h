// The soak run (issue 8): the simulator drives the robot back and forth along the corridor (corridor
// sweeps, a new one as soon as one ends) with laser, camera, the text extractor and — optionally — Text
// AMCL tracking it, in-process and as fast as the CPU goes, for a long simulated time. Every
// `window_s` simulated seconds it records the process's resident memory, the wall time the window took
// (so the update rates) and what went wrong, so a long run shows whether memory and speed stay flat.
// With a fault schedule (fault_run.h) it also injects faults and reports how localization recovers.
// A last, shorter window is reported when the run ends inside a window.
// ROS-free. Frames: poses are base_link in the map frame (the world frame of the simulator).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "doorplate_localization/sim/world.h"
#include "fault_run.h"

namespace doorplate_localization::tools {

struct SoakOptions {
  double duration_s = 3600.0;   // simulated
  double window_s = 300.0;      // simulated seconds per reported window
  double camera_rate_hz = 0.0;  // frames through the text extractor per simulated second; 0: the world's rate
  double speed_mps = 0.4;       // cruise speed of the sweep
  bool localizer = true;        // run Text AMCL (a TextAmclSession) on the ground-truth maps of the world
  int max_particles = 2000;     // of the localizer
  std::uint64_t seed = 1;       // simulator noise, filter and kidnap poses
  // Faults to inject (fault_run.h; needs the localizer). With a schedule the run ends when the last
  // fault has recovered or given up, or at duration_s, whichever comes first.
  FaultOptions faults;
};

struct SoakWindow {
  double end_sim_s = 0.0;
  double wall_s = 0.0;                 // wall-clock time the window took (depends on the machine's load)
  double cpu_s = 0.0;                  // CPU time of this process in the window (does not)
  double rss_mb = 0.0;                 // VmRSS at the window's end
  long long scans = 0;                 // laser scans simulated and fed to the sweep (and the filter)
  long long frames = 0;                // camera images rendered and given to the text extractor
  long long plate_reports = 0;         // reports of the extractor
  long long filter_updates = 0;        // laser updates the filter used
  double mean_error_m = 0.0;           // localizer: mean |estimate - truth| over the window's scans
  double max_error_m = 0.0;
  long long converged_scans = 0;       // scans after which the filter was kConverged
  long long errors = 0;                // exceptions caught from any component (each printed to stderr)
  int sweeps_completed = 0;
};

struct SoakResult {
  double start_rss_mb = 0.0;           // after loading the world, building the maps, the extractor and filter
  std::vector<SoakWindow> windows;
  double distance_m = 0.0;             // driven by the robot
  long long errors = 0;
  std::vector<std::string> first_errors;  // messages of the first few errors
  std::vector<FaultReport> faults;        // one per fault of the schedule that started and ended
};

// Runs the soak. Throws std::invalid_argument for bad options (field named) and whatever building the
// components throws (a missing Tesseract model, ...); errors during the run are counted, not thrown.
SoakResult RunSoak(const World& world, const SoakOptions& options);

// Resident set size of this process in MB (VmRSS of /proc/self/status), 0 if unreadable.
double ResidentMegabytes();

// CPU time this process has used, seconds (all threads).
double ProcessCpuSeconds();

}  // namespace doorplate_localization::tools
