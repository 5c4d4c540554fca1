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

// world_from_map of the mapping run: the mapping nodelet's map frame is the odometry frame at its SLAM's first
// processed scan (rbpf_slam.h), where odometry read `first_node` (node 0 of the saved trajectory, odom frame).
// So the truth composed with the inverse odometry at the odometry message that read that pose (nearest in
// position, 1 rad counted as 1 m; the first of equals, as when the robot stood still), not at the bag's first
// message: odometry drifts between the two when the mapper starts after the robot has moved (a 0.005 rad
// turn of the alignment is 0.2 m at 40 m). `mapping.odometry` and `.truth` sorted by time, not empty.
Pose2D WorldFromMapAtFirstNode(const RecordedRun& mapping, const Pose2D& first_node);

// Length of the path through the track's positions between two times (inclusive), metres.
double PathLength(const std::vector<StampedPose>& track, double from_s, double to_s);

}  // namespace doorplate_localization
