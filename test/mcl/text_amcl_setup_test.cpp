#include "doorplate_localization/mcl/text_amcl_setup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "mcl_fixtures.h"

namespace doorplate_localization {
namespace {

TEST(ParseLaserModelTypeTest, ReadsAmclNamesAndRejectsOthersNamingTheParameter) {
  for (LaserModelType t : {LaserModelType::kLikelihoodField, LaserModelType::kLikelihoodFieldProb,
                           LaserModelType::kBeam}) {
    EXPECT_EQ(ParseLaserModelType(ToString(t)), t);
  }
  try {
    ParseLaserModelType("likelihood");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("laser_model_type"), std::string::npos) << e.what();
  }
}

// Initializes at the truth in the asymmetric room, drives 1.5 m with scans and returns the final error.
double TrackingError(const TextAmclSetupOptions& options) {
  const OccupancyGrid room = test::AsymmetricRoom();
  const LocalizationGrid grid(room);
  auto amcl = MakeTextAmcl(options, room, nullptr);
  std::mt19937_64 rng(3);
  Pose2D truth{1.0, 0.6, 0.0}, odom;
  amcl->Initialize(truth, Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal());
  amcl->UpdateOdometry(odom);
  for (int i = 0; i < 30; ++i) {
    truth = truth.Compose({0.05, 0.0, 0.0});
    odom = odom.Compose({0.05, 0.0, 0.0});
    if (amcl->UpdateOdometry(odom)) amcl->UpdateLaser(test::SyntheticScan(grid, truth, &rng));
  }
  const Pose2D e = amcl->Estimate().pose;
  return std::hypot(e.x_m - truth.x_m, e.y_m - truth.y_m);
}

TEST(MakeTextAmclTest, EveryLaserModelTypeBuildsAFilterThatTracks) {
  for (LaserModelType t : {LaserModelType::kLikelihoodField, LaserModelType::kLikelihoodFieldProb,
                           LaserModelType::kBeam}) {
    TextAmclSetupOptions options;
    options.laser_model_type = t;
    options.filter.max_particles = 500;
    EXPECT_LT(TrackingError(options), 0.15) << ToString(t);
  }
}

TEST(MakeTextAmclTest, UsesPlateReadingsOnlyWithATextMapAndUseText) {
  const test::SymmetricCorridor corridor = test::MakeSymmetricCorridor(20.0);
  const TextLandmark& plate = corridor.text_map->landmarks[corridor.NorthPlate(1)];
  const Pose2D robot{plate.pose.x_m - 0.5, 0.6, 0.0};
  const PlateReading reading = test::ReadingOf(plate, robot);
  const auto used = [&](bool use_text, std::shared_ptr<const TextMap> text_map) {
    TextAmclSetupOptions options;
    options.use_text = use_text;
    options.filter.max_particles = 300;
    auto amcl = MakeTextAmcl(options, corridor.occupancy, text_map);
    amcl->GlobalLocalization();
    return amcl->UpdatePlate(reading).used;
  };
  EXPECT_TRUE(used(true, corridor.text_map));
  EXPECT_FALSE(used(false, corridor.text_map));
  EXPECT_FALSE(used(true, nullptr));
}

TEST(MakeTextAmclTest, RejectsAnEmptyTextMapAndBadOptionsNamingThem) {
  const OccupancyGrid room = test::AsymmetricRoom();
  try {
    MakeTextAmcl(TextAmclSetupOptions(), room, std::make_shared<TextMap>());
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("text map"), std::string::npos) << e.what();
  }
  TextAmclSetupOptions bad;
  bad.filter.min_particles = 0;
  EXPECT_THROW(MakeTextAmcl(bad, room, nullptr), std::invalid_argument);
}

// Issue 18: an all-occupied map (set_map of 100 x 100 cells of 100) threw from SampleFreePose at the first
// global localization; it is refused when the filter is made, naming the map.
TEST(MakeTextAmclTest, RefusesAMapWithoutAFreeCell) {
  const OccupancyGrid walls = test::MakeGrid(0, 0, 5.0, 5.0, 0.05, OccupancyGrid::kOccupied);  // 100 x 100
  try {
    MakeTextAmcl(TextAmclSetupOptions(), walls, nullptr);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "map: no free cell: all 10000 cells are occupied or unknown");
  }
}

}  // namespace
}  // namespace doorplate_localization
