#include "doorplate_localization/slam/pose_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

// An edge measuring `to`'s true pose in `from`'s frame.
PoseEdge ExactEdge(const std::vector<Pose2D>& truth, int from, int to, double information = 100.0) {
  PoseEdge edge;
  edge.from = from;
  edge.to = to;
  edge.measurement = truth[from].Between(truth[to]);
  edge.information = information * Eigen::Matrix3d::Identity();
  return edge;
}

double PositionError(const PoseGraph& graph, const std::vector<Pose2D>& truth) {
  double worst = 0.0;
  for (int i = 0; i < graph.num_nodes(); ++i) worst = std::max(worst, Norm(graph.node(i).Position() - truth[i].Position()));
  return worst;
}

// A 2 m square driven anticlockwise: the corners, turning 90° at each, and back to the start.
std::vector<Pose2D> Square() { return {{0, 0, 0}, {2, 0, M_PI / 2}, {2, 2, M_PI}, {0, 2, -M_PI / 2}, {1, 1, 0}}; }

TEST(PoseGraph, ASquareLoopWithNoisyStartingPosesConvergesToTheExactPoses) {
  const std::vector<Pose2D> truth = Square();
  PoseGraph graph;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise_m(0.0, 0.3), noise_rad(0.0, 0.2);
  graph.AddNode(truth[0]);
  for (std::size_t i = 1; i < truth.size(); ++i) {
    graph.AddNode({truth[i].x_m + noise_m(rng), truth[i].y_m + noise_m(rng), truth[i].theta_rad + noise_rad(rng)});
  }
  ASSERT_GT(PositionError(graph, truth), 0.2);
  for (int i = 0; i + 1 < 4; ++i) graph.AddEdge(ExactEdge(truth, i, i + 1));
  graph.AddEdge(ExactEdge(truth, 3, 0));  // closes the loop
  graph.AddEdge(ExactEdge(truth, 1, 4));
  graph.AddEdge(ExactEdge(truth, 4, 3));

  const PoseGraphSummary summary = graph.Optimize({});
  EXPECT_TRUE(summary.solver_ok);
  EXPECT_GT(summary.iterations, 1);
  EXPECT_LT(summary.final_cost, 1e-8 * summary.initial_cost);
  for (int i = 0; i < graph.num_nodes(); ++i) {
    EXPECT_NEAR(graph.node(i).x_m, truth[i].x_m, 1e-5) << "node " << i;
    EXPECT_NEAR(graph.node(i).y_m, truth[i].y_m, 1e-5) << "node " << i;
    EXPECT_NEAR(NormalizeAngle(graph.node(i).theta_rad - truth[i].theta_rad), 0.0, 1e-5) << "node " << i;
  }
}

// The square of the test above, started off by up to a metre, with every edge robust (the Huber kernel:
// linear convergence at the end, as on a real graph).
PoseGraph NoisyRobustSquare() {
  const std::vector<Pose2D> truth = Square();
  PoseGraph graph;
  graph.AddNode(truth[0]);
  for (std::size_t i = 1; i < truth.size(); ++i) graph.AddNode({truth[i].x_m + 0.5, truth[i].y_m - 0.4, truth[i].theta_rad + 0.3});
  std::vector<PoseEdge> edges = {ExactEdge(truth, 0, 1), ExactEdge(truth, 1, 2), ExactEdge(truth, 2, 3),
                                 ExactEdge(truth, 3, 0), ExactEdge(truth, 1, 4), ExactEdge(truth, 4, 3)};
  edges[3].measurement.x_m += 0.05;  // one inconsistent edge, so the kernel is active at the optimum
  for (PoseEdge& edge : edges) {
    edge.robust = true;
    graph.AddEdge(edge);
  }
  return graph;
}

TEST(PoseGraph, ItStopsOnceAStepMovesNoPositionByMinStepMAndNoAngleByMinStepRad) {
  PoseGraphOptions huge;  // any first step is below these: one iteration
  huge.min_step_m = huge.min_step_rad = 1e3;
  PoseGraph once = NoisyRobustSquare();
  EXPECT_EQ(once.Optimize(huge).iterations, 1);
  PoseGraphOptions tiny;  // what the stop used to be (1e-7 for every component)
  tiny.min_step_m = tiny.min_step_rad = 1e-7;
  PoseGraph fine = NoisyRobustSquare(), by_default = NoisyRobustSquare();
  const PoseGraphSummary fine_summary = fine.Optimize(tiny);
  const PoseGraphSummary default_summary = by_default.Optimize({});
  EXPECT_LT(default_summary.iterations, fine_summary.iterations);
  // Stopping at 0.1 mm / 1e-5 rad steps leaves the solution where the fine stop puts it, to well below a cell.
  for (int i = 0; i < fine.num_nodes(); ++i) {
    EXPECT_NEAR(by_default.node(i).x_m, fine.node(i).x_m, 1e-4) << "node " << i;
    EXPECT_NEAR(by_default.node(i).y_m, fine.node(i).y_m, 1e-4) << "node " << i;
    EXPECT_NEAR(NormalizeAngle(by_default.node(i).theta_rad - fine.node(i).theta_rad), 0.0, 1e-4) << "node " << i;
  }
}

TEST(PoseGraph, TheFirstNodeStaysWhereItStartedAndDefinesTheMapFrame) {
  // Every edge is relative: without the first node fixed the whole graph could slide.
  const std::vector<Pose2D> truth = {{3, -1, 0.4}, {4, -1, 0.4}, {5, 0, 1.0}};
  PoseGraph graph;
  graph.AddNode(truth[0]);
  graph.AddNode({0, 0, 0});
  graph.AddNode({0, 0, 0});
  graph.AddEdge(ExactEdge(truth, 0, 1));
  graph.AddEdge(ExactEdge(truth, 1, 2));
  graph.Optimize({});
  EXPECT_NEAR(graph.node(0).x_m, 3.0, 1e-6);
  EXPECT_NEAR(graph.node(0).y_m, -1.0, 1e-6);
  EXPECT_NEAR(graph.node(0).theta_rad, 0.4, 1e-6);
  EXPECT_LT(PositionError(graph, truth), 1e-5);
}

// A straight chain along x, 1 m per true step, started at dead reckoning, whose odometry edges all measure
// `odometry_step`; laser-like (non-odometry) edges measure the true step only in the first and last two
// segments.
PoseGraph ChainSeenByTheLaserAtItsEnds(int nodes, const Pose2D& odometry_step) {
  PoseGraph graph;
  std::vector<Pose2D> truth;
  for (int i = 0; i < nodes; ++i) truth.push_back({static_cast<double>(i), 0, 0});
  for (int i = 0; i < nodes; ++i) graph.AddNode({odometry_step.x_m * i, 0, 0});
  for (int i = 0; i + 1 < nodes; ++i) {
    PoseEdge odometry;
    odometry.from = i;
    odometry.to = i + 1;
    odometry.measurement = odometry_step;
    odometry.information = Eigen::Vector3d(2500, 2500, 2500).asDiagonal();  // 2 cm, 0.02 rad
    odometry.odometry = true;
    graph.AddEdge(odometry);
  }
  for (int i : {0, 1, nodes - 3, nodes - 2}) graph.AddEdge(ExactEdge(truth, i, i + 1, 1e4));
  return graph;
}

// Odometry 2 % long.
struct ScaledChain {
  static constexpr int kNodes = 21;
  PoseGraph graph = ChainSeenByTheLaserAtItsEnds(kNodes, {1.02, 0, 0});
};

TEST(PoseGraph, AnOdometryChainWithAWrongScaleIsRescaledByTheAlignments) {
  ScaledChain chain;
  const PoseGraphSummary summary = chain.graph.Optimize({});
  EXPECT_TRUE(summary.solver_ok);
  EXPECT_NEAR(chain.graph.odometry_scale(), 1.0 / 1.02, 0.003);
  const Pose2D far = chain.graph.node(ScaledChain::kNodes - 1);
  EXPECT_NEAR(far.x_m, ScaledChain::kNodes - 1, 0.05);
  EXPECT_NEAR(far.y_m, 0.0, 1e-6);
}

TEST(PoseGraph, WithoutScaleEstimationTheWrongOdometryScaleStretchesTheChain) {
  ScaledChain chain;
  PoseGraphOptions options;
  options.estimate_odometry_scale = false;
  chain.graph.Optimize(options);
  EXPECT_NEAR(chain.graph.odometry_scale(), 1.0, 1e-9);
  // 16 odometry-only steps 2% long, and the 4 shared steps a compromise weighted 4:1 to the truth.
  const double far_x = chain.graph.node(ScaledChain::kNodes - 1).x_m;
  EXPECT_NEAR(far_x - (ScaledChain::kNodes - 1), 16 * 0.02 + 4 * 0.004, 0.01);
}

// Odometry that turns 0.01 rad left per metre (unequal wheels).
PoseGraph DriftingChain(int nodes) { return ChainSeenByTheLaserAtItsEnds(nodes, {1.0, 0, 0.01}); }

TEST(PoseGraph, AnOdometryHeadingDriftIsCalibratedAndTheChainStaysStraight) {
  PoseGraph graph = DriftingChain(21);
  PoseGraphOptions options;
  options.estimate_odometry_heading_drift = true;
  // Only four segments see the drift: with the default prior (σ 0.01 rad/m) the prior's cost at the true
  // drift outweighs theirs and the estimate stops half-way; a weak prior lets the data decide.
  options.heading_drift_prior_sigma_rad_per_m = 0.1;
  EXPECT_TRUE(graph.Optimize(options).solver_ok);
  EXPECT_NEAR(graph.odometry_heading_drift_rad_per_m(), -0.01, 0.001);
  double worst_heading = 0.0;
  for (int i = 0; i < graph.num_nodes(); ++i) worst_heading = std::max(worst_heading, std::fabs(graph.node(i).theta_rad));
  EXPECT_LT(worst_heading, 0.01);
  EXPECT_NEAR(graph.node(20).y_m, 0.0, 0.05);
}

TEST(PoseGraph, WithoutDriftEstimationTheChainTurnsWithTheOdometry) {
  PoseGraph graph = DriftingChain(21);
  graph.Optimize({});  // the default: no drift estimated
  EXPECT_EQ(graph.odometry_heading_drift_rad_per_m(), 0.0);
  double worst_heading = 0.0;
  for (int i = 0; i < graph.num_nodes(); ++i) worst_heading = std::max(worst_heading, std::fabs(graph.node(i).theta_rad));
  EXPECT_GT(worst_heading, 0.03);  // the 16 odometry-only steps turn the middle of the chain
}

TEST(PoseGraph, ALandmarkSeenFromTwoNodesPullsThemIntoAgreement) {
  // Node 1 is 4 m ahead of node 0 in truth; the edge between them is sure across the corridor but
  // says almost nothing (and something wrong) along it. The landmark, at (2, 1), is seen by both.
  PoseGraph graph;
  graph.AddNode({0, 0, 0});
  graph.AddNode({4.5, 0.0, 0.0});
  PoseEdge along;
  along.from = 0;
  along.to = 1;
  along.measurement = {4.5, 0, 0};
  along.information = Eigen::Vector3d(1.0, 1e4, 1e4).asDiagonal();
  graph.AddEdge(along);
  const Vec2 truth_landmark{2, 1};
  const Vec2 seen_from_0{2, 1}, seen_from_1{-2, 1};
  const int landmark = graph.AddLandmark(Pose2D{0, 0, 0}.TransformPoint(seen_from_0));
  ASSERT_EQ(landmark, 0);
  ASSERT_EQ(graph.num_landmarks(), 1);
  LandmarkEdge edge;
  edge.landmark = landmark;
  edge.information = 100 * Eigen::Matrix2d::Identity();  // 10 cm
  edge.node = 0;
  edge.measurement = seen_from_0;
  graph.AddEdge(edge);
  edge.node = 1;
  edge.measurement = seen_from_1;
  graph.AddEdge(edge);
  // Before: the two nodes put the landmark half a metre apart.
  ASSERT_NEAR(Norm(graph.node(0).TransformPoint(seen_from_0) - graph.node(1).TransformPoint(seen_from_1)), 0.5, 1e-9);

  EXPECT_TRUE(graph.Optimize({}).solver_ok);
  // Landmark chain (information 50 in series) against the along-corridor edge (information 1).
  EXPECT_NEAR(graph.node(1).x_m, 4.0, 0.02);
  EXPECT_NEAR(graph.node(1).y_m, 0.0, 1e-3);
  EXPECT_LT(Norm(graph.node(0).TransformPoint(seen_from_0) - graph.node(1).TransformPoint(seen_from_1)), 0.02);
  EXPECT_LT(Norm(graph.landmark(landmark) - truth_landmark), 0.02);
}

TEST(PoseGraph, ARobustWrongLoopClosureMovesTheSolutionLessThanANonRobustOne) {
  // Eight poses on a circle of radius 2 m, each tied exactly to the next three (many good edges), and
  // a wrong closure that says node 6 is `error_m` off along x from where it is relative to node 2.
  std::vector<Pose2D> truth;
  for (int i = 0; i < 8; ++i) {
    const double a = i * M_PI / 4;
    truth.push_back({2 * std::cos(a), 2 * std::sin(a), a + M_PI / 2});
  }
  const auto solve = [&](bool robust, double error_m) {
    PoseGraph graph;
    for (const Pose2D& p : truth) graph.AddNode(p);
    for (int k = 1; k <= 3; ++k) {
      for (int i = 0; i < 8; ++i) graph.AddEdge(ExactEdge(truth, i, (i + k) % 8));
    }
    PoseEdge wrong = ExactEdge(truth, 2, 6);
    wrong.measurement.x_m += error_m;
    wrong.robust = robust;
    graph.AddEdge(wrong);
    EXPECT_TRUE(graph.Optimize({}).solver_ok);
    return PositionError(graph, truth);
  };
  const double plain = solve(false, 2.0), robust = solve(true, 2.0);
  EXPECT_GT(plain, 0.1);  // the wrong closure does bend a plain graph
  EXPECT_LT(robust, 0.5 * plain);
  // A plain edge pulls in proportion to its error; a Huber edge's pull is bounded.
  EXPECT_GT(plain, 1.8 * solve(false, 1.0));
  EXPECT_LT(robust, 1.2 * solve(true, 1.0));
}

TEST(PoseGraph, SquaredResidualIsTheEdgesMahalanobisErrorInTheFromNodesFrame) {
  PoseGraph graph;
  graph.AddNode({1, 1, M_PI / 2});
  graph.AddNode({1, 3, M_PI / 2});  // 2 m ahead of node 0, in its frame
  PoseEdge edge;
  edge.from = 0;
  edge.to = 1;
  edge.measurement = {1.5, 0.1, 0.05};  // errors 0.5 m ahead, 0.1 m sideways, 0.05 rad
  edge.information = Eigen::Vector3d(4.0, 100.0, 400.0).asDiagonal();
  EXPECT_NEAR(graph.SquaredResidual(edge), 4.0 * 0.25 + 100.0 * 0.01 + 400.0 * 0.0025, 1e-9);
  edge.measurement = {2.0, 0.0, 0.0};
  EXPECT_NEAR(graph.SquaredResidual(edge), 0.0, 1e-12);
  edge.to = 2;
  EXPECT_THROW(graph.SquaredResidual(edge), std::out_of_range);
}

TEST(PoseGraph, InvalidIndicesAndNonFiniteValuesThrow) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  PoseGraph graph;
  EXPECT_THROW(graph.AddNode({nan, 0, 0}), std::invalid_argument);
  EXPECT_THROW(graph.AddLandmark({0, inf}), std::invalid_argument);
  graph.AddNode({0, 0, 0});
  graph.AddNode({1, 0, 0});
  graph.AddLandmark({1, 1});
  PoseEdge edge;
  edge.from = 0;
  edge.to = 1;
  EXPECT_NO_THROW(graph.AddEdge(edge));
  for (const auto& [from, to] : std::vector<std::pair<int, int>>{{-1, 1}, {0, 2}, {2, 0}, {1, 1}}) {
    edge.from = from;
    edge.to = to;
    EXPECT_THROW(graph.AddEdge(edge), std::invalid_argument) << from << " -> " << to;
  }
  edge.from = 0;
  edge.to = 1;
  edge.measurement.theta_rad = nan;
  EXPECT_THROW(graph.AddEdge(edge), std::invalid_argument);
  edge.measurement.theta_rad = 0;
  edge.information(2, 2) = inf;
  EXPECT_THROW(graph.AddEdge(edge), std::invalid_argument);

  LandmarkEdge seen;
  seen.node = 1;
  seen.landmark = 0;
  EXPECT_NO_THROW(graph.AddEdge(seen));
  seen.landmark = 1;
  EXPECT_THROW(graph.AddEdge(seen), std::invalid_argument);
  seen.landmark = 0;
  seen.node = 2;
  EXPECT_THROW(graph.AddEdge(seen), std::invalid_argument);
  seen.node = 0;
  seen.measurement.x = nan;
  EXPECT_THROW(graph.AddEdge(seen), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization
