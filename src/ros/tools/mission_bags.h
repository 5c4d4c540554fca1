// What doorplate_mission_report reads from the two bags of a simulated mission (scripts/demo.sh): the
// mapping run (launch/mapping.launch, bag:=...) and the localization + go-to-room run
// (launch/localization.launch, bag:=...). Poses: base_link; truth in the world frame, odometry in odom,
// amcl_pose in the map frame; times in seconds of sim time.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct StampedPose {
  double time_s = 0.0;
  Pose2D pose;
};

struct StampedText {
  double time_s = 0.0;
  std::string text;
};

struct PlateReadEvent {
  double time_s = 0.0;
  std::string text;
  double confidence = 0.0;
};

struct RecordedRun {
  std::vector<StampedPose> truth;      // base_pose_ground_truth, world frame
  std::vector<StampedPose> odometry;   // odom, odom frame
  std::vector<StampedPose> estimate;   // amcl_pose, map frame (localization runs)
  std::vector<PlateReadEvent> plates;  // text_detections that crossed the image centre
  std::vector<StampedText> localizer_state;  // amcl/state
  std::vector<StampedText> go_to_room_status;  // go_to_room/status
  std::vector<StampedText> go_to_room_requests;  // go_to_room
};

// Reads every topic above that the bag holds (bag_reader.h). Throws BagReadError naming the bag if it cannot
// be read or holds no base_pose_ground_truth / odom messages.
RecordedRun ReadRecordedRun(const std::string& bag_path);

// The pose of `track` nearest in time to `time_s` (track sorted by time, not empty).
Pose2D PoseAtTime(const std::vector<StampedPose>& track, double time_s);

// Length of the path through the track's positions between two times (inclusive), metres.
double PathLength(const std::vector<StampedPose>& track, double from_s, double to_s);

}  // namespace doorplate_localization
