// Wheel odometry against a reference path, cut into segments of travel (issue 20, item 3): the input of
// the slip fit (odometry_slip_fit.h). ROS-free and log-free: a tool turns a log into OdometrySteps.
//
// Frames: a step's `odometry` and `reference` are the same motion of base_link between two consecutive
// scans, each expressed in base_link at the earlier scan (x forward, y left). Units: metres, radians,
// seconds.
#pragma once

#include <vector>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct OdometryStep {
  Pose2D odometry;               // what the wheels report
  Pose2D reference;              // what the reference (laser scan matching, ground truth) says
  double dt_s = 0.0;             // time the step took; 0 = unknown
  bool reference_valid = true;   // false: no reference for this step (scan matching failed)
  // Whether the reference constrains the translation along the travel direction (a featureless
  // corridor does not: laser scan matching then only echoes its starting guess, the odometry).
  bool along_constrained = true;
};

struct OdometrySegmentOptions {
  double segment_length_m = 1.0;  // a segment ends once the reference has moved this far (chord)
};

// One segment: consecutive steps with a valid, along-constrained reference.
struct OdometrySegment {
  int first_step = 0;              // index of its first step in the input
  int num_steps = 0;
  double start_arc_m = 0.0;        // reference path length before the segment (where on the floor)
  Vec2 start_position;             // reference path position at its start (frame of the first step)
  double reference_distance_m = 0.0;  // chord of the composed reference motion
  double odometry_distance_m = 0.0;   // chord of the composed odometry motion
  double reference_rotation_rad = 0.0;  // summed heading change (not wrapped: a 3π/2 turn stays 3π/2)
  double odometry_rotation_rad = 0.0;
  double duration_s = 0.0;         // 0 when a step's dt_s is unknown

  // Odometry distance over reference distance, minus 1 (the convention of OdometryNoiseOptions::scale_error).
  double ScaleError() const { return odometry_distance_m / reference_distance_m - 1.0; }
  // |reference rotation| per metre of reference travel, rad/m.
  double TurnRateRadPerM() const;
};

// Cuts `steps` into segments. A step without a valid, along-constrained reference ends the current
// segment and is left out; a segment shorter than segment_length_m at such a break or at the end is
// dropped (a short chord would make its scale error noisy). Throws std::invalid_argument for a
// non-positive segment_length_m.
std::vector<OdometrySegment> SplitIntoSegments(const std::vector<OdometryStep>& steps,
                                               const OdometrySegmentOptions& options);

}  // namespace doorplate_localization
