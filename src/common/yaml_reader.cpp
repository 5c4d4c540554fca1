#include "doorplate_localization/common/yaml_reader.h"

#include <cmath>
#include <sstream>

namespace doorplate_localization {

YamlField YamlField::Parse(const std::string& text, const std::string& source) {
  try {
    YAML::Node root = YAML::Load(text);
    if (!root.IsMap()) throw YamlFieldError(source + ": top level must be a mapping of fields");
    return YamlField(root, source, "");
  } catch (const YAML::Exception& e) {  // ParserException and yaml-cpp's other load errors
    std::ostringstream out;
    out << source << ": line " << e.mark.line + 1 << ", column " << e.mark.column + 1 << ": " << e.msg;
    throw YamlFieldError(out.str());
  }
}

YamlField::YamlField(YAML::Node node, std::string source, std::string path)
    : node_(std::move(node)), source_(std::move(source)), path_(std::move(path)) {}

void YamlField::Fail(const std::string& problem) const {
  throw YamlFieldError(source_ + ": " + (path_.empty() ? "(top level)" : path_) + ": " + problem);
}

bool YamlField::Has(const std::string& key) const { return node_.IsMap() && node_[key].IsDefined(); }

YamlField YamlField::Child(const std::string& key) const {
  const std::string child_path = path_.empty() ? key : path_ + "." + key;
  if (!node_.IsMap()) Fail("must be a mapping");
  YAML::Node child = node_[key];
  if (!child.IsDefined() || child.IsNull()) {
    throw YamlFieldError(source_ + ": " + child_path + ": required field is missing");
  }
  return YamlField(child, source_, child_path);
}

std::vector<YamlField> YamlField::Items() const {
  if (!node_.IsSequence()) Fail("must be a list");
  std::vector<YamlField> items;
  for (size_t i = 0; i < node_.size(); ++i) {
    items.emplace_back(node_[i], source_, path_ + "[" + std::to_string(i) + "]");
  }
  return items;
}

void YamlField::RequireOnlyKeys(const std::set<std::string>& allowed) const {
  if (!node_.IsMap()) Fail("must be a mapping");
  for (const auto& kv : node_) {
    // A key that is a list or a mapping (`? [a, b]: 1`) is no field name of ours (found by fuzzing).
    if (!kv.first.IsScalar()) Fail("field names must be plain words, got a list or mapping as a key");
    const std::string key = kv.first.Scalar();
    if (allowed.count(key) == 0) {
      std::string list;
      for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
      Fail("unknown field '" + key + "' (allowed: " + list + ")");
    }
  }
}

double YamlField::AsDouble() const {
  double v = 0.0;
  try {
    if (!node_.IsScalar()) Fail("must be a number");
    v = node_.as<double>();
  } catch (const YAML::Exception&) {
    Fail("must be a number, got '" + node_.Scalar() + "'");
  }
  if (!std::isfinite(v)) Fail("must be a finite number");
  return v;
}

int YamlField::AsInt() const {
  try {
    if (!node_.IsScalar()) Fail("must be an integer");
    return node_.as<int>();
  } catch (const YAML::Exception&) {
    Fail("must be an integer, got '" + node_.Scalar() + "'");
  }
}

bool YamlField::AsBool() const {
  try {
    if (!node_.IsScalar()) Fail("must be true or false");
    return node_.as<bool>();
  } catch (const YAML::Exception&) {
    Fail("must be true or false, got '" + node_.Scalar() + "'");
  }
}

std::string YamlField::AsString() const {
  if (!node_.IsScalar()) Fail("must be a string");
  return node_.Scalar();
}

std::vector<double> YamlField::AsDoubles(size_t expected_size) const {
  std::vector<double> values;
  for (const YamlField& item : Items()) values.push_back(item.AsDouble());
  if (values.size() != expected_size) {
    Fail("must be a list of " + std::to_string(expected_size) + " numbers, got " + std::to_string(values.size()));
  }
  return values;
}

void YamlField::Get(const std::string& key, double* value) const {
  if (Has(key)) *value = Child(key).AsDouble();
}
void YamlField::Get(const std::string& key, int* value) const {
  if (Has(key)) *value = Child(key).AsInt();
}
void YamlField::Get(const std::string& key, bool* value) const {
  if (Has(key)) *value = Child(key).AsBool();
}
void YamlField::Get(const std::string& key, std::string* value) const {
  if (Has(key)) *value = Child(key).AsString();
}

void YamlField::GetColor(const std::string& key, std::array<unsigned char, 3>* rgb) const {
  if (!Has(key)) return;
  const YamlField field = Child(key);
  const std::vector<double> v = field.AsDoubles(3);
  for (int i = 0; i < 3; ++i) {
    if (v[i] < 0 || v[i] > 255 || v[i] != std::floor(v[i])) field.Fail("colour components must be integers 0..255");
    (*rgb)[i] = static_cast<unsigned char>(v[i]);
  }
}

double YamlField::Positive(const std::string& key, double fallback) const {
  if (!Has(key)) return fallback;
  const YamlField f = Child(key);
  const double v = f.AsDouble();
  if (v <= 0.0) f.Fail("must be > 0, got " + std::to_string(v));
  return v;
}

double YamlField::NonNegative(const std::string& key, double fallback) const {
  if (!Has(key)) return fallback;
  const YamlField f = Child(key);
  const double v = f.AsDouble();
  if (v < 0.0) f.Fail("must be >= 0, got " + std::to_string(v));
  return v;
}

}  // namespace doorplate_localization
