#include "message_layout.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace doorplate_localization {
namespace {

// tf2_msgs/TFMessage's definition as roscpp's message traits give it (comments shortened).
const char* const kTfDefinition =
    "geometry_msgs/TransformStamped[] transforms\n"
    "\n"
    "================================================================================\n"
    "MSG: geometry_msgs/TransformStamped\n"
    "# This expresses a transform from coordinate frame header.frame_id\n"
    "Header header\n"
    "string child_frame_id # the frame id of the child frame\n"
    "Transform transform\n"
    "\n"
    "================================================================================\n"
    "MSG: std_msgs/Header\n"
    "uint32 seq\n"
    "time stamp\n"
    "string frame_id\n"
    "\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Transform\n"
    "Vector3 translation\n"
    "Quaternion rotation\n"
    "\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Vector3\n"
    "float64 x\nfloat64 y\nfloat64 z\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Quaternion\n"
    "float64 x\nfloat64 y\nfloat64 z\nfloat64 w\n";

// A serialized message built field by field (little-endian, as on the wire).
struct Bytes {
  std::vector<std::uint8_t> data;
  template <typename T>
  Bytes& Add(T value) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    data.insert(data.end(), p, p + sizeof(T));
    return *this;
  }
  Bytes& AddString(const std::string& s) {
    Add<std::uint32_t>(static_cast<std::uint32_t>(s.size()));
    data.insert(data.end(), s.begin(), s.end());
    return *this;
  }
  Bytes& AddTransform(const std::string& parent, const std::string& child) {
    Add<std::uint32_t>(7).Add<std::uint32_t>(100).Add<std::uint32_t>(0).AddString(parent).AddString(child);
    for (int i = 0; i < 7; ++i) Add<double>(i == 6 ? 1.0 : 0.5);
    return *this;
  }
  std::string Check(const MessageLayout& layout) const { return layout.Check(data.data(), data.size()); }
};

TEST(MessageLayoutTest, SmallestSizeCountsEveryFixedFieldAndEmptyStringsAndArrays) {
  EXPECT_EQ(MessageLayout("tf2_msgs/TFMessage", kTfDefinition).MinBytes(), 4u);
  // A transform: header (4 + 8 + 4) + child_frame_id (4) + 7 float64.
  const std::string stamped = std::string(kTfDefinition).substr(std::string(kTfDefinition).find("MSG: geometry_msgs/T"));
  EXPECT_EQ(MessageLayout("geometry_msgs/TransformStamped", stamped.substr(stamped.find('\n') + 1)).MinBytes(),
            16u + 4u + 56u);
  EXPECT_EQ(MessageLayout("x/Cov", "float64[36] covariance\nuint8[] data\n").MinBytes(), 288u + 4u);
}

TEST(MessageLayoutTest, AcceptsAWellFormedMessageAndBytesAfterIt) {
  const MessageLayout layout("tf2_msgs/TFMessage", kTfDefinition);
  Bytes two;
  two.Add<std::uint32_t>(2).AddTransform("odom", "base_link").AddTransform("base_link", "laser");
  EXPECT_EQ(two.Check(layout), "");
  two.Add<std::uint8_t>(9);
  EXPECT_EQ(two.Check(layout), "");
  EXPECT_EQ(Bytes().Add<std::uint32_t>(0).Check(layout), "");
}

// The fuzzer's find: a TFMessage claiming 2^32 - 2 transforms, which roscpp allocates (583 GB) before reading.
TEST(MessageLayoutTest, RefusesAnArrayCountBeyondTheBytesThatFollow) {
  const MessageLayout layout("tf2_msgs/TFMessage", kTfDefinition);
  Bytes huge;
  huge.Add<std::uint32_t>(4294967294u).AddTransform("odom", "base_link");
  EXPECT_EQ(huge.Check(layout), "tf2_msgs/TFMessage.transforms: 4294967294 elements of at least 76 bytes, but " +
                                    std::to_string(huge.data.size() - 4) + " bytes follow");
  Bytes two_of_one;
  two_of_one.Add<std::uint32_t>(2).AddTransform("odom", "base_link");
  EXPECT_NE(two_of_one.Check(layout), "");  // the second transform's fields run past the end
}

TEST(MessageLayoutTest, RefusesAStringOrFieldRunningPastTheEnd) {
  const MessageLayout layout("tf2_msgs/TFMessage", kTfDefinition);
  Bytes long_string;
  long_string.Add<std::uint32_t>(1).Add<std::uint32_t>(7).Add<std::uint64_t>(0).Add<std::uint32_t>(1u << 30);
  for (int i = 0; i < 80; ++i) long_string.Add<std::uint8_t>(0);
  EXPECT_EQ(long_string.Check(layout), "std_msgs/Header.frame_id: a string of 1073741824 bytes, but 80 bytes follow");
  Bytes cut;
  cut.Add<std::uint32_t>(1).AddTransform("odom", "base_link");
  cut.data.resize(cut.data.size() - 1);
  EXPECT_EQ(cut.Check(layout), "geometry_msgs/TransformStamped.transform: needs 56 bytes, but 55 bytes follow");
  EXPECT_EQ(Bytes().Check(layout), "tf2_msgs/TFMessage.transforms: its element count runs past the message's 0 bytes");
}

TEST(MessageLayoutTest, SkipsCommentsAndConstantsAndResolvesTypeNamesInThePackage) {
  const MessageLayout layout("pkg/Outer",
                             "int32 FOO=3\n"
                             "string BAR = a # not a comment in a constant\n"
                             "Inner inner  # pkg/Inner\n"
                             "uint8 flag\n"
                             "=====\n"
                             "MSG: pkg/Inner\n"
                             "byte[2] pair\n");
  EXPECT_EQ(layout.MinBytes(), 3u);
  EXPECT_EQ(Bytes().Add<std::uint8_t>(1).Add<std::uint8_t>(2).Add<std::uint8_t>(3).Check(layout), "");
  EXPECT_EQ(Bytes().Add<std::uint8_t>(1).Add<std::uint8_t>(2).Check(layout), "pkg/Outer.flag: needs 1 bytes, but 0 bytes follow");
}

TEST(MessageLayoutTest, CapsArraysOfElementsWithoutBytes) {
  const MessageLayout layout("pkg/Many", "std_msgs/Empty[] nothing\n=====\nMSG: std_msgs/Empty\n");
  EXPECT_EQ(Bytes().Add<std::uint32_t>(1000).Check(layout), "");
  EXPECT_NE(Bytes().Add<std::uint32_t>(1u << 20).Check(layout), "");
}

TEST(MessageLayoutTest, ADefinitionMissingAUsedTypeOrWithABadArrayIsAnError) {
  try {
    MessageLayout("pkg/A", "Missing m\n");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "pkg/A.m: type pkg/Missing is not defined in the definition of pkg/A");
  }
  EXPECT_THROW(MessageLayout("pkg/A", "uint8[x] m\n"), std::invalid_argument);
  EXPECT_THROW(MessageLayout("pkg/A", "uint8\n"), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization
