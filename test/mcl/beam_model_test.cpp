#include "doorplate_localization/mcl/beam_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "mcl_fixtures.h"

namespace doorplate_localization {
namespace {

class BeamModelTest : public ::testing::Test {
 protected:
  std::shared_ptr<LocalizationGrid> room_ = std::make_shared<LocalizationGrid>(test::AsymmetricRoom());
  const Pose2D truth_{1.5, 2.5, 0.4};

  std::vector<double> Score(BeamModel& model, const LaserScan& scan, const std::vector<Pose2D>& poses) {
    std::vector<Particle> ps;
    for (const Pose2D& p : poses) ps.push_back({p, 1.0});
    std::vector<double> ll;
    model.LogLikelihoods(scan, ps, &ll);
    return ll;
  }
};

TEST_F(BeamModelTest, BeamProbabilityIsAmclsFourPartMixture) {
  BeamModelOptions o;  // z_hit .95, z_short .1, z_max .05, z_rand .05, sigma .2, lambda .1
  BeamModel model(room_, o);
  const double max = 8.0;
  // A perfect hit: the Gaussian peak plus the uniform part.
  EXPECT_NEAR(model.BeamProbability(3.0, 3.0, max), 0.95 + 0.05 / max, 1e-12);
  // 1 m short: the Gaussian tail, the exponential short part and the uniform part.
  const double short_expected = 0.95 * std::exp(-1.0 / 0.08) + 0.1 * 0.1 * std::exp(-0.1 * 2.0) + 0.05 / max;
  EXPECT_NEAR(model.BeamProbability(2.0, 3.0, max), short_expected, 1e-12);
  // A max-range reading where the map also has nothing within range: the hit peak and z_max.
  EXPECT_NEAR(model.BeamProbability(max, max, max), 0.95 + 0.05, 1e-12);
  // An unexpected obstacle is likelier than an equally wrong long reading.
  EXPECT_GT(model.BeamProbability(1.0, 3.0, max), model.BeamProbability(5.0, 3.0, max));
}

TEST_F(BeamModelTest, PrefersTheTruePoseOverShiftedAndTurnedOnes) {
  std::mt19937_64 rng(5);
  const LaserScan scan = test::SyntheticScan(*room_, truth_, &rng);
  for (BeamCombination c : {BeamCombination::kAmclCubeSum, BeamCombination::kProduct}) {
    BeamModelOptions o;
    o.combination = c;
    BeamModel model(room_, o);
    const auto ll = Score(model, scan,
                          {truth_, {1.8, 2.5, 0.4}, {1.5, 2.2, 0.4}, {1.5, 2.5, 0.5}, {4.5, 1.5, 0.4 + M_PI}});
    for (size_t i = 1; i < ll.size(); ++i) EXPECT_GT(ll[0], ll[i]) << "pose " << i << " combination " << int(c);
  }
}

TEST_F(BeamModelTest, CountsNoEchoReadingsAsMaxRange) {
  // With a 3 m laser, beams along the room's long axis have no echo (+inf). A pose where the map agrees
  // (nothing within 3 m along those beams) must beat one where the map has a wall within range.
  const LaserScan scan = test::SyntheticScan(*room_, truth_, nullptr, 0.0, 3.0);
  int no_echo = 0;
  for (float r : scan.ranges_m) no_echo += std::isinf(r);
  ASSERT_GT(no_echo, 30);
  BeamModelOptions o;
  o.combination = BeamCombination::kProduct;
  BeamModel model(room_, o);
  const auto ll = Score(model, scan, {truth_, {4.0, 2.5, 0.4}});
  EXPECT_GT(ll[0], ll[1]);
  // Replacing the +inf readings by NaN (unusable) removes their evidence: the wrong pose, which has walls
  // within range along those beams, is no longer penalized for them.
  LaserScan stripped = scan;
  for (float& r : stripped.ranges_m) {
    if (std::isinf(r)) r = std::nanf("");
  }
  const auto ll_stripped = Score(model, stripped, {truth_, {4.0, 2.5, 0.4}});
  EXPECT_GT(ll[0] - ll[1], ll_stripped[0] - ll_stripped[1] + 1.0);
}

TEST_F(BeamModelTest, RejectsBadOptionsNamingTheField) {
  BeamModelOptions o;
  o.z_short = -1.0;
  try {
    BeamModel model(room_, o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("z_short"), std::string::npos);
  }
}

}  // namespace
}  // namespace doorplate_localization
