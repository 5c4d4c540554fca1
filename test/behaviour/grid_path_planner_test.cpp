#include "doorplate_localization/behaviour/grid_path_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

// A 0.05 m grid over [0, size_m]² (map frame, origin at (0, 0)): free where `is_free` says, else occupied.
OccupancyGrid MakeGrid(double size_m, const std::function<bool(Vec2)>& is_free) {
  const int cells = static_cast<int>(std::lround(size_m / 0.05));
  OccupancyGrid grid(cells, cells, 0.05, Pose2D{}, OccupancyGrid::kOccupied);
  for (int y = 0; y < cells; ++y) {
    for (int x = 0; x < cells; ++x) {
      if (is_free(grid.CellCenter(x, y))) grid.At(x, y) = OccupancyGrid::kFree;
    }
  }
  return grid;
}

// An L of 2 m wide corridors: along x (y in [0.5, 2.5], x in [0.5, 8.5]) and up along y at its far end
// (x in [6.5, 8.5], y up to 8.5). Inner corner at (6.5, 2.5).
OccupancyGrid LCorridor() {
  return MakeGrid(9.0, [](Vec2 p) {
    const bool along_x = p.x > 0.5 && p.x < 8.5 && p.y > 0.5 && p.y < 2.5;
    const bool along_y = p.x > 6.5 && p.x < 8.5 && p.y > 0.5 && p.y < 8.5;
    return along_x || along_y;
  });
}

double MinDistanceTo(const GridPath& path, Vec2 point) {
  double best = std::numeric_limits<double>::infinity();
  for (const Vec2& p : path.waypoints) best = std::min(best, Norm(p - point));
  return best;
}

TEST(GridPathPlanner, GoesRoundTheCornerOfAnLCorridorOnAWideArc) {
  const GridPathPlanner planner(GridPathPlannerOptions{}, LCorridor());
  const GridPath path = planner.Plan({1.5, 1.5}, {7.5, 7.5});
  ASSERT_TRUE(path.found) << path.failure;
  ASSERT_GE(path.waypoints.size(), 3u);
  EXPECT_NEAR(path.waypoints.front().x, 1.5, 1e-9);
  EXPECT_NEAR(path.waypoints.front().y, 1.5, 1e-9);
  EXPECT_NEAR(path.waypoints.back().x, 7.5, 1e-9);
  EXPECT_NEAR(path.waypoints.back().y, 7.5, 1e-9);
  for (const Vec2& p : path.waypoints) {
    EXPECT_GE(planner.ClearanceAt(p), 0.4) << "(" << p.x << ", " << p.y << ")";
  }
  EXPECT_GT(MinDistanceTo(path, {6.5, 2.5}), 0.6);  // not cutting the inner corner
  // Down the middle of both legs.
  for (const Vec2& p : path.waypoints) {
    if (p.x > 2.5 && p.x < 5.5) {
      EXPECT_NEAR(p.y, 1.5, 0.1);
    }
    if (p.y > 4.0 && p.y < 6.5) {
      EXPECT_NEAR(p.x, 7.5, 0.1);
    }
  }
  EXPECT_GT(path.length_m, 6.0 + 6.0 - 1.0);
  EXPECT_LT(path.length_m, 12.5);
  EXPECT_GE(path.min_clearance_m, 0.4);
  EXPECT_GT(path.mean_clearance_m, 0.85);
}

TEST(GridPathPlanner, WaypointsAreAboutTheSpacingApart) {
  const GridPathPlanner planner(GridPathPlannerOptions{}, LCorridor());
  const GridPath path = planner.Plan({1.5, 1.5}, {7.5, 7.5});
  ASSERT_TRUE(path.found);
  for (size_t i = 1; i < path.waypoints.size(); ++i) {
    const double step = Norm(path.waypoints[i] - path.waypoints[i - 1]);
    EXPECT_LE(step, 0.13 + 1e-6);  // the last one up to 1.3 spacings
    EXPECT_GT(step, 0.03);
  }
}

TEST(GridPathPlanner, RefusesAGoalInsideAnObstacle) {
  const GridPathPlanner planner(GridPathPlannerOptions{}, LCorridor());
  const GridPath in_wall = planner.Plan({1.5, 1.5}, {4.0, 4.0});  // inside the block inside the L
  EXPECT_FALSE(in_wall.found);
  EXPECT_NE(in_wall.failure.find("goal inside an obstacle"), std::string::npos) << in_wall.failure;
  const GridPath too_close = planner.Plan({1.5, 1.5}, {4.0, 0.6});  // 0.1 m from the wall: robot radius 0.2
  EXPECT_FALSE(too_close.found);
  EXPECT_NE(too_close.failure.find("goal inside an obstacle"), std::string::npos) << too_close.failure;
  const GridPath start_in_wall = planner.Plan({4.0, 4.0}, {1.5, 1.5});
  EXPECT_NE(start_in_wall.failure.find("start inside an obstacle"), std::string::npos) << start_in_wall.failure;
  const GridPath outside = planner.Plan({1.5, 1.5}, {20.0, 1.5});
  EXPECT_NE(outside.failure.find("outside the map"), std::string::npos) << outside.failure;
}

TEST(GridPathPlanner, RefusesAnUnreachableGoal) {
  // Two rooms split by a wall at x in [4, 5].
  const GridPathPlanner planner(GridPathPlannerOptions{},
                                MakeGrid(9.0, [](Vec2 p) { return p.y > 0.5 && p.y < 8.5 && p.x > 0.5 && p.x < 8.5 &&
                                                                  (p.x < 4.0 || p.x > 5.0); }));
  const GridPath path = planner.Plan({2.0, 4.0}, {7.0, 4.0});
  EXPECT_FALSE(path.found);
  EXPECT_NE(path.failure.find("no path"), std::string::npos) << path.failure;
  EXPECT_TRUE(path.waypoints.empty());
}

// Two rooms joined by a door of the given width in the wall x in [4, 5], centred at y = 4.5.
OccupancyGrid RoomsWithDoor(double door_m) {
  return MakeGrid(9.0, [door_m](Vec2 p) {
    const bool inside = p.y > 0.5 && p.y < 8.5 && p.x > 0.5 && p.x < 8.5;
    const bool wall = p.x >= 4.0 && p.x <= 5.0 && std::fabs(p.y - 4.5) > door_m / 2;
    return inside && !wall;
  });
}

TEST(GridPathPlanner, KeepsTheClearanceThroughADoorAndRefusesOneTooNarrow) {
  const GridPathPlanner planner(GridPathPlannerOptions{}, RoomsWithDoor(1.2));
  const GridPath path = planner.Plan({2.0, 2.0}, {7.0, 7.0});
  ASSERT_TRUE(path.found) << path.failure;
  EXPECT_GE(path.min_clearance_m, 0.4);
  for (const Vec2& p : path.waypoints) {
    if (p.x >= 4.0 && p.x <= 5.0) {
      EXPECT_NEAR(p.y, 4.5, 0.1);  // through the door's middle
    }
  }
  // 0.7 m: the robot (radius 0.2) would fit, but not with the 0.4 m clearance.
  const GridPath narrow = GridPathPlanner(GridPathPlannerOptions{}, RoomsWithDoor(0.7)).Plan({2.0, 2.0}, {7.0, 7.0});
  EXPECT_FALSE(narrow.found);
  EXPECT_NE(narrow.failure.find("no path"), std::string::npos);
}

TEST(GridPathPlanner, LeavesAStartCloseToAWallAndReachesAGoalCloseToOne) {
  const GridPathPlanner planner(GridPathPlannerOptions{}, LCorridor());
  // 0.3 m from the south wall (inside the 0.4 m clearance, outside the 0.2 m radius); goal likewise.
  const GridPath path = planner.Plan({1.5, 0.8}, {7.5, 8.2});
  ASSERT_TRUE(path.found) << path.failure;
  EXPECT_GE(path.min_clearance_m, 0.2);
}

TEST(GridPathPlanner, TreatsUnknownCellsAsObstaclesUnlessTold) {
  OccupancyGrid grid = LCorridor();
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      if (grid.At(x, y) == OccupancyGrid::kOccupied) grid.At(x, y) = OccupancyGrid::kUnknown;
    }
  }
  EXPECT_EQ(GridPathPlanner(GridPathPlannerOptions{}, grid).Plan({1.5, 1.5}, {4.0, 4.0}).found, false);
  GridPathPlannerOptions options;
  options.unknown_is_free = true;
  EXPECT_TRUE(GridPathPlanner(options, grid).Plan({1.5, 1.5}, {4.0, 4.0}).found);
}

TEST(GridPathPlanner, InvalidOptionsAndGridsNameTheField) {
  const OccupancyGrid grid = LCorridor();
  auto expect_field = [&grid](GridPathPlannerOptions o, const char* field) {
    try {
      GridPathPlanner planner(o, grid);
      ADD_FAILURE() << field << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  GridPathPlannerOptions o;
  o.clearance_m = 0.1;  // < robot_radius_m
  expect_field(o, "clearance_m");
  o = {};
  o.preferred_clearance_m = 0.3;
  expect_field(o, "preferred_clearance_m");
  o = {};
  o.wall_cost_weight = -1;
  expect_field(o, "wall_cost_weight");
  o = {};
  o.occupied_threshold = 0;
  expect_field(o, "occupied_threshold");
  o = {};
  o.waypoint_spacing_m = 0;
  expect_field(o, "waypoint_spacing_m");
  EXPECT_THROW(GridPathPlanner(GridPathPlannerOptions{}, OccupancyGrid{}), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization
