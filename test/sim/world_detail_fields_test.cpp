// The world file's detail sections (src/sim/world_detail_fields.cpp through ParseWorldYaml): every field
// checked, errors naming the file and the field, and the built-in realistic corridor.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/world_loader.h"

namespace doorplate_localization {
namespace {

const std::string kWorlds = std::string(DOORPLATE_SOURCE_DIR) + "/worlds/";

const std::string kBase = R"(
format_version: 1
name: tiny
walls:
  - {id: south, from: [0, 0], to: [10, 0], corridor_side: left}
  - {id: north, from: [0, 2], to: [10, 2], corridor_side: right}
  - {id: west, from: [0, 0], to: [0, 2], corridor_side: right}
  - {id: east, from: [10, 0], to: [10, 2], corridor_side: left}
doors:
  - {id: d1, wall: north, offset_m: 3.0}
plates:
  - {text: "214", door: d1}
robot:
  start: {x_m: 1, y_m: 1, theta_deg: 0}
)";

std::string ErrorOf(const std::string& extra) {
  try {
    ParseWorldYaml(kBase + extra, "w.yaml");
  } catch (const WorldFileError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(WorldDetailFields, ErrorsNameTheFileAndTheField) {
  EXPECT_EQ(ErrorOf("clutter:\n  - {type: sofa, wall: south, offset_m: 5}\n").rfind("w.yaml: clutter[0].type: unknown "
                                                                                   "clutter type 'sofa'", 0), 0u);
  EXPECT_EQ(ErrorOf("clutter:\n  - {type: bench, wall: south, offset_m: 5, colour: [1, 2, 3]}\n")
                .find("w.yaml: clutter[0]"), 0u);
  EXPECT_NE(ErrorOf("clutter:\n  - {type: bench, wall: south, offset_m: 5, colour: [1, 2, 3]}\n").find("colour"),
            std::string::npos);
  EXPECT_EQ(ErrorOf("clutter:\n  - {type: trolley, wall: south, offset_m: 5, length_m: 2}\n"),
            "w.yaml: clutter[0].length_m: type 'trolley' has a fixed size");
  EXPECT_EQ(ErrorOf("clutter:\n  - {type: radiator, wall: nort, offset_m: 5}\n"),
            "w.yaml: clutter[0].wall: no wall with id 'nort'");
  EXPECT_EQ(ErrorOf("glass:\n  - {from: [5, 0], to: [5, 2], laser_reflect_probability: 1.5}\n"),
            "w.yaml: glass[0].laser_reflect_probability: must be in [0.000000, 1.000000], got 1.500000");
  EXPECT_EQ(ErrorOf("people:\n  - {waypoints: [[2, 1], [2, 1]]}\n"),
            "w.yaml: people[0].waypoints[1]: must be at least 1 cm from the previous waypoint");
  EXPECT_EQ(ErrorOf("people:\n  - {waypoints: [[2, 1], [5, 1]], mode: zigzag}\n"),
            "w.yaml: people[0].mode: must be 'back_and_forth' or 'loop'");
  EXPECT_EQ(ErrorOf("people:\n  - {waypoints: [[2, 1], [5, 1]], speed: 1}\n").find("w.yaml: people[0]"), 0u);
}

TEST(WorldDetailFields, DoorDetailIsCheckedPerDoorAndPerRow) {
  const std::string row = "door_rows:\n  - {wall: south, first_offset_m: 6, spacing_m: 2, texts: [\"1\"], ";
  EXPECT_EQ(ErrorOf(row + "recess_m: 0.05, open: true}\n"),
            "w.yaml: door_rows[0].texts[0]: door 'south_door1': recess_m needs a closed door");
  EXPECT_EQ(ErrorOf(row + "frame_width_m: 0.07}\n"),
            "w.yaml: door_rows[0].texts[0]: door 'south_door1': give both frame_width_m and frame_depth_m (> 0), or "
            "neither");
  EXPECT_EQ(ErrorOf(row + "recess_m: 0.9}\n"),
            "w.yaml: door_rows[0].recess_m: must be in [0.000000, 0.500000], got 0.900000");
  EXPECT_EQ(ErrorOf(row + "recess_m: 0.05, frame_width_m: 0.07, frame_depth_m: 0.03}\n"), "(no error)");
}

TEST(WorldDetailFields, ClutterMustNotHidePlatesNorSwallowTheStart) {
  // The plate of d1 (north, offset 3, 1.6 m high) behind a plant's foliage (0.4-1.5 m) is fine, behind a
  // raised skirting it is not: a wall-mounted item may not cover a sign.
  EXPECT_EQ(ErrorOf("clutter:\n  - {type: plant, wall: north, offset_m: 3}\n"), "(no error)");
  EXPECT_EQ(ErrorOf("clutter:\n  - {type: fire_extinguisher, wall: north, offset_m: 3.1}\n"), "(no error)");
  const std::string err = ErrorOf("clutter:\n  - {type: bed, x_m: 1.2, y_m: 1.0}\n");
  EXPECT_EQ(err, "w.yaml: robot.start: start pose is inside or touching clutter 'bed1'");
}

TEST(WorldDetailFields, RunsBreakAtDoorsAndGlass) {
  const World world = ParseWorldYaml(kBase + "glass:\n  - {wall: north, offset_m: 7, width_m: 1.0}\n"
                                             "clutter:\n  - {type: handrail, wall: north}\n", "w.yaml");
  // North wall 0..10 with door d1 at 2.55..3.45 and glass at 6.5..7.5: three stretches.
  ASSERT_EQ(world.clutter.size(), 3u);
  EXPECT_EQ(world.clutter[0].id, "handrail1#1");
  EXPECT_NEAR(world.clutter[0].boxes[0].size_x_m, 2.55, 1e-9);
  EXPECT_NEAR(world.clutter[1].boxes[0].size_x_m, 6.5 - 3.45, 1e-9);
  EXPECT_NEAR(world.clutter[2].boxes[0].size_x_m, 2.5, 1e-9);
  // Against the north wall on the corridor side: the rail is 4 cm + half its 5 cm depth below y = 2.
  EXPECT_NEAR(world.clutter[0].pose.y_m, 2.0 - 0.065, 1e-9);
}

TEST(WorldDetailFields, RealisticCorridorKeepsThePaperCorridorsPlatesAndIsPassable) {
  const World plain = LoadWorldFile(kWorlds + "paper_real_corridor.yaml");
  const World real = LoadWorldFile(kWorlds + "paper_real_corridor_realistic.yaml");
  ASSERT_EQ(real.Plates().size(), plain.Plates().size());
  for (size_t i = 0; i < plain.Plates().size(); ++i) {
    EXPECT_EQ(real.Plates()[i]->text, plain.Plates()[i]->text);
    EXPECT_NEAR(Norm(real.SignPosition(*real.Plates()[i]) - plain.SignPosition(*plain.Plates()[i])), 0.0, 1e-12);
  }
  EXPECT_EQ(real.walls.size(), plain.walls.size());
  EXPECT_NEAR(real.start_pose.x_m, plain.start_pose.x_m, 1e-12);
  EXPECT_GE(real.people.size(), 2u);
  EXPECT_FALSE(real.glass.empty());
  // Between the end zones (x 2.2 .. 41) a 1.0 m lane stays free at laser and bumper heights.
  const OccupancyGrid grid = RasterizeWorld(real, 0.05, 0.25);
  for (double x = 2.3; x < 41.0; x += 0.05) {
    int free_run = 0, best = 0;
    for (double y = 0.025; y < 1.85; y += 0.05) {
      int cx = 0, cy = 0;
      grid.WorldToCell({x, y}, &cx, &cy);
      free_run = grid.At(cx, cy) == OccupancyGrid::kFree ? free_run + 1 : 0;
      best = std::max(best, free_run);
    }
    EXPECT_GE(best * 0.05, 1.0) << "at x = " << x;
  }
}

}  // namespace
}  // namespace doorplate_localization
