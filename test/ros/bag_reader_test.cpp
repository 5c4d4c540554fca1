#include "bag_reader.h"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <tf2_msgs/TFMessage.h>

#include "doorplate_localization/TextDetectionArray.h"

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

// The bag at `path` with the first `pattern` in it replaced by `replacement` (same length).
void PatchBag(const std::string& path, const std::string& pattern, const std::string& replacement) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = bytes.find(pattern);
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at, replacement.size(), replacement);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

std::string Le32(std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); }

// The layout read from T's definition text agrees with roscpp's serializer: an empty T is MinBytes long, a
// filled one passes, and the same bytes cut by one do not.
template <class T>
void ExpectLayoutMatchesRoscpp(const T& filled) {
  const MessageLayout layout(ros::message_traits::DataType<T>::value(), ros::message_traits::Definition<T>::value());
  EXPECT_EQ(layout.MinBytes(), ros::serialization::serializationLength(T())) << ros::message_traits::DataType<T>::value();
  std::vector<std::uint8_t> bytes(ros::serialization::serializationLength(filled));
  ros::serialization::OStream out(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  ros::serialization::serialize(out, filled);
  EXPECT_EQ(layout.Check(bytes.data(), bytes.size()), "") << ros::message_traits::DataType<T>::value();
  EXPECT_NE(layout.Check(bytes.data(), bytes.size() - 1), "") << ros::message_traits::DataType<T>::value();
}

TEST(InstantiateCheckedTest, EveryTypeTheToolsReadHasTheLayoutRoscppSerializes) {
  tf2_msgs::TFMessage tf;
  tf.transforms.resize(2);
  tf.transforms[1].child_frame_id = "laser";
  ExpectLayoutMatchesRoscpp(tf);
  ExpectLayoutMatchesRoscpp(Scan(3.0));
  nav_msgs::Odometry odom;
  odom.child_frame_id = "base_link";
  ExpectLayoutMatchesRoscpp(odom);
  geometry_msgs::PoseWithCovarianceStamped pose;
  pose.header.frame_id = "map";
  ExpectLayoutMatchesRoscpp(pose);
  std_msgs::String text;
  text.data = "E14-295";
  ExpectLayoutMatchesRoscpp(text);
  TextDetectionArray detections;
  detections.detections.resize(2);
  detections.detections[0].text = "3.21";
  ExpectLayoutMatchesRoscpp(detections);
}

TEST(InstantiateCheckedTest, ReadsWhatInstantiateReadsAndNullForAnotherType) {
  const std::string path = TempBag("checked");
  { rosbag::Bag(path, rosbag::bagmode::Write).write("/scan", ros::Time(1.0), Scan(1.0)); }
  int visited = 0;
  ReadBag(path, {}, [&visited](const rosbag::MessageInstance& m, const BagPosition&) {
    ++visited;
    const auto scan = InstantiateChecked<sensor_msgs::LaserScan>(m);
    ASSERT_TRUE(scan);
    EXPECT_EQ(*scan, *m.instantiate<sensor_msgs::LaserScan>());
    EXPECT_FALSE(InstantiateChecked<std_msgs::String>(m));
  });
  EXPECT_EQ(visited, 1);
}

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

// A bag header naming an encryptor plugin that is not installed: rosbag's open() lets pluginlib's exception
// through; the error names the bag and says what its header asks for.
TEST(ReadBagTest, AHeaderNamingAnEncryptorThatIsNotInstalledIsAnErrorNamingTheBag) {
  const std::string path = TempBag("encryptor");
  { rosbag::Bag(path, rosbag::bagmode::Write).write("/scan", ros::Time(1.0), Scan(1.0)); }
  // The header record (after the 13-byte version line) is padded to 4096 bytes: the field goes into the
  // header, and as many padding bytes come out of the data.
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string field = "encryptor=nope";
  const std::string entry = Le32(static_cast<std::uint32_t>(field.size())) + field;
  std::uint32_t header_length = 0, data_length = 0;
  std::memcpy(&header_length, &bytes[13], 4);
  std::memcpy(&data_length, &bytes[17 + header_length], 4);
  ASSERT_GT(data_length, entry.size());
  bytes = bytes.substr(0, 13) + Le32(header_length + static_cast<std::uint32_t>(entry.size())) +
          bytes.substr(17, header_length) + entry + Le32(data_length - static_cast<std::uint32_t>(entry.size())) +
          bytes.substr(21 + header_length + entry.size());
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  const std::string what = What([&] { ReadBag(path, {"/scan"}, kIgnore); });
  EXPECT_NE(what.find("bag_reader_encryptor.bag: not a readable bag: its header names an encryptor plugin that "
                      "cannot be loaded: "),
            std::string::npos)
      << what;
  EXPECT_NE(what.find("nope"), std::string::npos) << what;
}

// A scan whose ranges' length prefix says 1000 of the 3 floats there: refused before roscpp reads it.
TEST(ReadBagTest, AMessageThatDoesNotDeserializeIsAnErrorNamingTheBagTopicAndField) {
  const std::string path = TempBag("overrun");
  { rosbag::Bag(path, rosbag::bagmode::Write).write("/scan", ros::Time(1.0), Scan(1.0)); }
  const float ranges[] = {1.25f, 2.5f, 3.75f};
  PatchBag(path, Le32(3) + std::string(reinterpret_cast<const char*>(ranges), sizeof(ranges)), Le32(1000));
  int visited = 0;
  const std::string what = What([&] {
    ReadBag(path, {"/scan"}, [&visited](const rosbag::MessageInstance& m, const BagPosition&) {
      ++visited;
      InstantiateChecked<sensor_msgs::LaserScan>(m);
    });
  });
  EXPECT_EQ(visited, 1);
  EXPECT_NE(what.find("bag_reader_overrun.bag: not a readable bag: topic /scan, message at 1.000 s: "
                      "sensor_msgs/LaserScan.ranges: 1000 elements of at least 4 bytes, but 16 bytes follow"),
            std::string::npos)
      << what;
}

// The fuzzer's find (CI, issue 18): a TFMessage whose transforms count says 2^32 - 2; roscpp resized the vector
// to that (583 GB) before reading a byte, and ASan's allocator ended the tool.
TEST(ReadBagTfTest, ATransformCountBeyondTheMessageIsAnErrorNotAnAllocation) {
  const std::string path = TempBag("tf_count");
  {
    tf2_msgs::TFMessage msg;
    msg.transforms.resize(1);
    msg.transforms[0].header.frame_id = "odom";
    msg.transforms[0].child_frame_id = "base_link";
    msg.transforms[0].transform.rotation.w = 1.0;
    rosbag::Bag(path, rosbag::bagmode::Write).write("/tf", ros::Time(100.0), msg);
  }
  PatchBag(path, Le32(1) + Le32(0) + Le32(0) + Le32(0) + Le32(4) + "odom", Le32(4294967294u));
  const std::string what = What([&] { ReadBagTf(path); });
  EXPECT_NE(what.find("bag_reader_tf_count.bag: not a readable bag: topic /tf, message at 100.000 s: "
                      "tf2_msgs/TFMessage.transforms: 4294967294 elements of at least 76 bytes"),
            std::string::npos)
      << what;
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
