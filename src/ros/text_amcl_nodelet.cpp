// TextAmclNodelet (text_amcl_nodelet.h): start, maps, services, publishing and health; the scan and
// doorplate callbacks are in text_amcl_nodelet_inputs.cpp.
#include "text_amcl_nodelet.h"

#include <pluginlib/class_list_macros.hpp>

namespace doorplate_localization {

void TextAmclNodelet::onInit() {
  ros::NodeHandle& nh = getNodeHandle();
  ros::NodeHandle& pnh = getPrivateNodeHandle();
  std::shared_ptr<const BuildingMaps> start_maps;
  std::shared_ptr<const TextMap> text_map;  // one floor: ~text_map_file (null: laser only)
  try {
    options_ = LoadTextAmclOptions(pnh);  // loads ~building_file
    if (!options_.building) {             // one floor: ~text_map_file with the map the nodelet gets
      const LocalizerTextMap loaded = LoadLocalizerTextMap(options_, pnh.resolveName("text_map_file"));
      text_map = loaded.text_map;
      if (!loaded.problem.empty()) NODELET_ERROR("%s; localizing with the laser alone", loaded.problem.c_str());
      if (!loaded.warning.empty()) NODELET_WARN("text amcl: %s", loaded.warning.c_str());
    }
    start_maps = LocalizerStartMaps(options_, text_map, pnh.resolveName("map_file"));
  } catch (const std::exception& e) {
    NODELET_FATAL("%s", e.what());
    throw;
  }
  core_ = std::make_unique<LocalizerCore>(options_, text_map);
  tf_broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
  tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_);
  pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 2, /*latch=*/true);
  cloud_pub_ = nh.advertise<geometry_msgs::PoseArray>("particlecloud", 2, /*latch=*/true);
  markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("text_landmarks", 1, /*latch=*/true);
  state_pub_ = pnh.advertise<std_msgs::String>("state", 1, /*latch=*/true);
  floor_pub_ = pnh.advertise<std_msgs::String>("floor", 1, /*latch=*/true);
  diagnostics_pub_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 1);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    PublishState();
  }
  if (text_map) markers_pub_.publish(ToTextLandmarkMarkers(*text_map, options_.global_frame_id, ros::Time::now()));
  global_srv_ = nh.advertiseService("global_localization", &TextAmclNodelet::OnGlobalLocalization, this);
  nomotion_srv_ = nh.advertiseService("request_nomotion_update", &TextAmclNodelet::OnNoMotionUpdate, this);
  set_map_srv_ = nh.advertiseService("set_map", &TextAmclNodelet::OnSetMap, this);
  if (start_maps) {  // ~building_file or ~map_file: the nodelet owns the map and latches it on map
    map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, /*latch=*/true);
    const std::string param = pnh.resolveName(options_.building ? "building_file" : "map_file");
    const std::string& file = options_.building ? options_.building_file : options_.map_file;
    std::lock_guard<std::mutex> lock(mutex_);
    if (!UseMaps([&] { return core_->UseMaps(start_maps, file); }, file)) {
      NODELET_FATAL("%s = '%s' cannot be used (see above)", param.c_str(), file.c_str());
      throw std::runtime_error("unusable " + param + " " + file);
    }
  } else if (options_.use_map_topic) {
    map_sub_ = nh.subscribe("map", 1, &TextAmclNodelet::OnMap, this);
  } else {
    map_timer_ = nh.createWallTimer(ros::WallDuration(1.0), &TextAmclNodelet::RequestStaticMap, this);
  }
  initial_pose_sub_ = nh.subscribe("initialpose", 2, &TextAmclNodelet::OnInitialPose, this);
  scan_filter_ = std::make_unique<ScanTfFilter>(tf_buffer_, options_.odom_frame_id, kScanTfQueueSize,
      nh.getCallbackQueue(), [this](const auto& m) { OnScan(m); }, [this](const auto&, const auto& why, bool broken) {
        std::lock_guard<std::mutex> lock(mutex_);
        ScanDropped(why, broken);
      });
  scan_filter_->Subscribe(nh, "scan");
  detections_sub_ = nh.subscribe("text_detections", kTextDetectionsQueueSize, &TextAmclNodelet::OnDetections, this);
  if (options_.save_pose_rate_hz > 0.0) {
    save_timer_ = nh.createTimer(ros::Duration(1.0 / options_.save_pose_rate_hz), &TextAmclNodelet::SavePose, this);
  }
  health_timer_ = nh.createTimer(ros::Duration(1.0), &TextAmclNodelet::OnHealthTimer, this);
  reconfigure_ = std::make_unique<TextAmclReconfigureServer>(
      pnh, options_, [this](const TextAmclNodeOptions& o) { return Reconfigure(o); });
}

std::string TextAmclNodelet::Reconfigure(const TextAmclNodeOptions& o) {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::string problem = core_->Reconfigure(o.session.setup);
  if (!problem.empty()) return problem;
  options_ = o;
  PublishState();
  return "";
}

template <typename Use>
bool TextAmclNodelet::UseMaps(const Use& use, const std::string& source) {
  const LocalizerCore::MapChange change = use();
  if (!change.used) {
    NODELET_ERROR("text amcl: the map from %s is refused: %s; %s", source.c_str(), change.problem.c_str(),
                  core_->has_session() ? ("the map in force (" + core_->map_in_force() + ") is kept").c_str()
                                       : "still waiting for a usable map");
    return false;
  }
  if (!change.text_problem.empty()) {
    NODELET_ERROR("%s cannot be used with the map from %s: %s; localizing with the laser alone on it",
                  options_.text_map_file.c_str(), source.c_str(), change.text_problem.c_str());
  }
  const BuildingSession& b = core_->session();
  const OccupancyGrid& grid = b.maps().floors[static_cast<size_t>(b.floor())].grid;
  const TextAmclSessionOptions& o = options_.session;
  NODELET_INFO("text amcl: map %dx%d at %.3f m from %s (floor '%s' of %zu%s), %s laser model, %s; %d particles %s",
               grid.width, grid.height, grid.resolution_m, source.c_str(), b.floor_id().c_str(),
               b.maps().floors.size(), b.floor_certain() ? "" : ", until the plates decide",
               ToString(o.setup.laser_model_type), b.session().has_text_map() ? "with doorplates" : "laser only",
               o.setup.filter.max_particles,
               change.ran_queued_global_localization ? "globally (the queued global_localization request)"
               : o.start_with_global_localization    ? "globally"
                                                     : "at the start pose");
  PublishFloor(/*new_maps=*/true);
  PublishRestart();
  return true;
}

void TextAmclNodelet::PublishFloor(bool new_maps) {
  const BuildingSession& session = core_->session();
  const std::string& id = session.floor_id();
  if (!new_maps && id == floor_id_) return;
  if (!new_maps) {
    NODELET_INFO("text amcl: floor '%s' -> '%s' (the plates read; belief %.3f)", floor_id_.c_str(), id.c_str(),
                 session.belief().probabilities()[static_cast<size_t>(session.floor())]);
  }
  floor_id_ = id;
  const FloorMaps& floor = session.maps().floors[static_cast<size_t>(session.floor())];
  const ros::Time now = ros::Time::now();
  if (map_pub_) map_pub_.publish(ToOccupancyGridMsg(floor.grid, options_.global_frame_id, now));
  markers_pub_.publish(
      ToTextLandmarkMarkers(floor.text_map ? *floor.text_map : TextMap(), options_.global_frame_id, now));
  std_msgs::String msg;
  msg.data = id;
  floor_pub_.publish(msg);
}

void TextAmclNodelet::OnMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (options_.first_map_only && core_->has_session()) return;
  const std::string& topic = map_sub_.getTopic();
  OccupancyGrid grid;
  const std::string problem = FromOccupancyGridMsg(*msg, &grid);
  if (!problem.empty()) {
    NODELET_ERROR_THROTTLE(5.0, "%s: %s; ignoring this map%s", topic.c_str(), problem.c_str(),
                           core_->has_session() ? ", the map in force is kept" : "");
    return;
  }
  UseMaps([&] { return core_->UseGrid(grid, topic); }, topic);
}

void TextAmclNodelet::RequestStaticMap(const ros::WallTimerEvent&) {
  const std::string service = getNodeHandle().resolveName("static_map");
  nav_msgs::GetMap srv;
  if (!ros::service::exists(service, false) || !ros::service::call(service, srv)) {
    NODELET_WARN_THROTTLE(10.0, "text amcl: waiting for the %s service (or set ~map_file / ~use_map_topic)",
                          service.c_str());
    return;
  }
  OccupancyGrid grid;
  const std::string problem = FromOccupancyGridMsg(srv.response.map, &grid);
  std::lock_guard<std::mutex> lock(mutex_);
  if (!problem.empty()) {
    NODELET_ERROR_THROTTLE(10.0, "%s: %s; asking again", service.c_str(), problem.c_str());
    return;
  }
  if (UseMaps([&] { return core_->UseGrid(grid, service); }, service)) map_timer_.stop();
}

bool TextAmclNodelet::OnSetMap(nav_msgs::SetMap::Request& req, nav_msgs::SetMap::Response& res) {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::string& service = set_map_srv_.getService();
  OccupancyGrid grid;
  StartPose start;
  std::string problem = options_.building ? "the floors' maps come from " + options_.building_file : "";
  if (problem.empty()) problem = FromOccupancyGridMsg(req.map, &grid);
  if (problem.empty()) {
    problem = FromInitialPoseMsg(req.initial_pose, options_.global_frame_id, &start.mean, &start.covariance);
    if (!problem.empty()) problem = "initial_pose: " + problem;
  }
  if (!problem.empty()) {
    NODELET_ERROR("%s: %s; map not changed%s", service.c_str(), problem.c_str(),
                  core_->has_session() ? ", the map in force is kept" : "");
    res.success = false;
    return true;
  }
  const bool was_queued = core_->global_localization_queued();
  res.success = UseMaps([&] { return core_->UseGrid(grid, service, start); }, service);
  if (res.success && was_queued) {
    NODELET_INFO("%s: the queued global_localization request is cancelled: set_map gave a start pose",
                 service.c_str());
  }
  return true;
}

bool TextAmclNodelet::OnGlobalLocalization(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!core_->GlobalLocalization()) {
    NODELET_WARN("%s: no map in force yet: queued; the first map used will start with global localization",
                 global_srv_.getService().c_str());
    PublishState();
    return true;
  }
  const BuildingSession& session = core_->session();
  NODELET_INFO("text amcl: global localization on floor '%s'%s", session.floor_id().c_str(),
               session.floor_certain() ? "" : "; the floor is unknown until the plates decide");
  PublishRestart();
  return true;
}

bool TextAmclNodelet::OnNoMotionUpdate(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (core_->has_session()) core_->session().RequestNoMotionUpdate();
  return true;
}

void TextAmclNodelet::OnInitialPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::string& topic = initial_pose_sub_.getTopic();
  StartPose pose;
  std::string problem = FromInitialPoseMsg(*msg, options_.global_frame_id, &pose.mean, &pose.covariance);
  const bool was_queued = core_->global_localization_queued();
  if (problem.empty()) {
    try {
      core_->InitialPose(pose);  // restarts the session there, or is the start pose on the next map
    } catch (const std::exception& e) {
      problem = e.what();
    }
  }
  if (!problem.empty()) {
    NODELET_WARN_THROTTLE(2.0, "%s: %s; ignored", topic.c_str(), problem.c_str());
    return;
  }
  if (was_queued) NODELET_INFO("%s: the queued global_localization request is cancelled", topic.c_str());
  if (!core_->has_session()) return;
  NODELET_INFO("text amcl: initial pose (%.3f, %.3f, %.3f) on floor '%s'", pose.mean.x_m, pose.mean.y_m,
               pose.mean.theta_rad, core_->session().floor_id().c_str());
  PublishRestart();
}

void TextAmclNodelet::PublishRestart() {
  PublishFloor(/*new_maps=*/false);
  cloud_pub_.publish(ToParticleCloudMsg(core_->session().session().particles(), options_.global_frame_id,
                                        ros::Time::now()));
  last_cloud_time_ = ros::WallTime::now();
  PublishState();
}

void TextAmclNodelet::PublishFilter(const ros::Time& stamp, bool force_cloud) {
  PublishFloor(/*new_maps=*/false);
  const BuildingSession& session = core_->session();
  pose_pub_.publish(ToAmclPoseMsg(session.Estimate(), options_.global_frame_id, stamp));
  const ros::WallTime now = ros::WallTime::now();
  const double rate = options_.gui_publish_rate_hz;
  if (force_cloud || rate <= 0.0 || (now - last_cloud_time_).toSec() >= 1.0 / rate) {
    cloud_pub_.publish(ToParticleCloudMsg(session.session().particles(), options_.global_frame_id, stamp));
    last_cloud_time_ = now;
  }
  PublishState();
}

void TextAmclNodelet::PublishState() {
  const std::string state = core_->State(ros::Time::now().toSec());
  if (state == last_state_) return;
  last_state_ = state;
  std_msgs::String msg;
  msg.data = state;
  state_pub_.publish(msg);
  NODELET_INFO("text amcl: %s", state.c_str());
}

void TextAmclNodelet::OnHealthTimer(const ros::TimerEvent&) {
  std::lock_guard<std::mutex> lock(mutex_);
  const ros::Time now = ros::Time::now();
  PublishState();
  LocalizerHealth health = core_->Health(now.toSec());
  const double elapsed_s = last_health_time_.isZero() ? 0.0 : (now - last_health_time_).toSec();
  health.scan_rate_hz = elapsed_s > 0.0 ? scans_since_health_ / elapsed_s : 0.0;
  scans_since_health_ = 0;
  last_health_time_ = now;
  try {
    const ros::Time latest =
        tf_buffer_.lookupTransform(options_.odom_frame_id, options_.base_frame_id, ros::Time(0)).header.stamp;
    health.tf_age_s = std::max(0.0, (now - latest).toSec());
  } catch (const tf2::TransformException&) {
    health.tf_age_s = -1.0;
  }
  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = now;
  array.status.push_back(ToDiagnosticStatus(health, getName() + ": localization", getName()));
  diagnostics_pub_.publish(array);
}

void TextAmclNodelet::SavePose(const ros::TimerEvent&) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!core_->has_session()) return;
  const std::string state = core_->State(ros::Time::now().toSec());
  if (state != "tracking" && state != "converged") return;
  const PoseEstimate& e = core_->session().Estimate();
  const std::pair<const char*, double> saved[] = {
      {"initial_pose_x", e.pose.x_m},         {"initial_pose_y", e.pose.y_m},
      {"initial_pose_a", e.pose.theta_rad},   {"initial_cov_xx", e.covariance(0, 0)},
      {"initial_cov_yy", e.covariance(1, 1)}, {"initial_cov_aa", e.covariance(2, 2)}};
  for (const auto& [name, value] : saved) getPrivateNodeHandle().setParam(name, value);
}

}  // namespace doorplate_localization

PLUGINLIB_EXPORT_CLASS(doorplate_localization::TextAmclNodelet, nodelet::Nodelet)
