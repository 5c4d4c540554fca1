#include "bag_reader.h"

#include <algorithm>
#include <iomanip>
#include <new>
#include <sstream>

#include <pluginlib/exceptions.hpp>
#include <ros/exception.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2_msgs/TFMessage.h>

#include "bag_structure.h"

namespace doorplate_localization {
namespace {

std::vector<std::string> BothSpellings(const std::vector<std::string>& topics) {
  std::vector<std::string> both;
  for (const std::string& t : topics) {
    both.push_back(t);
    if (!t.empty() && t[0] == '/') both.push_back(t.substr(1));
    else both.push_back("/" + t);
  }
  return both;
}

// Runs `read` on the opened bag; rosbag's and the deserializer's errors become BagReadError naming `path`.
void WithBag(const std::string& path, const std::function<void(rosbag::Bag&)>& read) {
  const auto error = [&path](const std::string& what) { return BagReadError(path + ": not a readable bag: " + what); };
  // rosbag allocates what the file's lengths say before it checks them: they are checked first.
  const std::string structure_problem = CheckBagStructure(path);
  if (!structure_problem.empty()) throw error(structure_problem);
  try {
    // Opened after construction: when open() throws, ~Bag still frees the connections read so far (rosbag's
    // constructor that opens leaks them: fuzz/bag_reader_fuzz.cpp, LeakSanitizer).
    rosbag::Bag bag;
    try {
      bag.open(path, rosbag::bagmode::Read);
    } catch (const pluginlib::PluginlibException& e) {  // the header's `encryptor` names a plugin not installed
      throw error(std::string("its header names an encryptor plugin that cannot be loaded: ") + e.what());
    }
    read(bag);
  } catch (const ros::Exception& e) {  // rosbag::BagException and its kin, ros::serialization's overruns
    throw error(e.what());
  } catch (const std::bad_alloc&) {  // a length prefix in the file asked for more than there is
    throw error("a length in the file asks for more memory than there is (std::bad_alloc)");
  } catch (const std::length_error& e) {
    throw error(std::string("a length in the file is beyond what a vector holds (") + e.what() + ")");
  }
}

}  // namespace

std::vector<std::uint8_t> CheckedMessageBytes(const rosbag::MessageInstance& m, const MessageLayout& layout) {
  std::vector<std::uint8_t> bytes(m.size());
  ros::serialization::OStream out(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  m.write(out);
  const std::string problem = layout.Check(bytes.data(), bytes.size());
  if (!problem.empty()) {
    std::ostringstream what;
    what << "topic " << m.getTopic() << ", message at " << std::fixed << std::setprecision(3) << m.getTime().toSec()
         << " s: " << problem;
    throw ros::serialization::StreamOverrunException(what.str());
  }
  return bytes;
}

void ReadBag(const std::string& path, const std::vector<std::string>& topics,
             const std::function<void(const rosbag::MessageInstance&, const BagPosition&)>& visit) {
  WithBag(path, [&](rosbag::Bag& bag) {
    std::unique_ptr<rosbag::View> view = topics.empty()
        ? std::make_unique<rosbag::View>(bag)
        : std::make_unique<rosbag::View>(bag, rosbag::TopicQuery(BothSpellings(topics)));
    BagPosition position;
    position.total = view->size();
    for (const rosbag::MessageInstance& m : *view) {
      visit(m, position);
      ++position.index;
    }
  });
}

std::unique_ptr<tf2::BufferCore> ReadBagTf(const std::string& path) {
  std::unique_ptr<tf2::BufferCore> buffer;
  WithBag(path, [&](rosbag::Bag& bag) {
    rosbag::View all(bag);
    // In seconds, not ros::Time - ros::Time: stamps span up to 2^32 s, a ros::Duration 2^31 s (beyond it the
    // subtraction throws std::runtime_error; a fuzzing find). 1e9 s of cache keeps any bag's tf.
    const double span_s = all.size() == 0 ? 0.0 : all.getEndTime().toSec() - all.getBeginTime().toSec();
    buffer = std::make_unique<tf2::BufferCore>(ros::Duration(std::clamp(span_s + 60.0, 60.0, 1e9)));
    for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(BothSpellings({"/tf", "/tf_static"})))) {
      const auto msg = InstantiateChecked<tf2_msgs::TFMessage>(m);
      if (!msg) continue;
      const bool is_static = m.getTopic() == "/tf_static" || m.getTopic() == "tf_static";
      for (const geometry_msgs::TransformStamped& t : msg->transforms) buffer->setTransform(t, "bag", is_static);
    }
  });
  return buffer;
}

}  // namespace doorplate_localization
