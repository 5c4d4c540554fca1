#include "message_layout.h"

#include <cstring>
#include <map>
#include <sstream>
#include <stdexcept>

namespace doorplate_localization {
namespace {

// ROS nesting is a few levels deep (TFMessage: 4); deeper means a cycle in a malformed definition.
constexpr int kMaxDepth = 32;
// Elements of a type with no bytes at all (std_msgs/Empty[]) cannot be bounded by the bytes: a cap instead.
constexpr std::uint32_t kMaxEmptyElements = 1u << 16;

std::size_t PrimitiveBytes(const std::string& type) {
  static const std::map<std::string, std::size_t> kSizes = {
      {"bool", 1},    {"int8", 1},    {"uint8", 1},   {"byte", 1},    {"char", 1},    {"int16", 2},
      {"uint16", 2},  {"int32", 4},   {"uint32", 4},  {"int64", 8},   {"uint64", 8},  {"float32", 4},
      {"float64", 8}, {"time", 8},    {"duration", 8}};
  const auto it = kSizes.find(type);
  return it == kSizes.end() ? 0 : it->second;
}

std::string Trim(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::string PackageOf(const std::string& type) {
  const std::size_t slash = type.find('/');
  return slash == std::string::npos ? "" : type.substr(0, slash);
}

std::uint32_t ReadCount(const std::uint8_t* bytes) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes, 4);  // little-endian on the wire and on every host ROS 1 runs on
  return value;
}

}  // namespace

MessageLayout::MessageLayout(const std::string& datatype, const std::string& definition) {
  types_.push_back({datatype, {}, 0});
  std::istringstream lines(definition);
  std::string line;
  while (std::getline(lines, line)) {
    line = Trim(line.substr(0, line.find('#')));
    if (line.empty() || line.find_first_not_of('=') == std::string::npos) continue;
    if (line.rfind("MSG:", 0) == 0) {
      types_.push_back({Trim(line.substr(4)), {}, 0});
      continue;
    }
    const std::size_t type_end = line.find_first_of(" \t");
    if (type_end == std::string::npos) throw std::invalid_argument(types_.back().name + ": a line without a name: " + line);
    const std::string rest = Trim(line.substr(type_end));
    const std::size_t name_end = rest.find_first_of(" \t=");
    if (name_end != std::string::npos && Trim(rest.substr(name_end)).rfind('=', 0) == 0) continue;  // a constant
    Field field;
    field.name = rest.substr(0, name_end);
    std::string type = line.substr(0, type_end);
    const std::size_t bracket = type.find('[');
    if (bracket != std::string::npos) {
      field.is_array = true;
      const std::string length = type.substr(bracket + 1, type.size() - bracket - 2);
      if (type.back() != ']' || length.find_first_not_of("0123456789") != std::string::npos || length.size() > 9) {
        throw std::invalid_argument(types_.back().name + "." + field.name + ": malformed array type " + type);
      }
      field.fixed_length = !length.empty();
      field.length = field.fixed_length ? static_cast<std::uint32_t>(std::stoul(length)) : 0;
      type = type.substr(0, bracket);
    }
    if (type == "string") {
      field.kind = Kind::kString;
    } else if ((field.fixed_bytes = PrimitiveBytes(type)) > 0) {
      field.kind = Kind::kFixed;
    } else {
      field.kind = Kind::kMessage;
      if (type == "Header") type = "std_msgs/Header";
      else if (type.find('/') == std::string::npos) type = PackageOf(types_.back().name) + "/" + type;
    }
    field.type_name = type;
    types_.back().fields.push_back(field);
  }
  for (Type& owner : types_) {
    for (Field& field : owner.fields) {
      if (field.kind != Kind::kMessage) continue;
      std::size_t i = 0;
      while (i < types_.size() && types_[i].name != field.type_name) ++i;
      if (i == types_.size()) {
        throw std::invalid_argument(owner.name + "." + field.name + ": type " + field.type_name +
                                    " is not defined in the definition of " + datatype);
      }
      field.message = i;
    }
  }
  for (std::size_t t = types_.size(); t-- > 0;) ComputeMinBytes(t, 0);
}

std::size_t MessageLayout::ElementMinBytes(const Field& field) const {
  switch (field.kind) {
    case Kind::kFixed: return field.fixed_bytes;
    case Kind::kString: return 4;
    case Kind::kMessage: return types_[field.message].min_bytes;
  }
  return 0;
}

std::size_t MessageLayout::ComputeMinBytes(std::size_t type, int depth) {
  if (depth > kMaxDepth) throw std::invalid_argument(types_[type].name + ": its fields nest too deep (a cycle?)");
  std::size_t total = 0;
  for (const Field& field : types_[type].fields) {
    if (field.kind == Kind::kMessage) ComputeMinBytes(field.message, depth + 1);
    if (field.is_array && !field.fixed_length) total += 4;
    else total += ElementMinBytes(field) * (field.is_array ? field.length : 1);
  }
  types_[type].min_bytes = total;
  return total;
}

std::string MessageLayout::Walk(std::size_t type, const std::uint8_t* bytes, std::size_t size,
                                std::size_t* at) const {
  for (const Field& field : types_[type].fields) {
    const std::string where = types_[type].name + "." + field.name;
    std::uint32_t count = 1;
    if (field.is_array && field.fixed_length) {
      count = field.length;
    } else if (field.is_array) {
      if (size - *at < 4) return where + ": its element count runs past the message's " + std::to_string(size) + " bytes";
      count = ReadCount(bytes + *at);
      *at += 4;
    }
    const std::size_t element_bytes = ElementMinBytes(field);
    const std::size_t left = size - *at;
    if (!field.is_array && element_bytes > left) {
      return where + ": needs " + std::to_string(element_bytes) + " bytes, but " + std::to_string(left) + " bytes follow";
    }
    if (element_bytes == 0 ? count > kMaxEmptyElements : count > left / element_bytes) {
      return where + ": " + std::to_string(count) + " elements of at least " + std::to_string(element_bytes) +
             " bytes, but " + std::to_string(left) + " bytes follow";
    }
    if (field.kind == Kind::kFixed) {
      *at += static_cast<std::size_t>(count) * element_bytes;
      continue;
    }
    for (std::uint32_t i = 0; i < count; ++i) {
      if (field.kind == Kind::kMessage) {
        const std::string problem = Walk(field.message, bytes, size, at);
        if (!problem.empty()) return problem;
        continue;
      }
      if (size - *at < 4) return where + ": a string's length runs past the message's " + std::to_string(size) + " bytes";
      const std::uint32_t length = ReadCount(bytes + *at);
      *at += 4;
      if (length > size - *at) {
        return where + ": a string of " + std::to_string(length) + " bytes, but " + std::to_string(size - *at) +
               " bytes follow";
      }
      *at += length;
    }
  }
  return "";
}

std::string MessageLayout::Check(const std::uint8_t* bytes, std::size_t size) const {
  std::size_t at = 0;
  return Walk(0, bytes, size, &at);
}

}  // namespace doorplate_localization
