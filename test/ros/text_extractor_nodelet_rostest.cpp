// Checker node of text_extractor_nodelet.test: the simulator, the wall follower (started disabled) and the
// text extractor run in one nodelet manager. The extractor subscribes to the camera only while its output
// has subscribers, drops bad images with an error naming the topic and keeps running, and reads a plate of
// the north wall (the camera's side) with a small bearing when the plate crosses the image centre. Every
// wait is on a condition with a wall-clock timeout. Also checks LoadTextExtractorOptions against this node's
// parameters. The cases run in order: the drive starts only in the last one.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <ros/callback_queue.h>
#include <ros/master.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/String.h>
#include <std_srvs/SetBool.h>

#include "doorplate_localization/TextDetectionArray.h"
#include "text_extractor_options.h"
#include "rostest_util.h"

namespace doorplate_localization {
namespace {

using rostest_util::WaitFor;

// Nodes subscribed to `topic` (resolved name), from the master.
std::set<std::string> SubscribersOf(const std::string& topic) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  std::set<std::string> nodes;
  if (!ros::master::execute("getSystemState", args, result, payload, true)) return nodes;
  XmlRpc::XmlRpcValue& subscribers = payload[1];
  for (int i = 0; i < subscribers.size(); ++i) {
    if (static_cast<std::string>(subscribers[i][0]) != topic) continue;
    for (int j = 0; j < subscribers[i][1].size(); ++j) nodes.insert(static_cast<std::string>(subscribers[i][1][j]));
  }
  return nodes;
}

bool ManagerSubscribesToTheCamera() {
  return SubscribersOf("/camera/image_raw").count("/text_manager") == 1 &&
         SubscribersOf("/camera/camera_info").count("/text_manager") == 1;
}

bool ExtractorAdvertised() {
  ros::master::V_TopicInfo topics;
  ros::master::getTopics(topics);
  for (const ros::master::TopicInfo& t : topics) {
    if (t.name == "/text_detections") return true;
  }
  return false;
}

// LoadTextExtractorOptions, on parameters set under this node's private namespace.
TEST(LoadTextExtractorOptions, WithoutParametersGivesTheCoreDefaults) {
  const TextExtractorOptions options = LoadTextExtractorOptions(ros::NodeHandle("~empty")).extractor;
  const TextExtractorOptions defaults;
  EXPECT_EQ(options.max_regions_per_frame, defaults.max_regions_per_frame);
  EXPECT_EQ(options.detector.band.top_fraction, defaults.detector.band.top_fraction);
  EXPECT_EQ(options.detector.grouping.max_height_ratio, defaults.detector.grouping.max_height_ratio);
  EXPECT_EQ(options.tracker.max_height_ratio, defaults.tracker.max_height_ratio);
  EXPECT_EQ(options.validator.pattern, defaults.validator.pattern);
  EXPECT_TRUE(options.validator.known_rooms.empty());
}

TEST(LoadTextExtractorOptions, ReadsNestedValuesAndKnownRooms) {
  ros::NodeHandle nh("~good");
  nh.setParam("detector/band/top_px", 100);
  nh.setParam("detector/band/bottom_px", 300);
  nh.setParam("ocr/line_mode", std::string("single_word"));
  nh.setParam("validator/known_rooms", std::vector<std::string>{"201", "202A"});
  nh.setParam("tracker/max_height_ratio", 2.0);
  nh.setParam("tracker/min_voted_frames", 3);
  const TextExtractorOptions o = LoadTextExtractorOptions(nh).extractor;
  EXPECT_EQ(o.detector.band.top_px, 100);
  EXPECT_EQ(o.detector.band.bottom_px, 300);
  EXPECT_EQ(o.ocr.line_mode, OcrLineMode::kSingleWord);
  EXPECT_EQ(o.validator.known_rooms, (std::vector<std::string>{"201", "202A"}));
  EXPECT_EQ(o.tracker.max_height_ratio, 2.0);
  EXPECT_EQ(o.detector.grouping.max_height_ratio, LineGroupingOptions().max_height_ratio);  // not the tracker's
  EXPECT_EQ(o.tracker.min_voted_frames, 3);
}

// Expects LoadTextExtractorOptions to throw a ParameterError whose message contains `parameter` resolved.
void ExpectErrorNaming(const ros::NodeHandle& nh, const std::string& parameter) {
  rostest_util::ExpectLoadErrorNaming<ParameterError>(LoadTextExtractorOptions, nh, parameter);
}

TEST(LoadTextExtractorOptions, RejectsOutOfRangeMistypedAndInconsistentValuesNamingTheParameter) {
  ros::NodeHandle nh("~bad");
  nh.setParam("detector/band/top_fraction", 1.5);
  ExpectErrorNaming(nh, "detector/band/top_fraction");
  nh.setParam("detector/band/top_fraction", std::string("high"));
  ExpectErrorNaming(nh, "detector/band/top_fraction");
  nh.deleteParam("detector/band/top_fraction");
  nh.setParam("detector/band/top_px", 50);  // without bottom_px
  ExpectErrorNaming(nh, "detector/band/bottom_px");
  nh.deleteParam("detector/band/top_px");
  nh.setParam("tracker/min_voted_frames", 0);
  ExpectErrorNaming(nh, "tracker/min_voted_frames");
  nh.deleteParam("tracker/min_voted_frames");
  nh.setParam("ocr/line_mode", std::string("paragraph"));
  ExpectErrorNaming(nh, "ocr/line_mode");
}

TEST(LoadTextExtractorOptions, RejectsUnquotedOrInvalidKnownRoomsAndABadPattern) {
  ros::NodeHandle nh("~rooms");
  nh.setParam("validator/known_rooms", std::vector<int>{201, 202});  // YAML [201, 202]: numbers, not text
  ExpectErrorNaming(nh, "validator/known_rooms");
  nh.setParam("validator/known_rooms", std::vector<std::string>{"201", "lobby"});  // does not match the pattern
  ExpectErrorNaming(nh, "validator/known_rooms");
  nh.deleteParam("validator/known_rooms");
  nh.setParam("validator/pattern", std::string("[0-9"));
  ExpectErrorNaming(nh, "validator/pattern");
  nh.deleteParam("validator/pattern");
  nh.setParam("room_pattern", std::string("[0-9"));
  ExpectErrorNaming(nh, "room_pattern");
}

TEST(LoadTextExtractorOptions, RoomPatternAndItsOlderNameSetTheValidatorsPattern) {
  ros::NodeHandle nh("~room_pattern");
  EXPECT_EQ(LoadTextExtractorOptions(nh).extractor.validator.pattern, kDefaultRoomPattern);
  nh.setParam("room_pattern", std::string("[0-9]{3}|WC"));
  EXPECT_EQ(LoadTextExtractorOptions(nh).extractor.validator.pattern, "[0-9]{3}|WC");
  // The older name, as a user's own launch file sets it over the shipped config's room_pattern: it wins
  // (with a warning), as every renamed parameter of the package does.
  nh.setParam("validator/pattern", std::string("[0-9]{3}"));
  EXPECT_EQ(LoadTextExtractorOptions(nh).extractor.validator.pattern, "[0-9]{3}");
  nh.deleteParam("room_pattern");
  EXPECT_EQ(LoadTextExtractorOptions(nh).extractor.validator.pattern, "[0-9]{3}");
}

TEST(LoadTextExtractorOptions, AMissingTesseractModelNamesTheFolderParameterAndThePath) {
  ros::NodeHandle nh("~no_model");
  nh.setParam("ocr/tessdata_dir", std::string("/nonexistent/tessdata"));
  try {
    LoadTextExtractorOptions(nh);
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(nh.resolveName("ocr/tessdata_dir")), std::string::npos) << what;
    EXPECT_NE(what.find("/nonexistent/tessdata/eng.traineddata"), std::string::npos) << what;
  }
}

TEST(LoadTextExtractorOptions, BandGeometryIsOffByDefaultReadsTheMountAndPlatesWhenOnAndNamesABadValue) {
  ros::NodeHandle nh("~band_geometry");
  EXPECT_FALSE(LoadTextExtractorOptions(nh).band_from_geometry);
  nh.setParam("detector/band_from_geometry", true);
  nh.setParam("detector/band_geometry/camera_height_m", 1.1);
  nh.setParam("detector/band_geometry/text_top_max_m", 1.8);
  const TextExtractorNodeOptions o = LoadTextExtractorOptions(nh);
  ASSERT_TRUE(o.band_from_geometry);
  EXPECT_DOUBLE_EQ(o.band_geometry.mount_height_m, 1.1);
  EXPECT_DOUBLE_EQ(o.band_geometry.text_top_max_m, 1.8);
  EXPECT_DOUBLE_EQ(o.band_geometry.max_distance_m, BandGeometryOptions{}.max_distance_m);
  nh.setParam("detector/band_geometry/max_distance_m", 0.5);  // below min_distance_m
  ExpectErrorNaming(nh, "detector/band_geometry/max_distance_m");
}

// config/text_extractor.yaml claims to hold the structs' defaults: a default changed in the core without the
// file (or the reverse) would silently run the node with other values than the core's tests.
TEST(LoadTextExtractorOptions, TheShippedConfigHoldsTheCoreDefaults) {
  const TextExtractorOptions c = LoadTextExtractorOptions(ros::NodeHandle("/text_extractor")).extractor;
  const TextExtractorOptions d;
  EXPECT_EQ(c.max_regions_per_frame, d.max_regions_per_frame);
  const BandOptions &cb = c.detector.band, &db = d.detector.band;
  EXPECT_EQ(std::tie(cb.enabled, cb.top_fraction, cb.bottom_fraction, cb.top_px, cb.bottom_px),
            std::tie(db.enabled, db.top_fraction, db.bottom_fraction, db.top_px, db.bottom_px));
  const MserOptions &cm = c.detector.mser, &dm = d.detector.mser;
  EXPECT_EQ(std::tie(cm.delta, cm.min_area_px, cm.max_area_px, cm.max_variation),
            std::tie(dm.delta, dm.min_area_px, dm.max_area_px, dm.max_variation));
  const CharacterFilterOptions &cc = c.detector.character, &dc = d.detector.character;
  EXPECT_EQ(std::tie(cc.min_char_height_px, cc.max_char_height_px, cc.min_char_aspect, cc.max_char_aspect,
                     cc.min_fill_ratio, cc.max_fill_ratio, cc.min_contrast_grey),
            std::tie(dc.min_char_height_px, dc.max_char_height_px, dc.min_char_aspect, dc.max_char_aspect,
                     dc.min_fill_ratio, dc.max_fill_ratio, dc.min_contrast_grey));
  const LineGroupingOptions &cg = c.detector.grouping, &dg = d.detector.grouping;
  EXPECT_EQ(std::tie(cg.max_nested_coverage, cg.max_height_ratio, cg.max_center_offset_to_height,
                     cg.max_gap_to_height, cg.max_ink_difference_grey, cg.min_chars_per_line, cg.min_line_aspect,
                     cg.max_line_aspect),
            std::tie(dg.max_nested_coverage, dg.max_height_ratio, dg.max_center_offset_to_height,
                     dg.max_gap_to_height, dg.max_ink_difference_grey, dg.min_chars_per_line, dg.min_line_aspect,
                     dg.max_line_aspect));
  EXPECT_EQ(std::tie(c.detector.box_padding_to_height, c.detector.nms_enabled, c.detector.nms_max_iou),
            std::tie(d.detector.box_padding_to_height, d.detector.nms_enabled, d.detector.nms_max_iou));
  const TesseractOcrOptions &co = c.ocr, &dO = d.ocr;
  EXPECT_EQ(std::tie(co.tessdata_dir, co.language, co.line_mode, co.whitelist),
            std::tie(dO.tessdata_dir, dO.language, dO.line_mode, dO.whitelist));
  const OcrPreprocessOptions &cp = c.ocr.preprocess, &dp = d.ocr.preprocess;
  EXPECT_EQ(std::tie(cp.target_text_height_px, cp.border_px, cp.min_text_height_px, cp.ink_thinning_px),
            std::tie(dp.target_text_height_px, dp.border_px, dp.min_text_height_px, dp.ink_thinning_px));
  EXPECT_EQ(std::tie(c.validator.pattern, c.validator.known_rooms, c.validator.max_edit_distance),
            std::tie(d.validator.pattern, d.validator.known_rooms, d.validator.max_edit_distance));
  const PlateTrackerOptions &ct = c.tracker, &dt = d.tracker;
  EXPECT_EQ(std::tie(ct.max_center_jump_px, ct.max_vertical_offset_to_height, ct.max_height_ratio,
                     ct.max_missed_frames, ct.min_voted_frames),
            std::tie(dt.max_center_jump_px, dt.max_vertical_offset_to_height, dt.max_height_ratio,
                     dt.max_missed_frames, dt.min_voted_frames));
}

// The nodelet, in the manager.
TEST(TextExtractorNodelet, SubscribesToTheCameraOnlyWhileItsOutputIsWanted) {
  ASSERT_TRUE(WaitFor(ExtractorAdvertised, 60.0)) << "the text extractor nodelet did not start";
  EXPECT_FALSE(ManagerSubscribesToTheCamera());
  ros::NodeHandle nh;
  {
    ros::Subscriber sub =
        nh.subscribe<TextDetectionArray>("text_detections", 10, [&](const TextDetectionArray::ConstPtr&) {});
    EXPECT_TRUE(WaitFor(ManagerSubscribesToTheCamera));
  }
  EXPECT_TRUE(WaitFor([] { return SubscribersOf("/camera/image_raw").count("/text_manager") == 0; }));
  {
    ros::Subscriber sub =
        nh.subscribe<sensor_msgs::Image>("text_extractor/debug_image", 1, [&](const sensor_msgs::Image::ConstPtr&) {});
    EXPECT_TRUE(WaitFor(ManagerSubscribesToTheCamera));
  }
  EXPECT_TRUE(WaitFor([] { return SubscribersOf("/camera/image_raw").count("/text_manager") == 0; }));
}

TEST(TextExtractorNodelet, DropsBadImagesWithAnErrorNamingTheTopicAndKeepsPublishing) {
  ros::NodeHandle nh;
  const rostest_util::RosoutLog errors(rosgraph_msgs::Log::ERROR);
  int arrays = 0;
  ros::Subscriber sub = nh.subscribe<TextDetectionArray>(
      "text_detections", 10, [&](const TextDetectionArray::ConstPtr&) { ++arrays; });
  ros::Publisher bad_pub = nh.advertise<sensor_msgs::Image>("camera/image_raw", 1);
  ASSERT_TRUE(WaitFor(ManagerSubscribesToTheCamera));
  const auto contains = [&](const std::string& text) { return errors.Has("/camera/image_raw", text); };
  sensor_msgs::Image bad;
  bad.encoding = "32FC1";
  bad.width = 640;
  bad.height = 480;
  bad.step = 640 * 4;
  bad.data.assign(bad.step * bad.height, 0);
  EXPECT_TRUE(WaitFor([&] { return contains("unsupported encoding '32FC1'"); }, 30.0,
                      [&] { bad_pub.publish(bad); }));
  bad.encoding = "bgr8";
  bad.width = 320;
  bad.height = 240;
  bad.step = 320 * 3;
  bad.data.assign(bad.step * bad.height, 0);
  EXPECT_TRUE(WaitFor([&] { return contains("camera_info says 640x480"); }, 30.0, [&] { bad_pub.publish(bad); }));
  // Still alive: the simulator's images keep producing one array each.
  const int before = arrays;
  EXPECT_TRUE(WaitFor([&] { return arrays >= before + 5; }));
}

TEST(TextExtractorNodelet, ReadsTheNorthWallPlatesOnceEachWithASmallBearingAtTheirCrossing) {
  ros::NodeHandle nh, pnh("~");
  std::vector<std::string> north_texts;
  ASSERT_TRUE(pnh.getParam("north_wall_texts", north_texts));
  double max_abs_bearing_rad = 0.0;
  ASSERT_TRUE(pnh.getParam("max_abs_bearing_rad", max_abs_bearing_rad));
  std::vector<TextDetectionArray::ConstPtr> with_plates;
  const auto on_detections = [&](const TextDetectionArray::ConstPtr& m) {
    if (!m->detections.empty()) with_plates.push_back(m);
  };
  ros::Subscriber sub = nh.subscribe<TextDetectionArray>("text_detections", 50, on_detections);
  std::string state;
  ros::Subscriber state_sub = nh.subscribe<std_msgs::String>(
      "corridor_follower/state", 10, [&](const std_msgs::String::ConstPtr& m) { state = m->data; });
  ASSERT_TRUE(WaitFor(ManagerSubscribesToTheCamera));
  ros::ServiceClient enable = nh.serviceClient<std_srvs::SetBool>("corridor_follower/enable");
  ASSERT_TRUE(enable.waitForExistence(ros::Duration(30.0)));
  std_srvs::SetBool drive;
  drive.request.data = true;
  ASSERT_TRUE(enable.call(drive));

  // The first plate, then the rest of the corridor (15.5 m at 0.4 m/s: ~40 s of sim time).
  ASSERT_TRUE(WaitFor([&] { return !with_plates.empty(); }, 180.0)) << "no plate reported";
  EXPECT_TRUE(WaitFor([&] { return state == "end_reached"; }, 300.0)) << "state " << state;
  std::set<std::string> read;
  for (const TextDetectionArray::ConstPtr& array : with_plates) {
    EXPECT_EQ(array->header.frame_id, "camera_optical");
    EXPECT_GT(array->header.stamp.toSec(), 0.0);
    for (const TextDetection& plate : array->detections) {
      SCOPED_TRACE("plate '" + plate.text + "' at " + std::to_string(array->header.stamp.toSec()) + " s");
      EXPECT_NE(std::find(north_texts.begin(), north_texts.end(), plate.text), north_texts.end());
      EXPECT_TRUE(read.insert(plate.text).second) << "reported twice";
      EXPECT_LT(std::fabs(plate.bearing_rad), max_abs_bearing_rad);
      EXPECT_TRUE(plate.crossed_center);
      EXPECT_GE(plate.frame_count, 2u);  // tracker/min_voted_frames
      EXPECT_GT(plate.confidence, 0.0f);
      EXPECT_LE(plate.confidence, 1.0f);
      std::printf("read '%s' at %.2f s, bearing %+.4f rad, %u frames, confidence %.2f\n", plate.text.c_str(),
                  array->header.stamp.toSec(), plate.bearing_rad, plate.frame_count, plate.confidence);
    }
  }
  EXPECT_EQ(read.size(), north_texts.size()) << "every plate on the camera's side is read";
}

}  // namespace
}  // namespace doorplate_localization

int main(int argc, char** argv) {
  return doorplate_localization::rostest_util::RunCheckerTests(argc, argv, "text_extractor_checker");
}
