#include "scenario/yaml_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace sanet::scenario {
namespace {

std::string Describe(const YAML::Node& node) {
  if (node.IsNull()) return "nothing";
  if (node.IsMap()) return "a mapping";
  if (node.IsSequence()) return "a list";
  return "'" + node.Scalar() + "'";
}

std::string FormatLimit(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

ScenarioError::ScenarioError(const std::string& file, int line, const std::string& field, const std::string& message)
    : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : "") + ": " +
                         (field.empty() ? "" : "'" + field + "': ") + message),
      file_(file),
      line_(line),
      field_(field),
      message_(message) {}

void Field::Fail(const std::string& message) const { throw ScenarioError(*file_, line(), path_, message); }

void Field::ExpectMap() const {
  if (!node_.IsMap()) Fail("must be a mapping of keys to values, not " + Describe(node_));
}

void Field::ExpectKeys(std::initializer_list<const char*> allowed) const {
  ExpectKeys(std::vector<std::string>(allowed.begin(), allowed.end()));
}

void Field::ExpectKeys(const std::vector<std::string>& allowed) const {
  ExpectMap();
  std::set<std::string> seen;
  for (const auto& entry : node_) {
    const std::string key = entry.first.Scalar();
    const std::string path = path_.empty() ? key : path_ + "." + key;
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string list;
      for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
      throw ScenarioError(*file_, entry.first.Mark().line + 1, path, "unknown key (expected one of: " + list + ")");
    }
    if (!seen.insert(key).second) throw ScenarioError(*file_, entry.first.Mark().line + 1, path, "key given twice");
  }
}

std::optional<Field> Field::Get(const std::string& key) const {
  ExpectMap();
  for (const auto& entry : node_)
    if (entry.first.Scalar() == key) return Field(entry.second, path_.empty() ? key : path_ + "." + key, file_);
  return std::nullopt;
}

Field Field::Require(const std::string& key) const {
  auto f = Get(key);
  if (!f) Fail("missing required key '" + key + "'");
  return *f;
}

std::vector<Field> Field::Items() const {
  if (!node_.IsSequence()) Fail("must be a list, not " + Describe(node_));
  std::vector<Field> out;
  for (std::size_t i = 0; i < node_.size(); ++i)
    out.emplace_back(node_[i], path_ + "[" + std::to_string(i) + "]", file_);
  return out;
}

double Field::Number(double min, double max) const {
  if (!node_.IsScalar()) Fail("must be a number, not " + Describe(node_));
  const std::string& s = node_.Scalar();
  char* end = nullptr;
  errno = 0;
  const double d = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(d)) Fail("must be a number, not '" + s + "'");
  if (d < min || d > max) {
    if (max == HUGE_VAL) Fail("is " + s + ", must be at least " + FormatLimit(min));
    if (min == -HUGE_VAL) Fail("is " + s + ", must be at most " + FormatLimit(max));
    Fail("is " + s + ", must be between " + FormatLimit(min) + " and " + FormatLimit(max));
  }
  return d;
}

double Field::NumberAbove(double min_exclusive, double max) const {
  const double d = Number(-HUGE_VAL, max);
  if (d <= min_exclusive) Fail("is " + node_.Scalar() + ", must be greater than " + FormatLimit(min_exclusive));
  return d;
}

int Field::Integer(int min, int max) const {
  const double d = Number(min, max);
  if (d != std::floor(d)) Fail("must be a whole number, not '" + node_.Scalar() + "'");
  return static_cast<int>(d);
}

std::uint64_t Field::Unsigned() const {
  if (!node_.IsScalar()) Fail("must be a whole number, not " + Describe(node_));
  const std::string& s = node_.Scalar();
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
  if (s.empty() || s[0] == '-' || *end != '\0' || errno == ERANGE) Fail("must be a whole number >= 0, not '" + s + "'");
  return v;
}

bool Field::Bool() const {
  if (node_.IsScalar()) {
    const std::string& s = node_.Scalar();
    if (s == "true" || s == "True" || s == "yes") return true;
    if (s == "false" || s == "False" || s == "no") return false;
  }
  Fail("must be true or false, not " + Describe(node_));
}

std::string Field::Text() const {
  if (!node_.IsScalar() || node_.Scalar().empty()) Fail("must be a text value, not " + Describe(node_));
  return node_.Scalar();
}

std::vector<double> Field::Numbers(std::size_t count) const {
  if (!node_.IsSequence() || node_.size() != count)
    Fail("must be a list of " + std::to_string(count) + " numbers, not " + Describe(node_) +
         (node_.IsSequence() ? " of " + std::to_string(node_.size()) : ""));
  std::vector<double> out;
  for (const Field& item : Items()) out.push_back(item.Number(-HUGE_VAL, HUGE_VAL));
  return out;
}

namespace {

// Aliases let a few lines stand for billions of values (a "billion laughs"): the values are
// counted as the reader will meet them, aliases expanded, and a file beyond the limit is refused
// before anything walks it.
constexpr std::size_t kMaxValues = 1000000;

void CountValues(const YAML::Node& node, std::size_t& count, const std::string& path) {
  if (++count > kMaxValues)
    throw ScenarioError(path, node.Mark().line + 1, "",
                        "the file stands for more than 1,000,000 values once its aliases (*name) are expanded");
  if (node.IsSequence() || node.IsMap())
    for (const auto& item : node) {
      if (node.IsMap())
        CountValues(item.second, count, path);
      else
        CountValues(item, count, path);
    }
}

}  // namespace

namespace {

// A value that starts with '#' (an unquoted colour, `color: #ff0000`) is a comment to YAML, which
// in a flow mapping ({...}) breaks the syntax a line or two later: say so where it is near the error.
std::string CommentedValueNear(const std::string& text, int error_line) {
  std::istringstream lines(text);
  std::string line;
  for (int n = 1; std::getline(lines, line) && n <= error_line; ++n) {
    if (n >= error_line - 2 && line.find(": #") != std::string::npos)
      return " (line " + std::to_string(n) +
             " has a value that starts with '#', which YAML reads as a comment: write it in quotes, \"#rrggbb\")";
  }
  return "";
}

Field ParseYaml(std::istream& in, const std::string& name, const std::string& what = "a scenario") {
  auto file = std::make_shared<const std::string>(name);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    YAML::Node root = YAML::Load(text);
    if (!root.IsMap()) throw ScenarioError(name, 1, "", what + " must be a mapping of keys to values");
    std::size_t count = 0;
    CountValues(root, count, name);
    return Field(root, "", file);
  } catch (const YAML::Exception& e) {
    throw ScenarioError(name, e.mark.line + 1, "",
                        "YAML syntax error: " + e.msg + CommentedValueNear(text, e.mark.line + 1));
  }
}

}  // namespace

Field ParseYamlFile(const std::string& path, const std::string& what) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw ScenarioError(path, 0, "", "is a folder, not " + what + (what == "a scenario" ? " file" : ""));
  std::ifstream in(path);
  if (!in) throw ScenarioError(path, 0, "", std::string("cannot open the file: ") + std::strerror(errno));
  return ParseYaml(in, path, what);
}

Field ParseYamlText(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  return ParseYaml(in, name);
}

}  // namespace sanet::scenario
