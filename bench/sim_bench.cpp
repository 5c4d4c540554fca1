// Simulator speed: simulated seconds per wall-clock second (the real-time factor) for the robot driving
// down a built-in corridor with laser and camera at several rates, on one thread.
// Usage: doorplate_sim_bench [--world FILE] [--seconds S] [--seed N] [--markdown OUT.md]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cli_app.h"
#include "doorplate_localization/sim/simulator.h"
#include "doorplate_localization/sim/world_loader.h"

using namespace doorplate_localization;

namespace {

struct Case {
  const char* name;
  double laser_hz;
  double camera_hz;
  const char* laser_error_model = "gaussian";  // LaserOptions::error_model for this case
};

struct Result {
  Case c;
  double sim_s;
  double wall_s;
  int scans;
  int images;
};

Result RunCase(const World& world_file, const Case& c, double seconds, std::uint64_t seed) {
  World world = world_file;
  world.sensors.laser.error_model = c.laser_error_model;
  SimulatorOptions options;
  options.seed = seed;
  Simulator sim(world, options);
  sim.SetCommand(0.4, 0.0);
  const int steps = static_cast<int>(seconds / options.physics_step_s);
  // A sensor fires at the first step of each of its periods: when floor(t * rate) changes.
  const auto due = [&](double rate_hz, int step) {
    const double dt = options.physics_step_s;
    return rate_hz > 0 && std::floor(step * dt * rate_hz + 1e-9) != std::floor((step - 1) * dt * rate_hz + 1e-9);
  };
  int scans = 0, images = 0;
  double checksum = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) {
    sim.Step();
    if (due(c.laser_hz, i)) checksum += sim.Scan().ranges_m[0], ++scans;
    if (due(c.camera_hz, i)) checksum += sim.CameraImage().at<cv::Vec3b>(0, 0)[0], ++images;
    if (sim.bumped()) sim.Teleport(world.start_pose);  // keep driving for the whole run
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (checksum == -1.0) std::puts("");  // keep the work observable
  return {c, steps * options.physics_step_s, wall, scans, images};
}

struct Args {
  std::string world_file = std::string(DOORPLATE_SOURCE_DIR) + "/worlds/paper_real_corridor.yaml";
  std::string markdown;
  double seconds = 60.0;
  std::uint64_t seed = 1;
};

void AddOptions(CLI::App* app, Args* args) {
  app->add_option("--world", args->world_file, "world file")->capture_default_str();
  app->add_option("--seconds", args->seconds, "simulated seconds per configuration")->capture_default_str()
      ->check(tools::PositiveNumber());
  app->add_option("--seed", args->seed, "simulator seed")->capture_default_str()->transform(tools::Seed());
  app->add_option("--markdown", args->markdown, "also write the table to this file");
}

int Run(const Args& args) {
  const std::string& world_file = args.world_file;
  const std::string& markdown = args.markdown;
  const double seconds = args.seconds;
  const std::uint64_t seed = args.seed;
  World world;
  try {
    world = LoadWorldFile(world_file);
  } catch (const WorldFileError& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  const std::vector<Case> cases = {{"physics only (100 Hz)", 0, 0},
                                   {"laser 10 Hz", 10, 0},
                                   {"laser 10 Hz, fitted error model", 10, 0, "fitted"},
                                   {"laser 10 Hz + camera 10 Hz", 10, 10},
                                   {"laser 10 Hz + camera 30 Hz", 10, 30}};
  std::string table = "| configuration | simulated s | wall s | real-time factor | scans | images | wall ms per image |\n"
                      "|---|---|---|---|---|---|---|\n";
  std::vector<Result> results;
  for (const Case& c : cases) {
    const Result r = RunCase(world, c, seconds, seed);
    results.push_back(r);
    char per_image[32] = "–";
    if (r.images > 0) std::snprintf(per_image, sizeof(per_image), "%.2f", 1000.0 * r.wall_s / r.images);
    char row[256];
    std::snprintf(row, sizeof(row), "| %s | %.0f | %.2f | %.1f× | %d | %d | %s |\n", c.name, r.sim_s, r.wall_s,
                  r.sim_s / r.wall_s, r.scans, r.images, per_image);
    table += row;
    std::cout << row << std::flush;
  }
  // The laser alone: how much the fitted error model costs against the gaussian one, measured in this run.
  const double gaussian_rtf = results[1].sim_s / results[1].wall_s, fitted_rtf = results[2].sim_s / results[2].wall_s;
  char ratio[160];
  std::snprintf(ratio, sizeof(ratio), "\nLaser real-time factor, fitted / gaussian error model: %.2f\n",
                fitted_rtf / gaussian_rtf);
  std::cout << ratio;
  table += ratio;
  if (!markdown.empty()) {
    std::ofstream out(markdown);
    out << "# Simulator speed\n\nWorld `" << world.name << "`, robot driving at 0.4 m/s, physics step 10 ms, "
        << "seed " << seed << ", one thread. Real-time factor = simulated seconds per wall-clock second "
        << "(the baseline, 1×, is real time).\n\n" << table;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_sim_bench", "Simulator speed: real-time factor per sensor configuration.", AddOptions,
                        Run, argc, argv);
}
