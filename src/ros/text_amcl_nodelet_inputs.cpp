// TextAmclNodelet (text_amcl_nodelet.h): the sensor callbacks — scans (after the tf filter) and doorplate
// readings — into the session, with their logging.
#include "text_amcl_nodelet.h"

namespace doorplate_localization {

void TextAmclNodelet::ScanDropped(const std::string& why, bool broken) {
  core_->ScanDropped(why);
  if (broken) NODELET_ERROR_THROTTLE(2.0, "%s: %s; scan ignored", scan_filter_->topic().c_str(), why.c_str());
  else NODELET_WARN_THROTTLE(2.0, "%s: %s; scan ignored", scan_filter_->topic().c_str(), why.c_str());
}

void TextAmclNodelet::OnScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::string& topic = scan_filter_->topic();
  if (!core_->has_session()) {
    NODELET_WARN_THROTTLE(10.0, "%s: no map yet; scan ignored", topic.c_str());
    return;
  }
  std::string tf_problem;
  const std::optional<ScanPoses> tf =
      LookupScanPoses(tf_buffer_, options_.odom_frame_id, options_.base_frame_id, *msg, &tf_problem);
  if (!tf) return ScanDropped(tf_problem, /*broken=*/false);
  BuildingSession& session = core_->session();
  SessionUpdate update;
  try {
    update = session.AddScan(msg->header.stamp.toSec(), tf->base_in_odom,
                             ToLocalizationScan(*msg, tf->laser_in_base));
  } catch (const std::invalid_argument& e) {  // the scan (nothing changed)
    return ScanDropped(e.what(), /*broken=*/true);
  } catch (const std::exception& e) {  // the session: no estimate until it takes a scan again
    return Failed(topic, e.what());
  }
  core_->ScanTaken(ros::Time::now().toSec());
  ++scans_since_health_;
  if (!update.scan_ignored_reason.empty()) {
    NODELET_WARN_THROTTLE(2.0, "%s: %s; scan ignored, continuing from it", topic.c_str(),
                          update.scan_ignored_reason.c_str());
  }
  ReportPlates(update, detections_sub_.getTopic());
  if (update.estimate_changed) {
    PublishFilter(msg->header.stamp, /*force_cloud=*/!update.plates.empty());
  } else {
    PublishState();  // e.g. waiting_for_scan -> the filter's state
  }
  const std::optional<Pose2D>& map_to_odom = session.MapToOdom();
  if (options_.tf_broadcast && map_to_odom) {
    const ros::Time stamp = msg->header.stamp + ros::Duration(options_.transform_tolerance_s);
    tf_broadcaster_->sendTransform(
        ToTransformStampedMsg(*map_to_odom, options_.global_frame_id, options_.odom_frame_id, stamp));
  }
}

void TextAmclNodelet::OnDetections(const TextDetectionArray::ConstPtr& msg) {
  bool any = false;
  for (const TextDetection& d : msg->detections) any = any || IsPlateReport(d);
  if (!any) return;  // most images report no plate
  std::lock_guard<std::mutex> lock(mutex_);
  const std::string& topic = detections_sub_.getTopic();
  if (!core_->has_session()) return;
  BuildingSession& session = core_->session();
  if (!session.session().has_text_map()) {
    NODELET_WARN_ONCE("%s: doorplate readings are ignored: no usable text map (~text_map_file, ~use_text)",
                      topic.c_str());
    return;
  }
  std::string tf_problem;
  const std::optional<geometry_msgs::Transform> camera =
      LookupTransform(tf_buffer_, options_.base_frame_id, msg->header.frame_id,
                      msg->header.stamp, options_.tf_timeout_s, &tf_problem);
  if (!camera) {
    NODELET_WARN_THROTTLE(2.0, "%s: %s; detections ignored", topic.c_str(), tf_problem.c_str());
    return;
  }
  CameraAxis axis;
  const std::string axis_problem = ToCameraAxis(*camera, &axis);
  if (!axis_problem.empty()) {
    NODELET_WARN_THROTTLE(2.0, "%s: camera frame '%s' in %s: %s; detections ignored", topic.c_str(),
                          msg->header.frame_id.c_str(), options_.base_frame_id.c_str(), axis_problem.c_str());
    return;
  }
  std::vector<std::string> problems;
  const std::vector<PlateReading> readings = ToPlateReadings(*msg, axis, &problems);
  for (const std::string& p : problems) NODELET_WARN_THROTTLE(2.0, "%s: %s; ignored", topic.c_str(), p.c_str());
  // The odometry at the readings' stamp (0: now), if tf has it yet; else the session keeps them until a
  // scan's odometry reaches it.
  const ros::Time stamp = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
  const double stamp_s = stamp.toSec();
  std::string odom_problem;
  const std::optional<Pose2D> base_in_odom = LookupPlanarPose(tf_buffer_, options_.odom_frame_id,
                                                              options_.base_frame_id, stamp,
                                                              options_.tf_timeout_s, &odom_problem);
  try {
    if (base_in_odom) {
      ReportPlates(session.AddOdometry(stamp_s, *base_in_odom), topic);
    } else {
      NODELET_DEBUG("%s: %s; the readings wait for the next scan's odometry", topic.c_str(), odom_problem.c_str());
    }
    const SessionUpdate update = session.AddPlates(stamp_s, readings);
    ReportPlates(update, topic);
    if (update.estimate_changed) PublishFilter(stamp, /*force_cloud=*/true);
  } catch (const std::exception& e) {
    Failed(topic, e.what());
  }
}

void TextAmclNodelet::Failed(const std::string& topic, const std::string& what) {
  NODELET_ERROR_THROTTLE(2.0, "%s: the localizer failed: %s; no estimate until it takes a scan again",
                         topic.c_str(), what.c_str());
  core_->Failed(what);
  PublishState();
}

void TextAmclNodelet::ReportPlates(const SessionUpdate& update, const std::string& topic) {
  for (const PlateReadingOutcome& p : update.plates) {
    if (p.disposition == PlateDisposition::kWeighed) {
      NODELET_INFO("text amcl: %s", DescribePlateOutcome(p).c_str());
    } else if (p.disposition == PlateDisposition::kUnknownRoomFirst) {
      NODELET_WARN("%s: %s (text map of floor '%s': %s); its readings are ignored", topic.c_str(),
                   DescribePlateOutcome(p).c_str(), core_->session().floor_id().c_str(),
                   (options_.building ? options_.building_file : options_.text_map_file).c_str());
    } else if (p.disposition == PlateDisposition::kStale || p.disposition == PlateDisposition::kInvalid) {
      NODELET_WARN_THROTTLE(2.0, "%s: %s", topic.c_str(), DescribePlateOutcome(p).c_str());
    }
  }
}

}  // namespace doorplate_localization
