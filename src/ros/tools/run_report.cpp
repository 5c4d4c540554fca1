// doorplate_run_report: turns a rosbag of a simulated run into a short report: a top-down PNG of the world
// with the true and the odometry trajectories, a camera view rendered at the run's middle, and report.md
// with the distance driven, the odometry's drift and the corridor width the robot measured.
// Usage: doorplate_run_report --bag RUN.bag --world WORLD.yaml --out DIR [--title TEXT]
// Topics read: base_pose_ground_truth, odom (nav_msgs/Odometry), corridor_follower/corridor_width (Float32).
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
    rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
    for (const rosbag::MessageInstance& m : rosbag::View(bag)) {
      const std::string topic = m.getTopic();
      if (topic.find("base_pose_ground_truth") != std::string::npos) {
        if (auto msg = m.instantiate<nav_msgs::Odometry>()) truth.push_back(ToPose(*msg));
      } else if (topic.size() >= 4 && topic.compare(topic.size() - 4, 4, "odom") == 0) {
        if (auto msg = m.instantiate<nav_msgs::Odometry>()) odom.push_back(ToPose(*msg));
      } else if (topic.find("corridor_width") != std::string::npos) {
        if (auto msg = m.instantiate<std_msgs::Float32>()) widths.push_back(msg->data);
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
    std::cout << "report written to " << out_dir << "/report.md (driven " << driven << " m, odometry error "
              << dl::Norm(end_error.Position()) << " m)\n";
  } catch (const std::exception& e) {
    std::cerr << "doorplate_run_report: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
