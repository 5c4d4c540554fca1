// A small streaming JSON writer for the experiment results (RFC 8259 output, two-space indentation).
// Misuse (a value where a key is due, unbalanced End*) throws std::logic_error: results files are never
// written half-formed.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace doorplate_localization {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream* out);

  JsonWriter& BeginObject();
  JsonWriter& EndObject();
  JsonWriter& BeginArray();
  JsonWriter& EndArray();
  // The next member's name; only inside an object, before its value.
  JsonWriter& Key(const std::string& key);

  JsonWriter& Value(const std::string& value);
  JsonWriter& Value(const char* value);
  JsonWriter& Value(bool value);
  JsonWriter& Value(int value);
  JsonWriter& Value(std::int64_t value);
  JsonWriter& Value(std::uint64_t value);
  // Up to 10 significant digits; NaN and ±inf (no JSON form) are written as null.
  JsonWriter& Value(double value);
  JsonWriter& Null();

  // Key(key).Value(value).
  template <typename T>
  JsonWriter& Field(const std::string& key, const T& value) {
    return Key(key).Value(value);
  }

  // True once one top-level value has been completely written.
  bool complete() const { return stack_.empty() && wrote_top_level_; }

  // The JSON string literal for `text` (quotes included; control characters escaped as \uXXXX).
  static std::string Quote(const std::string& text);

 private:
  enum class Scope { kObject, kArray };
  struct Level {
    Scope scope;
    int count = 0;          // members or elements written so far
    bool key_pending = false;
  };
  void BeforeValue();
  void Raw(const std::string& text);
  void NewLine();

  std::ostream* out_;
  std::vector<Level> stack_;
  bool wrote_top_level_ = false;
};

}  // namespace doorplate_localization
