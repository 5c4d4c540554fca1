#include "doorplate_localization/mcl/plate_pose_sampler.h"

#include <gtest/gtest.h>

#include <cmath>

#include "doorplate_localization/mcl/plate_likelihood_model.h"
#include "mcl_fixtures.h"

namespace doorplate_localization {
namespace {

class PlatePoseSamplerTest : public ::testing::Test {
 protected:
  test::SymmetricCorridor corridor_ = test::MakeSymmetricCorridor();
  const int plate_index_ = corridor_.NorthPlate(4);
  const TextLandmark& plate_ = corridor_.text_map->landmarks[plate_index_];
  const Pose2D truth_{plate_.pose.x_m - 0.2, 0.8, 0.05};
  std::mt19937_64 rng_{11};
};

// The compatible landmark a sampled pose sees at the reading's bearing (and range), or -1.
int SeenPlate(const test::SymmetricCorridor& c, const PlateLikelihoodModel& model, const PlateReading& r,
              const Pose2D& p) {
  for (size_t i = 0; i < c.text_map->landmarks.size(); ++i) {
    const TextLandmark& l = c.text_map->landmarks[i];
    if (model.matcher().Similarity(r.text, l.text) == 0.0 || !model.InView(static_cast<int>(i), p.Position())) continue;
    const Pose2D rel = p.Between(l.pose);
    const bool bearing_ok = std::fabs(NormalizeAngle(std::atan2(rel.y_m, rel.x_m) - r.bearing_rad)) < 5 * 0.05;
    const bool range_ok = !r.range_m || std::fabs(std::hypot(rel.x_m, rel.y_m) - *r.range_m) < 5 * 0.2;
    if (bearing_ok && range_ok) return static_cast<int>(i);
  }
  return -1;
}

TEST_F(PlatePoseSamplerTest, SampledPosesSeeACompatiblePlateWhereTheReadingSays) {
  PlatePoseSampler sampler(corridor_.text_map, corridor_.grid, {});
  const PlateReading r = test::ReadingOf(plate_, truth_);
  const auto poses = sampler.Sample(r, 300, rng_);
  ASSERT_EQ(poses.size(), 300u);
  PlateLikelihoodModel model(corridor_.text_map, corridor_.grid, {});
  int at_read_plate = 0;
  for (const Pose2D& p : poses) {
    ASSERT_TRUE(corridor_.grid->IsFree(p.Position()));
    const int seen = SeenPlate(corridor_, model, r, p);
    ASSERT_GE(seen, 0) << p.x_m << ", " << p.y_m;
    at_read_plate += seen == plate_index_;
  }
  // In proportion to the match probabilities: 0.9 for "110", 0.03 for "118" (0/8), 0.005 for each
  // of nine plates one other edit away: 0.9 / 0.975 = 92 %.
  EXPECT_GT(at_read_plate, 0.85 * 300);
}

TEST_F(PlatePoseSamplerTest, WithoutARangeTheRobotStaysInTheFreeBandInFrontOfThePlate) {
  PlatePoseSampler sampler(corridor_.text_map, corridor_.grid, {});
  PlateReading r = test::ReadingOf(plate_, truth_);
  r.range_m.reset();
  const auto poses = sampler.Sample(r, 300, rng_);
  ASSERT_EQ(poses.size(), 300u);
  PlateLikelihoodModel model(corridor_.text_map, corridor_.grid, {});
  double mean_dx = 0.0;
  int n = 0;
  for (const Pose2D& p : poses) {
    const int seen = SeenPlate(corridor_, model, r, p);
    ASSERT_GE(seen, 0);
    // Typical distance 1.0 .. 2.0 m, cut by the 2 m corridor minus 0.2 m clearance.
    const double depth = seen % 2 == 1 ? 2.0 - p.y_m : p.y_m;  // odd indexes: north wall
    EXPECT_GE(depth, 1.0 - 1e-9);
    EXPECT_LE(depth, 1.8 + 1e-9);
    if (std::fabs(p.x_m - plate_.pose.x_m) < 3.0) mean_dx += p.x_m - plate_.pose.x_m, ++n;
  }
  EXPECT_NEAR(mean_dx / n, 0.0, 0.15);  // centred on the plate along the wall
}

TEST_F(PlatePoseSamplerTest, RepeatedNumbersSplitTheSamplesBetweenThePlates) {
  auto map = std::make_shared<TextMap>(*corridor_.text_map);
  const int twin = corridor_.SouthPlate(1);
  map->landmarks[twin].text = plate_.text;
  PlatePoseSampler sampler(map, corridor_.grid, {});
  const auto poses = sampler.Sample(test::ReadingOf(plate_, truth_), 400, rng_);
  ASSERT_EQ(poses.size(), 400u);
  int near_twin = 0;
  for (const Pose2D& p : poses) near_twin += std::fabs(p.x_m - map->landmarks[twin].pose.x_m) < 2.0;
  EXPECT_GT(near_twin, 150);  // binomial(400, 0.47): mean 188, sd 10 (6 % go to near-miss texts)
  EXPECT_LT(near_twin, 230);
}

TEST_F(PlatePoseSamplerTest, UnknownTextGivesNoPoseAndNoGridStillSamples) {
  PlatePoseSampler with_grid(corridor_.text_map, corridor_.grid, {});
  PlateReading r = test::ReadingOf(plate_, truth_);
  r.text = "9999";
  EXPECT_TRUE(with_grid.Sample(r, 10, rng_).empty());
  PlatePoseSampler no_grid(corridor_.text_map, nullptr, {});
  r = test::ReadingOf(plate_, truth_);
  r.range_m.reset();
  const auto poses = no_grid.Sample(r, 50, rng_);
  ASSERT_EQ(poses.size(), 50u);
  for (const Pose2D& p : poses) {
    EXPECT_GE(plate_.pose.y_m - p.y_m, 1.0 - 1e-9);  // typical distance 1..2 m in front of the plate
    EXPECT_LE(plate_.pose.y_m - p.y_m, 2.0 + 1e-9);
  }
}

}  // namespace
}  // namespace doorplate_localization
