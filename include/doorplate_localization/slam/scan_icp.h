// Point-to-line ICP between two laser scans (Censi, "An ICP variant using a point-to-line metric", ICRA
// 2008), and the information matrix of its result, for the pose-graph back end (slam_back_end.h).
//
// Frames: both point sets are in their own robot frame (base_link at their scan); the result is the pose
// of the query scan's frame in the reference scan's frame. Units: metres, radians.
//
// The information matrix is Σ JᵀJ / σ² over the inlier correspondences, J = ∂(nᵀ(R p + t − q))/∂(t, θ):
// along a featureless corridor every normal is across it, so the information along it is ~0 and the
// graph lets odometry decide there (the degeneracy is measured, not guessed). Beams are not independent
// (one range bias moves many points), so the sum is rescaled to `effective_points` correspondences.
// With a real laser's noise, mixed pixels and clutter, a few stray matches give the along-corridor axis a
// little information that is wrong and one-sided (what moves with the robot says "no motion"; measured in
// docs/results/table2-map.md, "Realistic corridor: the fix"). Hence, by default: no correspondence where
// the nearest reference echo has no line; each reference point weighs once however many query points it
// serves; and a direction with less than `degenerate_min_fraction` of the weight is degenerate (no motion
// and no information along it).
#pragma once

#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct ScanIcpOptions {
  double start_correspondence_m = 0.6;  // correspondence gate of the first iterations, shrinking to
  double final_correspondence_m = 0.15; // this one
  int max_iterations = 30;
  double point_sigma_m = 0.03;          // one correspondence's error across the line
  double effective_points = 10.0;       // information rescaled to this many independent correspondences
  // A reference point's line is fitted to it and its `normal_neighbours` neighbours on each side in scan
  // order that lie within max(normal_gap_m, normal_gap_per_m × range) of it (beams spread with range).
  int normal_neighbours = 5;
  double normal_gap_m = 0.25;
  double normal_gap_per_m = 0.06;
  double max_line_residual_m = 0.02;    // RMS off the line; grows by max_line_residual_per_m × range
  double max_line_residual_per_m = 0.003;
  // Fewer inliers (of the query points) and the scans are not aligned. Low on purpose: far echoes in the
  // open have no line normal to match (Málaga rawlog: 0.6 kept 125 of ~440 sequential pairs, 0.25 ~350).
  double min_inlier_fraction = 0.25;
  // A query point whose nearest reference echo has no line (a corner, clutter, a point with too few
  // neighbours) gets no correspondence; false: it takes the nearest echo that has one, up to the gate away.
  bool skip_points_nearest_no_line = true;
  // A translational direction whose information is below this fraction of the inliers' (Σ (n·v)² <
  // fraction × inliers, heading marginalised) is degenerate: the alignment keeps the guess along it and
  // reports no information there. 0: off (a damped solve, the information taken as it is).
  double degenerate_min_fraction = 0.02;
  // Each reference point is one sample of its surface: the m query points matched to it weigh 1/m each
  // (a scan seen from nearer, denser, does not outvote the sparser one). false: every match weighs 1.
  bool share_reference_points = true;
};

// A reference scan prepared once: points with line normals and a hash grid for neighbour lookups.
class IcpReference {
 public:
  // `points`: the scan's echoes in beam order, in the reference robot frame (range = distance to origin).
  IcpReference(const std::vector<Vec2>& points, const ScanIcpOptions& options);
  // Index of the nearest reference point with a normal within `max_distance_m` of `p`, or -1.
  int Nearest(const Vec2& p, double max_distance_m) const;
  // Index of the nearest reference echo within `max_distance_m` of `p` if that echo has a normal;
  // -1 if there is no echo that close or the nearest one has no normal.
  int NearestIfLine(const Vec2& p, double max_distance_m) const;
  const std::vector<Vec2>& points() const { return points_; }
  const std::vector<Vec2>& normals() const { return normals_; }
  int size() const { return static_cast<int>(points_.size()); }

 private:
  // Cell (cx, cy) as one key; a multiplication, not a shift, since cx may be negative.
  long long Key(int cx, int cy) const { return static_cast<long long>(cx) * (1LL << 32) + static_cast<unsigned>(cy); }
  std::vector<Vec2> points_;   // only points with a line normal
  std::vector<Vec2> normals_;  // unit
  std::vector<Vec2> no_line_;  // echoes without a normal
  double cell_m_;
  std::unordered_map<long long, std::vector<int>> cells_;          // points_ by cell
  std::unordered_map<long long, std::vector<int>> no_line_cells_;  // no_line_ by cell
};

struct ScanIcpResult {
  bool aligned = false;        // converged with enough inliers
  Pose2D relative;             // query frame in the reference frame
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();  // of `relative` (x, y, θ)
  double inlier_fraction = 0.0;
  double rms_m = 0.0;          // point-to-line residual of the inliers
  int iterations = 0;
  bool degenerate = false;     // a translation the scans do not fix was kept at the guess (no information)
};

// Aligns `query` (its own frame) to `reference` starting from `initial` (query frame in reference frame).
ScanIcpResult AlignScans(const IcpReference& reference, const std::vector<Vec2>& query, const Pose2D& initial,
                         const ScanIcpOptions& options);

}  // namespace doorplate_localization
