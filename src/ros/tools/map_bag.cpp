// doorplate_map_bag: maps a rosbag offline through the same mapping session (slam/mapping_session.h),
// option table and message conversions (slam_conversions.h) as SlamMappingNodelet; the back end is solved
// once, at the end. Reads the scans, tf (/tf and /tf_static: odom -> base_link,
// base_link -> laser and -> camera) and, unless --no-text, the text detections, and writes
//   DIR/map.pgm, DIR/map.yaml       the session's map after the final solve (map_server format)
//   DIR/map.text_map.yaml           the text-landmark map (docs/text-map-format.md)
//   DIR/trajectory.txt              `scan_index x y theta` per processed scan (posterior mean trajectory,
//                                   RbpfSlam::MeanTrajectory, as doorplate_map_log writes it)
// all atomically, and a progress line on stderr every few seconds. The bag is read (bag_reader.h) twice: all tf first
// (so a transform recorded after a scan still serves it), then the scans and detections in time order.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <sensor_msgs/LaserScan.h>
#include <tf2/buffer_core.h>
#include <tf2/exceptions.h>

#include "bag_reader.h"
#include "cli_app.h"
#include "map_tool_output.h"
#include "output_guard.h"
#include "progress_line.h"
#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/ros/slam_conversions.h"
#include "doorplate_localization/ros/tf_lookup.h"
#include "doorplate_localization/slam/mapping_session.h"
#include "doorplate_localization/slam/rbpf_slam_options.h"

namespace dl = doorplate_localization;
namespace tools = dl::tools;
using tools::UsageError;

namespace {

const char kDescription[] = "Maps a rosbag offline through the mapping nodelet's session, options and conversions.";
const char kNotes[] =
    "--set changes any SLAM option by its name in the one option table (TextSlamOptionNames(): e.g.\n"
    "num_particles, linear_update_m, matcher.field_sigma_m, text.plate_sigma_m); the mapping nodelet\n"
    "takes the same names as parameters (with / for .).";

struct Args {
  std::string bag, out_dir, scan_topic = "/scan", detections_topic = "/text_detections", map_frame = "map";
  std::string map_name = "map";
  std::vector<std::string> sets;
  bool no_text = false;
  double progress_s = 5.0;
  dl::SlamInputFrames frames;
  dl::MappingSessionOptions options = [] {
    dl::MappingSessionOptions o;
    o.camera_wait_s = dl::kDefaultCameraWaitS;  // the nodelet's: scans and plates in stamp order
    return o;
  }();
};

std::string Topic(const std::string& name) { return name.empty() || name[0] == '/' ? name : "/" + name; }

void AddOptions(CLI::App* app, Args* args) {
  app->footer(kNotes);
  app->add_option("BAG", args->bag, "the rosbag")->required();
  app->add_option("--out-dir", args->out_dir, "output folder DIR")->required();
  app->add_option("--seed", args->options.slam.slam.seed, "filter seed")->capture_default_str()->transform(tools::Seed());
  app->add_option("--set", args->sets, "NAME=VALUE: a SLAM option (repeatable)")->allow_extra_args(false);
  app->add_option("--scan-topic", args->scan_topic, "laser scans")->capture_default_str();
  app->add_option("--detections-topic", args->detections_topic, "text detections")->capture_default_str();
  app->add_flag("--no-text", args->no_text, "laser only: ignore the text detections");
  app->add_option("--camera-wait-s", args->options.camera_wait_s, "a scan waits for the detection arrays up to its "
                  "stamp at most this long (the nodelet's ~camera_wait_s; 0: no waiting)")
      ->capture_default_str()->check(tools::Number(0.0));
  app->add_option("--odom-frame", args->frames.odom_frame, "odometry frame")->capture_default_str();
  app->add_option("--base-frame", args->frames.base_frame, "robot frame")->capture_default_str();
  app->add_option("--map-frame", args->map_frame, "map frame")->capture_default_str();
  app->add_option("--map-name", args->map_name, "file name of the maps, without '/'")->capture_default_str();
  app->add_option("--max-range-m", args->frames.max_range_m, "readings at or beyond it are no-echo (the nodelet's "
                  "~maxRange; 0 = the scan's range_max)")->capture_default_str()->check(tools::Number(0.0));
  app->add_option("--min-valid-beams", args->frames.min_valid_beams, "a scan with fewer valid beams is dropped")
      ->capture_default_str()->transform(tools::WholeNumber(0));
  app->add_option("--progress-s", args->progress_s, "a progress line on stderr every this many seconds (rewritten in "
                  "place twice a second on a terminal; 0: none)")->capture_default_str()->check(tools::Number(0.0));
  app->callback([args] {
    if (args->no_text) args->options.camera_wait_s = 0.0;  // as the nodelet without use_text
    args->scan_topic = Topic(args->scan_topic);
    args->detections_topic = Topic(args->detections_topic);
    for (const std::string& set : args->sets) {
      tools::ApplySetOption(set, [&](const std::string& name, double v) { dl::SetTextSlamOption(name, v, &args->options.slam); });
    }
    if (args->map_name.empty() || args->map_name.find('/') != std::string::npos) {
      throw UsageError("--map-name must be a file name without '/'");
    }
  });
}

struct Counters {
  long scans = 0, scans_dropped = 0, arrays = 0, arrays_dropped = 0, plates_used = 0, plates_ignored = 0;
};

void Warn(long* count, const std::string& topic, const std::string& problem) {
  if (++*count <= 5) std::fprintf(stderr, "doorplate_map_bag: %s: %s; dropping it\n", topic.c_str(), problem.c_str());
}

void CountPlates(const std::vector<dl::MappingPlateOutcome>& outcomes, Counters* n) {
  for (const dl::MappingPlateOutcome& o : outcomes) {
    ++(o.result.used() ? n->plates_used : n->plates_ignored);
    if (!o.result.used()) {
      std::fprintf(stderr, "doorplate_map_bag: plate '%s' not used: %s\n", o.sighting.text.c_str(), o.result.reason.c_str());
    }
  }
}

int MapBag(const Args& args) {
  const tools::Stopwatch clock;
  const std::string base = args.out_dir + "/" + args.map_name;
  tools::RefuseOverwritingInputs({{"BAG", args.bag}},
                                 {{"--out-dir", base + ".pgm"}, {"--out-dir", base + ".yaml"},
                                  {"--out-dir", base + ".text_map.yaml"}, {"--out-dir", args.out_dir + "/trajectory.txt"}});
  dl::MappingSession session(args.options);           // bad options (--set num_particles=1e9) before the bag
  std::filesystem::create_directories(args.out_dir);  // fails early, before a long run, if it cannot
  const std::unique_ptr<tf2::BufferCore> tf = dl::ReadBagTf(args.bag);  // BagReadError names the bag
  const dl::TransformLookup lookup = [&tf](const std::string& target, const std::string& source,
                                           const ros::Time& stamp, std::string* problem)
      -> std::optional<geometry_msgs::Transform> {
    return dl::LookupTransform(*tf, target, source, stamp, problem);
  };

  std::vector<std::string> topics{args.scan_topic};
  if (!args.no_text) topics.push_back(args.detections_topic);
  const dl::RbpfSlam& filter = session.slam().slam();
  Counters n;
  tools::ProgressLine progress({args.progress_s});
  double driven_m = 0.0;  // odometry path length over the scans used
  std::optional<dl::Pose2D> last_odom;
  dl::ReadBag(args.bag, topics, [&](const rosbag::MessageInstance& m, const dl::BagPosition& at) {
    if (const auto scan_msg = dl::InstantiateChecked<sensor_msgs::LaserScan>(m)) {
      ++n.scans;
      dl::LaserScan scan;
      dl::Pose2D odom_pose;
      const std::string problem = dl::PrepareSlamScan(*scan_msg, lookup, args.frames, &scan, &odom_pose);
      if (!problem.empty()) return Warn(&n.scans_dropped, args.scan_topic, problem);
      if (last_odom) driven_m += dl::Norm(odom_pose.Position() - last_odom->Position());
      last_odom = odom_pose;
      const dl::MappingUpdate update = session.AddScan(scan_msg->header.stamp.toSec(), odom_pose, scan);
      if (!update.scan_refused_reason.empty()) Warn(&n.scans_dropped, args.scan_topic, update.scan_refused_reason);
      CountPlates(update.plates, &n);  // sightings recorded before the scans near their stamp
    } else if (const auto array = dl::InstantiateChecked<dl::TextDetectionArray>(m)) {
      ++n.arrays;
      std::vector<dl::PlateReading> sightings;
      std::vector<std::string> rejected;
      dl::Pose2D odom_pose;
      const std::string problem = dl::PrepareSlamSightings(*array, lookup, args.frames, &sightings, &odom_pose, &rejected);
      if (!problem.empty()) return Warn(&n.arrays_dropped, args.detections_topic, problem);
      for (const std::string& r : rejected) std::fprintf(stderr, "doorplate_map_bag: detection %s\n", r.c_str());
      CountPlates(session.AddPlates(array->header.stamp.toSec(), odom_pose, sightings).plates, &n);
    }
    if (progress.Due(clock.Seconds())) {
      const dl::RbpfSlamStats& s = filter.stats();
      progress.Show("doorplate_map_bag: message %zu/%zu, %.1f m driven, scans %d processed of %ld, plates read %ld "
                    "(used %ld), %d landmarks, neff %.1f, %.1f s, peak RSS %.0f MB", at.index + 1, at.total, driven_m,
                    s.scans_processed, n.scans, n.plates_used + n.plates_ignored, n.plates_used,
                    session.slam().num_landmarks(), s.last_neff, clock.Seconds(), tools::PeakRssMb());
    }
  });
  progress.Finish();
  if (filter.stats().scans_processed == 0) {
    throw std::runtime_error(args.bag + ": no usable scan on " + args.scan_topic + " (" + std::to_string(n.scans) +
                             " messages, " + std::to_string(n.scans_dropped) + " dropped); nothing written");
  }
  CountPlates(session.Flush().plates, &n);  // what still waited for the camera
  session.Solve();
  dl::TextMap text_map = session.GetTextMap();
  text_map.frame_id = args.map_frame;
  tools::SaveMapPair(*session.Map(), text_map, base);
  tools::WriteTrajectory(filter.MeanTrajectory(), args.out_dir + "/trajectory.txt");
  const dl::RbpfSlamStats& s = filter.stats();
  std::fprintf(stderr,
               "doorplate_map_bag: done: %ld scans (%ld dropped), %d processed, %ld detection arrays (%ld dropped), "
               "plates %ld used / %ld ignored, %zu landmarks, %.1f s, peak RSS %.0f MB; wrote %s.{pgm,yaml,text_map.yaml}, "
               "%s/trajectory.txt\n",
               n.scans, n.scans_dropped, s.scans_processed, n.arrays, n.arrays_dropped, n.plates_used, n.plates_ignored,
               text_map.landmarks.size(), clock.Seconds(), tools::PeakRssMb(), base.c_str(), args.out_dir.c_str());
  return 0;
}

}  // namespace

// BagReadError (rosbag's errors, naming the bag), bad options, write errors: all name the file (exit status 1).
int main(int argc, char** argv) {
  return tools::RunTool("doorplate_map_bag", kDescription, AddOptions, MapBag, argc, argv);
}
