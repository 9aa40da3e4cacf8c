#pragma once
// Reading a YAML document with messages that name the file, line, key path and what was expected:
//   "scene.yaml:12: hinges[2].child: expected 'body.node' or 'ground', got 'yoke'".
// A YamlField is one node with its key path; missing keys report the line of the enclosing map.
// Private to io/ (the only module that links yaml-cpp).
#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "seflex/common/error.hpp"

namespace seflex::scene::detail {

/// "did you mean 'x'?" for the candidate closest to `word` (edit distance), or "" when none is close.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

class YamlField {
 public:
  YamlField(YAML::Node node, std::string path, const std::string* file, int line)
      : node_(std::move(node)), path_(std::move(path)), file_(file), line_(line) {
    if (node_.IsDefined() && !node_.Mark().is_null()) line_ = node_.Mark().line + 1;
  }

  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  SourceRef where() const { return SourceRef{*file_, line_}; }
  bool present() const { return node_.IsDefined() && !node_.IsNull(); }

  /// Throws InputError "file:line: path: what".
  [[noreturn]] void fail(const std::string& what) const;

  // Structure.
  void expect_map() const;
  void expect_sequence() const;
  /// Every key must be one of `allowed` (unknown keys: error with a "did you mean" hint; duplicate keys: error).
  void check_keys(std::initializer_list<const char*> allowed) const;
  bool has(const char* key) const;
  YamlField operator[](const char* key) const;  ///< a map's child (possibly missing)
  std::size_t size() const { return node_.IsSequence() ? node_.size() : 0; }
  YamlField at(std::size_t i) const;            ///< a sequence's element

  // Scalars (the field must be present).
  std::string text() const;
  double number() const;                  ///< finite
  double positive() const;                ///< > 0
  double non_negative() const;            ///< >= 0
  int integer() const;
  bool boolean() const;
  Eigen::Vector3d vector3() const;        ///< [x, y, z]
  std::vector<double> numbers() const;    ///< [a, b, ...]

  // Optional children of a map.
  double number_or(const char* key, double fallback) const { return has(key) ? (*this)[key].number() : fallback; }
  std::string text_or(const char* key, const std::string& fallback) const { return has(key) ? (*this)[key].text() : fallback; }
  bool boolean_or(const char* key, bool fallback) const { return has(key) ? (*this)[key].boolean() : fallback; }
  /// A required child (error "missing key" at the map's line).
  YamlField required(const char* key, const std::string& expected) const;

 private:
  YAML::Node node_;
  std::string path_;
  const std::string* file_;
  int line_ = 0;
};

/// Parse a whole document (syntax errors become InputError with the line). `file` must outlive the fields.
YamlField load_yaml(const std::string& text, const std::string* file);

}  // namespace seflex::scene::detail
