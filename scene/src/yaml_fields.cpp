#include "yaml_fields.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace seflex::scene::detail {

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string shown(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  return "nothing";
}

}  // namespace

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
  std::size_t best = std::string::npos;
  std::string pick;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best) {
      best = d;
      pick = c;
    }
  }
  if (pick.empty() || best > std::max<std::size_t>(2, pick.size() / 3)) return "";
  return "did you mean '" + pick + "'?";
}

void YamlField::fail(const std::string& what) const {
  throw InputError(where(), (path_.empty() ? std::string() : path_ + ": ") + what);
}

void YamlField::expect_map() const {
  if (!node_.IsMap()) fail("expected a map of keys, got " + shown(node_));
}

void YamlField::expect_sequence() const {
  if (!node_.IsSequence()) fail("expected a list, got " + shown(node_));
}

void YamlField::check_keys(std::initializer_list<const char*> allowed) const {
  expect_map();
  const std::vector<std::string> names(allowed.begin(), allowed.end());
  std::set<std::string> seen;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const YamlField key(it->first, path_, file_, line_);
    if (!it->first.IsScalar()) key.fail("keys must be plain names");
    const std::string k = it->first.Scalar();
    const std::string child = path_.empty() ? k : path_ + "." + k;
    if (!seen.insert(k).second) YamlField(it->first, child, file_, line_).fail("key given twice");
    if (std::find(names.begin(), names.end(), k) == names.end()) {
      std::string allowed_list;
      for (const auto& n : names) allowed_list += (allowed_list.empty() ? "" : ", ") + n;
      const std::string hint = did_you_mean(k, names);
      YamlField(it->first, child, file_, line_)
          .fail("unknown key" + (hint.empty() ? std::string() : " (" + hint + ")") + "; expected one of: " + allowed_list);
    }
  }
}

bool YamlField::has(const char* key) const {
  if (!node_.IsMap()) return false;
  const YAML::Node c = node_[key];
  return c.IsDefined() && !c.IsNull();
}

YamlField YamlField::operator[](const char* key) const {
  const std::string child = path_.empty() ? key : path_ + "." + key;
  if (!node_.IsMap()) return YamlField(YAML::Node(YAML::NodeType::Undefined), child, file_, line_);
  return YamlField(node_[key], child, file_, line_);
}

YamlField YamlField::at(std::size_t i) const {
  return YamlField(node_[i], path_ + "[" + std::to_string(i) + "]", file_, line_);
}

YamlField YamlField::required(const char* key, const std::string& expected) const {
  if (!has(key)) {
    const std::string child = path_.empty() ? key : path_ + "." + key;
    YamlField(YAML::Node(YAML::NodeType::Undefined), child, file_, line_).fail("missing (expected " + expected + ")");
  }
  return (*this)[key];
}

std::string YamlField::text() const {
  if (!node_.IsScalar()) fail("expected a text value, got " + shown(node_));
  return node_.Scalar();
}

double YamlField::number() const {
  if (!node_.IsScalar()) fail("expected a number, got " + shown(node_));
  const std::string& s = node_.Scalar();
  double x = 0.0;
  std::size_t pos = 0;
  try {
    x = std::stod(s, &pos);
  } catch (const std::exception&) {
    pos = 0;
  }
  if (pos == 0 || pos != s.size()) fail("expected a number, got '" + s + "'");
  if (!std::isfinite(x)) fail("expected a finite number, got '" + s + "'");
  return x;
}

double YamlField::positive() const {
  const double x = number();
  if (!(x > 0.0)) fail("expected a number > 0, got " + node_.Scalar());
  return x;
}

double YamlField::non_negative() const {
  const double x = number();
  if (!(x >= 0.0)) fail("expected a number >= 0, got " + node_.Scalar());
  return x;
}

int YamlField::integer() const {
  if (!node_.IsScalar()) fail("expected an integer, got " + shown(node_));
  const std::string& s = node_.Scalar();
  std::size_t pos = 0;
  long v = 0;
  try {
    v = std::stol(s, &pos);
  } catch (const std::exception&) {
    pos = 0;
  }
  if (pos == 0 || pos != s.size() || v < -1000000000L || v > 1000000000L) fail("expected an integer, got '" + s + "'");
  return static_cast<int>(v);
}

bool YamlField::boolean() const {
  if (node_.IsScalar()) {
    const std::string& s = node_.Scalar();
    if (s == "true" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "no" || s == "off") return false;
  }
  fail("expected true or false, got " + shown(node_));
}

Eigen::Vector3d YamlField::vector3() const {
  if (!node_.IsSequence() || node_.size() != 3) fail("expected a vector [x, y, z] of 3 numbers, got " + shown(node_) +
                                                     (node_.IsSequence() ? " of " + std::to_string(node_.size()) : ""));
  return Eigen::Vector3d(at(0).number(), at(1).number(), at(2).number());
}

std::vector<double> YamlField::numbers() const {
  if (!node_.IsSequence()) fail("expected a list of numbers [a, b, ...], got " + shown(node_));
  std::vector<double> v;
  for (std::size_t i = 0; i < node_.size(); ++i) v.push_back(at(i).number());
  return v;
}

YamlField load_yaml(const std::string& text, const std::string* file) {
  try {
    return YamlField(YAML::Load(text), "", file, 1);
  } catch (const YAML::Exception& e) {
    throw InputError(SourceRef{*file, e.mark.is_null() ? 0 : e.mark.line + 1},
                     "not valid YAML: " + e.msg + (e.mark.is_null() ? std::string() : " (column " + std::to_string(e.mark.column + 1) + ")"));
  }
}

}  // namespace seflex::scene::detail
