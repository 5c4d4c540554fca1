// map -> odom publish latency of the Text AMCL nodelet, end to end: for every scan the localizer used, the
// wall-clock time from the scan's arrival at this node to the arrival of the map -> odom transform computed
// from it (stamped scan stamp + transform_tolerance, as amcl does). Both travel the same loopback transport,
// so the difference is the localizer's own delay (queueing, tf lookups, filter update, publishing).
// Runs beside launch/localization.launch (bench/amcl_latency.sh starts both); prints one markdown row.
// Usage: doorplate_amcl_latency --duration-s S --label TEXT [--transform-tolerance-s T]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include "cli_app.h"

namespace {

double Percentile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1) + 0.5))];
}

struct Args {
  double duration_s = 60.0, tolerance_s = 0.1;
  std::string label = "run";
};

void AddOptions(CLI::App* app, Args* args) {
  app->add_option("--duration-s", args->duration_s, "wall-clock seconds to measure")->capture_default_str()
      ->check(doorplate_localization::tools::PositiveNumber());
  app->add_option("--label", args->label, "first column of the row")->capture_default_str();
  app->add_option("--transform-tolerance-s", args->tolerance_s, "the localizer's transform_tolerance")
      ->capture_default_str()->check(doorplate_localization::tools::Number(0.0));
}

int Run(const Args& args) {
  const double duration_s = args.duration_s, tolerance_s = args.tolerance_s;
  const std::string& label = args.label;
  ros::NodeHandle nh;
  std::map<long, ros::WallTime> scan_arrivals;  // scan stamp (ns) -> wall time of arrival
  std::vector<double> latencies_ms;
  int scans = 0;
  const long tolerance_ns = static_cast<long>(std::llround(tolerance_s * 1e9));
  auto scan_sub = nh.subscribe<sensor_msgs::LaserScan>("scan", 100, [&](const sensor_msgs::LaserScan::ConstPtr& m) {
    scan_arrivals[m->header.stamp.toNSec()] = ros::WallTime::now();
    ++scans;
  }, ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  auto tf_sub = nh.subscribe<tf2_msgs::TFMessage>("tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& m) {
    const ros::WallTime now = ros::WallTime::now();
    for (const auto& t : m->transforms) {
      if (t.child_frame_id != "odom" || t.header.frame_id != "map") continue;
      const auto it = scan_arrivals.find(static_cast<long>(t.header.stamp.toNSec()) - tolerance_ns);
      if (it == scan_arrivals.end()) continue;
      latencies_ms.push_back((now - it->second).toSec() * 1e3);
      scan_arrivals.erase(scan_arrivals.begin(), std::next(it));  // each scan once; older ones were not used
    }
  }, ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(duration_s);
  while (ros::ok() && ros::WallTime::now() < end) ros::spinOnce(), ros::WallDuration(0.001).sleep();
  std::printf("| %s | %d | %zu | %.2f | %.2f | %.2f |\n", label.c_str(), scans, latencies_ms.size(),
              Percentile(latencies_ms, 0.5), Percentile(latencies_ms, 0.95), Percentile(latencies_ms, 1.0));
  return latencies_ms.empty() ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "amcl_latency", ros::init_options::AnonymousName);  // takes the ROS remappings out of argv
  return doorplate_localization::tools::RunTool("doorplate_amcl_latency", "map -> odom publish latency of the Text "
                                                "AMCL nodelet (one markdown row).", AddOptions, Run, argc, argv);
}
