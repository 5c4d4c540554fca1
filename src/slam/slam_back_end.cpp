#include "doorplate_localization/slam/slam_back_end.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace doorplate_localization {

std::vector<std::vector<int>> SlamBackEnd::LoopClosureCandidates(
    int n, const std::function<const Pose2D&(int)>& pose_of) const {
  std::vector<std::vector<int>> candidates(n);
  if (!(options_.loop_closure_radius_m > 0)) return candidates;
  const int separation = options_.loop_closure_min_separation;
  for (int j = separation; j < n; ++j) {
    if (!nodes_[j].has_points) continue;
    std::vector<std::pair<double, int>> near;  // (distance, node)
    for (int i = 0; i + separation <= j; ++i) {
      if (!nodes_[i].has_points) continue;
      const double d = Norm(pose_of(i).Position() - pose_of(j).Position());
      if (d < options_.loop_closure_radius_m) near.emplace_back(d, i);
    }
    std::sort(near.begin(), near.end());
    // The nearest node of each earlier visit: a candidate within separation / 2 nodes of a nearer one is
    // the same visit seen a step later.
    for (const auto& [d, i] : near) {
      bool same_visit = false;
      for (int k : candidates[j]) same_visit = same_visit || std::abs(k - i) < std::max(1, separation / 2);
      if (!same_visit) candidates[j].push_back(i);
      if (static_cast<int>(candidates[j].size()) >= options_.loop_closure_max_tries) break;
    }
  }
  return candidates;
}

SlamBackEnd::SlamBackEnd(const SlamBackEndOptions& options) : options_(ValidatedSlamBackEndOptions(options)) {}

bool SlamBackEnd::AddNode(std::vector<Vec2> points, const Pose2D& odometry_pose, const Pose2D& front_end_pose,
                          bool front_end_pinned) {
  const std::optional<int> anchor = FullPlaceAnchor(front_end_pose, odometry_pose);
  NoteTurnArounds(odometry_pose);
  nodes_.push_back({std::move(points), odometry_pose, front_end_pose, front_end_pinned, true,
                    OdometryPathTo(odometry_pose), turn_arounds_});
  if (!anchor) return true;
  const int node = num_nodes() - 1;
  const Pose2D guess = nodes_[*anchor].front_end.Between(front_end_pose);
  if (const std::optional<PoseEdge> edge = Align(*anchor, node, guess, true)) anchor_edges_.push_back(*edge);
  nodes_.back().points = {};
  nodes_.back().points.shrink_to_fit();
  nodes_.back().has_points = false;
  ++nodes_on_mapped_ground_;
  return false;
}

void SlamBackEnd::ReplaceNodePoints(int node, std::vector<Vec2> points) {
  if (node < 0 || node >= num_nodes() || !nodes_[node].has_points) {
    throw std::invalid_argument("SlamBackEnd::ReplaceNodePoints: node " + std::to_string(node) + " of " +
                                std::to_string(num_nodes()) + " has no points to replace");
  }
  if (node < sequential_done_) {
    throw std::logic_error("SlamBackEnd::ReplaceNodePoints: node " + std::to_string(node) + " is already aligned");
  }
  nodes_[node].points = std::move(points);
  references_.remove_if([node](const auto& r) { return r.first == node; });  // built from the old points
}

void SlamBackEnd::AddPlateReading(int plate_id, int node, const Vec2& in_node_frame) {
  if (plate_id < 0 || node < 0 || node >= num_nodes()) {
    throw std::invalid_argument("SlamBackEnd::AddPlateReading: plate " + std::to_string(plate_id) + " at node " +
                                std::to_string(node) + " of " + std::to_string(num_nodes()));
  }
  plates_.push_back({plate_id, node, in_node_frame});
}

const IcpReference& SlamBackEnd::Reference(int node) const {
  auto it = std::find_if(references_.begin(), references_.end(), [node](const auto& r) { return r.first == node; });
  if (it != references_.end()) {
    references_.splice(references_.begin(), references_, it);
  } else {
    references_.emplace_front(std::piecewise_construct, std::forward_as_tuple(node),
                              std::forward_as_tuple(nodes_[node].points, options_.icp));
    if (references_.size() > kReferenceCacheSize) references_.pop_back();
  }
  return references_.front().second;
}

std::optional<PoseEdge> SlamBackEnd::Align(int from, int to, const Pose2D& initial, bool loop_closure,
                                           bool* degenerate) const {
  const ScanIcpResult r = AlignScans(Reference(from), nodes_[to].points, initial, options_.icp);
  if (degenerate) *degenerate = r.degenerate;
  if (!r.aligned) return std::nullopt;
  if (loop_closure && r.rms_m > options_.loop_closure_max_rms_m) return std::nullopt;
  if (!loop_closure && !AgreesWithOdometry(initial, r.relative)) return std::nullopt;
  PoseEdge edge;
  edge.from = from;
  edge.to = to;
  edge.measurement = r.relative;
  edge.information = r.information;
  // Huber beyond huber_sigmas, sequential too: a false match cannot pull the solution onto itself (slam_back_end.h).
  edge.robust = true;
  return edge;
}

std::optional<PoseEdge> SlamBackEnd::AlignLoopClosure(int from, int to, const Pose2D& initial, bool* degenerate,
                                                      SlamBackEndResult* count) const {
  const AlignmentKey key{from, to, initial.x_m, initial.y_m, initial.theta_rad};
  RememberedAlignment& remembered = loop_alignments_[key];
  if (remembered.used_in_solve > 0) {  // aligned before with these very inputs
    ++count->loop_alignments_reused;
  } else {
    remembered.edge = Align(from, to, initial, true, &remembered.degenerate);
    ++count->loop_alignments_computed;
  }
  remembered.used_in_solve = solves_;
  if (degenerate) *degenerate = remembered.degenerate;
  return remembered.edge;
}

PoseGraph SlamBackEnd::BaseGraph(std::map<int, int>* landmark_of_plate, const std::vector<Pose2D>& history,
                                 const std::vector<bool>& sequential_kept) const {
  PoseGraph graph;
  for (const Node& node : nodes_) graph.AddNode(node.front_end);
  const bool use_history = options_.front_end_history_sigma_m > 0;  // Optimize checked the size
  const auto history_edge_at = [this](int j) { return HistoryHolds(j - 1, j); };
  // Odometry between consecutive nodes, except where a history edge holds them: the filter's trajectory
  // already took the odometry in, and its systematic errors (scale, heading drift), added again along
  // hundreds of edges, would bend the chain (freiburg-079 seed 3: 0.114 m ATE without loop closures,
  // where the history alone has 0.073 m).
  for (int j = 1; j < num_nodes(); ++j) {
    if (!history_edge_at(j)) graph.AddEdge(OdometryEdge(j - 1, j));
  }
  if (use_history) {
    const double var_t = options_.front_end_history_sigma_m * options_.front_end_history_sigma_m;
    const double var_r = options_.front_end_history_sigma_rad * options_.front_end_history_sigma_rad;
    for (int j = 1; j < num_nodes(); ++j) {
      if (!history_edge_at(j)) continue;
      PoseEdge edge;
      edge.from = j - 1;
      edge.to = j;
      edge.measurement = history[j - 1].Between(history[j]);
      edge.information = Eigen::Vector3d(1.0 / var_t, 1.0 / var_t, 1.0 / var_r).asDiagonal();
      graph.AddEdge(edge);
    }
  }
  for (std::size_t k = 0; k < sequential_edges_.size(); ++k) {  // none where the history holds
    if (sequential_kept.at(k)) graph.AddEdge(sequential_edges_[k]);
  }
  for (const PoseEdge& edge : anchor_edges_) graph.AddEdge(edge);
  landmark_of_plate->clear();
  for (const PlateReading& reading : plates_) {
    auto it = landmark_of_plate->find(reading.plate_id);
    if (it == landmark_of_plate->end()) {
      const int landmark = graph.AddLandmark(nodes_[reading.node].front_end.TransformPoint(reading.in_node_frame));
      it = landmark_of_plate->emplace(reading.plate_id, landmark).first;
    }
    LandmarkEdge edge;
    edge.node = reading.node;
    edge.landmark = it->second;
    edge.measurement = reading.in_node_frame;
    edge.information = Eigen::Matrix2d::Identity() / (options_.plate_sigma_m * options_.plate_sigma_m);
    graph.AddEdge(edge);
  }
  return graph;
}

bool SlamBackEnd::HistoryHolds(int from, int to) const {
  if (!(options_.front_end_history_sigma_m > 0)) return false;
  for (int k = from; k <= to; ++k) {
    if (!nodes_[k].front_end_pinned) return false;
  }
  return true;
}

bool SlamBackEnd::PlatesCloseALoop() const {
  std::map<int, std::pair<int, int>> first_last;  // plate id -> (first, last) node that read it
  for (const PlateReading& reading : plates_) {
    auto [it, inserted] = first_last.emplace(reading.plate_id, std::make_pair(reading.node, reading.node));
    if (!inserted) {
      it->second.first = std::min(it->second.first, reading.node);
      it->second.second = std::max(it->second.second, reading.node);
    }
    if (it->second.second - it->second.first >= options_.loop_closure_min_separation) return true;
  }
  return false;
}

SlamBackEndResult SlamBackEnd::Optimize(const std::vector<Pose2D>& front_end_history, int pending_node) const {
  SlamBackEndResult result;
  const int n = num_nodes();
  if (n == 0) return result;
  if (options_.front_end_history_sigma_m > 0 && static_cast<int>(front_end_history.size()) != n) {
    throw std::invalid_argument("SlamBackEnd::Optimize: front_end_history has " +
                                std::to_string(front_end_history.size()) + " poses for " + std::to_string(n) +
                                " nodes (front_end_history_sigma_m > 0 needs one per node)");
  }
  if (pending_node != -1 && (pending_node < sequential_done_ || pending_node >= n)) {
    throw std::invalid_argument("SlamBackEnd::Optimize: pending_node " + std::to_string(pending_node) +
                                " is not a node of " + std::to_string(n) + " still unaligned (from " +
                                std::to_string(sequential_done_) + ")");
  }
  ++solves_;
  const int aligned_end = pending_node == -1 ? n : pending_node;  // nodes [0, aligned_end) take alignments
  // Sequential alignments: node j against nodes j-1, j-2, j-4, ... (odometry as the starting guess).
  for (int j = sequential_done_; j < aligned_end; ++j) {
    for (int offset = 1; offset <= options_.max_sequential_offset && j - offset >= 0; offset *= 2) {
      const int i = j - offset;
      if (!nodes_[i].has_points || !nodes_[j].has_points || HistoryHolds(i, j)) continue;
      const Pose2D initial = nodes_[i].odometry.Between(nodes_[j].odometry);
      if (std::hypot(initial.x_m, initial.y_m) > options_.max_alignment_distance_m) continue;
      if (const std::optional<PoseEdge> edge = Align(i, j, initial, false)) sequential_edges_.push_back(*edge);
    }
  }
  sequential_done_ = std::max(sequential_done_, aligned_end);

  std::map<int, int> landmark_of_plate;
  std::vector<bool> sequential_kept(sequential_edges_.size(), true);
  PoseGraph graph = BaseGraph(&landmark_of_plate, front_end_history, sequential_kept);
  result.alignment_edges = static_cast<int>(sequential_edges_.size());
  result.plate_readings = static_cast<int>(plates_.size());
  result.nodes_on_mapped_ground = nodes_on_mapped_ground_;
  result.mapped_ground_alignments = mapped_ground_alignments();
  // Loop closures, aligned afresh at every solve (an alignment made in an earlier solve started from a rougher
  // estimate and may have settled elsewhere). First where the front end's poses say the robot came back: the
  // filter closes loops itself (its particles' maps), which a graph of odometry and sequential alignments
  // alone has forgotten by its first solve (on real logs that solve drifts metres away, and a search around
  // it finds no true revisit). Then where this solve says so, and the graph is solved again.
  // Nodes whose front-end pose is trusted to propose loop closures: pinned, and so are their neighbours within
  // front_end_pinned_neighbours in sequence (one matched scan amid degenerate ones sits in a map the filter
  // built from odometry along the axis).
  std::vector<bool> trusted(n, false);
  for (int i = 0; i < n; ++i) {
    bool all = true;
    for (int k = std::max(0, i - options_.front_end_pinned_neighbours);
         k <= std::min(n - 1, i + options_.front_end_pinned_neighbours) && all; ++k) {
      all = nodes_[k].front_end_pinned;
    }
    trusted[i] = all;
  }
  std::set<std::pair<int, int>> closed;  // pairs tried (kept, refused by ICP or dropped by the check)
  std::vector<PoseEdge> loops;           // in the graph
  std::vector<bool> has_closure(n, false);  // node j took a closure with an earlier node
  std::set<std::pair<int, int>> kept_a_guess;  // closures whose alignment kept its guess along some direction
  const bool front_end_first = options_.loop_closure_proposal_order == 1 ||
                               (options_.loop_closure_proposal_order == 0 && !PlatesCloseALoop());
  // only_pinned: front-end proposals (trusted nodes only, and only for nodes without a closure yet).
  const auto close_loops = [&](const auto& pose_of, bool only_pinned) {
    int added = 0;
    const std::vector<std::vector<int>> candidates = LoopClosureCandidates(aligned_end, pose_of);
    for (int j = 0; j < aligned_end; ++j) {
      if (only_pinned && !front_end_first && has_closure[j]) continue;
      int closed_here = 0;
      for (int i : candidates[j]) {
        if (closed_here >= options_.loop_closures_per_node) break;
        if (only_pinned && !(trusted[i] && trusted[j])) continue;
        if (!closed.insert({i, j}).second) continue;
        bool degenerate = false;
        if (const std::optional<PoseEdge> edge =
                AlignLoopClosure(i, j, pose_of(i).Between(pose_of(j)), &degenerate, &result)) {
          graph.AddEdge(*edge);
          loops.push_back(*edge);
          if (degenerate) kept_a_guess.insert({i, j});
          has_closure[j] = true;
          ++added, ++closed_here;
        }
      }
    }
    return added;
  };
  // Consistency check (after a solve): a loop closure the solution misses by more than
  // loop_closure_max_residual_sigmas (Mahalanobis, the alignment's own information) is a false match of
  // look-alike places (two corners, two door recesses) that the rest of the graph (odometry, the plates,
  // the other closures) contradicts. The Huber kernel only bounds each one's pull; a few dozen of them still
  // bend a floor. Dropped, and the graph is rebuilt and solved again, up to loop_closure_check_rounds times.
  // The graph rebuilt with `kept` as its loop closures (those of `loops` not in it counted as dropped), solved.
  const auto solve_with_loops = [&](std::vector<PoseEdge> kept) {
    result.loop_closures_dropped += static_cast<int>(loops.size() - kept.size());
    loops = std::move(kept);
    graph = BaseGraph(&landmark_of_plate, front_end_history, sequential_kept);
    for (const PoseEdge& edge : loops) graph.AddEdge(edge);
    result.summary = graph.Optimize(options_.graph);
  };
  // The sequential alignments are checked alike (sequential_max_residual_sigmas): those missed by more are
  // left out of this solve's graph (they stay cached: the next solve checks them again).
  const double gate = options_.loop_closure_max_residual_sigmas * options_.loop_closure_max_residual_sigmas;
  const double sequential_gate = options_.sequential_max_residual_sigmas * options_.sequential_max_residual_sigmas;
  const auto check_alignments = [&] {
    for (int round = 0; round < options_.loop_closure_check_rounds && (gate > 0 || sequential_gate > 0); ++round) {
      std::vector<PoseEdge> kept;
      for (const PoseEdge& edge : loops) {
        if (!(gate > 0) || graph.SquaredResidual(edge) <= gate) kept.push_back(edge);
      }
      bool sequential_dropped = false;
      for (std::size_t k = 0; k < sequential_edges_.size() && sequential_gate > 0; ++k) {
        if (sequential_kept[k] && graph.SquaredResidual(sequential_edges_[k]) > sequential_gate) {
          sequential_kept[k] = false;
          sequential_dropped = true;
          ++result.sequential_alignments_dropped;
        }
      }
      if (kept.size() == loops.size() && !sequential_dropped) return;
      solve_with_loops(std::move(kept));
    }
  };
  const auto solve_and_check = [&] {
    result.summary = graph.Optimize(options_.graph);
    check_alignments();
  };
  // Each closes loops where its poses say, then (if it added any) solves and checks; true if it added any.
  const auto close_and_solve = [&](const auto& pose_of, bool only_pinned) {
    if (close_loops(pose_of, only_pinned) == 0) return false;
    solve_and_check();
    return true;
  };
  const auto close_at_solved = [&] {
    std::vector<Pose2D> solved;
    for (int i = 0; i < n; ++i) solved.push_back(graph.node(i));
    return close_and_solve([&](int i) -> const Pose2D& { return solved[i]; }, false);
  };
  const auto close_at_front_end = [&] {
    return close_and_solve([&](int i) -> const Pose2D& { return nodes_[i].front_end; }, true);
  };
  if (front_end_first) {
    if (!close_at_front_end()) solve_and_check();
    close_at_solved();
  } else {
    solve_and_check();
    close_at_solved();
    close_at_front_end();
    close_at_solved();
  }
  // Loop closures that kept their guess along a direction the scans do not fix are aligned again from the
  // solution. One proposed at the front end's poses started from a guess that may be metres off along a
  // corridor (a laser-only filter shrinks a featureless one): its measurement carries those metres, which
  // the information's little weight along the corridor turned into a pull on heading (paper corridor seed
  // 4: the whole map turned 0.009 rad about the first node). From the solution the guess is near the truth;
  // one that no longer aligns from there is dropped. The others fixed every direction from the scans, and
  // where the solution is worse than the front end (real logs) a new start would only cost.
  if (!kept_a_guess.empty()) {
    std::vector<PoseEdge> realigned;
    for (const PoseEdge& edge : loops) {
      if (!kept_a_guess.count({edge.from, edge.to})) {
        realigned.push_back(edge);
      } else if (const std::optional<PoseEdge> again =
                     AlignLoopClosure(edge.from, edge.to, graph.node(edge.from).Between(graph.node(edge.to)),
                                      nullptr, &result)) {
        realigned.push_back(*again);
      }
    }
    solve_with_loops(std::move(realigned));
    check_alignments();
  }
  result.loop_closures = static_cast<int>(loops.size());
  for (auto it = loop_alignments_.begin(); it != loop_alignments_.end();) {
    it = it->second.used_in_solve == solves_ ? std::next(it) : loop_alignments_.erase(it);
  }

  for (int i = 0; i < n; ++i) result.poses.push_back(graph.node(i));
  for (const auto& [plate_id, landmark] : landmark_of_plate) {
    if (plate_id >= static_cast<int>(result.plates.size())) result.plates.resize(plate_id + 1);
    result.plates[plate_id] = graph.landmark(landmark);
  }
  result.odometry_scale = graph.odometry_scale();
  result.odometry_heading_drift_rad_per_m = graph.odometry_heading_drift_rad_per_m();
  return result;
}

}  // namespace doorplate_localization
