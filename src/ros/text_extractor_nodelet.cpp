// TextExtractorNodelet: the doorplate text extractor (paper Sec. 3.2) as a thin nodelet over TextExtractor.
// Subscribes camera/image_raw (bgr8, rgb8 or mono8) and camera/camera_info (fx, cx turn columns into
// bearings) LAZILY: only while text_detections or ~debug_image has a subscriber (image_proc style), so an
// idle extractor costs nothing and the simulator renders no images for it. Publishes, for every processed
// image, text_detections (doorplate_localization/TextDetectionArray, header = the image's) holding the
// plates reported in that image, one per plate as it crosses the image centre (usually none), and, while
// subscribed, ~debug_image (bgr8: band, centre line, text boxes with their readings, reported plates).
// Parameters: text_extractor_options.h, docs/parameters.md.
// Threading: one TextExtractor (one Tesseract instance, not thread-safe) per nodelet, used under mutex_;
// callbacks run on the nodelet's single-threaded queue. Run several nodelets for several cameras.
#include <chrono>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>

#include "doorplate_localization/ros/text_conversions.h"
#include "doorplate_localization/ros/text_detection_conversions.h"
#include "text_extractor_options.h"

namespace doorplate_localization {

class TextExtractorNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    CheckOpenMpThreadLimit();
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    try {
      const TextExtractorNodeOptions node = LoadTextExtractorOptions(pnh);
      options_ = node.extractor;
      if (node.band_from_geometry) band_geometry_ = node.band_geometry;
      extractor_ = std::make_unique<TextExtractor>(options_);  // loads the Tesseract model
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      throw;
    }
    image_topic_ = nh.resolveName("camera/image_raw");
    info_topic_ = nh.resolveName("camera/camera_info");
    // Under connect_mutex_: a subscriber may connect before both publishers are assigned.
    std::lock_guard<std::mutex> lock(connect_mutex_);
    const ros::SubscriberStatusCallback on_connect = [this](const ros::SingleSubscriberPublisher&) { OnConnect(); };
    detections_pub_ = nh.advertise<TextDetectionArray>("text_detections", kTextDetectionsQueueSize, on_connect, on_connect);
    debug_pub_ = pnh.advertise<sensor_msgs::Image>("debug_image", 1, on_connect, on_connect);
    NODELET_INFO("text extractor: Tesseract '%s' from %s, %zu known rooms; waiting for subscribers",
                 options_.ocr.language.c_str(), ResolveTessdataDir(options_.ocr).c_str(),
                 options_.validator.known_rooms.size());
  }

  // Tesseract parallelises its LSTM with OpenMP (num_threads(10) clauses). Without OMP_THREAD_LIMIT=1 each
  // OCR call wakes a team of threads that take the cores from the simulator and the localizer: measured in
  // the simulated corridor (real_time_factor 2, one 22 s run each), the manager peaked at 20 threads
  // instead of 14 and used 29 % more CPU for the same plates. libgomp reads the variable once, in its
  // constructor, when the manager loads this library (which pulls in libtesseract and libgomp), i.e.
  // BEFORE onInit: a setenv() here was measured to have no effect. So it must be in the manager's
  // environment (scripts/env.sh, <env> in the launch files); here its absence is reported.
  void CheckOpenMpThreadLimit() {
    const char* limit = std::getenv("OMP_THREAD_LIMIT");
    if (limit != nullptr && std::string(limit) == "1") return;
    NODELET_WARN("OMP_THREAD_LIMIT is %s in the nodelet manager's environment, not 1: Tesseract's OpenMP "
                 "threads will compete for the CPU. Set it before the manager starts (<env "
                 "name=\"OMP_THREAD_LIMIT\" value=\"1\"/> in the launch file, or scripts/env.sh).",
                 limit == nullptr ? "unset" : limit);
  }

  // Subscribes to the camera while someone wants our output, unsubscribes when nobody does.
  void OnConnect() {
    std::lock_guard<std::mutex> lock(connect_mutex_);
    const bool wanted = detections_pub_.getNumSubscribers() > 0 || debug_pub_.getNumSubscribers() > 0;
    if (wanted == subscribed_) return;
    subscribed_ = wanted;
    if (!wanted) {
      image_sub_.shutdown();
      info_sub_.shutdown();
      NODELET_DEBUG("text extractor: no subscribers, unsubscribed from %s", image_topic_.c_str());
      return;
    }
    {
      std::lock_guard<std::mutex> processing(mutex_);
      extractor_->Reset();  // tracks from before the pause would match unrelated boxes
    }
    ros::NodeHandle& nh = getNodeHandle();
    info_sub_ = nh.subscribe("camera/camera_info", 1, &TextExtractorNodelet::OnCameraInfo, this);
    image_sub_ = nh.subscribe("camera/image_raw", 1, &TextExtractorNodelet::OnImage, this);  // newest only
    NODELET_DEBUG("text extractor: subscribed to %s", image_topic_.c_str());
  }

  void OnCameraInfo(const sensor_msgs::CameraInfo::ConstPtr& info) {
    CameraGeometry geometry;
    const std::string problem = ReadCameraGeometry(*info, &geometry);
    if (!problem.empty()) {
      NODELET_ERROR_THROTTLE(5.0, "%s: %s; ignoring it", info_topic_.c_str(), problem.c_str());
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    TextExtractorOptions options = options_;
    try {
      if (band_geometry_) {  // ~detector/band_from_geometry: the band from this camera's intrinsics
        BandGeometryOptions band = *band_geometry_;
        band.image_height_px = geometry.height_px;
        band.fy_px = info->K[4];
        band.cy_px = info->K[5];
        options.detector.band = BandFromGeometry(band);
      }
    } catch (const std::exception& e) {
      NODELET_ERROR_THROTTLE(5.0, "%s: no band from geometry: %s", info_topic_.c_str(), e.what());
      return;
    }
    const bool same_band = options.detector.band.top_px == options_.detector.band.top_px &&
                           options.detector.band.bottom_px == options_.detector.band.bottom_px;
    if (has_geometry_ && same_band && geometry.fx_px == options_.tracker.fx_px &&
        geometry.cx_px == options_.tracker.cx_px) {
      geometry_ = geometry;
      return;
    }
    // The tracker's bearings and centre line come from fx, cx (and the band may come from fy, cy): rebuild
    // the extractor (normally once).
    options.tracker.fx_px = geometry.fx_px;
    options.tracker.cx_px = geometry.cx_px;
    try {
      extractor_ = std::make_unique<TextExtractor>(options);
    } catch (const std::exception& e) {
      NODELET_ERROR_THROTTLE(5.0, "%s: cannot use fx %.3f, cx %.3f: %s", info_topic_.c_str(), geometry.fx_px,
                             geometry.cx_px, e.what());
      return;
    }
    options_ = options;
    geometry_ = geometry;
    has_geometry_ = true;
    NODELET_INFO("text extractor: %s: %dx%d, fx %.2f px, cx %.2f px%s", info_topic_.c_str(), geometry.width_px,
                 geometry.height_px, geometry.fx_px, geometry.cx_px,
                 band_geometry_ ? (", band rows " + std::to_string(options_.detector.band.top_px) + "-" +
                                   std::to_string(options_.detector.band.bottom_px) + " from geometry").c_str()
                                : "");
  }

  // validate → convert → core → publish.
  void OnImage(const sensor_msgs::Image::ConstPtr& image) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!has_geometry_) {
      NODELET_WARN_THROTTLE(5.0, "%s: no camera_info received on %s yet; dropping images", image_topic_.c_str(),
                            info_topic_.c_str());
      return;
    }
    const std::string problem = ValidateCameraImage(*image, geometry_);
    if (!problem.empty()) {
      NODELET_ERROR_THROTTLE(2.0, "%s: %s; dropping it", image_topic_.c_str(), problem.c_str());
      return;
    }
    std::vector<PlateReport> reports;
    cv_bridge::CvImageConstPtr cv_image;
    const auto start = std::chrono::steady_clock::now();
    try {
      cv_image = ToExtractorImage(image);
      reports = extractor_->Process(cv_image->image, image->header.stamp.toSec());
    } catch (const std::exception& e) {  // cv_bridge::Exception, or a band that does not fit the image
      NODELET_ERROR_THROTTLE(2.0, "%s: %s; dropping it", image_topic_.c_str(), e.what());
      return;
    }
    const double took_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (const PlateReport& r : reports) {
      NODELET_INFO("text extractor: plate '%s' at %.3f rad (%d frames, confidence %.2f, stamp %.2f s)",
                   r.text.c_str(), r.bearing_rad, r.voted_frame_count, r.confidence, r.stamp_s);
    }
    NODELET_DEBUG("text extractor: %zu boxes, %zu reports in %.1f ms", extractor_->last_observations().size(),
                  reports.size(), took_ms);
    detections_pub_.publish(ToTextDetectionArrayMsg(reports, image->header));
    if (debug_pub_.getNumSubscribers() > 0) {
      const cv::Range band = ResolveBandRows(options_.detector.band, cv_image->image.rows);
      debug_pub_.publish(ToTextDebugImageMsg(cv_image->image, image->header, band, options_.tracker.cx_px,
                                             extractor_->last_observations(), reports));
    }
  }

  TextExtractorOptions options_;  // tracker.fx_px / cx_px: from the last camera_info used
  std::optional<BandGeometryOptions> band_geometry_;  // set: the band comes from each camera_info
  std::unique_ptr<TextExtractor> extractor_;
  std::mutex mutex_;  // guards extractor_, options_, geometry_, has_geometry_
  CameraGeometry geometry_;
  bool has_geometry_ = false;
  std::string image_topic_, info_topic_;
  std::mutex connect_mutex_;  // guards the subscriptions and subscribed_
  bool subscribed_ = false;
  ros::Publisher detections_pub_, debug_pub_;
  ros::Subscriber image_sub_, info_sub_;
};

}  // namespace doorplate_localization

PLUGINLIB_EXPORT_CLASS(doorplate_localization::TextExtractorNodelet, nodelet::Nodelet)
