// doorplate_map_rawlog: maps an MRPT rawlog (action-observation pairs: CActionRobotMovement2D odometry
// increments, CObservation2DRangeScan scans, read with MRPT's own CRawlog) offline through the mapping
// session the mapping nodelet runs (slam/mapping_session.h, no plates, same option table; one scan per
// action-observation pair, stamped by the pair's index in seconds), writes DIR/map.{pgm,yaml} (the solved map) and
// DIR/trajectory.txt (`scan_index x y theta`, posterior mean) atomically, and prints the final pose: the
// best particle's pose at the end of the log, in the map frame (= the odometry frame of the first
// scan; the rawlog's odometry starts at the origin). With --expect "x y yaw_deg" it also prints the
// difference to that pose, e.g. MRPT's own regression value for the Málaga Telecom Faculty loop
// (RBPF_SLAM_App_unittest: [3.4548 -18.0399 -86.48 deg], passed when the SE(3) log of the difference
// is below 1.0), and exits 3 if it is not below --max-error (default 1.0). A progress line on stderr every
// few seconds (progress_line.h).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>

#include "cli_app.h"
#include "map_tool_output.h"
#include "output_guard.h"
#include "progress_line.h"
#include "rawlog_reader.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/slam/mapping_session.h"
#include "doorplate_localization/slam/rbpf_slam_options.h"

namespace dl = doorplate_localization;
namespace tools = dl::tools;
using tools::UsageError;

namespace {

const char kDescription[] = "Maps an MRPT rawlog offline through the mapping nodelet's session.";
const char kNotes[] =
    "e.g. /usr/share/mrpt/datasets/'2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog' (mrpt-common)\n"
    "--expect \"3.4548 -18.0399 -86.48\" (MRPT's regression value for it): exit status 3 when the final pose\n"
    "is not within --max-error of it.";

struct Args {
  std::string rawlog, out_dir, sensor_label, expect;
  std::vector<std::string> sets;
  bool has_expected = false;
  dl::Pose2D expected;
  double max_error = 1.0, progress_s = 5.0;
  dl::MappingSessionOptions options;
};

void AddOptions(CLI::App* app, Args* args) {
  app->footer(kNotes);
  app->add_option("RAWLOG", args->rawlog, "the MRPT rawlog")->required();
  app->add_option("--out-dir", args->out_dir, "output folder DIR")->required();
  app->add_option("--seed", args->options.slam.slam.seed, "filter seed")->capture_default_str()->transform(tools::Seed());
  app->add_option("--set", args->sets, "NAME=VALUE: a SLAM option of the one option table (repeatable)")
      ->allow_extra_args(false);
  app->add_option("--sensor-label", args->sensor_label, "use only the scans of this sensor label");
  app->add_option("--expect", args->expect, "\"X Y YAW_DEG\": the final pose expected");
  app->add_option("--max-error", args->max_error, "|log| of the difference to --expect below which it passes")
      ->capture_default_str()->check(tools::Number());
  app->add_option("--progress-s", args->progress_s, "a progress line on stderr every this many seconds (rewritten in "
                  "place twice a second on a terminal; 0: none)")->capture_default_str()->check(tools::Number(0.0));
  app->callback([args] {
    for (const std::string& set : args->sets) {
      tools::ApplySetOption(set, [&](const std::string& name, double v) { dl::SetTextSlamOption(name, v, &args->options.slam); });
    }
    if (args->expect.empty()) return;
    std::istringstream in(args->expect);
    double yaw_deg = 0;
    if (!(in >> args->expected.x_m >> args->expected.y_m >> yaw_deg)) throw UsageError("--expect: want \"X Y YAW_DEG\"");
    args->expected.theta_rad = yaw_deg * M_PI / 180.0;
    args->has_expected = true;
  });
}

// An MRPT scan as the core's LaserScan: MRPT's beam angles (getScanAngle), invalid beams at the device's
// maximum range as no echo (+inf), other invalid beams skipped (NaN); the mounting's x, y, yaw.
dl::LaserScan ToLaserScan(const mrpt::obs::CObservation2DRangeScan& obs) {
  dl::LaserScan scan;
  const std::size_t n = obs.getScanSize();
  scan.angle_min_rad = obs.getScanAngle(0);
  scan.angle_increment_rad = n > 1 ? obs.getScanAngle(1) - obs.getScanAngle(0) : 0.0;
  scan.ranges_m.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float r = obs.getScanRange(i);
    if (obs.getScanRangeValidity(i)) scan.ranges_m[i] = r;
    else if (r >= 0.99f * obs.maxRange) scan.ranges_m[i] = std::numeric_limits<float>::infinity();
    else scan.ranges_m[i] = std::numeric_limits<float>::quiet_NaN();
  }
  scan.laser_pose = {obs.sensorPose.x(), obs.sensorPose.y(), obs.sensorPose.yaw()};
  return scan;
}

// ‖log(Δ)‖ of the planar difference Δ = expected⁻¹ ⊕ actual in SE(2) (= MRPT's SE(3) log norm for
// planar poses): the rotation angle and the translation mapped through V(θ)⁻¹.
double LogNorm(const dl::Pose2D& expected, const dl::Pose2D& actual) {
  const dl::Pose2D d = expected.Between(actual);
  const double t = d.theta_rad;
  double a = 1.0, b = 0.0;  // V = a I + b J
  if (std::fabs(t) > 1e-9) {
    a = std::sin(t) / t;
    b = (1.0 - std::cos(t)) / t;
  }
  const double det = a * a + b * b;
  const double ux = (a * d.x_m + b * d.y_m) / det, uy = (-b * d.x_m + a * d.y_m) / det;
  return std::sqrt(ux * ux + uy * uy + t * t);
}

int Run(const Args& args) {
  const tools::Stopwatch clock;
  tools::RefuseOverwritingInputs({{"RAWLOG", args.rawlog}},
                                 {{"--out-dir", args.out_dir + "/map.pgm"}, {"--out-dir", args.out_dir + "/map.yaml"},
                                  {"--out-dir", args.out_dir + "/trajectory.txt"}});
  std::filesystem::create_directories(args.out_dir);
  mrpt::obs::CRawlog rawlog;
  tools::LoadRawlog(args.rawlog, &rawlog);  // RawlogError naming the file, without MRPT's call stack
  dl::MappingSession session(args.options);
  const dl::RbpfSlam& filter = session.slam().slam();
  dl::Pose2D odometry;
  mrpt::obs::CActionCollection::Ptr actions;
  mrpt::obs::CSensoryFrame::Ptr frame;
  std::size_t entry = 0;
  int scans = 0, pairs = 0;
  double driven_m = 0.0;  // odometry path length
  tools::ProgressLine progress({args.progress_s});
  while (entry < rawlog.size() && rawlog.getActionObservationPair(actions, frame, entry)) {
    ++pairs;
    if (progress.Due(clock.Seconds())) {
      const dl::RbpfSlamStats& s = filter.stats();
      progress.Show("doorplate_map_rawlog: entry %zu/%zu, %.1f m driven, %d scans, processed %d, neff %.1f, %.1f s, "
                    "peak RSS %.0f MB", entry, rawlog.size(), driven_m, scans, s.scans_processed, s.last_neff,
                    clock.Seconds(), tools::PeakRssMb());
    }
    if (actions) {
      if (const auto move = actions->getBestMovementEstimation()) {
        const mrpt::poses::CPose2D d = move->poseChange->getMeanVal();
        odometry = odometry.Compose({d.x(), d.y(), d.phi()});
        driven_m += std::hypot(d.x(), d.y());
      }
    }
    if (!frame) continue;
    for (const auto& obs : *frame) {
      const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs);
      if (!scan || scan->getScanSize() < 2) continue;
      if (!args.sensor_label.empty() && scan->sensorLabel != args.sensor_label) continue;
      session.AddScan(static_cast<double>(pairs), odometry, ToLaserScan(*scan));
      ++scans;
      break;  // one scan per step, as MRPT's RBPF inserts one sensory frame per action
    }
  }
  progress.Finish();
  if (filter.stats().scans_processed == 0) throw std::runtime_error(args.rawlog + ": no 2D range scan");
  session.Flush();  // nothing waits here (no camera), but every loop ends this way
  session.Solve();  // the back end, and the map rendered at its poses
  // Nothing is written unless the run made a map and a finite trajectory (an older result stays).
  const dl::OccupancyGrid& grid = *session.Map();
  const std::vector<dl::TrajectoryPoint> trajectory = filter.MeanTrajectory();
  tools::RequireFiniteTrajectory(trajectory, args.rawlog);
  tools::RequireUsableMap(grid, args.rawlog);
  dl::SaveOccupancyMap(grid, args.out_dir + "/map");
  tools::WriteTrajectory(trajectory, args.out_dir + "/trajectory.txt");
  // At the end of the log: the best particle's pose moved on by the odometry since its last processed scan
  // (MRPT's estimated path has one pose per action-observation pair, the last at the end of the log).
  const dl::Pose2D best = session.slam().BestPose().Compose(session.LastProcessedOdometry().Between(odometry));
  std::printf("doorplate_map_rawlog: %d action-observation pairs, %d scans, %d processed, %.1f s, peak RSS %.0f MB\n",
              pairs, scans, filter.stats().scans_processed,
              clock.Seconds(), tools::PeakRssMb());
  std::printf("final pose (best particle, end of the log): %.4f %.4f %.2f deg\n", best.x_m, best.y_m,
              best.theta_rad * 180.0 / M_PI);
  if (session.BackEndResult()) {  // solved above; reported, not what --expect checks
    const dl::Pose2D graph = session.PoseAtOdometry(odometry);
    std::printf("final pose (pose-graph back end, end of the log): %.4f %.4f %.2f deg", graph.x_m, graph.y_m,
                graph.theta_rad * 180.0 / M_PI);
    if (args.has_expected) std::printf(", |log| to the expected pose %.3f", LogNorm(args.expected, graph));
    const dl::SlamBackEndResult& r = *session.BackEndResult();
    std::printf(" (%d nodes, %d alignments, %d loop closures (%d dropped as inconsistent), odometry scale %.4f)\n",
                static_cast<int>(r.poses.size()), r.alignment_edges, r.loop_closures, r.loop_closures_dropped,
                r.odometry_scale);
  }
  std::printf("odometry alone at the end of the log: %.4f %.4f %.2f deg\n", odometry.x_m, odometry.y_m,
              odometry.theta_rad * 180.0 / M_PI);
  if (!args.has_expected) return 0;
  const double dist = std::hypot(best.x_m - args.expected.x_m, best.y_m - args.expected.y_m);
  const double dyaw = std::fabs(dl::NormalizeAngle(best.theta_rad - args.expected.theta_rad));
  const double log_norm = LogNorm(args.expected, best);
  std::printf("expected %.4f %.4f %.2f deg: position error %.3f m, heading error %.2f deg, |log| %.3f (%s %.2f)\n",
              args.expected.x_m, args.expected.y_m, args.expected.theta_rad * 180.0 / M_PI, dist, dyaw * 180.0 / M_PI,
              log_norm, log_norm < args.max_error ? "below" : "NOT below", args.max_error);
  return log_norm < args.max_error ? 0 : 3;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_map_rawlog", kDescription, AddOptions, Run, argc, argv);
}
