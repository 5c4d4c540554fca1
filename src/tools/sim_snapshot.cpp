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
#include <utility>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_app.h"
#include "output_guard.h"
#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/sim/camera_renderer.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/people.h"
#include "doorplate_localization/sim/top_down_view.h"
#include "doorplate_localization/sim/world_loader.h"

namespace dl = doorplate_localization;

namespace {

const char kDescription[] =
    "Renders what the simulated camera sees at one pose of a world file, and optionally a top-down view of "
    "the world.";
const char kNotes[] =
    "The pose (base_link in the world frame) defaults to the world's robot start; give all of --x, --y and\n"
    "--theta (or --theta-deg), or none. --clean renders without blur, noise or lighting changes.";

struct Args {
  std::string world, camera_out, topdown_out;
  std::optional<double> x, y, theta, theta_deg;
  std::uint64_t seed = 1;
  double speed_mps = 0.0, yaw_rate_rps = 0.0, time_s = 0.0;
  bool clean = false;
  int benchmark_frames = 0;
};

namespace tools = doorplate_localization::tools;
using tools::UsageError;

void AddOptions(CLI::App* app, Args* args) {
  app->footer(kNotes);
  app->add_option("--world", args->world, "world file (worlds/*.yaml)")->required();
  app->add_option("--camera", args->camera_out, "the camera image to write (PNG)")->required();
  app->add_option("--topdown", args->topdown_out, "also write the top-down view here");
  app->add_option("--x", args->x, "x of the pose, m")->check(tools::Number());
  app->add_option("--y", args->y, "y of the pose, m")->check(tools::Number());
  app->add_option("--theta", args->theta, "heading of the pose, rad")->check(tools::Number());
  app->add_option("--theta-deg", args->theta_deg, "heading of the pose, degrees")->check(tools::Number());
  app->add_option("--seed", args->seed, "seeds the camera noise and the laser scan")->capture_default_str()
      ->transform(tools::Seed());
  app->add_option("--speed", args->speed_mps, "speed for the motion blur, m/s")->capture_default_str()
      ->check(tools::Number());
  app->add_option("--yaw-rate", args->yaw_rate_rps, "yaw rate for the motion blur, rad/s")->capture_default_str()
      ->check(tools::Number());
  app->add_option("--time", args->time_s, "place the world's people where they are this many simulated seconds in")
      ->capture_default_str()->check(tools::Number(0.0));
  app->add_flag("--clean", args->clean, "render without blur, noise or lighting changes");
  app->add_option("--benchmark", args->benchmark_frames, "render this many frames and print the time per frame")
      ->transform(tools::WholeNumber(0));
  app->callback([args] {
    if (args->theta_deg) args->theta = *args->theta_deg * M_PI / 180.0;
    if (args->x.has_value() != args->y.has_value() || args->x.has_value() != args->theta.has_value()) {
      throw UsageError("give all of --x, --y and --theta (or --theta-deg), or none");
    }
  });
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
  if (args.x) {  // a pose at 1e300 m rendered an empty picture (issue 18): the world's limit, as its start's
    for (const auto& [option, value] : {std::pair{"--x", *args.x}, std::pair{"--y", *args.y}}) {
      const std::string problem = dl::limits::CheckCoordinate(value);
      if (!problem.empty()) throw tools::UsageError(std::string(option) + ": " + problem);
    }
  }
  const dl::Pose2D pose = args.x ? dl::Pose2D{*args.x, *args.y, *args.theta} : world.start_pose;
  const dl::CameraRenderer camera(world, world.sensors.camera);
  std::mt19937_64 rng(args.seed);
  Write(args.camera_out, args.clean ? camera.RenderClean(pose)
                                    : camera.Render(pose, args.speed_mps, args.yaw_rate_rps, rng));
  if (!args.topdown_out.empty()) {
    const dl::LaserSimulator laser(world.sensors.laser);
    const dl::LaserScan scan = laser.Simulate(world, pose, rng);
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
  return tools::RunTool("doorplate_sim_snapshot", kDescription, AddOptions, Run, argc, argv);
}
