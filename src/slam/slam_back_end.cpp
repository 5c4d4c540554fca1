#include "doorplate_localization/slam/slam_back_end.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

const SlamBackEndOptions& Validated(const SlamBackEndOptions& o) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("SlamBackEndOptions." + what); };
  if (o.max_sequential_offset < 1) fail("max_sequential_offset: must be >= 1");
  if (!(o.max_alignment_distance_m > 0)) fail("max_alignment_distance_m: must be > 0");
  if (!(o.loop_closure_radius_m >= 0)) fail("loop_closure_radius_m: must be >= 0");
  if (o.loop_closure_min_separation < 1) fail("loop_closure_min_separation: must be >= 1");
  if (!(o.loop_closure_max_rms_m > 0)) fail("loop_closure_max_rms_m: must be > 0");
  if (!(o.icp.min_inlier_fraction > 0 && o.icp.min_inlier_fraction <= 1)) fail("icp.min_inlier_fraction: must be in (0, 1]");
  for (double v : {o.odometry_trans_m2_per_m, o.odometry_trans_m2_per_rad, o.odometry_rot_rad2_per_m,
                   o.odometry_rot_rad2_per_rad}) {
    if (!(v >= 0)) fail("odometry_*: noise terms must be >= 0");
  }
  if (!(o.odometry_min_sigma_m > 0) || !(o.odometry_min_sigma_rad > 0)) fail("odometry_min_sigma_*: must be > 0");
  if (!(o.plate_sigma_m > 0)) fail("plate_sigma_m: must be > 0");
  if (!(o.icp.point_sigma_m > 0) || !(o.icp.effective_points > 0)) fail("icp: point_sigma_m and effective_points must be > 0");
  if (!(o.icp.degenerate_min_fraction >= 0 && o.icp.degenerate_min_fraction < 1)) {
    fail("icp.degenerate_min_fraction: must be in [0, 1)");
  }
  if (!(o.graph.scale_prior_sigma > 0)) fail("graph.scale_prior_sigma: must be > 0");
  return o;
}

}  // namespace

SlamBackEnd::SlamBackEnd(const SlamBackEndOptions& options) : options_(Validated(options)) {}

void SlamBackEnd::AddNode(std::vector<Vec2> points, const Pose2D& odometry_pose, const Pose2D& front_end_pose) {
  nodes_.push_back({std::move(points), odometry_pose, front_end_pose, std::nullopt});
}

void SlamBackEnd::AddPlateReading(int plate_id, int node, const Vec2& in_node_frame) {
  if (plate_id < 0 || node < 0 || node >= num_nodes()) {
    throw std::invalid_argument("SlamBackEnd::AddPlateReading: plate " + std::to_string(plate_id) + " at node " +
                                std::to_string(node) + " of " + std::to_string(num_nodes()));
  }
  plates_.push_back({plate_id, node, in_node_frame});
}

const IcpReference& SlamBackEnd::Reference(int node) const {
  Node& n = nodes_[node];
  if (!n.reference) n.reference.emplace(n.points, options_.icp);
  return *n.reference;
}

PoseEdge SlamBackEnd::OdometryEdge(int from, int to) const {
  PoseEdge edge;
  edge.from = from;
  edge.to = to;
  edge.odometry = true;
  edge.measurement = nodes_[from].odometry.Between(nodes_[to].odometry);
  const double d = std::hypot(edge.measurement.x_m, edge.measurement.y_m);
  const double turn = std::abs(edge.measurement.theta_rad);
  const double var_t = options_.odometry_trans_m2_per_m * d + options_.odometry_trans_m2_per_rad * turn +
                       options_.odometry_min_sigma_m * options_.odometry_min_sigma_m;
  const double var_r = options_.odometry_rot_rad2_per_m * d + options_.odometry_rot_rad2_per_rad * turn +
                       options_.odometry_min_sigma_rad * options_.odometry_min_sigma_rad;
  edge.information = Eigen::Vector3d(1.0 / var_t, 1.0 / var_t, 1.0 / var_r).asDiagonal();
  return edge;
}

std::optional<PoseEdge> SlamBackEnd::Align(int from, int to, const Pose2D& initial, bool loop_closure) const {
  const ScanIcpResult r = AlignScans(Reference(from), nodes_[to].points, initial, options_.icp);
  if (!r.aligned) return std::nullopt;
  if (loop_closure && r.rms_m > options_.loop_closure_max_rms_m) return std::nullopt;
  PoseEdge edge;
  edge.from = from;
  edge.to = to;
  edge.measurement = r.relative;
  edge.information = r.information;
  edge.robust = loop_closure;
  return edge;
}

SlamBackEndResult SlamBackEnd::Optimize() const {
  SlamBackEndResult result;
  const int n = num_nodes();
  if (n == 0) return result;
  // Sequential alignments: node j against nodes j-1, j-2, j-4, ... (odometry as the starting guess).
  for (int j = sequential_done_; j < n; ++j) {
    for (int offset = 1; offset <= options_.max_sequential_offset && j - offset >= 0; offset *= 2) {
      const int i = j - offset;
      const Pose2D initial = nodes_[i].odometry.Between(nodes_[j].odometry);
      if (std::hypot(initial.x_m, initial.y_m) > options_.max_alignment_distance_m) continue;
      if (const std::optional<PoseEdge> edge = Align(i, j, initial, false)) sequential_edges_.push_back(*edge);
    }
  }
  sequential_done_ = n;

  PoseGraph graph;
  for (const Node& node : nodes_) graph.AddNode(node.front_end);
  for (int j = 1; j < n; ++j) graph.AddEdge(OdometryEdge(j - 1, j));
  for (const PoseEdge& edge : sequential_edges_) graph.AddEdge(edge);
  std::map<int, int> landmark_of_plate;
  for (const PlateReading& reading : plates_) {
    auto it = landmark_of_plate.find(reading.plate_id);
    if (it == landmark_of_plate.end()) {
      const int landmark = graph.AddLandmark(nodes_[reading.node].front_end.TransformPoint(reading.in_node_frame));
      it = landmark_of_plate.emplace(reading.plate_id, landmark).first;
    }
    LandmarkEdge edge;
    edge.node = reading.node;
    edge.landmark = it->second;
    edge.measurement = reading.in_node_frame;
    edge.information = Eigen::Matrix2d::Identity() / (options_.plate_sigma_m * options_.plate_sigma_m);
    graph.AddEdge(edge);
  }
  result.alignment_edges = static_cast<int>(sequential_edges_.size());
  result.plate_readings = static_cast<int>(plates_.size());
  result.summary = graph.Optimize(options_.graph);

  // Loop closures: each node against the nearest earlier node far enough back in sequence.
  if (options_.loop_closure_radius_m > 0) {
    for (int j = options_.loop_closure_min_separation; j < n; ++j) {
      int nearest = -1;
      double nearest_d = options_.loop_closure_radius_m;
      for (int i = 0; i + options_.loop_closure_min_separation <= j; ++i) {
        const double d = Norm(graph.node(i).Position() - graph.node(j).Position());
        if (d < nearest_d) nearest_d = d, nearest = i;
      }
      if (nearest < 0) continue;
      // Aligned afresh at every solve, from this solve's relative pose: an alignment made in an earlier solve
      // started from a rougher estimate and may have settled elsewhere.
      const Pose2D initial = graph.node(nearest).Between(graph.node(j));
      if (const std::optional<PoseEdge> edge = Align(nearest, j, initial, true)) {
        graph.AddEdge(*edge);
        ++result.loop_closures;
      }
    }
    if (result.loop_closures > 0) result.summary = graph.Optimize(options_.graph);
  }

  for (int i = 0; i < n; ++i) result.poses.push_back(graph.node(i));
  for (const auto& [plate_id, landmark] : landmark_of_plate) {
    if (plate_id >= static_cast<int>(result.plates.size())) result.plates.resize(plate_id + 1);
    result.plates[plate_id] = graph.landmark(landmark);
  }
  result.odometry_scale = graph.odometry_scale();
  return result;
}

}  // namespace doorplate_localization
