// Localizer speed on one core: time per TextAmcl::UpdateLaser with the likelihood-field model for
// 500 / 2000 / 5000 particles and 60 (amcl's laser_max_beams default) / 360 beams of a 360-beam scan,
// split into the sensor model alone and the whole update (which resamples every resample_interval = 2
// updates, with KLD pinned to the particle count); plus the clustering behind Estimate() and the
// likelihood-field build time for a 50 m and a 200 m square map. Goal: 2000 particles, 60 beams <= 2 ms.
// Usage: doorplate_mcl_bench [--iterations N] [--markdown OUT.md] (--help: the options)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "cli_app.h"
#include "doorplate_localization/mcl/diff_drive_motion_model.h"
#include "doorplate_localization/mcl/grid_ray_caster.h"
#include "doorplate_localization/mcl/likelihood_field_model.h"
#include "doorplate_localization/mcl/text_amcl.h"

using namespace doorplate_localization;

namespace {

using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point since) { return std::chrono::duration<double, std::milli>(Clock::now() - since).count(); }

void Fill(OccupancyGrid* g, double x0, double y0, double x1, double y1, std::int8_t v) {
  for (int y = 0; y < g->height; ++y) {
    for (int x = 0; x < g->width; ++x) {
      const double cx = g->origin.x_m + (x + 0.5) * g->resolution_m, cy = g->origin.y_m + (y + 0.5) * g->resolution_m;
      if (cx >= x0 && cx <= x1 && cy >= y0 && cy <= y1) g->cells[static_cast<size_t>(y) * g->width + x] = v;
    }
  }
}

// A hospital-like floor (size_m × size_m): corridors 2.4 m wide every 10 m, rooms 4 m wide off them.
OccupancyGrid Floor(double size_m) {
  OccupancyGrid g;
  g.resolution_m = 0.05;
  g.width = g.height = static_cast<int>(size_m / g.resolution_m);
  g.cells.assign(static_cast<size_t>(g.width) * g.height, OccupancyGrid::kOccupied);
  for (double y = 2.0; y + 2.4 < size_m; y += 10.0) {
    Fill(&g, 1.0, y, size_m - 1.0, y + 2.4, OccupancyGrid::kFree);                    // corridor
    for (double x = 1.5; x + 3.6 < size_m - 1.0; x += 4.0) {
      Fill(&g, x, y + 2.5, x + 3.6, std::min(y + 9.8, size_m - 1.0), OccupancyGrid::kFree);  // room
      Fill(&g, x + 1.0, y + 2.35, x + 2.0, y + 2.55, OccupancyGrid::kFree);                 // its door
    }
  }
  return g;
}

struct Row {
  int particles;
  int beams;
  double model_ms;
  double update_ms;
  double estimate_ms;
};

Row Measure(const std::shared_ptr<const LocalizationGrid>& grid, int particles, int beams, int iterations) {
  LikelihoodFieldModelOptions laser;
  laser.beams.laser_max_beams = beams;
  auto model = std::make_shared<LikelihoodFieldModel>(grid, laser);
  TextAmclOptions o;
  o.min_particles = o.max_particles = particles;  // pin the count: measure the same N every time
  TextAmclModels models;
  models.grid = grid;
  models.motion = std::make_shared<DiffDriveMotionModel>(OdometryMotionModelOptions());
  models.laser = model;
  models.resampler = std::make_shared<LowVarianceResampler>();
  TextAmcl amcl(o, models);
  const Pose2D truth{20.0, 3.2, 0.1};
  amcl.Initialize(truth, Eigen::Vector3d(0.09, 0.09, 0.01).asDiagonal());
  LaserScan geometry;
  geometry.angle_min_rad = -M_PI;
  geometry.angle_increment_rad = 2.0 * M_PI / 360.0;
  geometry.min_range_m = 0.15;
  geometry.max_range_m = 16.0;
  geometry.laser_pose = {0.1, 0.0, 0.0};
  const LaserScan scan = CastScan(*grid, truth, geometry, 360);

  // Each figure is the best of three blocks of `iterations` runs (the machine is shared).
  const auto best_of_3 = [&](const auto& body) {
    double best = 1e300;
    for (int block = 0; block < 3; ++block) {
      const auto t = Clock::now();
      for (int i = 0; i < iterations; ++i) body();
      best = std::min(best, Ms(t) / iterations);
    }
    return best;
  };
  std::vector<double> ll;
  const double model_ms = best_of_3([&] { model->LogLikelihoods(scan, amcl.particles(), &ll); });
  const double update_ms = best_of_3([&] {
    amcl.ForceUpdate();
    amcl.UpdateLaser(scan);
  });
  double checksum = 0.0;
  const double estimate_ms =
      best_of_3([&] { checksum += ClusterParticles(amcl.particles(), o.histogram_bin).clusters.size(); });
  if (checksum == -1.0 || ll.empty()) std::puts("");  // keep the work observable
  return {particles, beams, model_ms, update_ms, estimate_ms};
}

struct Args {
  int iterations = 200;
  std::string markdown;
};

void AddOptions(CLI::App* app, Args* args) {
  app->add_option("--iterations", args->iterations, "calls per timed block (each figure: the best of three blocks)")
      ->capture_default_str()->transform(tools::WholeNumber(1));
  app->add_option("--markdown", args->markdown, "also write the tables to this file");
}

int Run(const Args& args) {
  const int iterations = args.iterations;
  const std::string& markdown = args.markdown;
  // Prints markdown as it goes; `out` collects the same text for --markdown.
  std::string out;
  const auto emit = [&](const std::string& text) {
    out += text;
    std::cout << text << std::flush;
  };
  emit("## Likelihood-field build\n\n| map | cells | build ms |\n|---|---|---|\n");
  std::shared_ptr<const LocalizationGrid> floor;
  for (double size : {50.0, 200.0}) {
    auto grid = std::make_shared<const LocalizationGrid>(Floor(size));
    double build_ms = 1e300;
    for (int k = 0; k < 3; ++k) {  // best of three
      const auto t = Clock::now();
      LikelihoodFieldModel model(grid, {});
      build_ms = std::min(build_ms, Ms(t));
    }
    char row[160];
    std::snprintf(row, sizeof(row), "| %.0f m × %.0f m, 5 cm | %d × %d | %.1f |\n", size, size, grid->width(),
                  grid->height(), build_ms);
    emit(row);
    if (size == 50.0) floor = grid;
  }
  emit("\n## UpdateLaser (likelihood field, 360-beam scan)\n\n"
       "| particles | beams used | sensor model ms | UpdateLaser ms (incl. resampling every 2nd) | "
       "clustering (Estimate) ms |\n|---|---|---|---|---|\n");
  for (int particles : {500, 2000, 5000}) {
    for (int beams : {60, 360}) {
      const Row r = Measure(floor, particles, beams, iterations);
      char row[200];
      std::snprintf(row, sizeof(row), "| %d | %d | %.3f | %.3f | %.3f |\n", r.particles, r.beams, r.model_ms,
                    r.update_ms, r.estimate_ms);
      emit(row);
    }
  }
  if (!markdown.empty()) {
    std::ofstream file(markdown);
    file << "# Localizer speed\n\nOne thread; each figure is the best of three blocks of " << iterations
         << " calls. Hospital-like floor map (corridors every 10 m, rooms off them), particles around the true "
         << "pose (σ 0.3 m, 0.1 rad), KLD pinned to the particle count.\n\n" << out;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_mcl_bench", "Localizer speed: likelihood-field build, UpdateLaser and clustering.",
                        AddOptions, Run, argc, argv);
}
