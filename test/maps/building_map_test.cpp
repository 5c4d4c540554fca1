#include "doorplate_localization/maps/building_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "doorplate_localization/maps/map_io.h"
#include "map_test_util.h"

namespace doorplate_localization {
namespace {

using test::Contains;
using test::ErrorOf;

// Two floors and one lift; paths relative to the building file's folder.
const char kTwoFloors[] =
    "format_version: 1\n"
    "name: tiny_two_floors\n"
    "floors:\n"
    "  - {id: \"2\", occupancy_map: h2.yaml, text_map: h2.text_map.yaml}\n"
    "  - {id: \"3\", occupancy_map: h3.yaml, text_map: h3.text_map.yaml, world: ../worlds/h3.yaml}\n"
    "lifts:\n"
    "  - id: A\n"
    "    stops:\n"
    "      - {floor: \"2\", x_m: 1.05, y_m: 0.55, yaw_rad: 1.5707963268}\n"
    "      - {floor: \"3\", x_m: 1.05, y_m: 0.55, yaw_rad: 1.5707963268}\n";

// `kTwoFloors` with `from` replaced by `to` (the fixture must contain `from`).
std::string Edited(const std::string& from, const std::string& to) {
  std::string text = kTwoFloors;
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

std::string ParseError(const std::string& yaml) {
  return ErrorOf<BuildingFileError>([&] { ParseBuildingFile(yaml, "b.building.yaml", ""); });
}

// A floor's map pair in `dir`: a 2 m x 1 m grid at 0.1 m (origin (0, 0)), free but for the cell around
// (0.55, 0.55) m, and a text map with one plate `room`.
void WriteFloorMaps(const test::TempDir& dir, const std::string& base, const std::string& room) {
  OccupancyGrid grid(20, 10, 0.1, Pose2D{}, OccupancyGrid::kFree);
  grid.At(5, 5) = OccupancyGrid::kOccupied;
  SaveOccupancyMap(grid, dir.Path(base));
  TextMap text_map;
  text_map.occupancy_map = base + ".yaml";
  TextLandmark plate;
  plate.text = room;
  plate.pose = {1.5, 1.0, -M_PI / 2};
  text_map.landmarks = {plate};
  SaveTextMap(text_map, dir.Path(base + ".text_map.yaml"));
}

TEST(ParseBuildingFile, ReadsFloorsAndLiftsAsWritten) {
  const BuildingFile b = ParseBuildingFile(kTwoFloors, "b.building.yaml", "");
  EXPECT_EQ(b.name, "tiny_two_floors");
  ASSERT_EQ(b.floors.size(), 2u);
  EXPECT_EQ(b.floors[1].id, "3");
  EXPECT_EQ(b.floors[1].world, "../worlds/h3.yaml");
  EXPECT_EQ(b.floors[0].world, "");
  EXPECT_EQ(b.FloorIndex("3"), 1);
  EXPECT_EQ(b.FloorIndex("4"), -1);
  ASSERT_EQ(b.lifts.size(), 1u);
  ASSERT_NE(b.lifts[0].StopOn("3"), nullptr);
  EXPECT_DOUBLE_EQ(b.lifts[0].StopOn("3")->pose.x_m, 1.05);
  EXPECT_EQ(b.lifts[0].StopOn("4"), nullptr);
}

TEST(LoadBuildingFile, ResolvesRelativePathsAgainstItsFolderAndKeepsAbsoluteOnes) {
  test::TempDir dir;
  const std::string path =
      dir.Write("maps/b.building.yaml", Edited("h2.yaml, ", "/data/h2.yaml, "));
  const BuildingFile b = LoadBuildingFile(path);
  EXPECT_EQ(b.floors[0].occupancy_map, "/data/h2.yaml");
  EXPECT_EQ(b.floors[0].text_map, dir.Path("maps/h2.text_map.yaml"));
  EXPECT_EQ(b.floors[1].world, dir.Path("worlds/h3.yaml"));
}

TEST(SaveBuildingFile, SaveThenLoadGivesTheSameBuildingWithPathsRelativeToTheFile) {
  test::TempDir dir;
  const BuildingFile b = LoadBuildingFile(dir.Write("maps/b.building.yaml", kTwoFloors));
  SaveBuildingFile(b, dir.Path("maps/copy.building.yaml"));
  const std::string text = dir.Read("maps/copy.building.yaml");
  EXPECT_TRUE(Contains(text, "occupancy_map: \"h2.yaml\"")) << text;
  EXPECT_TRUE(Contains(text, "world: \"../worlds/h3.yaml\"")) << text;
  const BuildingFile back = LoadBuildingFile(dir.Path("maps/copy.building.yaml"));
  EXPECT_EQ(back.name, b.name);
  ASSERT_EQ(back.floors.size(), b.floors.size());
  for (size_t i = 0; i < b.floors.size(); ++i) {
    EXPECT_EQ(back.floors[i].id, b.floors[i].id);
    EXPECT_EQ(back.floors[i].occupancy_map, b.floors[i].occupancy_map);
    EXPECT_EQ(back.floors[i].text_map, b.floors[i].text_map);
    EXPECT_EQ(back.floors[i].world, b.floors[i].world);
  }
  ASSERT_EQ(back.lifts.size(), 1u);
  ASSERT_EQ(back.lifts[0].stops.size(), 2u);
  EXPECT_EQ(back.lifts[0].id, "A");
  EXPECT_EQ(back.lifts[0].stops[1].floor, "3");
  EXPECT_NEAR(back.lifts[0].stops[1].pose.theta_rad, 1.5707963268, 1e-9);
}

TEST(SaveBuildingFile, RefusesAnInvalidBuildingNamingThePathAndWritesNothing) {
  test::TempDir dir;
  BuildingFile b = ParseBuildingFile(kTwoFloors, "b.building.yaml", "");
  b.lifts[0].stops[1].floor = "2";
  const std::string error = ErrorOf<BuildingFileError>([&] { SaveBuildingFile(b, dir.Path("b.building.yaml")); });
  EXPECT_TRUE(Contains(error, dir.Path("b.building.yaml"))) << error;
  EXPECT_TRUE(Contains(error, "lifts[0].stops[1].floor")) << error;
  EXPECT_TRUE(dir.List().empty());
}

TEST(ParseBuildingFile, UnknownFieldIsAnErrorNamingIt) {
  const std::string error = ParseError(Edited("id: A", "id: A\n    speed_mps: 1"));
  EXPECT_TRUE(Contains(error, "b.building.yaml: lifts[0]: unknown field 'speed_mps'")) << error;
}

TEST(ParseBuildingFile, DuplicateFloorIdIsAnError) {
  const std::string error = ParseError(Edited("id: \"3\"", "id: \"2\""));
  EXPECT_TRUE(Contains(error, "b.building.yaml: floors[1].id: duplicate floor id '2' (also floors[0])")) << error;
}

TEST(ParseBuildingFile, LiftStopOnAnUnknownFloorIsAnError) {
  const std::string error = ParseError(Edited("{floor: \"3\"", "{floor: \"4\""));
  EXPECT_TRUE(Contains(error, "b.building.yaml: lifts[0].stops[1].floor: no floor '4' (floors: 2, 3)")) << error;
}

TEST(ParseBuildingFile, LiftWithOneStopIsAnError) {
  const std::string error =
      ParseError(Edited("      - {floor: \"3\", x_m: 1.05, y_m: 0.55, yaw_rad: 1.5707963268}\n", ""));
  EXPECT_TRUE(Contains(error, "b.building.yaml: lifts[0].stops: a lift needs at least 2 stops, got 1")) << error;
}

TEST(ParseBuildingFile, OtherBadContentNamesTheField) {
  EXPECT_TRUE(Contains(ParseError(Edited("format_version: 1", "format_version: 2")), "format_version: unsupported"));
  EXPECT_TRUE(Contains(ParseError(Edited("name: tiny_two_floors", "name: \"\"")), "name: must not be empty"));
  EXPECT_TRUE(Contains(ParseError(Edited("{floor: \"3\"", "{floor: \"2\"")),
                       "lifts[0].stops[1].floor: lift 'A' stops on floor '2' twice (also lifts[0].stops[0])"));
  EXPECT_TRUE(Contains(ParseError(Edited("x_m: 1.05", "x_m: .nan")), "lifts[0].stops[0].x_m: must be a finite number"));
  EXPECT_TRUE(Contains(ParseError(Edited("occupancy_map: h2.yaml, text_map: h2.text_map.yaml", "")),
                       "floors[0]: floor '2' names no file"));
  EXPECT_TRUE(Contains(ParseError("format_version: 1\nname: x\nfloors: []\n"), "floors: must list at least one floor"));
  EXPECT_TRUE(Contains(ParseError("format_version: 1\nname: x\n"), "floors: required field is missing"));
}

TEST(LoadBuildingMaps, LoadsEveryFloorsMapsAndFindsARoomOnTheRightFloor) {
  test::TempDir dir;
  WriteFloorMaps(dir, "h2", "214");
  WriteFloorMaps(dir, "h3", "314");
  const std::string path = dir.Write("b.building.yaml", kTwoFloors);
  const BuildingMaps maps = LoadBuildingMaps(LoadBuildingFile(path), path);
  EXPECT_EQ(maps.name, "tiny_two_floors");
  ASSERT_EQ(maps.floors.size(), 2u);
  EXPECT_EQ(maps.floors[1].grid.width, 20);
  EXPECT_EQ(maps.FloorIndex("3"), 1);
  EXPECT_EQ(maps.FloorsOfRoom("314"), std::vector<int>{1});
  EXPECT_EQ(maps.FloorsOfRoom("214"), std::vector<int>{0});
  EXPECT_TRUE(maps.FloorsOfRoom("999").empty());
  ASSERT_EQ(maps.lifts.size(), 1u);
}

TEST(LoadBuildingMaps, FindsARoomNumberedAlikeOnEveryFloorThatHasIt) {
  test::TempDir dir;
  WriteFloorMaps(dir, "h2", "E14-295");
  WriteFloorMaps(dir, "h3", "E14-295");
  const std::string path = dir.Write("b.building.yaml", kTwoFloors);
  const BuildingMaps maps = LoadBuildingMaps(LoadBuildingFile(path), path);
  EXPECT_EQ(maps.FloorsOfRoom("e14 295"), (std::vector<int>{0, 1}));  // canonical forms
}

TEST(LoadBuildingMaps, MissingMapFileNamesTheFloorAndTheFile) {
  test::TempDir dir;
  WriteFloorMaps(dir, "h2", "214");
  WriteFloorMaps(dir, "h3", "314");
  std::filesystem::remove(dir.Path("h3.text_map.yaml"));
  const std::string path = dir.Write("b.building.yaml", kTwoFloors);
  const std::string error = ErrorOf<BuildingFileError>([&] { LoadBuildingMaps(LoadBuildingFile(path), path); });
  EXPECT_TRUE(Contains(error, path + ": floors[1] (id '3'): " + dir.Path("h3.text_map.yaml") + ": cannot open"))
      << error;
}

TEST(LoadBuildingMaps, FloorWithoutAMapPairIsAnError) {
  test::TempDir dir;
  WriteFloorMaps(dir, "h2", "214");
  const std::string path =
      dir.Write("b.building.yaml", Edited("occupancy_map: h3.yaml, text_map: h3.text_map.yaml, ", ""));
  const std::string error = ErrorOf<BuildingFileError>([&] { LoadBuildingMaps(LoadBuildingFile(path), path); });
  EXPECT_TRUE(Contains(error, path + ": floors[1] (id '3'): no occupancy_map")) << error;
}

TEST(LoadBuildingMaps, LiftStopOnAnOccupiedCellIsAnError) {
  test::TempDir dir;
  WriteFloorMaps(dir, "h2", "214");
  WriteFloorMaps(dir, "h3", "314");
  const std::string path = dir.Write("b.building.yaml", Edited("{floor: \"3\", x_m: 1.05", "{floor: \"3\", x_m: 0.55"));
  const std::string error = ErrorOf<BuildingFileError>([&] { LoadBuildingMaps(LoadBuildingFile(path), path); });
  EXPECT_TRUE(Contains(error, path + ": lifts[0].stops[1]: (0.55, 0.55) m is on an occupied (100) cell (5, 5) of "
                                     "floor '3'; a stop must be on a free cell"))
      << error;
}

TEST(ValidateBuildingMaps, StopOutsideTheGridAndDuplicateFloorsAreErrors) {
  BuildingMaps maps;
  for (const char* id : {"2", "3"}) {
    maps.floors.push_back({id, OccupancyGrid(20, 10, 0.1, Pose2D{}, OccupancyGrid::kFree),
                           std::make_shared<const TextMap>()});
  }
  maps.lifts = {{"A", {{"2", {1.0, 0.5, 0.0}}, {"3", {5.0, 0.5, 0.0}}}}};
  EXPECT_TRUE(Contains(ErrorOf<BuildingFileError>([&] { ValidateBuildingMaps(maps, "truth"); }),
                       "truth: lifts[0].stops[1]: (5, 0.5) m is outside the grid of floor '3'"));
  maps.lifts[0].stops[1].pose.x_m = 1.0;
  EXPECT_NO_THROW(ValidateBuildingMaps(maps, "truth"));
  maps.floors[1].id = "2";
  EXPECT_TRUE(Contains(ErrorOf<BuildingFileError>([&] { ValidateBuildingMaps(maps, "truth"); }),
                       "truth: floors[1].id: duplicate floor id '2' (also floors[0])"));
}

}  // namespace
}  // namespace doorplate_localization
