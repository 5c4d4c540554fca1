// doorplate_map_log: maps a CARMEN log (FLASER lines; odometry from the second pose triple) offline with
// the same RbpfSlam the mapping nodelet runs, and writes the real-log protocol's outputs:
//   DIR/trajectory.txt        `scan_index x y theta` per processed scan: the posterior mean trajectory
//                              (RbpfSlam::MeanTrajectory); DIR/trajectory_best.txt: the best particle's
//   DIR/map.pgm, DIR/map.yaml  the best particle's map, map_server format
//   DIR/map_trajectory.png     the map with the trajectory drawn over it
// and a progress line on stderr every few seconds.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_args.h"
#include "map_tool_output.h"
#include "output_guard.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/slam/carmen_reader.h"
#include "doorplate_localization/slam/rbpf_slam.h"
#include "doorplate_localization/slam/rbpf_slam_options.h"

namespace dl = doorplate_localization;

namespace {

const char kUsage[] =
    "usage: doorplate_map_log --log FILE.log --out DIR [--seed S] [--particles N]\n"
    "         [--progress-s SECONDS] [--set NAME=VALUE]... [--dump-particles]\n"
    "  FILE.log: a CARMEN log (unpacked). --set changes any numeric RbpfSlamOptions field, e.g.\n"
    "  --set linear_update_m=0.5 --set matcher.field_sigma_m=0.05 (see docs/slam.md for the names).\n"
    "  --dump-particles also writes every particle's trajectory (trajectory_particleI.txt).\n";

namespace tools = doorplate_localization::tools;
using tools::UsageError;

struct Args {
  std::string log, out;
  bool dump_particles = false;
  double progress_s = 5.0;
  dl::RbpfSlamOptions options;
};

Args ParseArgs(int argc, char** argv) {
  Args args;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    tools::ExitIfHelp(option, kUsage);
    if (option == "--dump-particles") {
      args.dump_particles = true;
      continue;
    }
    const std::string value = tools::TakeValue(argc, argv, &i);
    if (option == "--log") {
      args.log = value;
    } else if (option == "--out") {
      args.out = value;
    } else if (option == "--progress-s") {
      args.progress_s = tools::ParseNumber(option, value);
    } else if (option == "--seed") {
      args.options.seed = static_cast<std::uint64_t>(tools::ParseWholeNumber(option, value, 0));
    } else if (option == "--particles") {
      args.options.num_particles = static_cast<int>(tools::ParseWholeNumber(option, value, 1));
    } else if (option == "--set") {
      tools::ApplySetOption(value,
                            [&](const std::string& name, double v) { SetRbpfSlamOption(name, v, &args.options); });
    } else {
      throw UsageError("unknown option '" + option + "'");
    }
  }
  if (args.log.empty() || args.out.empty()) throw UsageError("--log and --out are required");
  return args;
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
  dl::RbpfSlam slam(args.options);
  double next_progress = args.progress_s;
  for (const dl::CarmenScan& record : log.scans) {
    slam.AddScan(record.scan, record.odometry_pose, record.scan_index);
    if (clock.Seconds() >= next_progress) {
      next_progress += args.progress_s;
      const dl::RbpfSlamStats& s = slam.stats();
      std::fprintf(stderr,
                   "doorplate_map_log: scan %d/%zu, processed %d, neff %.1f, resamplings %d, weak %ld, "
                   "jumps rejected %ld, maps %.0f MB, %.1f s, peak RSS %.0f MB\n",
                   s.scans_seen, log.scans.size(), s.scans_processed, s.last_neff, s.resamplings,
                   s.weak_matches, s.rejected_jumps, slam.MapMemoryBytes() / 1e6, clock.Seconds(), tools::PeakRssMb());
    }
  }
  const dl::SlamParticle& best = slam.BestParticle();
  const std::vector<dl::TrajectoryPoint> trajectory = slam.MeanTrajectory();
  const dl::OccupancyGrid grid = best.map.ToOccupancyGrid();
  // Nothing is written unless the run made a map and a finite trajectory (an older result stays).
  tools::RequireFiniteTrajectory(trajectory, args.log);
  tools::RequireUsableMap(grid, args.log);
  tools::WriteTrajectory(trajectory, args.out + "/trajectory.txt");
  tools::WriteTrajectory(slam.BestTrajectory(), args.out + "/trajectory_best.txt");
  if (args.dump_particles) {
    for (std::size_t i = 0; i < slam.particles().size(); ++i) {
      tools::WriteTrajectory(dl::UnrollTrajectory(slam.particles()[i].trajectory),
                             args.out + "/trajectory_particle" + std::to_string(i) + ".txt");
    }
  }
  dl::SaveOccupancyMap(grid, map_base);
  WritePicture(grid, trajectory, args.out + "/map_trajectory.png");
  const dl::RbpfSlamStats& s = slam.stats();
  std::fprintf(stderr,
               "doorplate_map_log: done: %d scans, %d processed, %d resamplings, %ld matches, %ld weak, "
               "%ld jumps rejected, no-return %.2f m, maps %.0f MB, %.1f s, peak RSS %.0f MB\n",
               s.scans_seen, s.scans_processed, s.resamplings, s.matches, s.weak_matches,
               s.rejected_jumps, log.no_return_range_m, slam.MapMemoryBytes() / 1e6, clock.Seconds(),
               tools::PeakRssMb());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return tools::RunTool("doorplate_map_log", kUsage, ParseArgs, Run, argc, argv); }
