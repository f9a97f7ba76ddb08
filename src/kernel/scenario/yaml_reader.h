// Strict, located reading of YAML: every value knows its file, line and dotted field path, and
// every mistake becomes a ScenarioError saying all three.
#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sanet::scenario {

class ScenarioError : public std::runtime_error {
 public:
  ScenarioError(const std::string& file, int line, const std::string& field, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  std::string field_;
  std::string message_;
};

class Field {
 public:
  Field(YAML::Node node, std::string path, std::shared_ptr<const std::string> file)
      : node_(std::move(node)), path_(std::move(path)), file_(std::move(file)) {}

  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }
  int line() const { return node_.Mark().line + 1; }
  const YAML::Node& node() const { return node_; }
  bool IsMap() const { return node_.IsMap(); }
  bool IsSequence() const { return node_.IsSequence(); }
  bool IsScalar() const { return node_.IsScalar(); }

  // The mapping's keys must be among `allowed`, each at most once.
  void ExpectKeys(std::initializer_list<const char*> allowed) const;
  void ExpectKeys(const std::vector<std::string>& allowed) const;
  std::optional<Field> Get(const std::string& key) const;
  Field Require(const std::string& key) const;
  std::vector<Field> Items() const;  // of a sequence

  double Number(double min, double max) const;
  double NumberAbove(double min_exclusive, double max) const;
  int Integer(int min, int max) const;
  std::uint64_t Unsigned() const;
  bool Bool() const;
  std::string Text() const;
  std::vector<double> Numbers(std::size_t count) const;  // a list of exactly `count` numbers

  [[noreturn]] void Fail(const std::string& message) const;

 private:
  void ExpectMap() const;
  YAML::Node node_;
  std::string path_;
  std::shared_ptr<const std::string> file_;
};

// Parses a file; syntax errors become ScenarioErrors with the line. `what` names the kind of file
// in errors ("a scenario", "a robot's file").
Field ParseYamlFile(const std::string& path, const std::string& what = "a scenario");
// The same for text that came from elsewhere; `name` stands for its file in errors.
Field ParseYamlText(const std::string& text, const std::string& name);

}  // namespace sanet::scenario
