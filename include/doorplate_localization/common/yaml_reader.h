// Strict YAML field access for our file formats (world files, text maps): every error names the file and
// the field path ("worlds/x.yaml: doors[2].width_m: must be > 0, got -1"), and unknown keys are errors so
// that typos never pass silently.
#pragma once

#include <array>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace doorplate_localization {

// Thrown for any unusable content; what() is "<source>: <field path>: <problem>".
class YamlFieldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A YAML node with its field path. Accessors throw YamlFieldError.
class YamlField {
 public:
  // Parses text; syntax errors become YamlFieldError with the line and column.
  static YamlField Parse(const std::string& text, const std::string& source);

  YamlField(YAML::Node node, std::string source, std::string path);

  bool Has(const std::string& key) const;
  YamlField Child(const std::string& key) const;            // required key
  std::vector<YamlField> Items() const;                     // this must be a sequence
  // Throws if the mapping has a key outside `allowed`.
  void RequireOnlyKeys(const std::set<std::string>& allowed) const;

  double AsDouble() const;
  int AsInt() const;
  bool AsBool() const;
  std::string AsString() const;
  std::vector<double> AsDoubles(size_t expected_size) const;

  // Optional-with-default helpers: keep `value` when `key` is absent.
  void Get(const std::string& key, double* value) const;
  void Get(const std::string& key, int* value) const;
  void Get(const std::string& key, bool* value) const;
  void Get(const std::string& key, std::string* value) const;
  void GetColor(const std::string& key, std::array<unsigned char, 3>* rgb) const;

  // Range checks on a present value.
  double Positive(const std::string& key, double fallback) const;
  double NonNegative(const std::string& key, double fallback) const;

  [[noreturn]] void Fail(const std::string& problem) const;
  const std::string& path() const { return path_; }
  const YAML::Node& node() const { return node_; }

 private:
  YAML::Node node_;
  std::string source_;
  std::string path_;
};

}  // namespace doorplate_localization
