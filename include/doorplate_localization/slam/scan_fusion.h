// The back end's node points from several consecutive laser scans instead of one (the idea of
// Cartographer's accumulated range data, and of moving-least-squares point smoothing): the SLAM processes
// one scan per `linear_update_m` (0.5 m), and a 10 Hz laser takes a dozen between; each of those is a new
// draw of the range noise on the same surfaces. The node's own echoes are kept (their number, beam order
// and place along each surface), and each is moved across its surface onto the line fitted to it and to
// the echoes near it in the few scans before and after it, brought into the node's frame by odometry (a few centimetres
// of driving: odometry's error there is far below the range noise). With k scans the noise across a wall
// falls by up to √k, and with it the noise of the heading each scan-to-scan alignment measures (the
// error that bends a long corridor's map: docs/results/table2-map.md).
//
// Frames: every scan's points are in base_link at that scan; odometry poses are base_link in odom;
// Fuse(id) returns scan id's points in its base_link. Units: metres, radians.
#pragma once

#include <deque>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct ScanFusionOptions {
  // A node's points are fused with up to this many scans before it and after it (0 and 0: off, the scan's
  // points as they are). ScanFusionOptions{} is off; SlamBackEndOptions::node_fusion sets the back end's.
  int scans_before = 0;
  int scans_after = 0;
  double max_distance_m = 0.3;      // scans further (odometry) from the node's scan are not used
  double max_rotation_rad = 0.1;    // ... nor those turned further
  // A point's neighbourhood: the echoes of all used scans within max(radius_m, radius_per_m × range).
  double radius_m = 0.1;
  double radius_per_m = 0.05;
  int min_neighbours = 4;           // fewer (the point itself included): the point is left as it is
  // RMS distance of the neighbourhood off its fitted line above max_residual_m + max_residual_per_m × range
  // (a corner, a door frame, clutter, a person): the point is left as it is.
  double max_residual_m = 0.03;
  double max_residual_per_m = 0.005;
};

// `o` if every field is in range; else throws std::invalid_argument "ScanFusionOptions.<field>: <rule>".
const ScanFusionOptions& ValidatedScanFusionOptions(const ScanFusionOptions& o);

class ScanFusion {
 public:
  // Throws std::invalid_argument naming the field if an option is out of range.
  explicit ScanFusion(const ScanFusionOptions& options);

  bool enabled() const { return options_.scans_before > 0 || options_.scans_after > 0; }
  // Remembers one scan: its echoes in base_link (beam order) and its odometry pose. Returns its id (0, 1, 2,
  // ... in order of Add). The last scans_before + scans_after + 1 scans are remembered.
  long Add(std::vector<Vec2> points, const Pose2D& odometry_pose);
  // Scan `id`'s points, each moved along the normal of the line fitted to its neighbourhood (in scan `id`
  // and in the remembered scans up to scans_before before and scans_after after it that lie within
  // max_distance_m and max_rotation_rad of it by odometry) onto that line; points with too few neighbours or
  // a neighbourhood that is no line stay as they are. Throws std::out_of_range if `id` is not remembered.
  std::vector<Vec2> Fuse(long id) const;
  // Remembered scans after `id` that Fuse(id) would use (it uses at most scans_after).
  int UsableScansAfter(long id) const;
  // ... and before it.
  int UsableScansBefore(long id) const;
  // Whether scan `id` is still remembered (Fuse(id) works).
  bool Remembered(long id) const { return id >= next_id_ - static_cast<long>(scans_.size()) && id < next_id_; }
  // Whether no scan added after now can be used for `id`: scans_after of them are in, or the latest is
  // beyond the odometry limits (the robot drove on), or `id` is no longer remembered.
  bool Complete(long id) const;

 private:
  struct Scan {
    std::vector<Vec2> points;
    Pose2D odometry;
  };
  const Scan& At(long id) const;
  bool Usable(const Scan& center, const Scan& other) const;

  const ScanFusionOptions options_;
  std::deque<Scan> scans_;  // oldest first; scans_.back() has id next_id_ - 1
  long next_id_ = 0;
};

}  // namespace doorplate_localization
