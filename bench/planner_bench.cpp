// Grid path planners on the ring floor's ground-truth map (issue 17): MRPT's PlannerSimple2D (wavefront,
// obstacles grown by robotRadius) beside GridPathPlanner (A* on a wall-distance cost), on the same four
// long queries: time per query and the clearance of the path's points (distance to the nearest occupied
// cell centre, metres). Numbers in docs/results/floor-goto.md.
//   doorplate_planner_bench [--map map.yaml]   (default: maps/hospital_floor_ring.yaml of the source tree)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <string>
#include <vector>

#include <mrpt/nav/planners/PlannerSimple2D.h>

#include "cli_app.h"
#include "doorplate_localization/behaviour/grid_path_planner.h"
#include "doorplate_localization/maps/map_io.h"

namespace dl = doorplate_localization;
namespace tools = dl::tools;

namespace {

using Clock = std::chrono::steady_clock;

struct Query {
  dl::Vec2 start, goal;
  const char* name;
};

const Query kQueries[] = {{{20, 1.2}, {11, -10}, "south -> south branch"},
                          {{20, 1.2}, {30, 25.4}, "south -> north (door goal)"},
                          {{5, 1.0}, {52, 13.4}, "south -> east branch (door goal)"},
                          {{30, 25}, {11, -11}, "north -> south branch"}};

double Seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// Distance from `p` to the nearest occupied cell centre (within 1.5 m), metres.
double Clearance(const dl::OccupancyGrid& g, dl::Vec2 p) {
  int cx = 0, cy = 0;
  if (!g.WorldToCell(p, &cx, &cy)) return 0.0;
  double best = 1.5;
  const int r = static_cast<int>(1.5 / g.resolution_m);
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (g.InBounds(cx + dx, cy + dy) && g.At(cx + dx, cy + dy) >= 50) {
        best = std::min(best, std::hypot(dx, dy) * g.resolution_m);
      }
    }
  }
  return best;
}

void Report(const dl::OccupancyGrid& g, const char* name, const std::vector<dl::Vec2>& path, double seconds) {
  if (path.empty()) {
    std::printf("    %-34s no path (%.3f s)\n", name, seconds);
    return;
  }
  double length = 0, min_c = 1e9, sum_c = 0;
  for (size_t i = 0; i < path.size(); ++i) {
    if (i > 0) length += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
    const double c = Clearance(g, path[i]);
    min_c = std::min(min_c, c);
    sum_c += c;
  }
  std::printf("    %-34s %6.3f s  length %5.1f m  clearance min %.2f m, mean %.2f m\n", name, seconds, length, min_c,
              sum_c / path.size());
}

struct Args {
  std::string map = std::string(DOORPLATE_SOURCE_DIR) + "/maps/hospital_floor_ring.yaml";
};

void AddOptions(CLI::App* app, Args* args) {
  app->add_option("--map", args->map, "occupancy map YAML (map_server format) the four queries run on; they are "
                  "the ring floor's coordinates")->capture_default_str()->check(CLI::ExistingFile);
}

int Run(const Args& args) {
  const std::string& map_path = args.map;
  const dl::OccupancyGrid g = dl::LoadOccupancyMap(map_path);
  std::printf("%s: %d x %d cells of %.2f m\n", map_path.c_str(), g.width, g.height, g.resolution_m);

  Clock::time_point t0 = Clock::now();
  mrpt::maps::COccupancyGridMap2D mrpt_map;
  mrpt_map.setSize(g.origin.x_m, g.origin.x_m + g.WidthM(), g.origin.y_m, g.origin.y_m + g.HeightM(),
                   g.resolution_m, 0.5f);
  const int nx = std::min<int>(g.width, mrpt_map.getSizeX()), ny = std::min<int>(g.height, mrpt_map.getSizeY());
  for (int y = 0; y < ny; ++y) {
    for (int x = 0; x < nx; ++x) {
      const int v = g.At(x, y);  // MRPT cells hold the probability of FREE space
      mrpt_map.setCell(x, y, v < 0 ? 0.5f : (v >= 50 ? 0.0f : 1.0f));
    }
  }
  std::printf("MRPT PlannerSimple2D (grid conversion %.3f s)\n", Seconds(t0, Clock::now()));
  for (const float radius : {0.3f, 0.5f, 0.6f, 0.8f}) {
    std::printf("  robotRadius %.2f m\n", radius);
    mrpt::nav::PlannerSimple2D planner;
    planner.robotRadius = radius;
    planner.minStepInReturnedPath = 0.1f;
    for (const Query& q : kQueries) {
      std::deque<mrpt::math::TPoint2D> found;
      bool not_found = false;
      const Clock::time_point a = Clock::now();
      planner.computePath(mrpt_map, mrpt::poses::CPose2D(q.start.x, q.start.y, 0),
                          mrpt::poses::CPose2D(q.goal.x, q.goal.y, 0), found, not_found);
      const double s = Seconds(a, Clock::now());
      std::vector<dl::Vec2> path;
      if (!not_found) {
        for (const auto& p : found) path.push_back({p.x, p.y});
      }
      Report(g, q.name, path, s);
    }
  }

  t0 = Clock::now();
  const dl::GridPathPlanner ours(dl::GridPathPlannerOptions{}, g);
  std::printf("GridPathPlanner, default options (clearance image %.3f s)\n", Seconds(t0, Clock::now()));
  for (const Query& q : kQueries) {
    const dl::GridPath path = ours.Plan(q.start, q.goal);
    Report(g, q.name, path.waypoints, path.plan_seconds);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_planner_bench", "MRPT's PlannerSimple2D beside GridPathPlanner on four long queries "
                        "of the ring floor: time per query, path length and clearance.", AddOptions, Run, argc, argv);
}
