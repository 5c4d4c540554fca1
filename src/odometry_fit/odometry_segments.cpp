#include "doorplate_localization/odometry_fit/odometry_segments.h"

#include <cmath>
#include <stdexcept>

namespace doorplate_localization {

double OdometrySegment::TurnRateRadPerM() const {
  return reference_distance_m > 0.0 ? std::fabs(reference_rotation_rad) / reference_distance_m : 0.0;
}

std::vector<OdometrySegment> SplitIntoSegments(const std::vector<OdometryStep>& steps,
                                               const OdometrySegmentOptions& options) {
  if (!(options.segment_length_m > 0.0)) {
    throw std::invalid_argument("OdometrySegmentOptions.segment_length_m must be > 0");
  }
  std::vector<OdometrySegment> segments;
  Pose2D path;          // reference path in the frame of the first step (invalid steps follow odometry)
  double arc_m = 0.0;
  bool open = false;
  OdometrySegment current;
  Pose2D odometry_sum, reference_sum;  // composed motions since the segment's start
  bool duration_known = true;
  for (int i = 0; i < static_cast<int>(steps.size()); ++i) {
    const OdometryStep& step = steps[i];
    const bool usable = step.reference_valid && step.along_constrained;
    if (!usable) {
      open = false;  // a segment shorter than segment_length_m is dropped
    } else {
      if (!open) {
        current = OdometrySegment();
        current.first_step = i;
        current.start_arc_m = arc_m;
        current.start_position = path.Position();
        odometry_sum = reference_sum = Pose2D();
        duration_known = true;
        open = true;
      }
      odometry_sum = odometry_sum.Compose(step.odometry);
      reference_sum = reference_sum.Compose(step.reference);
      current.num_steps++;
      current.reference_rotation_rad += step.reference.theta_rad;
      current.odometry_rotation_rad += step.odometry.theta_rad;
      current.duration_s += step.dt_s;
      duration_known = duration_known && step.dt_s > 0.0;
      current.reference_distance_m = std::hypot(reference_sum.x_m, reference_sum.y_m);
      current.odometry_distance_m = std::hypot(odometry_sum.x_m, odometry_sum.y_m);
      if (current.reference_distance_m >= options.segment_length_m) {
        if (!duration_known) current.duration_s = 0.0;
        segments.push_back(current);
        open = false;
      }
    }
    const Pose2D& motion = step.reference_valid ? step.reference : step.odometry;
    path = path.Compose(motion);
    arc_m += std::hypot(motion.x_m, motion.y_m);
  }
  return segments;
}

}  // namespace doorplate_localization
