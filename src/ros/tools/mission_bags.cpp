#include "mission_bags.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <std_msgs/String.h>
#include <tf2/utils.h>

#include "bag_reader.h"
#include "doorplate_localization/TextDetectionArray.h"

namespace doorplate_localization {
namespace {

Pose2D ToPose(const geometry_msgs::Pose& pose) {
  return {pose.position.x, pose.position.y, tf2::getYaw(pose.orientation)};
}

// Latched string topics are recorded once per (re)publication; time is the bag's receive time.
void AddText(const rosbag::MessageInstance& m, std::vector<StampedText>* out) {
  if (auto msg = InstantiateChecked<std_msgs::String>(m)) out->push_back({m.getTime().toSec(), msg->data});
}

}  // namespace

RecordedRun ReadRecordedRun(const std::string& bag_path) {
  RecordedRun run;
  ReadBag(bag_path, {}, [&run](const rosbag::MessageInstance& m, const BagPosition&) {
    const std::string topic = m.getTopic().rfind('/', 0) == 0 ? m.getTopic().substr(1) : m.getTopic();
    if (topic == "base_pose_ground_truth") {
      if (auto msg = InstantiateChecked<nav_msgs::Odometry>(m)) {
        run.truth.push_back({msg->header.stamp.toSec(), ToPose(msg->pose.pose)});
      }
    } else if (topic == "odom") {
      if (auto msg = InstantiateChecked<nav_msgs::Odometry>(m)) {
        run.odometry.push_back({msg->header.stamp.toSec(), ToPose(msg->pose.pose)});
      }
    } else if (topic == "amcl_pose") {
      if (auto msg = InstantiateChecked<geometry_msgs::PoseWithCovarianceStamped>(m)) {
        run.estimate.push_back({msg->header.stamp.toSec(), ToPose(msg->pose.pose)});
      }
    } else if (topic == "text_detections") {
      if (auto msg = InstantiateChecked<TextDetectionArray>(m)) {
        for (const TextDetection& d : msg->detections) {
          if (d.crossed_center && !d.text.empty()) {
            run.plates.push_back({msg->header.stamp.toSec(), d.text, d.confidence});
          }
        }
      }
    } else if (topic == "amcl/state") {
      AddText(m, &run.localizer_state);
    } else if (topic == "go_to_room/status") {
      AddText(m, &run.go_to_room_status);
    } else if (topic == "go_to_room") {
      AddText(m, &run.go_to_room_requests);
    }
  });
  if (run.truth.empty() || run.odometry.empty()) {
    throw BagReadError(bag_path + ": needs base_pose_ground_truth and odom messages, found " +
                       std::to_string(run.truth.size()) + " and " + std::to_string(run.odometry.size()));
  }
  const auto by_time = [](const StampedPose& a, const StampedPose& b) { return a.time_s < b.time_s; };
  for (auto* track : {&run.truth, &run.odometry, &run.estimate}) std::stable_sort(track->begin(), track->end(), by_time);
  return run;
}

Pose2D PoseAtTime(const std::vector<StampedPose>& track, double time_s) {
  const auto it = std::lower_bound(track.begin(), track.end(), time_s,
                                   [](const StampedPose& p, double t) { return p.time_s < t; });
  if (it == track.begin()) return track.front().pose;
  if (it == track.end()) return track.back().pose;
  return time_s - std::prev(it)->time_s < it->time_s - time_s ? std::prev(it)->pose : it->pose;
}

Pose2D WorldFromMapAtFirstNode(const RecordedRun& mapping, const Pose2D& first_node) {
  const StampedPose* best = &mapping.odometry.front();
  double best_d = std::numeric_limits<double>::infinity();
  for (const StampedPose& o : mapping.odometry) {
    const double d = Norm(o.pose.Position() - first_node.Position()) +
                     std::abs(NormalizeAngle(o.pose.theta_rad - first_node.theta_rad));
    if (d < best_d) best_d = d, best = &o;
  }
  return PoseAtTime(mapping.truth, best->time_s).Compose(best->pose.Inverse());
}

double PathLength(const std::vector<StampedPose>& track, double from_s, double to_s) {
  double length = 0.0;
  for (size_t i = 1; i < track.size(); ++i) {
    if (track[i - 1].time_s < from_s || track[i].time_s > to_s) continue;
    length += Norm(track[i].pose.Position() - track[i - 1].pose.Position());
  }
  return length;
}

}  // namespace doorplate_localization
