#include "json_writer.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace doorplate_localization {

JsonWriter::JsonWriter(std::ostream* out) : out_(out) {
  if (out_ == nullptr) throw std::invalid_argument("JsonWriter: null stream");
}

std::string JsonWriter::Quote(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        quoted += "\\\"";
        break;
      case '\\':
        quoted += "\\\\";
        break;
      case '\n':
        quoted += "\\n";
        break;
      case '\t':
        quoted += "\\t";
        break;
      case '\r':
        quoted += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escape[8];
          std::snprintf(escape, sizeof(escape), "\\u%04x", static_cast<unsigned>(c));
          quoted += escape;
        } else {
          quoted += c;  // UTF-8 bytes pass through unchanged
        }
    }
  }
  return quoted + "\"";
}

void JsonWriter::NewLine() { *out_ << '\n' << std::string(2 * stack_.size(), ' '); }

void JsonWriter::BeforeValue() {
  if (stack_.empty()) {
    if (wrote_top_level_) throw std::logic_error("JsonWriter: a second top-level value");
    return;
  }
  Level& level = stack_.back();
  if (level.scope == Scope::kObject) {
    if (!level.key_pending) throw std::logic_error("JsonWriter: a value inside an object needs a Key first");
    level.key_pending = false;
    return;  // Key already wrote the separator
  }
  if (level.count++ > 0) *out_ << ',';
  NewLine();
}

void JsonWriter::Raw(const std::string& text) {
  BeforeValue();
  *out_ << text;
  if (stack_.empty()) wrote_top_level_ = true;
}

JsonWriter& JsonWriter::Key(const std::string& key) {
  if (stack_.empty() || stack_.back().scope != Scope::kObject) {
    throw std::logic_error("JsonWriter: Key('" + key + "') outside an object");
  }
  Level& level = stack_.back();
  if (level.key_pending) throw std::logic_error("JsonWriter: Key('" + key + "') after a key without value");
  if (level.count++ > 0) *out_ << ',';
  NewLine();
  *out_ << Quote(key) << ": ";
  level.key_pending = true;
  return *this;
}

JsonWriter& JsonWriter::BeginObject() {
  Raw("{");
  stack_.push_back({Scope::kObject});
  return *this;
}

JsonWriter& JsonWriter::BeginArray() {
  Raw("[");
  stack_.push_back({Scope::kArray});
  return *this;
}

JsonWriter& JsonWriter::EndObject() {
  if (stack_.empty() || stack_.back().scope != Scope::kObject || stack_.back().key_pending) {
    throw std::logic_error("JsonWriter: EndObject without an open object (or after a dangling key)");
  }
  const bool empty = stack_.back().count == 0;
  stack_.pop_back();
  if (!empty) NewLine();
  *out_ << '}';
  if (stack_.empty()) *out_ << '\n';
  return *this;
}

JsonWriter& JsonWriter::EndArray() {
  if (stack_.empty() || stack_.back().scope != Scope::kArray) {
    throw std::logic_error("JsonWriter: EndArray without an open array");
  }
  const bool empty = stack_.back().count == 0;
  stack_.pop_back();
  if (!empty) NewLine();
  *out_ << ']';
  if (stack_.empty()) *out_ << '\n';
  return *this;
}

JsonWriter& JsonWriter::Value(const std::string& value) {
  Raw(Quote(value));
  return *this;
}
JsonWriter& JsonWriter::Value(const char* value) { return Value(std::string(value)); }
JsonWriter& JsonWriter::Value(bool value) {
  Raw(value ? "true" : "false");
  return *this;
}
JsonWriter& JsonWriter::Value(int value) {
  Raw(std::to_string(value));
  return *this;
}
JsonWriter& JsonWriter::Value(std::int64_t value) {
  Raw(std::to_string(value));
  return *this;
}
JsonWriter& JsonWriter::Value(std::uint64_t value) {
  Raw(std::to_string(value));
  return *this;
}
JsonWriter& JsonWriter::Value(double value) {
  if (!std::isfinite(value)) return Null();
  char text[32];
  std::snprintf(text, sizeof(text), "%.10g", value);
  Raw(text);
  return *this;
}
JsonWriter& JsonWriter::Null() {
  Raw("null");
  return *this;
}

}  // namespace doorplate_localization
