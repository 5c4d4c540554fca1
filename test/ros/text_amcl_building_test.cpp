// Tests of the floors TextAmclNodelet localizes on (text_amcl_building.h): ~building_file, ~map_file and
// ~text_map_file loaded with errors naming the parameter, and the session started on them. No ROS master.
#include "text_amcl_building.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

const std::string kSource = DOORPLATE_SOURCE_DIR;

// Names parameters as the nodelet named "amcl" would; holds no values (the tests set the options directly).
class NamesOnly : public ParamSource {
 public:
  std::optional<ParamValue> Get(const std::string&, const ParamValue&) const override { return std::nullopt; }
  bool Has(const std::string&) const override { return false; }
  std::string Resolve(const std::string& name) const override { return "/amcl/" + name; }
  void Warn(const std::string&) const override {}
};

// What ParameterError `f` throws ("" when none).
template <typename F>
std::string ErrorOf(const F& f) {
  try {
    f();
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

// A 4 m x 2 m room with walls all round and one plate on its south wall.
std::shared_ptr<const BuildingMaps> Room(const std::string& id, bool with_plate) {
  OccupancyGrid grid(40, 20, 0.1, Pose2D{}, OccupancyGrid::kFree);
  for (int x = 0; x < 40; ++x) grid.At(x, 0) = grid.At(x, 19) = OccupancyGrid::kOccupied;
  for (int y = 0; y < 20; ++y) grid.At(0, y) = grid.At(39, y) = OccupancyGrid::kOccupied;
  auto text = std::make_shared<TextMap>();
  if (with_plate) text->landmarks.push_back({"101", Pose2D{2.0, 0.1, M_PI / 2}, 1.5, "south", 0, 0.0});
  return OneFloorBuilding(grid, text, id);
}

TextAmclNodeOptions SmallFilter() {
  TextAmclNodeOptions o;
  o.session.setup.filter.min_particles = 50;
  o.session.setup.filter.max_particles = 200;
  o.session.start_with_global_localization = true;
  return o;
}

TEST(LoadLocalizerBuilding, LoadsEveryFloorsMapsAndTheLiftsOfAMapsBuildingFile) {
  TextAmclNodeOptions o;
  EXPECT_EQ(LoadLocalizerBuilding(o, NamesOnly()), nullptr) << "no ~building_file: no building";
  o.building_file = kSource + "/maps/hospital_two_floors.building.yaml";
  o.start_floor = "3";
  const std::shared_ptr<const BuildingMaps> maps = LoadLocalizerBuilding(o, NamesOnly());
  ASSERT_NE(maps, nullptr);
  ASSERT_EQ(maps->floors.size(), 2u);
  EXPECT_EQ(maps->floors[0].id, "2");
  EXPECT_EQ(maps->floors[1].id, "3");
  ASSERT_NE(maps->floors[1].text_map, nullptr);
  EXPECT_FALSE(maps->floors[1].text_map->Find("305").empty());
  EXPECT_EQ(maps->lifts.size(), 2u);
}

TEST(LoadLocalizerBuilding, AnUnusableFileOrAnUnknownStartFloorIsAnErrorNamingTheParameter) {
  TextAmclNodeOptions o;
  o.building_file = kSource + "/maps/no_such.building.yaml";
  const std::string missing = ErrorOf([&] { LoadLocalizerBuilding(o, NamesOnly()); });
  EXPECT_EQ(missing.rfind("/amcl/building_file = '" + o.building_file + "' cannot be used: ", 0), 0u) << missing;
  o.building_file = kSource + "/maps/hospital_floor_ring.yaml";  // a map, not a building
  EXPECT_NE(ErrorOf([&] { LoadLocalizerBuilding(o, NamesOnly()); }).find("/amcl/building_file"), std::string::npos);
  o.building_file = kSource + "/maps/hospital_two_floors.building.yaml";
  o.start_floor = "4";
  const std::string floor = ErrorOf([&] { LoadLocalizerBuilding(o, NamesOnly()); });
  EXPECT_EQ(floor, "/amcl/start_floor: no floor '4' in " + o.building_file + " (floors: 2, 3)");
}

TEST(LocalizerStartMaps, IsTheBuildingOrTheMapFileAsOneFloorOrNothingForTheMapTopic) {
  TextAmclNodeOptions o;
  EXPECT_EQ(LocalizerStartMaps(o, nullptr, "/amcl/map_file"), nullptr);
  o.map_file = kSource + "/maps/paper_sim_closed_doors.yaml";
  o.start_floor = "1";
  auto text = std::make_shared<const TextMap>();
  const auto one = LocalizerStartMaps(o, text, "/amcl/map_file");
  ASSERT_NE(one, nullptr);
  ASSERT_EQ(one->floors.size(), 1u);
  EXPECT_EQ(one->floors[0].id, "1");
  EXPECT_EQ(one->floors[0].text_map, text);
  EXPECT_GT(one->floors[0].grid.width, 0);
  o.map_file = kSource + "/maps/no_such_map.yaml";
  const std::string error = ErrorOf([&] { LocalizerStartMaps(o, nullptr, "/amcl/map_file"); });
  EXPECT_EQ(error.rfind("/amcl/map_file = '" + o.map_file + "' cannot be used: ", 0), 0u) << error;
  o.building_file = kSource + "/maps/hospital_two_floors.building.yaml";
  o.start_floor = "";
  o.building = LoadLocalizerBuilding(o, NamesOnly());
  EXPECT_EQ(LocalizerStartMaps(o, nullptr, "/amcl/map_file"), o.building) << "the building wins over ~map_file";
}

TEST(LoadLocalizerTextMap, NamesTheParameterWhenUnsetOrUnreadableAndIsNullWithoutText) {
  TextAmclNodeOptions o;
  LocalizerTextMap loaded = LoadLocalizerTextMap(o, "/amcl/text_map_file");
  EXPECT_EQ(loaded.text_map, nullptr);
  EXPECT_EQ(loaded.warning, "/amcl/text_map_file is not set: localizing with the laser alone");
  o.text_map_file = kSource + "/maps/no_such.text_map.yaml";
  loaded = LoadLocalizerTextMap(o, "/amcl/text_map_file");
  EXPECT_EQ(loaded.text_map, nullptr);
  EXPECT_EQ(loaded.problem.rfind("/amcl/text_map_file: ", 0), 0u) << loaded.problem;
  o.text_map_file = kSource + "/maps/paper_sim_closed_doors.text_map.yaml";
  loaded = LoadLocalizerTextMap(o, "/amcl/text_map_file");
  ASSERT_NE(loaded.text_map, nullptr);
  EXPECT_EQ(loaded.text_map->landmarks.size(), 10u);
  EXPECT_TRUE(loaded.problem.empty() && loaded.warning.empty());
  o.global_frame_id = "world";
  EXPECT_NE(LoadLocalizerTextMap(o, "/amcl/text_map_file").warning.find("differs from global_frame_id 'world'"),
            std::string::npos);
  o.session.setup.use_text = false;
  loaded = LoadLocalizerTextMap(o, "/amcl/text_map_file");
  EXPECT_TRUE(loaded.text_map == nullptr && loaded.problem.empty() && loaded.warning.empty());
}

TEST(StartBuildingSession, OnOneFloorWhoseTextMapIsRefusedRunsLaserOnlySayingWhy) {
  std::string problem;
  const auto good = StartBuildingSession(ToBuildingSessionOptions(SmallFilter()), Room("", true), &problem);
  EXPECT_TRUE(problem.empty()) << problem;
  EXPECT_TRUE(good->session().has_text_map());
  EXPECT_TRUE(good->floor_certain()) << "one floor is always certain";
  const auto laser_only = StartBuildingSession(ToBuildingSessionOptions(SmallFilter()), Room("", false), &problem);
  EXPECT_NE(problem.find("no landmarks"), std::string::npos) << problem;
  EXPECT_FALSE(laser_only->session().has_text_map());
  EXPECT_EQ(laser_only->maps().floors[0].text_map, nullptr);
}

TEST(StartBuildingSession, OnSeveralFloorsTheTextMapsAreRequiredAndAnUnknownStartFloorIsUncertain) {
  auto maps = std::make_shared<BuildingMaps>(*Room("2", true));
  maps->floors.push_back(Room("3", false)->floors[0]);
  std::string problem;
  try {  // refused at the start, not at the switch to floor 3
    StartBuildingSession(ToBuildingSessionOptions(SmallFilter()), maps, &problem);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("floor '3': "), std::string::npos) << e.what();
  }
  maps->floors[1] = Room("3", true)->floors[0];
  auto text3 = std::make_shared<TextMap>(*maps->floors[1].text_map);
  text3->landmarks[0].text = "301";
  maps->floors[1].text_map = text3;
  const auto session = StartBuildingSession(ToBuildingSessionOptions(SmallFilter()), maps, &problem);
  EXPECT_TRUE(problem.empty());
  EXPECT_EQ(session->floor_id(), "2") << "the first floor's map until the plates decide";
  EXPECT_FALSE(session->floor_certain());
  EXPECT_NE(session->Status().state, LocalizationState::kConverged);
  TextAmclNodeOptions on3 = SmallFilter();
  on3.start_floor = "3";
  EXPECT_EQ(StartBuildingSession(ToBuildingSessionOptions(on3), maps, &problem)->floor_id(), "3");
}

}  // namespace
}  // namespace doorplate_localization
