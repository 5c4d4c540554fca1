// The pose-graph back end of text SLAM: the particle filter (rbpf_slam.h) is the front end that runs
// live; at the end (and whenever a map is asked for) this graph re-estimates the whole trajectory and
// the plates, and the map is rendered again from it (the split of Cartographer and of Grisetti et al.'s
// graph-SLAM tutorial).
//
// Graph (pose_graph.h): one node per processed scan; edges
//  - odometry between consecutive nodes, translation times one unknown odometry scale factor; its
//    noise grows with the distance driven and the angle turned (the filter's motion model);
//  - scan alignment (point-to-line ICP, scan_icp.h) from each node to the nodes 1, 2, 4, ... back, within
//    `max_sequential_offset`: their information says what the laser fixes (nothing along a featureless
//    corridor, everything near an end wall), so odometry fills in exactly where the laser cannot; Huber
//    kernel, and after each solve those missed by more than `sequential_max_residual_sigmas` are left out
//    of it (someone walking by);
//  - loop closures: each node is aligned with the nearest node of earlier visits at least
//    `loop_closure_min_separation` nodes away within `loop_closure_radius_m` (Huber kernel), proposed
//    where the front end's poses and where a solve put them (in the order loop_closure_proposal_order
//    says), afresh at every solve (an alignment whose nodes and guess are the same to the bit as in the
//    previous solve is taken from it: the same result, not computed twice); after each
//    solve, closures the solution misses by more than `loop_closure_max_residual_sigmas` are dropped as
//    false matches and the graph is solved again; last, every closure whose alignment kept its guess along
//    a direction the scans do not fix is aligned again from the solution (one that no longer aligns is
//    dropped) and the graph solved once more;
//  - on mapped ground (a place that already holds max_nodes_per_place nodes with their scans), a new
//    node keeps no scan: it is aligned once with the place's nearest node (a loop closure made as it is
//    added, kept between solves) and its points are dropped, so hours of patrol over the same corridor
//    add a pose and two edges per scan, not a scan (Cartographer trims its pure-localization
//    trajectories for the same reason); such nodes take no other alignments;
//  - optionally (front_end_history_sigma_m > 0; the structured-building profile): between consecutive nodes
//    the front end pinned, the filter's posterior mean trajectory as a relative-pose edge, in place of the
//    odometry edge and the scan alignments there;
//  - doorplates: each reading is the plate's position in its node's frame (bearing and range, σ
//    `plate_sigma_m`); a plate read twice is a loop closure, and the odometry edges between the nodes
//    where adjacent plates were read are the paper's inter-plate distances (eq. 13; eq. 14's sum is
//    the chain of them).
// Frames: map frame = the first node's frame as the filter set it; node points are in base_link.
#pragma once

#include <cstddef>
#include <functional>
#include <list>
#include <map>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/slam/pose_graph.h"
#include "doorplate_localization/slam/scan_fusion.h"
#include "doorplate_localization/slam/scan_icp.h"

namespace doorplate_localization {

// The back end's node fusion: 3 scans before and after, within 0.3 m and 0.015 rad (docs/slam.md "Back end").
inline ScanFusionOptions DefaultNodeFusion() {
  ScanFusionOptions o;
  o.scans_before = 3;
  o.scans_after = 3;
  o.max_distance_m = 0.3;
  o.max_rotation_rad = 0.015;
  return o;
}

struct SlamBackEndOptions {
  bool enabled = true;
  int max_sequential_offset = 8;             // align each node with nodes 1, 2, 4, ... up to this back
  double max_alignment_distance_m = 8.0;     // pairs further apart (by odometry) are not aligned
  double loop_closure_radius_m = 1.5;
  int loop_closure_min_separation = 20;      // nodes apart in sequence to count as a loop closure
  double loop_closure_max_rms_m = 0.05;      // alignments worse than this are not used
  // Per node, loop closures are tried with the nearest node of up to this many earlier visits (a laser of
  // less than 360° sees nothing in common with a visit in the opposite direction), and at most
  // loop_closures_per_node of them are kept.
  int loop_closure_max_tries = 4;
  int loop_closures_per_node = 2;
  // The front end's poses propose loop closures only between nodes that were pinned (AddNode) together with
  // this many neighbours on each side in sequence.
  int front_end_pinned_neighbours = 1;
  // After each solve, loop closures whose residual (Mahalanobis, by the alignment's information) exceeds
  // this many sigmas are dropped as false matches and the graph is solved again without them, up to
  // loop_closure_check_rounds times per solve. 0: off.
  double loop_closure_max_residual_sigmas = 9.0;
  int loop_closure_check_rounds = 3;
  // The same check for the sequential alignments (in the same rounds, also after a solve without loop
  // closures): one the solution misses by more than this many sigmas is left out of this solve. A person
  // walking near the robot is the one thing along a featureless corridor an alignment can lock onto; seen at
  // two places in two scans 4 m apart, it made an alignment 1 m short with the information of a door frame
  // (docs/slam.md, "Consistency check of the sequential alignments"). Every alignment, sequential or loop
  // closure, takes the Huber kernel of graph.huber_sigmas, or a false one pulls the solution onto itself and
  // hides its residual. 0: off.
  double sequential_max_residual_sigmas = 9.0;
  // Who proposes loop closures first. 1: the front end's poses, before the first solve; then that solve's.
  // 2: a first solve without closures, then the front end's poses for the nodes that found none, then the
  // solution's again. 0 (auto): 2 when a plate was read from two nodes at least loop_closure_min_separation
  // apart (the plates close loops no look-alike place can fake, so the first solve is the better proposer;
  // a bent front end proposes false closures), else 1 (laser only: that solve has drifted, and the front
  // end's map is the better proposer).
  int loop_closure_proposal_order = 0;
  // A sequential alignment further from its odometry guess than this many odometry sigmas (the noise
  // below plus the scale prior's, in translation or in heading) is dropped as a false match. 0: off.
  double sequential_gate_sigmas = 5.0;
  // Odometry noise (1σ) of one step: translation σ² = trans_m2_per_m · d + trans_m2_per_rad · |Δθ|,
  // heading σ² = rot_rad2_per_m · d + rot_rad2_per_rad · |Δθ|, plus the floor below.
  double odometry_trans_m2_per_m = 0.001;
  double odometry_trans_m2_per_rad = 0.0004;
  double odometry_rot_rad2_per_m = 0.0004;
  double odometry_rot_rad2_per_rad = 0.004;
  double odometry_min_sigma_m = 0.005;
  double odometry_min_sigma_rad = 0.005;
  double plate_sigma_m = 0.15;
  // Edges from the front end's history (its posterior mean trajectory at the solve, which carries the loops
  // the filter closed in its particles' maps): between consecutive pinned nodes (see AddNode), the history's
  // relative pose with these sigmas (x and y; heading); the scan alignments spanning only pinned nodes are
  // then left out (the filter matched each of those scans to its whole map, not to one other scan). For
  // structured buildings, with the front end's degeneracy-aware proposal off (degenerate_min_points 0:
  // every node pinned): docs/results/real-logs.md. 0: off.
  double front_end_history_sigma_m = 0.0;
  double front_end_history_sigma_rad = 0.0;
  // Scan budget on mapped ground (bounds memory over hours of patrol): a place (front-end poses within
  // place_radius_m, heading within place_max_heading_diff_rad) that already holds max_nodes_per_place
  // nodes with scans from earlier visits (at least loop_closure_min_separation nodes back) takes new nodes
  // without their scans (see above). 0: off (every node keeps its scan). The default lets about three
  // passes each way keep their scans (a node every linear_update_m).
  int max_nodes_per_place = 6;
  double place_radius_m = 0.5;
  double place_max_heading_diff_rad = 0.8;
  // An earlier node is another visit of the place only if odometry says the robot came back to it: between
  // them odometry moved it by at most place_radius_m or this fraction of the distance it drove. A single
  // straight pass moves it by all of that distance, so a front end whose poses stand still in a featureless
  // stretch (its scan match fixes nothing along the corridor) does not make one pass fill a place; a pass
  // after a turn-around or a lap comes back with an odometry displacement of its drift only. In [0, 1];
  // 1: no check (every earlier node in the place counts, the rule before 2026-12-07).
  double place_max_odometry_displacement_fraction = 0.5;
  // ... or if the robot turned round since it: odometry's heading (unwrapped, node to node) moved by at least
  // place_turn_around_rad from where it stood at the last such turn. A pass after a turn-around is another visit
  // whatever odometry's displacement says: a robot moved without the mapper being told (a kidnap, a lift, a
  // push) comes back to its places with odometry displaced by the move (the nodelet soak, 2026-12-07:
  // docs/results/nodelet_soak.md). One straight pass never turns round. 0: off.
  double place_turn_around_rad = 2.5;
  // A node's points (what the alignments match): its scan's echoes, each moved onto the line fitted to it
  // and its neighbours in the 3 scans before and the 3 after it that odometry says were taken within 0.3 m
  // and 0.015 rad of it (scan_fusion.h: less range noise, so less heading noise in every alignment; the
  // wall follower's gentle steering is in, turns are left out, where odometry's own heading error would
  // smear the fused echoes). Applied by the caller
  // that sees every scan (TextSlam), not by AddNode. scans_before = scans_after = 0: off.
  ScanFusionOptions node_fusion = DefaultNodeFusion();
  ScanIcpOptions icp;
  PoseGraphOptions graph;
};

// `o` if every field is in range; else throws std::invalid_argument "SlamBackEndOptions.<field>: <rule>".
const SlamBackEndOptions& ValidatedSlamBackEndOptions(const SlamBackEndOptions& o);

struct SlamBackEndResult {
  std::vector<Pose2D> poses;                // per node, map frame
  std::vector<std::optional<Vec2>> plates;  // per plate id, map frame (unset: never read)
  double odometry_scale = 1.0;              // estimated true distance ÷ odometry distance
  double odometry_heading_drift_rad_per_m = 0.0;  // estimated true − measured heading change per metre
  int alignment_edges = 0;
  int loop_closures = 0;                    // in the final graph
  int loop_closures_dropped = 0;            // by the consistency check (loop_closure_max_residual_sigmas) or
                                            // because they no longer align from the solution
  int sequential_alignments_dropped = 0;    // by the consistency check (sequential_max_residual_sigmas)
  int plate_readings = 0;
  int nodes_on_mapped_ground = 0;           // nodes added without their scan (max_nodes_per_place)
  int mapped_ground_alignments = 0;         // ... of them aligned with their place's node (in the graph)
  int loop_alignments_computed = 0;         // loop-closure alignments this solve ran ICP for
  int loop_alignments_reused = 0;           // ... and took from the previous solve (same nodes and guess)
  PoseGraphSummary summary;                 // of the final solve
};

class SlamBackEnd {
 public:
  // Throws std::invalid_argument naming the field if an option is out of range.
  explicit SlamBackEnd(const SlamBackEndOptions& options);

  // One processed scan: its echoes in base_link (beam order), the odometry pose (base_link in odom) and
  // the front end's estimate (base_link in map), used as the starting point. `front_end_pinned`: the front
  // end's scan match fixed the position in every direction (false: along one axis it came from odometry,
  // e.g. in a featureless corridor); only pinned nodes take loop closures the front end's poses propose.
  // Returns whether the node kept its points (false: mapped ground, max_nodes_per_place).
  bool AddNode(std::vector<Vec2> points, const Pose2D& odometry_pose, const Pose2D& front_end_pose,
               bool front_end_pinned = true);
  // Node `node`'s points replaced (the same scan's echoes, refined: scan_fusion.h), before any alignment used
  // them: throws std::logic_error once Optimize has aligned the node, std::invalid_argument for a node that
  // does not exist or kept no points (mapped ground).
  void ReplaceNodePoints(int node, std::vector<Vec2> points);
  // A plate reading: the plate's position in the frame of node `node` (0-based, < num_nodes()).
  void AddPlateReading(int plate_id, int node, const Vec2& in_node_frame);

  // With max_nodes_per_place > 0: the nearest node with points of the place around `front_end_pose` (map
  // frame) when that place already holds max_nodes_per_place of them from earlier visits (a node added now,
  // at `odometry_pose` (odom frame), would be loop_closure_min_separation or more after them, and odometry
  // says the robot came back: place_max_odometry_displacement_fraction; its scan would map nothing new);
  // unset when the place has room or the budget is off.
  std::optional<int> FullPlaceAnchor(const Pose2D& front_end_pose, const Pose2D& odometry_pose) const;

  // Builds and solves the graph (sequential alignments are computed once per node and kept).
  // `front_end_history`: per node, the front end's pose as its trajectory estimate at this moment has it (the
  // filter's posterior mean, map frame); used with front_end_history_sigma_m > 0, and then it must hold one
  // pose per node (else std::invalid_argument).
  // `pending_node` (-1: none): a node whose points ReplaceNodePoints will still refine (node fusion waiting
  // for the scans after it). It and the nodes after it take no alignment in this solve (odometry and plates
  // hold them; the next solve aligns them), so a solve in the middle of a run changes nothing the final one
  // computes. Must be -1 or a node not aligned yet (else std::invalid_argument).
  SlamBackEndResult Optimize(const std::vector<Pose2D>& front_end_history = {}, int pending_node = -1) const;
  int num_nodes() const { return static_cast<int>(nodes_.size()); }
  // Nodes added without their points (mapped ground), and those of them aligned with their place's node.
  int nodes_on_mapped_ground() const { return nodes_on_mapped_ground_; }
  int mapped_ground_alignments() const { return static_cast<int>(anchor_edges_.size()); }
  // The odometry pose given with node `node` (0-based, < num_nodes()).
  const Pose2D& NodeOdometry(int node) const { return nodes_.at(node).odometry; }
  const SlamBackEndOptions& options() const { return options_; }

 private:
  struct Node {
    std::vector<Vec2> points;
    Pose2D odometry;
    Pose2D front_end;
    bool front_end_pinned = true;
    bool has_points = true;                 // false: added on mapped ground, points dropped
    double odometry_path_m = 0.0;           // distance driven (odometry) from node 0 to this node
    int turn_arounds = 0;                   // odometry's turn-arounds from node 0 to this node (TurnAroundsAt)
  };
  struct PlateReading {
    int plate_id;
    int node;
    Vec2 in_node_frame;
  };
  // Node `node`'s ICP reference (line normals, cell index: ~30 kB, five times its points), from a cache of
  // the kReferenceCacheSize most recently used ones: the alignments use few references at a time (the nodes
  // 1-8 back, the nodes of one earlier visit), and keeping one per node grew the mapper by ~30 kB per scan
  // (the hour's soak, docs/results/nodelet_soak.md). Built again when evicted (same points: same reference,
  // same results). Valid until the next call.
  const IcpReference& Reference(int node) const;
  static constexpr std::size_t kReferenceCacheSize = 64;
  // For each node j < n, the nodes a loop closure with j is tried with, nearest first (by `pose_of`): within
  // loop_closure_radius_m, at least loop_closure_min_separation earlier, the nearest of each earlier visit,
  // at most loop_closure_max_tries.
  std::vector<std::vector<int>> LoopClosureCandidates(int n, const std::function<const Pose2D&(int)>& pose_of) const;
  // Translation and heading variance of an odometry step (the noise options above, without the scale).
  std::pair<double, double> OdometryVariances(const Pose2D& step) const;
  PoseEdge OdometryEdge(int from, int to) const;
  // The odometry distance driven from node 0 to `odometry_pose` through every node so far (0 with none).
  double OdometryPathTo(const Pose2D& odometry_pose) const {
    if (nodes_.empty()) return 0.0;
    return nodes_.back().odometry_path_m + Norm(odometry_pose.Position() - nodes_.back().odometry.Position());
  }
  // The turn-arounds (place_turn_around_rad) counted so far, with a node at `odometry_pose` added next; and
  // that count noted for a node added there (AddNode).
  int TurnAroundsAt(const Pose2D& odometry_pose) const;
  void NoteTurnArounds(const Pose2D& odometry_pose);
  // The graph without loop closures: nodes at the front end's poses, odometry, sequential alignments and
  // plates (landmark index per plate id into `landmark_of_plate`).
  // `sequential_kept`: per sequential alignment (sequential_edges_), whether it goes in.
  PoseGraph BaseGraph(std::map<int, int>* landmark_of_plate, const std::vector<Pose2D>& history,
                      const std::vector<bool>& sequential_kept) const;
  // Whether history edges (front_end_history_sigma_m > 0) hold nodes from..to together: all of them pinned.
  // Such a span takes no odometry edge and no sequential alignment (none is computed).
  bool HistoryHolds(int from, int to) const;
  // Whether some plate was read from two nodes at least loop_closure_min_separation apart in sequence.
  bool PlatesCloseALoop() const;
  // Whether an alignment's result lies within sequential_gate_sigmas of the odometry's relative pose.
  bool AgreesWithOdometry(const Pose2D& odometry, const Pose2D& aligned) const;
  // `degenerate` (if given): whether the alignment kept the guess along a direction the scans do not fix.
  std::optional<PoseEdge> Align(int from, int to, const Pose2D& initial, bool loop_closure,
                                bool* degenerate = nullptr) const;
  // Align(..., loop_closure = true) for Optimize's loop closures, remembered from one solve to the next by
  // its exact inputs (nodes and guess to the bit: the same inputs give the same result, so nothing changes
  // but the time): the closures proposed at the front end's poses, which do not move, are aligned once, not
  // at every solve. Counts the call in count->loop_alignments_computed or _reused.
  std::optional<PoseEdge> AlignLoopClosure(int from, int to, const Pose2D& initial, bool* degenerate,
                                           SlamBackEndResult* count) const;

  const SlamBackEndOptions options_;
  mutable std::vector<Node> nodes_;
  std::vector<PlateReading> plates_;
  mutable std::vector<PoseEdge> sequential_edges_;  // cached alignments
  mutable int sequential_done_ = 0;                  // nodes whose sequential alignments are cached
  mutable std::list<std::pair<int, IcpReference>> references_;  // most recently used first
  // AlignLoopClosure's results by (from, to, guess x, y, θ); an entry not used by the latest Optimize is
  // dropped at its end (a guess from a solved pose rarely comes again), so it holds one solve's.
  struct RememberedAlignment {
    std::optional<PoseEdge> edge;
    bool degenerate = false;
    int used_in_solve = 0;  // the Optimize call (solves_, from 1) that last used it
  };
  using AlignmentKey = std::tuple<int, int, double, double, double>;
  mutable std::map<AlignmentKey, RememberedAlignment> loop_alignments_;
  mutable int solves_ = 0;                           // Optimize calls so far
  std::vector<PoseEdge> anchor_edges_;               // mapped-ground nodes aligned with their place's node
  int nodes_on_mapped_ground_ = 0;
  double unwrapped_heading_rad_ = 0.0;  // odometry's heading at the last node, unwrapped from node 0 on
  double turn_reference_rad_ = 0.0;     // ... at the last turn-around (or node 0)
  int turn_arounds_ = 0;

};

}  // namespace doorplate_localization
