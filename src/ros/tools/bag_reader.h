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

#include <rosbag/message_instance.h>
#include <tf2/buffer_core.h>

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

// Every transform on /tf and /tf_static (either spelling) of the bag, kept for the bag's whole span plus 60 s,
// so a transform recorded after a message still serves it. A malformed transform is logged by tf2 and
// skipped. Throws BagReadError as ReadBag.
std::unique_ptr<tf2::BufferCore> ReadBagTf(const std::string& path);

}  // namespace doorplate_localization
