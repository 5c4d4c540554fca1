// doorplate_run_report: turns a rosbag of a simulated run into a short report: a top-down PNG of the world
// with the true and the odometry trajectories, a camera view rendered at the run's middle, and report.md
// with the distance driven, the odometry's drift and the corridor width the robot measured, and the plates
// the text extractor read (text, time, where the robot truly was, which plate of the world that is).
// Usage: doorplate_run_report --bag RUN.bag --world WORLD.yaml --out DIR [--title TEXT]
// Topics read: base_pose_ground_truth, odom (nav_msgs/Odometry), corridor_follower/corridor_width (Float32),
// text_detections (doorplate_localization/TextDetectionArray).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <nav_msgs/Odometry.h>
#include <opencv2/imgcodecs.hpp>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <std_msgs/Float32.h>
#include <tf2/utils.h>

#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/sim/camera_renderer.h"
#include "doorplate_localization/sim/top_down_view.h"
#include "doorplate_localization/sim/world_loader.h"

namespace dl = doorplate_localization;

namespace {

dl::Pose2D ToPose(const nav_msgs::Odometry& msg) {
  return {msg.pose.pose.position.x, msg.pose.pose.position.y, tf2::getYaw(msg.pose.pose.orientation)};
}

double PathLength(const std::vector<dl::Pose2D>& poses) {
  double length = 0.0;
  for (size_t i = 1; i < poses.size(); ++i) length += dl::Norm(poses[i].Position() - poses[i - 1].Position());
  return length;
}

struct PlateRead {
  std::string text;
  double time_s = 0.0;
  double bearing_rad = 0.0;
};

// The sample of `poses` (stamped `times_s`, ascending) nearest in time to `time_s`.
dl::Pose2D PoseAt(const std::vector<dl::Pose2D>& poses, const std::vector<double>& times_s, double time_s) {
  const size_t i = std::lower_bound(times_s.begin(), times_s.end(), time_s) - times_s.begin();
  if (i == 0) return poses.front();
  if (i == times_s.size()) return poses.back();
  return time_s - times_s[i - 1] < times_s[i] - time_s ? poses[i - 1] : poses[i];
}

// The world's plates on the camera's side of the path that the robot drove past: the plate's along-track
// coordinate at the nearest true pose is within the path, and it lies to the camera's side there.
std::vector<const dl::TextSign*> PlatesPassed(const dl::World& world, const std::vector<dl::Pose2D>& truth) {
  const double side = world.sensors.camera.side == "left" ? 1.0 : -1.0;
  std::vector<const dl::TextSign*> passed;
  for (const dl::TextSign* plate : world.Plates()) {
    const dl::Vec2 position = world.SignPosition(*plate);
    size_t nearest = 0;
    for (size_t i = 1; i < truth.size(); ++i) {
      if (dl::Norm(truth[i].Position() - position) < dl::Norm(truth[nearest].Position() - position)) nearest = i;
    }
    const dl::Vec2 d = position - truth[nearest].Position();
    const double c = std::cos(truth[nearest].theta_rad), s = std::sin(truth[nearest].theta_rad);
    const double along_m = c * d.x + s * d.y, lateral_m = -s * d.x + c * d.y;
    const bool inside_path = nearest > 0 && nearest + 1 < truth.size();
    if ((inside_path || std::fabs(along_m) < 0.5) && side * lateral_m > 0.0) passed.push_back(plate);
  }
  return passed;
}

// Appends the "plates read" section: one row per reported plate, then the plates passed but not read.
void WritePlatesRead(std::ostream& md, const dl::World& world, const std::vector<PlateRead>& reads,
                     const std::vector<dl::Pose2D>& truth, const std::vector<double>& truth_times_s) {
  const std::vector<const dl::TextSign*> passed = PlatesPassed(world, truth);
  int correct = 0;
  md << "\n## Plates read (text_detections)\n\n"
     << "| text | time (s) | bearing (rad) | robot x, y (true, m) | plate x, y (world, m) | plate on camera side |\n"
     << "|---|---|---|---|---|---|\n";
  std::vector<std::string> read_texts;
  for (const PlateRead& r : reads) {
    const dl::Pose2D robot = PoseAt(truth, truth_times_s, r.time_s);
    md << "| " << r.text << " | " << r.time_s << " | " << r.bearing_rad << " | " << robot.x_m << ", " << robot.y_m
       << " | ";
    const auto plate =
        std::find_if(passed.begin(), passed.end(), [&](const dl::TextSign* p) { return p->text == r.text; });
    if (plate != passed.end()) {
      const dl::Vec2 at = world.SignPosition(**plate);
      md << at.x << ", " << at.y << " | yes |\n";
      if (std::find(read_texts.begin(), read_texts.end(), r.text) == read_texts.end()) ++correct;
    } else {
      md << "- | no: not a plate the camera passed |\n";
    }
    read_texts.push_back(r.text);
  }
  md << "\n" << correct << " of the " << passed.size() << " plates on the camera's side were read ("
     << reads.size() << " reports).";
  std::string missed;
  for (const dl::TextSign* p : passed) {
    if (std::find(read_texts.begin(), read_texts.end(), p->text) == read_texts.end()) missed += " " + p->text;
  }
  md << (missed.empty() ? std::string("\n") : " Not read:" + missed + ".\n");
}

int Usage() {
  std::cerr << "usage: doorplate_run_report --bag RUN.bag --world WORLD.yaml --out DIR [--title TEXT]\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string bag_path, world_path, out_dir, title = "Simulated corridor run";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--bag") bag_path = value;
    else if (key == "--world") world_path = value;
    else if (key == "--out") out_dir = value;
    else if (key == "--title") title = value;
    else return Usage();
  }
  if (bag_path.empty() || world_path.empty() || out_dir.empty() || argc % 2 == 0) return Usage();
  try {
    const dl::World world = dl::LoadWorldFile(world_path);
    std::vector<dl::Pose2D> truth, odom;
    std::vector<double> widths;
    std::vector<double> truth_times_s;
    std::vector<PlateRead> reads;
    bool text_recorded = false;
    rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
    for (const rosbag::MessageInstance& m : rosbag::View(bag)) {
      const std::string topic = m.getTopic();
      if (topic.find("base_pose_ground_truth") != std::string::npos) {
        if (auto msg = m.instantiate<nav_msgs::Odometry>()) {
          truth.push_back(ToPose(*msg));
          truth_times_s.push_back(msg->header.stamp.toSec());
        }
      } else if (topic.size() >= 4 && topic.compare(topic.size() - 4, 4, "odom") == 0) {
        if (auto msg = m.instantiate<nav_msgs::Odometry>()) odom.push_back(ToPose(*msg));
      } else if (topic.find("corridor_width") != std::string::npos) {
        if (auto msg = m.instantiate<std_msgs::Float32>()) widths.push_back(msg->data);
      } else if (topic.find("text_detections") != std::string::npos) {
        if (auto msg = m.instantiate<dl::TextDetectionArray>()) {
          text_recorded = true;
          for (const dl::TextDetection& d : msg->detections) {
            reads.push_back({d.text, msg->header.stamp.toSec(), d.bearing_rad});
          }
        }
      }
    }
    if (truth.size() < 2 || odom.size() < 2) {
      throw std::runtime_error(bag_path + ": needs base_pose_ground_truth and odom messages, found " +
                               std::to_string(truth.size()) + " and " + std::to_string(odom.size()));
    }
    // Odometry starts at its own origin where the robot started: express it in the world frame.
    std::vector<dl::Pose2D> odom_in_world;
    const dl::Pose2D odom_origin = truth.front().Compose(odom.front().Inverse());
    for (const dl::Pose2D& p : odom) odom_in_world.push_back(odom_origin.Compose(p));

    dl::TopDownView view(world);
    view.DrawTrajectory(odom_in_world, cv::Scalar(40, 40, 220), 2);
    view.DrawTrajectory(truth, cv::Scalar(40, 160, 40), 2);
    view.DrawRobot(truth.back());
    view.DrawLegend(0, "green: true path   red: wheel odometry", cv::Scalar(30, 30, 30));
    const std::string map_png = out_dir + "/trajectory.png";
    if (!cv::imwrite(map_png, view.image())) throw std::runtime_error(map_png + ": cannot write");
    const dl::CameraRenderer camera(world, world.sensors.camera);
    std::mt19937_64 rng(1);
    const std::string camera_png = out_dir + "/camera_mid_run.png";
    if (!cv::imwrite(camera_png, camera.Render(truth[truth.size() / 2], 0.4, 0.0, rng))) {
      throw std::runtime_error(camera_png + ": cannot write");
    }

    const double driven = PathLength(truth);
    const dl::Pose2D end_error = truth.back().Between(odom_in_world.back());
    double width_mean = 0.0;
    for (double w : widths) width_mean += w;
    if (!widths.empty()) width_mean /= widths.size();
    std::ofstream md(out_dir + "/report.md");
    md << std::fixed << std::setprecision(3);
    md << "# " << title << "\n\nWorld `" << world.name << "` (" << world_path << ").\n\n"
       << "| quantity | value |\n|---|---|\n"
       << "| distance driven (ground truth) | " << driven << " m |\n"
       << "| distance by wheel odometry | " << PathLength(odom) << " m |\n"
       << "| odometry position error at the end | " << dl::Norm(end_error.Position()) << " m |\n"
       << "| odometry heading error at the end | " << std::fabs(end_error.theta_rad) * 180.0 / M_PI << " deg |\n"
       << "| corridor width measured by the laser (mean of " << widths.size() << ") | " << width_mean << " m |\n"
       << "| final true pose | (" << truth.back().x_m << ", " << truth.back().y_m << ", "
       << truth.back().theta_rad << ") |\n\n"
       << "![trajectory](trajectory.png)\n\n![camera](camera_mid_run.png)\n";
    if (text_recorded) WritePlatesRead(md, world, reads, truth, truth_times_s);
    std::cout << "report written to " << out_dir << "/report.md (driven " << driven << " m, odometry error "
              << dl::Norm(end_error.Position()) << " m)\n";
  } catch (const std::exception& e) {
    std::cerr << "doorplate_run_report: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
