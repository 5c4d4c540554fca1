// Tests of the floors TextAmclNodelet localizes on (text_amcl_building.h): ~building_file, ~map_file and
// ~text_map_file loaded with errors naming the parameter, and the session started on them. No ROS master.
#include "text_amcl_building.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

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

// --- LocalizerCore: the nodelet's requests and ~state (issue 18, issue 19's amcl habits) ---

// SmallFilter started at a known pose in the room (not globally).
TextAmclNodeOptions AtAPose() {
  TextAmclNodeOptions o = SmallFilter();
  o.session.start_with_global_localization = false;
  o.session.initial_pose = {1.0, 1.0, 0.0};
  o.session.initial_covariance = Eigen::Vector3d(0.01, 0.01, 0.001).asDiagonal();
  return o;
}

double SpreadX(const BuildingSession& session) {
  double lo = 1e9, hi = -1e9;
  for (const Particle& p : session.session().particles()) {
    lo = std::min(lo, p.pose.x_m);
    hi = std::max(hi, p.pose.x_m);
  }
  return hi - lo;
}

TEST(LocalizerCore, ARefusedMapLeavesTheSessionTheMapAndTheStateAsTheyWere) {
  LocalizerCore core(AtAPose(), nullptr);
  EXPECT_EQ(core.State(0.0), "waiting_for_map");
  const LocalizerCore::MapChange first = core.UseMaps(Room("", true), "/amcl/map_file");
  ASSERT_TRUE(first.used) << first.problem;
  EXPECT_EQ(core.State(1.0), "waiting_for_scan");
  core.ScanTaken(1.0);
  const std::string state = core.State(1.5);
  const BuildingSession* before = &core.session();
  const std::vector<Particle> particles = core.session().session().particles();
  const std::string map = core.map_in_force();
  EXPECT_EQ(map, "/amcl/map_file: 40 x 20 at 0.100 m");

  // set_map of an all-occupied 100 x 100 map (issue 18): refused, naming why; nothing changed.
  const OccupancyGrid walls(100, 100, 0.05, Pose2D{}, OccupancyGrid::kOccupied);
  const LocalizerCore::MapChange refused = core.UseGrid(walls, "/set_map", StartPose{{1.0, 1.0, 0.0}});
  EXPECT_FALSE(refused.used);
  EXPECT_NE(refused.problem.find("no free cell: all 10000 cells are occupied or unknown"), std::string::npos)
      << refused.problem;
  EXPECT_EQ(&core.session(), before);
  EXPECT_EQ(core.session().session().particles().size(), particles.size());
  EXPECT_EQ(core.session().session().particles()[0].pose.x_m, particles[0].pose.x_m);
  EXPECT_EQ(core.map_in_force(), map);
  EXPECT_EQ(core.State(1.5), state);
  // Global localization still works on the map in force.
  EXPECT_TRUE(core.GlobalLocalization());
  EXPECT_GT(SpreadX(core.session()), 3.0);
  // An absurd map (20000 x 20000 would be refused by the message check; here a grid beyond the cell limit
  // cannot even be made) and a grid too fine are refused the same way.
  OccupancyGrid fine(4, 4, 0.1, Pose2D{}, OccupancyGrid::kFree);
  fine.resolution_m = 1e-6;
  EXPECT_NE(core.UseGrid(fine, "/map").problem.find("resolution_m"), std::string::npos);
  EXPECT_EQ(&core.session(), before);
}

// dynamic_reconfigure (issue 19): new filter options replace the session by one continuing from it (the
// particles stay); refused options change nothing; without a map they are the next map's.
TEST(LocalizerCore, ReconfigureKeepsTheParticlesRefusedChangesNothingAndBeforeAMapWaits) {
  LocalizerCore core(AtAPose(), nullptr);
  TextAmclSetupOptions setup = AtAPose().session.setup;
  setup.filter.max_particles = setup.filter.min_particles;
  EXPECT_EQ(core.Reconfigure(setup), "");
  ASSERT_TRUE(core.UseMaps(Room("", true), "/map").used);
  EXPECT_EQ(core.session().session().particles().size(), static_cast<size_t>(setup.filter.min_particles))
      << "the map's session drew the reconfigured max_particles";
  const std::vector<Particle> particles = core.session().session().particles();
  setup.filter.update_min_d_m = 0.7;
  EXPECT_EQ(core.Reconfigure(setup), "");
  EXPECT_EQ(core.session().session().options().setup.filter.update_min_d_m, 0.7);
  ASSERT_EQ(core.session().session().particles().size(), particles.size());
  EXPECT_EQ(core.session().session().particles().back().pose.y_m, particles.back().pose.y_m);
  const BuildingSession* before = &core.session();
  setup.filter.resample_interval = 0;
  EXPECT_NE(core.Reconfigure(setup).find("resample_interval"), std::string::npos);
  EXPECT_EQ(&core.session(), before);
  EXPECT_EQ(core.session().session().options().setup.filter.resample_interval,
            AtAPose().session.setup.filter.resample_interval);
}

TEST(LocalizerCore, GlobalLocalizationBeforeAMapIsQueuedAndStartsTheFirstMapGlobally) {
  LocalizerCore core(AtAPose(), nullptr);
  EXPECT_FALSE(core.GlobalLocalization()) << "no map: queued, not run";
  EXPECT_TRUE(core.global_localization_queued());
  EXPECT_EQ(NodeStateText(core.Health(0.0)), "waiting_for_map");
  EXPECT_TRUE(core.Health(0.0).global_localization_queued);
  // A refused map keeps the request queued.
  EXPECT_FALSE(core.UseGrid(OccupancyGrid(10, 10, 0.1, Pose2D{}, OccupancyGrid::kOccupied), "/map").used);
  EXPECT_TRUE(core.global_localization_queued());
  const LocalizerCore::MapChange change = core.UseMaps(Room("", true), "/map");
  ASSERT_TRUE(change.used) << change.problem;
  EXPECT_TRUE(change.ran_queued_global_localization);
  EXPECT_FALSE(core.global_localization_queued());
  EXPECT_GT(SpreadX(core.session()), 3.0) << "spread over the 4 m room, not at ~initial_pose (1, 1)";
  // With a text map, converged waits for a plate (converge_after_plate), so no early false "converged".
  EXPECT_NE(core.session().Status().state, LocalizationState::kConverged);
}

TEST(LocalizerCore, AnInitialPoseOrASetMapPoseCancelsAQueuedGlobalLocalization) {
  LocalizerCore core(AtAPose(), nullptr);
  core.GlobalLocalization();
  core.InitialPose(StartPose{{3.0, 1.0, 0.0}, Eigen::Vector3d(0.01, 0.01, 0.001).asDiagonal()});
  EXPECT_FALSE(core.global_localization_queued());
  const LocalizerCore::MapChange change = core.UseMaps(Room("", true), "/map");
  ASSERT_TRUE(change.used);
  EXPECT_FALSE(change.ran_queued_global_localization);
  EXPECT_NEAR(core.session().Estimate().pose.x_m, 3.0, 0.1) << "the latest request (the pose) wins";
  core.GlobalLocalization();  // runs now: a map is in force
  EXPECT_GT(SpreadX(core.session()), 3.0);
  const LocalizerCore::MapChange set_map = core.UseGrid(Room("", true)->floors[0].grid, "/set_map",
                                                        StartPose{{2.0, 1.0, 0.0}, Eigen::Matrix3d::Identity() * 1e-4});
  ASSERT_TRUE(set_map.used) << set_map.problem;
  EXPECT_NEAR(core.session().Estimate().pose.x_m, 2.0, 0.05) << "set_map starts at its pose";
  // An initial pose the filter refuses (not positive semi-definite) changes nothing.
  const double x = core.session().Estimate().pose.x_m;
  EXPECT_THROW(core.InitialPose(StartPose{{1.0, 1.0, 0.0}, -Eigen::Matrix3d::Identity()}), std::invalid_argument);
  EXPECT_EQ(core.session().Estimate().pose.x_m, x);
}

TEST(LocalizerCore, StateWaitsForScansAfterEveryRestartGoesStaleAndReportsErrors) {
  TextAmclNodeOptions o = AtAPose();
  o.scan_timeout_s = 2.0;
  LocalizerCore core(o, nullptr);
  ASSERT_TRUE(core.UseMaps(Room("", true), "/map").used);
  EXPECT_EQ(core.State(10.0), "waiting_for_scan");
  core.ScanTaken(10.0);
  const std::string filter_state = StateText(core.session().Status().state, core.session().Status().lost_reason);
  EXPECT_EQ(core.State(11.0), filter_state);
  EXPECT_EQ(core.State(12.5), "waiting_for_scan") << "no scan for 2.5 s";
  core.ScanTaken(12.5);
  core.Failed("std::bad_alloc");
  EXPECT_EQ(core.State(12.6), "error: std::bad_alloc");
  EXPECT_EQ(core.Health(12.6).error, "std::bad_alloc");
  core.ScanTaken(12.7);
  EXPECT_EQ(core.State(12.8), filter_state) << "the next scan taken clears the error";
  core.InitialPose(StartPose{{2.0, 1.0, 0.0}, Eigen::Matrix3d::Identity() * 1e-4});
  EXPECT_EQ(core.State(12.8), "waiting_for_scan") << "a restart publishes no estimate until a scan";
  EXPECT_TRUE(core.GlobalLocalization());
  EXPECT_EQ(core.State(12.9), "waiting_for_scan");
}

TEST(LocalizerCore, CountsTheScansDroppedAcrossRestartsAndKeepsTheLastReason) {
  LocalizerCore core(AtAPose(), nullptr);
  EXPECT_EQ(core.Health(1.0).scans_dropped, 0);
  EXPECT_EQ(core.Health(1.0).last_scan_dropped, "");
  core.ScanDropped("header.frame_id is empty");  // before any map: still counted
  ASSERT_TRUE(core.UseMaps(Room("", true), "/map").used);
  core.ScanDropped("no tf from 'laser' to 'odom' at the scan's stamp 2.000 s: older than tf's cache holds");
  core.ScanTaken(3.0);
  const LocalizerHealth h = core.Health(3.0);
  EXPECT_EQ(h.scans_dropped, 2);
  EXPECT_EQ(h.last_scan_dropped,
            "no tf from 'laser' to 'odom' at the scan's stamp 2.000 s: older than tf's cache holds");
  EXPECT_EQ(core.State(3.0), StateText(core.session().Status().state, core.session().Status().lost_reason))
      << "drops alone do not change the state";
}

}  // namespace
}  // namespace doorplate_localization
