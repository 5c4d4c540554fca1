#include "doorplate_localization/sim/world_loader.h"

#include <gtest/gtest.h>

#include <functional>

namespace doorplate_localization {
namespace {

const std::string kWorlds = std::string(DOORPLATE_SOURCE_DIR) + "/worlds/";

const char* kMinimal = R"(
format_version: 1
name: tiny
walls:
  - {id: south, from: [0, 0], to: [10, 0], corridor_side: left}
  - {id: north, from: [0, 2], to: [10, 2], corridor_side: right}
doors:
  - {id: d1, wall: north, offset_m: 3.0}
plates:
  - {text: "214", door: d1, along_door_m: 0.7}
robot:
  start: {x_m: 1, y_m: 1, theta_deg: 90}
)";

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const WorldFileError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(LoadWorldFile, ReadsThePaperRealCorridor) {
  const World world = LoadWorldFile(kWorlds + "paper_real_corridor.yaml");
  EXPECT_EQ(world.name, "paper_real_corridor");
  EXPECT_EQ(world.Plates().size(), 16u);
  EXPECT_NEAR(world.walls[0].segment.Length(), 43.5, 1e-9);
  EXPECT_NEAR(world.walls[1].segment.a.y - world.walls[0].segment.a.y, 1.85, 1e-9);
  EXPECT_FALSE(world.surfaces.empty());
}

TEST(LoadWorldFile, ReadsEveryBuiltInWorld) {
  for (const char* name : {"paper_sim_closed_doors", "paper_sim_open_doors", "paper_real_corridor", "hospital_ward"}) {
    EXPECT_NO_THROW(LoadWorldFile(kWorlds + name + ".yaml")) << name;
  }
  const World open = LoadWorldFile(kWorlds + "paper_sim_open_doors.yaml");
  const World closed = LoadWorldFile(kWorlds + "paper_sim_closed_doors.yaml");
  EXPECT_EQ(open.Plates().size(), 10u);
  EXPECT_GT(open.surfaces.size(), closed.surfaces.size());  // rooms behind open doors
}

TEST(ParseWorldYaml, PlacesAPlateBesideItsDoorAndConvertsDegrees) {
  const World world = ParseWorldYaml(kMinimal, "tiny.yaml");
  ASSERT_EQ(world.signs.size(), 1u);
  EXPECT_NEAR(world.signs[0].offset_m, 3.7, 1e-12);
  EXPECT_EQ(world.signs[0].door_index, 0);
  EXPECT_FALSE(world.signs[0].corridor_side_left);  // copied from the north wall
  EXPECT_NEAR(world.start_pose.theta_rad, M_PI / 2, 1e-12);
}

TEST(ParseWorldYaml, BrokenFilesNameTheFileAndTheField) {
  EXPECT_EQ(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "wall: north", "wall: nort"), "w.yaml"); }),
            "w.yaml: doors[0].wall: no wall with id 'nort'");
  EXPECT_EQ(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "format_version: 1", "format_version: 7"), "w.yaml"); }),
            "w.yaml: format_version: unsupported version 7 (this build reads version 1)");
  EXPECT_NE(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "offset_m: 3.0", "offset_m: 9.9"), "w.yaml"); })
                .find("w.yaml: doors[0]: door 'd1' does not fit on wall 'north'"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "{id: north", "{id: south"), "w.yaml"); })
                .find("walls[1].id: duplicate wall id 'south'"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "along_door_m", "along_dor_m"), "w.yaml"); })
                .find("plates[0]: unknown field 'along_dor_m'"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "y_m: 1,", "y_m: 0.1,"), "w.yaml"); })
                .find("robot: start pose is inside or touching a wall"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "[0, 2]", "[0, 2"), "w.yaml"); }).find("w.yaml: line"),
            std::string::npos);
}

TEST(ParseWorldYaml, SensorOverridesAreValidated) {
  const std::string with_sensors = std::string(kMinimal) + "sensors: {laser: {num_beams: 720, max_range_m: 8}}\n";
  const World world = ParseWorldYaml(with_sensors, "w.yaml");
  EXPECT_EQ(world.sensors.laser.num_beams, 720);
  EXPECT_DOUBLE_EQ(world.sensors.laser.max_range_m, 8.0);
  EXPECT_EQ(ErrorOf([] { ParseWorldYaml(std::string(kMinimal) + "sensors: {camera: {side: up}}\n", "w.yaml"); }),
            "w.yaml: sensors.camera.side: must be 'left' or 'right'");
}

TEST(LoadWorldFile, AMissingFileIsNamed) {
  EXPECT_EQ(ErrorOf([] { LoadWorldFile("/nonexistent/x.yaml"); }), "/nonexistent/x.yaml: cannot open world file");
}

}  // namespace
}  // namespace doorplate_localization
