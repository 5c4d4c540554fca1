// doorplate_sim_snapshot: renders what the simulated camera sees at one pose of a world file, and
// optionally a top-down view of the world (walls, doors, signs with their text, robot, camera field of
// view and one simulated laser scan). For looking at worlds and at the camera's images; with
// --benchmark it also times the renderer.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_args.h"
#include "output_guard.h"
#include "doorplate_localization/sim/camera_renderer.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/people.h"
#include "doorplate_localization/sim/top_down_view.h"
#include "doorplate_localization/sim/world_loader.h"

namespace dl = doorplate_localization;

namespace {

const char kUsage[] =
    "usage: doorplate_sim_snapshot --world FILE --camera OUT.png [--topdown OUT2.png]\n"
    "         [--x X_M --y Y_M (--theta RAD | --theta-deg DEG)] [--seed S]\n"
    "         [--speed MPS] [--yaw-rate RPS] [--time S] [--clean] [--benchmark N]\n"
    "  The pose (base_link in the world frame) defaults to the world's robot start.\n"
    "  --time places the world's people where they are S simulated seconds in (default 0).\n"
    "  --seed seeds the camera noise and the laser scan (default 1); --speed and --yaw-rate set the\n"
    "  motion blur; --clean renders without blur, noise or lighting changes; --benchmark N renders N\n"
    "  frames and prints the time per frame.\n";

struct Args {
  std::string world, camera_out, topdown_out;
  std::optional<double> x, y, theta;
  std::uint64_t seed = 1;
  double speed_mps = 0.0, yaw_rate_rps = 0.0, time_s = 0.0;
  bool clean = false;
  int benchmark_frames = 0;
};

namespace tools = doorplate_localization::tools;
using tools::ParseNumber;
using tools::UsageError;

Args ParseArgs(int argc, char** argv) {
  Args args;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    tools::ExitIfHelp(option, kUsage);
    if (option == "--clean") {
      args.clean = true;
      continue;
    }
    const std::string value = tools::TakeValue(argc, argv, &i);
    if (option == "--world") args.world = value;
    else if (option == "--camera") args.camera_out = value;
    else if (option == "--topdown") args.topdown_out = value;
    else if (option == "--x") args.x = ParseNumber(option, value);
    else if (option == "--y") args.y = ParseNumber(option, value);
    else if (option == "--theta") args.theta = ParseNumber(option, value);
    else if (option == "--theta-deg") args.theta = ParseNumber(option, value) * M_PI / 180.0;
    else if (option == "--speed") args.speed_mps = ParseNumber(option, value);
    else if (option == "--yaw-rate") args.yaw_rate_rps = ParseNumber(option, value);
    else if (option == "--time") {
      args.time_s = ParseNumber(option, value);
      if (!(args.time_s >= 0.0)) throw UsageError("--time must be >= 0");
    }
    else if (option == "--seed") args.seed = static_cast<std::uint64_t>(
        tools::ParseWholeNumber(option, value, 0, 1e19));
    else if (option == "--benchmark") args.benchmark_frames = static_cast<int>(
        tools::ParseWholeNumber(option, value, 0));
    else throw UsageError("unknown option '" + option + "'");
  }
  if (args.world.empty()) throw UsageError("--world is required");
  if (args.camera_out.empty()) throw UsageError("--camera is required");
  if (args.x.has_value() != args.y.has_value() || args.x.has_value() != args.theta.has_value()) {
    throw UsageError("give all of --x, --y and --theta (or --theta-deg), or none");
  }
  return args;
}

void Write(const std::string& path, const cv::Mat& image) {
  if (!cv::imwrite(path, image)) throw std::runtime_error(path + ": cannot write the image");
}

// Times Render and RenderClean: wall time and process CPU time (all threads; robust to a busy machine).
void Benchmark(const dl::CameraRenderer& camera, const dl::Pose2D& pose, const Args& args) {
  using Clock = std::chrono::steady_clock;
  const auto ms_since = [](Clock::time_point t, std::clock_t c, double* wall_ms, double* cpu_ms) {
    *wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - t).count();
    *cpu_ms = 1000.0 * static_cast<double>(std::clock() - c) / CLOCKS_PER_SEC;
  };
  std::mt19937_64 rng(args.seed);
  std::vector<double> wall[2], cpu[2];
  for (int i = 0; i < args.benchmark_frames; ++i) {
    const dl::Pose2D p{pose.x_m + 0.01 * i, pose.y_m, pose.theta_rad};  // driving past
    for (int clean = 0; clean < 2; ++clean) {
      const auto t = Clock::now();
      const std::clock_t c = std::clock();
      const cv::Mat image =
          clean ? camera.RenderClean(p) : camera.Render(p, args.speed_mps, args.yaw_rate_rps, rng);
      double wall_ms, cpu_ms;
      ms_since(t, c, &wall_ms, &cpu_ms);
      wall[clean].push_back(wall_ms);
      cpu[clean].push_back(cpu_ms);
    }
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  for (int clean = 0; clean < 2; ++clean) {
    std::cout << (clean ? "RenderClean" : "Render") << ": wall median " << median(wall[clean]) << " ms, min "
              << *std::min_element(wall[clean].begin(), wall[clean].end()) << " ms; CPU median "
              << median(cpu[clean]) << " ms; " << wall[clean].size() << " frames\n";
  }
}

int Run(const Args& args) {
  tools::RefuseOverwritingInputs({{"--world", args.world}},
                                 {{"--camera", args.camera_out}, {"--topdown", args.topdown_out}});
  dl::World world = dl::LoadWorldFile(args.world);
  dl::PlacePeople(world, args.time_s);
  const dl::Pose2D pose = args.x ? dl::Pose2D{*args.x, *args.y, *args.theta} : world.start_pose;
  const dl::CameraRenderer camera(world, world.sensors.camera);
  std::mt19937_64 rng(args.seed);
  Write(args.camera_out, args.clean ? camera.RenderClean(pose)
                                    : camera.Render(pose, args.speed_mps, args.yaw_rate_rps, rng));
  if (!args.topdown_out.empty()) {
    const dl::LaserSimulator laser(world.sensors.laser);
    const dl::SimulatedScan scan = laser.Simulate(world, pose, rng);
    dl::TopDownView view(world);
    view.DrawScan(scan, pose.Compose(laser.MountPose()));
    view.DrawCameraFov(camera, pose);
    view.DrawRobot(pose);
    Write(args.topdown_out, view.image());
  }
  if (args.benchmark_frames > 0) Benchmark(camera, pose, args);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_sim_snapshot", kUsage, ParseArgs, Run, argc, argv);
}
