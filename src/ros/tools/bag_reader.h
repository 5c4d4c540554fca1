// Reading a rosbag for the offline tools (doorplate_map_bag, doorplate_mission_report): the messages of some
// topics in time order and the bag's tf. Every error of rosbag's reader and of roscpp's deserializer while
// reading (a corrupt header, chunk or index, a message that does not deserialize, a length prefix asking for
// more memory than there is) becomes one BagReadError naming the bag. The file's record structure is checked
// first (bag_structure.h), as rosbag allocates what its length fields say.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/make_shared.hpp>
#include <ros/serialization.h>
#include <rosbag/message_instance.h>
#include <tf2/buffer_core.h>

#include "message_layout.h"

namespace doorplate_localization {

// "<bag>: not a readable bag: <rosbag's message>" or "<bag>: <what is missing>".
class BagReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where a message is in the read: its index (0-based) among `total` messages of the topics.
struct BagPosition {
  std::size_t index = 0;
  std::size_t total = 0;
};

// Calls visit(message, position) for every message of the bag at `path` on one of `topics`, in time order
// (all topics when `topics` is empty). A topic matches as given ("/scan") and without its leading slash
// ("scan", as some recorders store it). Throws BagReadError "<path>: not a readable bag: ..." when the bag
// cannot be opened or read, or a message instantiated inside `visit` cannot be deserialized; other
// exceptions of `visit` pass unchanged.
void ReadBag(const std::string& path, const std::vector<std::string>& topics,
             const std::function<void(const rosbag::MessageInstance&, const BagPosition&)>& visit);

// The serialized bytes of `m`, checked against `layout` (MessageLayout::Check). Throws
// ros::serialization::StreamOverrunException "topic <topic>, message at <t> s: <problem>" when they fail it.
std::vector<std::uint8_t> CheckedMessageBytes(const rosbag::MessageInstance& m, const MessageLayout& layout);

// `m` as a T, or null when it is not a T (as rosbag's MessageInstance::instantiate<T>). Unlike instantiate, the
// bytes are checked against T's layout before roscpp deserializes them, so a length prefix beyond the message's
// bytes (a corrupt or crafted bag) is an error, not an allocation of what it says (up to hundreds of GB). Inside
// ReadBag's `visit` the error becomes a BagReadError naming the bag, the topic and the field. Every message the
// bag tools read is read with this.
template <class T>
boost::shared_ptr<T> InstantiateChecked(const rosbag::MessageInstance& m) {
  if (!m.isType<T>()) return nullptr;
  static const MessageLayout layout(ros::message_traits::DataType<T>::value(),
                                    ros::message_traits::Definition<T>::value());
  std::vector<std::uint8_t> bytes = CheckedMessageBytes(m, layout);
  auto msg = boost::make_shared<T>();
  ros::serialization::IStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  ros::serialization::deserialize(stream, *msg);
  return msg;
}

// Every transform on /tf and /tf_static (either spelling) of the bag, kept for the bag's whole span plus 60 s,
// so a transform recorded after a message still serves it. A malformed transform is logged by tf2 and
// skipped. Throws BagReadError as ReadBag.
std::unique_ptr<tf2::BufferCore> ReadBagTf(const std::string& path);

}  // namespace doorplate_localization
