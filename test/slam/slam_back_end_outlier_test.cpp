// SlamBackEnd's consistency check of the sequential alignments (sequential_max_residual_sigmas). A second
// test file of slam_back_end.cpp (slam_back_end_test.cpp holds the other rules).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "doorplate_localization/slam/slam_back_end.h"
#include "slam_back_end_test_fixtures.h"

namespace doorplate_localization {
namespace {

// A hospital bed being wheeled (1.0 m along the corridor, 0.6 m across) whose west end is at x, in the
// corridor's north half.
std::vector<Segment> Bed(double x) {
  const double y0 = 0.25, y1 = 0.85;
  return {{{x, y0}, {x + 1.0, y0}}, {{x + 1.0, y0}, {x + 1.0, y1}}, {{x + 1.0, y1}, {x, y1}}, {{x, y1}, {x, y0}}};
}

// Nine nodes 0.5 m apart down the featureless corridor (360 beams), exact odometry. A bed wheeled west is
// seen by node 0 with its west end at x = 5.0 m and by node 8 (4 s later) at 4.5 m, by no node between: the
// alignment of nodes 0 and 8 locks onto its end (the only thing along the corridor it can lock onto) and
// puts node 8 0.5 m too far on; every other alignment is degenerate along x, and a plate read from nodes 0
// and 8 (sigma 1 cm here) contradicts it.
SlamBackEndResult SolveRunPastABed(double sequential_max_residual_sigmas) {
  SlamBackEndOptions o;
  o.plate_sigma_m = 0.01;
  o.sequential_max_residual_sigmas = sequential_max_residual_sigmas;
  SlamBackEnd back_end(o);
  const Vec2 plate{2.0, 1.025};
  for (int i = 0; i <= 8; ++i) {
    const Pose2D pose{0.5 * i, 0.0, 0.0};
    std::vector<Segment> walls = test::Corridor();
    if (i == 0 || i == 8) {
      const std::vector<Segment> bed = Bed(i == 0 ? 5.0 : 4.5);
      walls.insert(walls.end(), bed.begin(), bed.end());
    }
    back_end.AddNode(test::Points(test::Scan(walls, pose, 360, 16.0)), pose, pose);
    if (i == 0 || i == 8) back_end.AddPlateReading(0, i, pose.Inverse().TransformPoint(plate));
  }
  return back_end.Optimize();
}

TEST(SlamBackEnd, ASequentialAlignmentTheRestOfTheGraphContradictsIsLeftOut) {
  const SlamBackEndResult unchecked = SolveRunPastABed(0.0);
  EXPECT_EQ(unchecked.sequential_alignments_dropped, 0);
  // (Its Huber kernel bounds the pull; still it moves node 8 off the plate's and the odometry's 4 m.)
  EXPECT_GT(unchecked.poses.at(8).x_m, 4.01) << "the bed's alignment did not pull (the test would show nothing)";
  const SlamBackEndResult checked = SolveRunPastABed(9.0);
  EXPECT_EQ(checked.sequential_alignments_dropped, 1);
  EXPECT_NEAR(checked.poses.at(8).x_m, 4.0, 0.005);
  EXPECT_NEAR(checked.poses.at(8).y_m, 0.0, 0.005);
}

}  // namespace
}  // namespace doorplate_localization
