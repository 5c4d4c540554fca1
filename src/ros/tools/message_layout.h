// The wire layout of a ROS 1 message type, read from its full definition text, and a check of serialized bytes
// against it before roscpp deserializes them. roscpp's deserializer (ros/serialization.h, VectorSerializer)
// resizes a vector to what its length prefix says before it checks that the bytes hold that many elements: a
// bag whose tf2_msgs/TFMessage claimed 2^32 - 2 transforms made the bag tools ask for 583 GB
// (fuzz/bag_reader_fuzz.cpp). The check bounds every length prefix by the bytes that follow it, so a message that
// passes deserializes with allocations no larger than a small multiple of its own size.
//
// The definition text is what ros::message_traits::Definition<T>::value() gives (and what a bag's connection
// header stores as message_definition): the type's own fields, then for every type it uses a separator line of
// '=' and "MSG: <package>/<Type>" followed by that type's fields. Comments (#) and constants (`type NAME=value`)
// are skipped; `Header` is std_msgs/Header; an unqualified type name is in the package of the type using it.
// The serialization: http://wiki.ros.org/msg#Serialization (little-endian; a string or variable-length
// array is a uint32 count and its elements; a fixed-length array `T[N]` only its N elements).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace doorplate_localization {

class MessageLayout {
 public:
  // Parses `definition` of the type `datatype` ("tf2_msgs/TFMessage"). Throws std::invalid_argument naming the
  // type and the field for a field type that is neither a ROS primitive nor defined in the text, or a malformed
  // array length.
  MessageLayout(const std::string& datatype, const std::string& definition);

  // "" when bytes[0, size) hold a message of this type: every string's and variable-length array's count fits
  // in the bytes that follow it (each element counted at its smallest serialized size) and no field runs past
  // `size`; else the first problem, e.g. "tf2_msgs/TFMessage.transforms: 4294967294 elements of at least 57
  // bytes, but 12 bytes follow". Bytes after the message are allowed, as roscpp allows them.
  std::string Check(const std::uint8_t* bytes, std::size_t size) const;

  // The smallest serialized size of a message of this type, in bytes (every string and variable array empty).
  std::size_t MinBytes() const { return types_.front().min_bytes; }

 private:
  enum class Kind { kFixed, kString, kMessage };
  struct Field {
    std::string name;
    Kind kind = Kind::kFixed;
    std::size_t fixed_bytes = 0;  // kFixed: the primitive's size
    std::size_t message = 0;      // kMessage: index in types_
    bool is_array = false;
    bool fixed_length = false;     // T[N]
    std::uint32_t length = 0;      // N
    std::string type_name;         // as resolved, until linked
  };
  struct Type {
    std::string name;
    std::vector<Field> fields;
    std::size_t min_bytes = 0;
  };

  std::size_t ElementMinBytes(const Field& field) const;
  std::size_t ComputeMinBytes(std::size_t type, int depth);
  // Walks one message of types_[type] from *at; "" or the problem.
  std::string Walk(std::size_t type, const std::uint8_t* bytes, std::size_t size, std::size_t* at) const;

  std::vector<Type> types_;  // [0]: the message's own type
};

}  // namespace doorplate_localization
