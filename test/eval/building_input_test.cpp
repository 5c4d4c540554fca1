// Loading the building an experiment runs in: the worlds building file and the maps building file.
#include "building_input.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "eval_args.h"

namespace doorplate_localization {
namespace {

const std::string kRoot = DOORPLATE_SOURCE_DIR;

TEST(BuildingInput, TheMapsDefaultToTheMapsFolderBesideTheWorlds) {
  EXPECT_EQ(DefaultBuildingMapPath("worlds/b.building.yaml", "b"), "maps/b.building.yaml");
  EXPECT_EQ(DefaultBuildingMapPath("b.building.yaml", "b"), "../maps/b.building.yaml");
}

TEST(BuildingInput, LoadsTheTwoFloorHospitalWithAWorldAndMapsPerFloor) {
  std::string map_path;
  const LocalizeBuilding b =
      LoadLocalizeBuilding(kRoot + "/worlds/hospital_two_floors.building.yaml", "", &map_path);
  EXPECT_EQ(b.name, "hospital_two_floors");
  ASSERT_EQ(b.worlds.size(), 2u);
  ASSERT_EQ(b.maps->floors.size(), 2u);
  EXPECT_EQ(b.maps->floors[1].id, "3");
  EXPECT_EQ(b.worlds[1].name, "hospital_floor3_ring");
  EXPECT_EQ(b.maps->floors[1].text_map->landmarks.front().text.substr(0, 1), "3");
  EXPECT_EQ(b.ground_truth_grids.size(), 2u);
  EXPECT_EQ(b.maps->lifts.size(), 2u);
  EXPECT_EQ(std::filesystem::path(map_path).filename(), "hospital_two_floors.building.yaml");
}

TEST(BuildingInput, MapsThatListOtherFloorsAreRefusedNamingBothFiles) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "building_input_test";
  std::filesystem::create_directories(dir);
  const std::string maps = (dir / "swapped.building.yaml").string();
  std::ofstream(maps) << "format_version: 1\nname: swapped\nfloors:\n"
                      << "  - {id: \"3\", occupancy_map: " << kRoot << "/maps/hospital_floor3_ring.yaml, text_map: "
                      << kRoot << "/maps/hospital_floor3_ring.text_map.yaml}\n"
                      << "  - {id: \"2\", occupancy_map: " << kRoot << "/maps/hospital_floor_ring.yaml, text_map: "
                      << kRoot << "/maps/hospital_floor_ring.text_map.yaml}\n";
  try {
    LoadLocalizeBuilding(kRoot + "/worlds/hospital_two_floors.building.yaml", maps, nullptr);
    FAIL() << "accepted maps with the floors swapped";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("floors[0] (id '2')"), std::string::npos) << what;
    EXPECT_NE(what.find(maps + " lists floor '3' there"), std::string::npos) << what;
  }
}

TEST(BuildingInput, GivingBothOrNeitherWorldAndBuildingIsAUsageError) {
  EXPECT_THROW(LoadExperimentBuilding("localize", "", "", "", nullptr), UsageError);
  EXPECT_THROW(LoadExperimentBuilding("localize", "w.yaml", "b.yaml", "", nullptr), UsageError);
}

}  // namespace
}  // namespace doorplate_localization
