#include "bag_reader.h"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <tf2_msgs/TFMessage.h>

namespace doorplate_localization {
namespace {

std::string TempBag(const std::string& name) { return ::testing::TempDir() + "/bag_reader_" + name + ".bag"; }

sensor_msgs::LaserScan Scan(double stamp_s) {
  sensor_msgs::LaserScan scan;
  scan.header.stamp = ros::Time(stamp_s);
  scan.header.frame_id = "laser";
  scan.angle_increment = 0.1f;
  scan.range_max = 10.0f;
  scan.ranges = {1.25f, 2.5f, 3.75f};
  return scan;
}

std::string What(const std::function<void()>& read) {
  try {
    read();
  } catch (const BagReadError& e) {
    return e.what();
  }
  return "no BagReadError";
}

const auto kIgnore = [](const rosbag::MessageInstance&, const BagPosition&) {};

TEST(ReadBagTest, VisitsTheTopicsMessagesInTimeOrderUnderEitherSpelling) {
  const std::string path = TempBag("topics");
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    bag.write("/scan", ros::Time(12.0), Scan(12.0));
    bag.write("scan", ros::Time(11.0), Scan(11.0));  // recorded without the leading slash
    std_msgs::String other;
    other.data = "x";
    bag.write("/other", ros::Time(11.5), other);
  }
  std::vector<double> stamps;
  std::vector<BagPosition> positions;
  ReadBag(path, {"/scan"}, [&](const rosbag::MessageInstance& m, const BagPosition& at) {
    stamps.push_back(m.instantiate<sensor_msgs::LaserScan>()->header.stamp.toSec());
    positions.push_back(at);
  });
  EXPECT_EQ(stamps, (std::vector<double>{11.0, 12.0}));
  ASSERT_EQ(positions.size(), 2u);
  EXPECT_EQ(positions[1].index, 1u);
  EXPECT_EQ(positions[1].total, 2u);
  int all = 0;
  ReadBag(path, {}, [&all](const rosbag::MessageInstance&, const BagPosition&) { ++all; });
  EXPECT_EQ(all, 3);
}

TEST(ReadBagTest, NamesTheBagItCannotOpenOrRead) {
  EXPECT_NE(What([] { ReadBag(TempBag("missing"), {}, kIgnore); }).find("bag_reader_missing.bag: not a readable bag: "),
            std::string::npos);
  const std::string garbage = TempBag("garbage");
  std::ofstream(garbage) << "no bag at all\n";
  const std::string what = What([&] { ReadBagTf(garbage); });
  EXPECT_NE(what.find("bag_reader_garbage.bag: not a readable bag: Error reading version line"), std::string::npos) << what;
}

// A scan whose ranges' length prefix says 1000 of the 3 floats there: roscpp's deserializer overruns its buffer.
TEST(ReadBagTest, AMessageThatDoesNotDeserializeIsAnErrorNamingTheBag) {
  const std::string path = TempBag("overrun");
  { rosbag::Bag(path, rosbag::bagmode::Write).write("/scan", ros::Time(1.0), Scan(1.0)); }
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const float ranges[] = {1.25f, 2.5f, 3.75f};
  std::string pattern("\x03\x00\x00\x00", 4);
  pattern.append(reinterpret_cast<const char*>(ranges), sizeof(ranges));
  const std::size_t at = bytes.find(pattern);
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at, 4, std::string("\xe8\x03\x00\x00", 4));  // 1000
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  int visited = 0;
  const std::string what = What([&] {
    ReadBag(path, {"/scan"}, [&visited](const rosbag::MessageInstance& m, const BagPosition&) {
      ++visited;
      m.instantiate<sensor_msgs::LaserScan>();
    });
  });
  EXPECT_EQ(visited, 1);
  EXPECT_NE(what.find("bag_reader_overrun.bag: not a readable bag: "), std::string::npos) << what;
}

TEST(ReadBagTfTest, KeepsEveryTransformOfTheBagAndTheStaticOnes) {
  const std::string path = TempBag("tf");
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    for (int i = 0; i <= 1; ++i) {
      tf2_msgs::TFMessage msg;
      msg.transforms.resize(1);
      msg.transforms[0].header.stamp = ros::Time(100.0 + 50.0 * i);  // 50 s apart: beyond tf2's default 10 s
      msg.transforms[0].header.frame_id = "odom";
      msg.transforms[0].child_frame_id = "base_link";
      msg.transforms[0].transform.translation.x = 2.0 * i;
      msg.transforms[0].transform.rotation.w = 1.0;
      bag.write("/tf", msg.transforms[0].header.stamp, msg);
    }
    tf2_msgs::TFMessage laser;
    laser.transforms.resize(1);
    laser.transforms[0].header.frame_id = "base_link";
    laser.transforms[0].child_frame_id = "laser";
    laser.transforms[0].transform.translation.z = 0.3;
    laser.transforms[0].transform.rotation.w = 1.0;
    bag.write("tf_static", ros::Time(100.0), laser);
  }
  const auto tf = ReadBagTf(path);
  const auto t = tf->lookupTransform("odom", "laser", ros::Time(125.0)).transform;
  EXPECT_DOUBLE_EQ(t.translation.x, 1.0);  // interpolated between the two odometry transforms
  EXPECT_DOUBLE_EQ(t.translation.z, 0.3);
}

// The fuzzer's find: stamps 4e9 s apart (ros::Time holds them, a ros::Duration does not) made ReadBagTf throw
// rosbag's std::runtime_error "Duration is out of dual 32-bit range", unnamed and uncaught.
TEST(ReadBagTfTest, ReadsABagWhoseStampsSpanMoreThanADurationHolds) {
  const std::string path = TempBag("span");
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    bag.write("/scan", ros::Time(1.0), Scan(1.0));
    bag.write("/scan", ros::Time(4e9), Scan(4e9));
  }
  EXPECT_NO_THROW(ReadBagTf(path));
}

}  // namespace
}  // namespace doorplate_localization
