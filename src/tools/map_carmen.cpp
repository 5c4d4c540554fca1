// doorplate_map_log: maps a CARMEN log (FLASER lines; odometry from the second pose triple) offline through
// the mapping session the mapping nodelet runs (slam/mapping_session.h), and writes the real-log protocol's
// outputs:
//   DIR/trajectory.txt        `scan_index x y theta` per processed scan: --method slam (default): the back
//                              end's solved trajectory (the nodelet's SLAM: filter + pose graph); --method
//                              rbpf: the laser-only filter's posterior mean (RbpfSlam::MeanTrajectory; the
//                              filter as docs/results/real-logs.md measured it). DIR/trajectory_best.txt:
//                              the best particle's history (both methods)
//   DIR/map.pgm, DIR/map.yaml  the session's map (slam: rendered at the solved poses; rbpf: the best
//                              particle's), map_server format
//   DIR/map_trajectory.png     the map with the trajectory drawn over it
// and a progress line on stderr every few seconds (progress_line.h). Scan stamps are the log's ipc_timestamps
// when they increase from line to line, else the FLASER order (one second per line; said on stderr).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_app.h"
#include "map_tool_output.h"
#include "output_guard.h"
#include "progress_line.h"
#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/slam/carmen_reader.h"
#include "doorplate_localization/slam/mapping_session.h"
#include "doorplate_localization/slam/rbpf_slam_options.h"

namespace dl = doorplate_localization;

namespace {

const char kDescription[] = "Maps a CARMEN log offline through the mapping nodelet's session.";
const char kNotes[] =
    "FILE.log: a CARMEN log (unpacked). --method slam (default): the mapping nodelet's SLAM (filter with\n"
    "TextSlamOptions' defaults and the pose-graph back end); rbpf: the laser-only filter alone\n"
    "(RbpfSlamOptions' defaults, no back end; docs/results/real-logs.md). --set changes any option of the\n"
    "one option table (TextSlamOptionNames), after --method, e.g. --set linear_update_m=0.5\n"
    "--set matcher.field_sigma_m=0.05 (docs/slam.md).";

namespace tools = doorplate_localization::tools;
using tools::UsageError;

struct Args {
  std::string log, out, method = "slam";
  std::optional<std::uint64_t> seed;
  std::optional<int> particles;
  std::vector<std::string> sets;
  bool dump_particles = false;
  double progress_s = 5.0;
  bool laser_only = false;  // --method rbpf
  dl::MappingSessionOptions options;
};

void AddOptions(CLI::App* app, Args* args) {
  app->footer(kNotes);
  app->add_option("--log", args->log, "the CARMEN log FILE.log")->required();
  app->add_option("--out", args->out, "output folder DIR")->required();
  app->add_option("--method", args->method, "slam or rbpf")->capture_default_str()
      ->check(CLI::IsMember({"slam", "rbpf"}));
  app->add_option("--seed", args->seed, "filter seed [the option table's]")->transform(tools::Seed());
  app->add_option("--particles", args->particles, "number of particles [the method's]")
      ->transform(tools::WholeNumber(1, dl::limits::kMaxParticles));
  app->add_option("--progress-s", args->progress_s, "a progress line on stderr every this many seconds (rewritten in "
                  "place twice a second on a terminal; 0: none)")->capture_default_str()->check(tools::Number(0.0));
  app->add_option("--set", args->sets, "NAME=VALUE: a SLAM option (repeatable)")->allow_extra_args(false);
  app->add_flag("--dump-particles", args->dump_particles, "also write every particle's trajectory "
                "(trajectory_particleI.txt)");
  // --method first: it picks the defaults the other options change.
  app->callback([args] {
    args->laser_only = args->method == "rbpf";
    if (args->laser_only) {
      args->options.slam.slam = dl::RbpfSlamOptions{};
      args->options.slam.back_end.enabled = false;
    }
    if (args->seed) args->options.slam.slam.seed = *args->seed;
    if (args->particles) args->options.slam.slam.num_particles = *args->particles;
    for (const std::string& set : args->sets) {
      tools::ApplySetOption(set, [&](const std::string& name, double v) { SetTextSlamOption(name, v, &args->options.slam); });
    }
  });
}

// The map in grey (unknown mid-grey, free white, occupied black), north up, trajectory in red; at most
// 1200 pixels on a side.
void WritePicture(const dl::OccupancyGrid& grid, const std::vector<dl::TrajectoryPoint>& trajectory,
                  const std::string& path) {
  cv::Mat image(grid.height, grid.width, CV_8UC3);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const int v = grid.At(x, y);
      const std::uint8_t grey = v < 0 ? 205 : static_cast<std::uint8_t>(255 - v * 255 / 100);
      image.at<cv::Vec3b>(grid.height - 1 - y, x) = {grey, grey, grey};
    }
  }
  std::vector<cv::Point> line;
  for (const dl::TrajectoryPoint& p : trajectory) {
    line.emplace_back(static_cast<int>((p.pose.x_m - grid.origin.x_m) / grid.resolution_m),
                      grid.height - 1 - static_cast<int>((p.pose.y_m - grid.origin.y_m) / grid.resolution_m));
  }
  constexpr int kMaxSide = 1200;
  const double shrink = std::min(1.0, double(kMaxSide) / std::max(grid.width, grid.height));
  cv::polylines(image, line, false, cv::Scalar(0, 0, 255), std::max(2, static_cast<int>(std::lround(2 / shrink))),
                cv::LINE_AA);
  if (shrink < 1.0) cv::resize(image, image, cv::Size(), shrink, shrink, cv::INTER_AREA);
  if (!cv::imwrite(path, image)) throw std::runtime_error(path + ": cannot write the image");
}

int Run(const Args& args) {
  const tools::Stopwatch clock;
  const std::string map_base = args.out + "/map";
  tools::RefuseOverwritingInputs({{"--log", args.log}},
                                 {{"--out", args.out + "/trajectory.txt"}, {"--out", args.out + "/trajectory_best.txt"},
                                  {"--out", map_base + ".pgm"}, {"--out", map_base + ".yaml"},
                                  {"--out", args.out + "/map_trajectory.png"}});
  std::filesystem::create_directories(args.out);  // fails early, before a long run, if it cannot
  const dl::CarmenLog log = dl::ReadCarmenLogFile(args.log);
  if (log.scans.empty()) {
    const bool gz = args.log.size() > 3 && args.log.compare(args.log.size() - 3, 3, ".gz") == 0;
    throw std::runtime_error(args.log + ": no FLASER lines" + (gz ? " (a .gz log must be unpacked first)" : ""));
  }
  // The log's ipc_timestamps as scan stamps if they increase, else the FLASER order.
  bool increasing = true;
  for (std::size_t i = 1; i < log.scans.size() && increasing; ++i) {
    increasing = log.scans[i].timestamp_s > log.scans[i - 1].timestamp_s;
  }
  if (!increasing) {
    std::fprintf(stderr, "doorplate_map_log: %s: the ipc_timestamps do not increase line by line; scans are stamped "
                 "by their FLASER order instead\n", args.log.c_str());
  }
  dl::MappingSession session(args.options);
  const dl::RbpfSlam& filter = session.slam().slam();
  tools::ProgressLine progress({args.progress_s});
  double driven_m = 0.0;  // odometry path length
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const dl::CarmenScan& record = log.scans[i];
    session.AddScan(increasing ? record.timestamp_s : record.scan_index, record.odometry_pose, record.scan);
    if (i > 0) driven_m += dl::Norm(record.odometry_pose.Position() - log.scans[i - 1].odometry_pose.Position());
    if (progress.Due(clock.Seconds())) {
      const dl::RbpfSlamStats& s = filter.stats();
      progress.Show("doorplate_map_log: scan %d/%zu, %.1f m driven, processed %d, neff %.1f, resamplings %d, weak %ld, "
                    "jumps rejected %ld, maps %.0f MB, %.1f s, peak RSS %.0f MB",
                    s.scans_seen, log.scans.size(), driven_m, s.scans_processed, s.last_neff, s.resamplings,
                    s.weak_matches, s.rejected_jumps, filter.MapMemoryBytes() / 1e6, clock.Seconds(),
                    tools::PeakRssMb());
    }
  }
  progress.Finish();
  session.Flush();  // nothing waits here (no camera), but every loop ends this way
  session.Solve();  // the back end (slam), and the map
  std::vector<dl::TrajectoryPoint> trajectory;
  if (args.laser_only) {
    trajectory = filter.MeanTrajectory();
  } else {
    const std::vector<dl::Pose2D> poses = session.Trajectory();
    for (std::size_t i = 0; i < poses.size(); ++i) trajectory.push_back({session.processed_scan_indices().at(i), poses[i]});
  }
  const dl::OccupancyGrid& grid = *session.Map();
  // Nothing is written unless the run made a map and a finite trajectory (an older result stays).
  tools::RequireFiniteTrajectory(trajectory, args.log);
  tools::RequireUsableMap(grid, args.log);
  tools::WriteTrajectory(trajectory, args.out + "/trajectory.txt");
  tools::WriteTrajectory(filter.BestTrajectory(), args.out + "/trajectory_best.txt");
  if (args.dump_particles) {
    for (std::size_t i = 0; i < filter.particles().size(); ++i) {
      tools::WriteTrajectory(dl::UnrollTrajectory(filter.particles()[i].trajectory),
                             args.out + "/trajectory_particle" + std::to_string(i) + ".txt");
    }
  }
  dl::SaveOccupancyMap(grid, map_base);
  WritePicture(grid, trajectory, args.out + "/map_trajectory.png");
  const dl::RbpfSlamStats& s = filter.stats();
  std::fprintf(stderr,
               "doorplate_map_log: done (%s): %d scans, %d processed, %d resamplings, %ld matches, %ld weak, "
               "%ld jumps rejected, no-return %.2f m, maps %.0f MB, %.1f s, peak RSS %.0f MB\n",
               args.laser_only ? "rbpf" : "slam", s.scans_seen, s.scans_processed, s.resamplings, s.matches,
               s.weak_matches, s.rejected_jumps, log.no_return_range_m, filter.MapMemoryBytes() / 1e6, clock.Seconds(),
               tools::PeakRssMb());
  if (session.BackEndResult()) {
    const dl::SlamBackEndResult& r = *session.BackEndResult();
    std::fprintf(stderr, "doorplate_map_log: back end: %d nodes, %d alignments, %d loop closures (%d dropped as "
                 "inconsistent), %d on mapped ground without their scan (%d aligned), odometry scale %.4f\n",
                 static_cast<int>(r.poses.size()), r.alignment_edges, r.loop_closures, r.loop_closures_dropped,
                 r.nodes_on_mapped_ground, r.mapped_ground_alignments, r.odometry_scale);
    if (r.odometry_heading_drift_rad_per_m != 0.0) {  // estimated (back_end.graph.estimate_odometry_heading_drift)
      std::fprintf(stderr, "doorplate_map_log: back end: odometry heading drift %.5f rad/m\n",
                   r.odometry_heading_drift_rad_per_m);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_map_log", kDescription, AddOptions, Run, argc, argv);
}
