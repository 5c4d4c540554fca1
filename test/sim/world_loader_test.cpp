#include "doorplate_localization/sim/world_loader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <utility>

#include <opencv2/imgcodecs.hpp>

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

// Issue 15 item 5: the world must stay as hard as specified (small, dim, varied, unevenly lit).
TEST(LoadWorldFile, SmallDimPlatesIsSmallLowContrastAndUnevenlyLit) {
  const World world = LoadWorldFile(kWorlds + "small_dim_plates.yaml");
  EXPECT_NEAR(world.walls[0].segment.Length(), 25.0, 1e-9);
  ASSERT_EQ(world.Plates().size(), 10u);
  const auto luma = [](const ColorRgb& c) { return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]; };
  std::set<std::pair<int, bool>> looks;
  for (const TextSign* plate : world.Plates()) {
    SCOPED_TRACE(plate->text);
    EXPECT_DOUBLE_EQ(plate->width_m, 0.18);
    EXPECT_DOUBLE_EQ(plate->height_m, 0.09);
    EXPECT_GE(plate->center_height_m, 1.45);
    EXPECT_LE(plate->center_height_m, 1.78);
    EXPECT_LT(luma(plate->background) - luma(plate->foreground), 110.0);  // the defaults differ by 222
    EXPECT_GT(luma(plate->background) - luma(plate->foreground), 40.0);   // still readable
    looks.insert({static_cast<int>(plate->font), plate->italic});
  }
  EXPECT_GE(looks.size(), 5u);
  double darkest = 1.0, brightest = 1.0;
  for (double x = 0.0; x <= 25.0; x += 0.25) {
    darkest = std::min(darkest, world.LightingGain({x, 1.0}));
    brightest = std::max(brightest, world.LightingGain({x, 1.0}));
  }
  EXPECT_LT(darkest, 0.5);
  EXPECT_GT(brightest, 1.5);
}

TEST(LoadWorldFile, ReadsEveryBuiltInWorld) {
  for (const char* name : {"paper_sim_closed_doors", "paper_sim_open_doors", "paper_real_corridor", "hospital_ward",
                           "small_dim_plates", "hospital_floor_ring"}) {
    EXPECT_NO_THROW(LoadWorldFile(kWorlds + name + ".yaml")) << name;
  }
  const World open = LoadWorldFile(kWorlds + "paper_sim_open_doors.yaml");
  const World closed = LoadWorldFile(kWorlds + "paper_sim_closed_doors.yaml");
  EXPECT_EQ(open.Plates().size(), 10u);
  EXPECT_GT(open.surfaces.size(), closed.surfaces.size());  // rooms behind open doors
}

// Issue 17: a whole floor: ≥ 150 m of corridor, ≥ 60 unique 2xx plates on both walls of every corridor,
// each facing its corridor, about one door in five open, a lift lobby with two plateless lift doors.
TEST(LoadWorldFile, HospitalFloorRingHasPlatesFacingBothWallsOfEveryCorridor) {
  const World world = LoadWorldFile(kWorlds + "hospital_floor_ring.yaml");
  ASSERT_EQ(world.corridors.size(), 7u);
  double total_m = 0.0;
  for (const CorridorSpec& c : world.corridors) total_m += c.id == "lift_lobby" ? 0.0 : c.centreline.Length();
  EXPECT_GE(total_m, 150.0);
  const auto plates = world.Plates();
  EXPECT_GE(plates.size(), 60u);
  std::set<std::string> texts;
  std::map<std::string, std::set<bool>> sides;  // corridor id -> sides of its centreline holding plates
  for (const TextSign* plate : plates) {
    SCOPED_TRACE(plate->text);
    EXPECT_TRUE(texts.insert(plate->text).second);
    EXPECT_EQ(plate->text.size(), 3u);
    EXPECT_EQ(plate->text[0], '2');
    // A point 0.3 m in front of the plate lies inside exactly one corridor's strip.
    const Vec2 front = world.SignPosition(*plate) + 0.3 * world.CorridorNormal(plate->wall_index);
    int inside = 0;
    for (const CorridorSpec& c : world.corridors) {
      if (PointSegmentDistance(front, c.centreline) >= c.width_m / 2) continue;
      ++inside;
      const Vec2 along = c.centreline.b - c.centreline.a;
      sides[c.id].insert(Cross(along, world.SignPosition(*plate) - c.centreline.a) > 0);
    }
    EXPECT_EQ(inside, 1);
  }
  for (const CorridorSpec& c : world.corridors) {
    if (c.id != "lift_lobby") {
      EXPECT_EQ(sides[c.id].size(), 2u) << c.id;
    }
  }
  int open = 0, unplated = 0;
  for (size_t d = 0; d < world.doors.size(); ++d) {
    open += world.doors[d].open;
    unplated += std::none_of(plates.begin(), plates.end(),
                             [&](const TextSign* p) { return p->door_index == static_cast<int>(d); });
  }
  EXPECT_EQ(unplated, 2);  // the lifts
  EXPECT_GE(open, static_cast<int>(plates.size()) / 7);
  EXPECT_LE(open, static_cast<int>(plates.size()) / 3);
  EXPECT_TRUE(std::any_of(world.signs.begin(), world.signs.end(),
                          [](const TextSign& s) { return s.kind == TextKind::kDistractor && s.text == "LIFT"; }));
}

TEST(ParseWorldYaml, ReadsCorridorsAndNamesBadOnes) {
  const std::string good =
      std::string(kMinimal) + "corridors:\n  - {id: main, from: [0, 1], to: [10, 1], width_m: 2}\n";
  const World world = ParseWorldYaml(good, "w.yaml");
  ASSERT_EQ(world.corridors.size(), 1u);
  EXPECT_EQ(world.corridors[0].id, "main");
  EXPECT_DOUBLE_EQ(world.corridors[0].centreline.b.x, 10.0);
  EXPECT_DOUBLE_EQ(world.corridors[0].width_m, 2.0);
  EXPECT_TRUE(ParseWorldYaml(kMinimal, "w.yaml").corridors.empty());
  const auto error = [&](const std::string& line) {
    return ErrorOf([&] { ParseWorldYaml(good + "  - " + line + "\n", "w.yaml"); });
  };
  EXPECT_EQ(error("{id: main, from: [0, 1], to: [5, 1], width_m: 2}"),
            "w.yaml: corridors[1].id: duplicate corridor id 'main'");
  EXPECT_EQ(error("{id: b, from: [3, 1], to: [3, 1], width_m: 2}"),
            "w.yaml: corridors[1].to: must be at least 1 mm from 'from'");
  EXPECT_EQ(error("{id: b, from: [0, 1], to: [5, 1], width_m: 0}"),
            "w.yaml: corridors[1].width_m: must be > 0, got 0.000000");
  EXPECT_NE(error("{id: b, from: [0, .nan], to: [5, 1], width_m: 2}").find("w.yaml: corridors[1].from"),
            std::string::npos);
  EXPECT_NE(error("{id: b, from: [0, 1], to: [5, 1]}").find("w.yaml: corridors[1]"), std::string::npos);
  EXPECT_NE(error("{id: b, from: [0, 1], to: [5, 1], width_m: 2, widht: 3}").find("unknown field 'widht'"),
            std::string::npos);
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

TEST(ParseWorldYaml, WallsMayMeetAtTheirEndsButNotCrossOrOverlap) {
  const std::string north = "  - {id: north, from: [0, 2], to: [10, 2], corridor_side: right}\n";
  const auto with = [&](const std::string& extra) { return Replace(kMinimal, north, north + extra); };
  // A corner and a T-junction (an end on the other wall's middle) are fine.
  EXPECT_NO_THROW(ParseWorldYaml(with("  - {id: end, from: [10, 0], to: [10, 2], corridor_side: left}\n"), "w.yaml"));
  EXPECT_NO_THROW(ParseWorldYaml(with("  - {id: stub, from: [5, 2], to: [5, 4], corridor_side: left}\n"), "w.yaml"));
  EXPECT_EQ(ErrorOf([&] {
              ParseWorldYaml(with("  - {id: cross, from: [5, -1], to: [5, 0.5], corridor_side: left}\n"), "w.yaml");
            }),
            "w.yaml: walls[2]: crosses wall 'south' at (5.000, 0.000); walls may meet at their ends, not cross");
  EXPECT_EQ(ErrorOf([&] {
              ParseWorldYaml(with("  - {id: again, from: [8, 0], to: [12, 0], corridor_side: left}\n"), "w.yaml");
            }),
            "w.yaml: walls[2]: lies on wall 'south' for 2.000 m; walls may meet at their ends, not overlap");
  // Collinear walls that only touch end to end are one wall in two pieces: fine.
  EXPECT_NO_THROW(ParseWorldYaml(with("  - {id: more, from: [10, 0], to: [12, 0], corridor_side: left}\n"), "w.yaml"));
}

TEST(ParseWorldYaml, AbsurdCoordinatesAreRefusedNamingTheFieldAndTheLimit) {
  EXPECT_EQ(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "x_m: 1,", "x_m: 1e300,"), "w.yaml"); }),
            "w.yaml: robot.start.x_m: must be finite and within +-1e+06 m (limits::kMaxCoordinateM), got 1e+300");
  EXPECT_NE(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "to: [10, 0]", "to: [1e7, 0]"), "w.yaml"); })
                .find("w.yaml: walls[0].to[0]: must be finite and within +-1e+06 m"),
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

// A temporary folder holding a world file and a 40 × 20 px image: left half red, right half green.
class WorldWithImage : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("world_loader_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_ / "faces");
    cv::Mat face(20, 40, CV_8UC3, cv::Scalar(0, 0, 255));
    face.colRange(20, 40).setTo(cv::Scalar(0, 255, 0));
    ASSERT_TRUE(cv::imwrite((dir_ / "faces" / "plate.png").string(), face));
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string Write(const std::string& yaml) {
    const std::string path = (dir_ / "world.yaml").string();
    std::ofstream(path) << yaml;
    return path;
  }
  std::filesystem::path dir_;
};

TEST_F(WorldWithImage, ImageSignPathsAreRelativeToTheWorldFile) {
  const World world =
      LoadWorldFile(Write(Replace(kMinimal, "along_door_m: 0.7}", "along_door_m: 0.7, image: faces/plate.png}")));
  ASSERT_EQ(world.signs.size(), 1u);
  EXPECT_EQ(world.signs[0].image_path, (dir_ / "faces" / "plate.png").string());
  EXPECT_EQ(world.signs[0].text, "214");  // still the ground truth
}

TEST_F(WorldWithImage, AMissingOrUnreadableImageNamesTheFieldAndTheFile) {
  const std::string missing = Write(Replace(kMinimal, "along_door_m: 0.7}", "along_door_m: 0.7, image: no.png}"));
  const std::string error = ErrorOf([&] { LoadWorldFile(missing); });
  EXPECT_NE(error.find(missing + ": plates[0].image: cannot read image '" + (dir_ / "no.png").string() + "'"),
            std::string::npos) << error;
  std::ofstream(dir_ / "text.png") << "not a png";
  const std::string garbage = Write(Replace(kMinimal, "along_door_m: 0.7}", "along_door_m: 0.7, image: text.png}"));
  EXPECT_NE(ErrorOf([&] { LoadWorldFile(garbage); }).find("plates[0].image: cannot read image"), std::string::npos);
}

TEST(ParseWorldYaml, ReadsFontsTextSizeAndStrokes) {
  const World world = ParseWorldYaml(
      Replace(kMinimal, "along_door_m: 0.7}",
              "along_door_m: 0.7, size_m: [0.18, 0.09], font: complex_small, italic: true, text_height_m: 0.025, "
              "stroke_to_cap_height: 0.08}"),
      "w.yaml");
  const TextSign& sign = world.signs.at(0);
  EXPECT_EQ(sign.font, SignFont::kComplexSmall);
  EXPECT_TRUE(sign.italic);
  EXPECT_DOUBLE_EQ(sign.text_height_m, 0.025);
  EXPECT_DOUBLE_EQ(sign.stroke_to_cap_height, 0.08);
  EXPECT_NE(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "along_door_m: 0.7}", "along_door_m: 0.7, font: arial}"),
                                       "w.yaml"); }).find("plates[0].font: font must be one of"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { ParseWorldYaml(Replace(kMinimal, "along_door_m: 0.7}",
                                                "along_door_m: 0.7, text_height_m: 0.5}"), "w.yaml"); })
                .find("text_height_m must be <= the sign height"),
            std::string::npos);
}

TEST(ParseWorldYaml, ReadsLightingZones) {
  const World world = ParseWorldYaml(
      std::string(kMinimal) +
          "lighting:\n  - {min: [2, -1], max: [6, 3], gain: 0.3, gain_at_max: 1.8, edge_m: 0.5}\n"
          "  - {min: [0, 0], max: [1, 2], gain: 2, axis: y}\n",
      "w.yaml");
  ASSERT_EQ(world.lighting.size(), 2u);
  EXPECT_DOUBLE_EQ(world.lighting[0].gain_at_max, 1.8);
  EXPECT_DOUBLE_EQ(world.lighting[0].edge_m, 0.5);
  EXPECT_TRUE(world.lighting[0].axis_x);
  EXPECT_DOUBLE_EQ(world.lighting[1].gain_at_max, 2.0);  // defaults to gain: a uniform zone
  EXPECT_FALSE(world.lighting[1].axis_x);
  EXPECT_EQ(ErrorOf([] { ParseWorldYaml(std::string(kMinimal) + "lighting:\n  - {min: [2, 0], max: [1, 2]}\n",
                                        "w.yaml"); }),
            "w.yaml: lighting[0].max: must be >= min in x and y");
}

TEST(ParseWorldYaml, ReadsCameraIntrinsics) {
  const World world = ParseWorldYaml(
      std::string(kMinimal) +
          "sensors: {camera: {width_px: 1280, height_px: 720, fx_px: 900, fy_px: 905, cx_px: 630.5, cy_px: 370}}\n",
      "w.yaml");
  const CameraOptions& c = world.sensors.camera;
  EXPECT_EQ(c.width_px, 1280);
  EXPECT_EQ(c.height_px, 720);
  EXPECT_DOUBLE_EQ(c.fx_px, 900.0);
  EXPECT_DOUBLE_EQ(c.fy_px, 905.0);
  EXPECT_DOUBLE_EQ(c.cx_px, 630.5);
  EXPECT_DOUBLE_EQ(c.cy_px, 370.0);
  EXPECT_EQ(ErrorOf([] { ParseWorldYaml(std::string(kMinimal) + "sensors: {camera: {cx_px: 700}}\n", "w.yaml"); }),
            "w.yaml: sensors.camera: cx_px must be in [0, width_px - 1]");
  EXPECT_EQ(ErrorOf([] { ParseWorldYaml(std::string(kMinimal) +
                                            "sensors: {camera: {fx_px: 500, horizontal_fov_deg: 70}}\n", "w.yaml"); }),
            "w.yaml: sensors.camera: give horizontal_fov_deg or fx_px, not both");
}

}  // namespace
}  // namespace doorplate_localization
