#include "doorplate_localization/laser_fit/beam_tally.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace doorplate_localization {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

ExpectedBeam Hit(double range_m, double incidence_deg = 10.0) {
  return {ExpectedKind::kHit, range_m, incidence_deg * M_PI / 180.0, true};
}
ExpectedBeam Nothing() { return {ExpectedKind::kNothing, 40.0, 0.0, false}; }
ExpectedBeam Unknown() { return {}; }

TEST(BeamTallier, SortsReturnsOnAPlainWall) {
  BeamTallier tallier(BeamTallyOptions{});
  // Five beams on a wall 3 m away (no depth edges): core, core, dropout, short, long.
  const std::vector<ExpectedBeam> expected(5, Hit(3.0, 20.0));
  const std::vector<BeamOutcome> out = tallier.AddScan(expected, {3.01f, 2.98f, kInf, 1.2f, 4.0f}, 40.0);
  EXPECT_EQ(out, (std::vector<BeamOutcome>{BeamOutcome::kCore, BeamOutcome::kCore, BeamOutcome::kDropout,
                                           BeamOutcome::kShort, BeamOutcome::kLong}));
  const BeamTally& t = tallier.tally();
  ASSERT_EQ(t.core.size(), 2u);
  EXPECT_NEAR(t.core[0].error_m, 0.01, 1e-6);
  EXPECT_NEAR(t.core[1].incidence_deg, 20.0, 1e-4);
  const int range_bin = BeamTallier::Bin(tallier.options().range_bins_m, 3.0);
  const int incidence_bin = BeamTallier::Bin(tallier.options().incidence_bins_deg, 20.0);
  EXPECT_EQ(t.dropout_by_range.events[range_bin], 1);
  EXPECT_EQ(t.dropout_by_range.trials[range_bin], 5);
  EXPECT_EQ(t.dropout_by_incidence.trials[incidence_bin], 5);
  EXPECT_EQ(t.short_readings_m, std::vector<float>{1.2f});
  EXPECT_DOUBLE_EQ(t.LongRate(), 1.0 / 4.0);  // of the four beams with a return
  EXPECT_DOUBLE_EQ(t.ShortRate(), 1.0 / 5.0);
}

TEST(BeamTallier, FindsMixedPixelsAtADepthEdge) {
  BeamTallier tallier(BeamTallyOptions{});
  const std::vector<ExpectedBeam> expected = {Hit(2.0), Hit(2.0), Hit(2.0), Hit(6.0), Hit(6.0), Hit(6.0)};
  const std::vector<BeamOutcome> out = tallier.AddScan(expected, {2.0f, 2.0f, 4.0f, 2.02f, kInf, 6.0f}, 40.0);
  EXPECT_EQ(out[2], BeamOutcome::kMixed);     // between the near wall at 2 m and the far one at 6 m
  EXPECT_EQ(out[3], BeamOutcome::kEdgeNear);  // the far-wall beam read the near wall
  EXPECT_EQ(out[4], BeamOutcome::kDropout);   // beam 4's neighbours are at 6 m too: not an edge
  EXPECT_EQ(tallier.tally().edge_trials, 2);
  EXPECT_DOUBLE_EQ(tallier.tally().MixedRate(), 0.5);
}

TEST(BeamTallier, SkipsBeamsItCannotJudge) {
  BeamTallier tallier(BeamTallyOptions{});
  const std::vector<ExpectedBeam> expected = {Unknown(), Hit(3.0), Hit(3.0), Hit(3.0), Nothing(), Nothing()};
  const std::vector<BeamOutcome> out = tallier.AddScan(expected, {1.0f, 3.0f, NAN, 3.0f, 12.0f, 39.5f}, 40.0);
  EXPECT_EQ(out[0], BeamOutcome::kSkipped);  // unknown expectation
  EXPECT_EQ(out[1], BeamOutcome::kSkipped);  // its neighbour is unknown: an edge cannot be ruled out
  EXPECT_EQ(out[2], BeamOutcome::kSkipped);  // an invalid reading
  EXPECT_EQ(out[3], BeamOutcome::kSkipped);  // next to free space
  EXPECT_EQ(out[4], BeamOutcome::kShort);    // something 12 m away where nothing was expected
  EXPECT_EQ(out[5], BeamOutcome::kFreeClear);  // within the gate of the cast's end
  EXPECT_EQ(tallier.tally().free_trials, 2);
  EXPECT_EQ(tallier.tally().short_in_free, 1);
}

TEST(BeamTallier, BinsAreHalfOpenExceptTheLast) {
  const std::vector<double> edges = {0, 1, 2};
  EXPECT_EQ(BeamTallier::Bin(edges, 0.0), 0);
  EXPECT_EQ(BeamTallier::Bin(edges, 1.0), 1);
  EXPECT_EQ(BeamTallier::Bin(edges, 2.0), 1);
  EXPECT_EQ(BeamTallier::Bin(edges, 2.1), -1);
  EXPECT_EQ(BeamTallier::Bin(edges, -0.1), -1);
  EXPECT_EQ(BeamTallier::Bin(edges, NAN), -1);
}

TEST(BeamTallier, RejectsBadOptionsAndMismatchedScans) {
  BeamTallyOptions bad;
  bad.range_bins_m = {0, 2, 1};
  EXPECT_THROW(BeamTallier{bad}, std::invalid_argument);
  BeamTallier tallier(BeamTallyOptions{});
  EXPECT_THROW(tallier.AddScan({Hit(1.0)}, {1.0f, 2.0f}, 40.0), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization
