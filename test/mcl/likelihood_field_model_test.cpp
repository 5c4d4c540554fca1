#include "doorplate_localization/mcl/likelihood_field_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "mcl_fixtures.h"

namespace doorplate_localization {
namespace {

class LikelihoodFieldModelTest : public ::testing::Test {
 protected:
  std::shared_ptr<LocalizationGrid> room_ = std::make_shared<LocalizationGrid>(test::AsymmetricRoom());
  const Pose2D truth_{1.5, 2.5, 0.4};

  std::vector<double> Score(LikelihoodFieldModel& model, const LaserScan& scan,
                            const std::vector<Pose2D>& poses) {
    std::vector<Particle> ps;
    for (const Pose2D& p : poses) ps.push_back({p, 1.0});
    std::vector<double> ll;
    model.LogLikelihoods(scan, ps, &ll);
    return ll;
  }
};

TEST_F(LikelihoodFieldModelTest, DistanceFieldMeasuresTheDistanceToTheNearestObstacle) {
  LikelihoodFieldModel model(room_, {});
  EXPECT_NEAR(model.ObstacleDistance({1.0, 2.0}), 1.0, 0.06);   // west wall at x = 0 (cell centre -0.025)
  EXPECT_NEAR(model.ObstacleDistance({2.3, 0.5}), 0.5, 0.06);   // south wall and inner box, both ~0.5 m
  EXPECT_NEAR(model.ObstacleDistance({3.0, 3.0}), 1.0, 0.06);   // north wall at y = 4
  EXPECT_NEAR(model.ObstacleDistance({2.3, 1.2}), 0.0, 1e-9);   // inside the inner box
  EXPECT_DOUBLE_EQ(model.ObstacleDistance({50.0, 50.0}), 2.0);  // off the grid: laser_likelihood_max_dist_m
}

TEST(LikelihoodFieldModel, UnknownCellsMeasureTheirDistanceToOccupiedOnesLikeAmcl) {
  // A wall at x = 1.0 .. 1.1, unknown space beyond x = 1.5: only occupied cells attract end points.
  OccupancyGrid g = test::MakeGrid(0, 0, 3.0, 1.0, 0.05, 0);
  test::FillRect(&g, 1.0, 0.0, 1.1, 1.0, OccupancyGrid::kOccupied);
  test::FillRect(&g, 1.5, 0.0, 3.0, 1.0, OccupancyGrid::kUnknown);
  LikelihoodFieldModel model(std::make_shared<LocalizationGrid>(g), {});
  EXPECT_NEAR(model.ObstacleDistance({1.775, 0.5}), 0.7, 0.01);  // unknown cell: its distance to the wall
  EXPECT_NEAR(model.ObstacleDistance({0.425, 0.5}), 0.6, 0.01);  // free cell, the same rule
  EXPECT_DOUBLE_EQ(model.ObstacleDistance({-0.5, 0.5}), 2.0);  // off the grid: the maximum
}

TEST_F(LikelihoodFieldModelTest, PrefersTheTruePoseOverShiftedAndTurnedOnes) {
  std::mt19937_64 rng(5);
  const LaserScan scan = test::SyntheticScan(*room_, truth_, &rng);
  for (BeamCombination c : {BeamCombination::kAmclCubeSum, BeamCombination::kProduct}) {
    LikelihoodFieldModelOptions o;
    o.combination = c;
    LikelihoodFieldModel model(room_, o);
    const auto ll = Score(model, scan,
                          {truth_, {1.8, 2.5, 0.4}, {1.5, 2.2, 0.4}, {1.5, 2.5, 0.5}, {4.5, 1.5, 0.4 + M_PI}});
    for (size_t i = 1; i < ll.size(); ++i) EXPECT_GT(ll[0], ll[i]) << "pose " << i << " combination " << int(c);
  }
}

TEST_F(LikelihoodFieldModelTest, UsesTheLaserMountingPose) {
  LaserScan geometry = test::ScanGeometry();
  geometry.laser_pose = {0.3, 0.1, 0.5};
  LaserScan scan = CastScan(*room_, truth_, geometry, 360);
  LikelihoodFieldModel model(room_, {});
  const double right_mount = Score(model, scan, {truth_})[0];
  scan.laser_pose = {};  // pretend the laser sits at base_link
  EXPECT_GT(right_mount, Score(model, scan, {truth_})[0]);
}

TEST_F(LikelihoodFieldModelTest, SkipsMaxRangeAndInvalidReadingsAndUsesLaserMaxBeams) {
  LaserScan scan = test::ScanGeometry();
  scan.ranges_m.assign(360, std::numeric_limits<float>::infinity());
  scan.ranges_m[7] = std::nanf("");
  LikelihoodFieldModel model(room_, {});
  const auto ll = Score(model, scan, {truth_, {4.0, 1.0, 2.0}});
  EXPECT_EQ(ll[0], 0.0);  // log(1 + empty sum): no information
  EXPECT_EQ(ll[1], 0.0);
  EXPECT_EQ(model.last_used_beams(), 0);
  Score(model, test::SyntheticScan(*room_, truth_), {truth_});
  EXPECT_EQ(model.last_used_beams(), 60);  // amcl's laser_max_beams default, all hits in a closed room
}

TEST_F(LikelihoodFieldModelTest, BeamSkippingIgnoresBeamsOnAnUnmappedObstacle) {
  LaserScan scan = test::SyntheticScan(*room_, truth_);
  for (int i = 170; i < 190; ++i) scan.ranges_m[i] = 0.5f;  // a person 0.5 m ahead, not in the map
  LikelihoodFieldModelOptions o;
  o.do_beamskip = true;
  LikelihoodFieldModel model(room_, o);
  std::vector<Pose2D> around;  // a converged cloud around the truth
  std::mt19937_64 rng(2);
  std::normal_distribution<double> n(0.0, 0.03);
  for (int i = 0; i < 200; ++i) around.push_back({truth_.x_m + n(rng), truth_.y_m + n(rng), truth_.theta_rad + n(rng)});
  Score(model, scan, around);
  EXPECT_GE(model.last_skipped_beams(), 2);  // 20 of 360 readings: ~3 of the 60 used beams
  EXPECT_LE(model.last_skipped_beams(), 5);
  // When too many beams would be skipped, the filter has probably converged to a wrong pose: every beam
  // is used. (A cloud spread over this small room still has ~20 % of the beams "skipped".)
  LikelihoodFieldModelOptions strict = o;
  strict.beam_skip_error_threshold = 0.15;
  LikelihoodFieldModel fallback(room_, strict);
  Score(fallback, scan, around);
  EXPECT_GE(fallback.last_skipped_beams(), 2);  // 4 of 60 < 15 %: skipping stays on
  std::vector<Pose2D> spread;
  for (int i = 0; i < 200; ++i) spread.push_back(room_->SampleFreePose(rng));
  Score(fallback, scan, spread);
  EXPECT_EQ(fallback.last_skipped_beams(), 0);
  EXPECT_EQ(fallback.last_used_beams(), 60);
}

TEST_F(LikelihoodFieldModelTest, RejectsBadOptionsNamingTheField) {
  LikelihoodFieldModelOptions o;
  o.sigma_hit_m = 0.0;
  try {
    LikelihoodFieldModel model(room_, o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sigma_hit_m"), std::string::npos);
  }
  EXPECT_THROW(LikelihoodFieldModel(nullptr, {}), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization
