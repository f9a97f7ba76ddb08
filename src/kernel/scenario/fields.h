// Declarations of a scenario section's fields, each written once: key, type, unit, default,
// range and meaning, with how to read it (checked, with file:line errors) and how to print its
// effective value. The loader reads through them, `sanet validate --print` prints through them,
// `sanet list` and the reference tables in docs/scenario.md are made from them (a test compares
// the docs with `sanet list --markdown`).
#pragma once

#include <yaml-cpp/yaml.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "scenario/yaml_reader.h"

namespace sanet::scenario {

// What a reader of the docs sees of one field.
struct FieldInfo {
  std::string key, type, unit, default_text, range, meaning;
};
inline const char* const kRequired = "required";  // the default of a field that must be given

// Shortest text that reads back as the same double ("0.005", "9.81", "1e-06").
std::string ShortNumber(double value);
YAML::Node NumberNode(double value);
// "[0, 100]", "(0, 0.1]", "any"
std::string RangeText(double min, double max, bool min_exclusive);
// A markdown table of fields: | Key | Type | Unit | Default | Range | Meaning |
std::string MarkdownTable(const std::vector<FieldInfo>& fields);

// Access to a member of S, for a field's reader and printer: Member(&RunSpec::duration).
template <typename S, typename T>
std::function<T&(S&)> Member(T S::*m) {
  return [m](S& s) -> T& { return s.*m; };
}

template <typename S>
class Fields {
 public:
  template <typename T>
  using Access = std::function<T&(S&)>;

  // A number in [min, max], or (min, max] with `min_exclusive`.
  Fields& Number(const char* key, Access<double> at, const char* unit, double min, double max, const char* meaning,
                 bool min_exclusive = false) {
    return Add(
        {key, "number", unit, "", RangeText(min, max, min_exclusive), meaning},
        [=](const Field& f, S& s) { at(s) = min_exclusive ? f.NumberAbove(min, max) : f.Number(min, max); },
        [=](const S& s) { return NumberNode(at(const_cast<S&>(s))); });
  }
  template <typename T>
  Fields& Whole(const char* key, Access<T> at, const char* unit, int min, int max, const char* meaning) {
    return Add(
        {key, "whole number", unit, "", RangeText(min, max, false), meaning},
        [=](const Field& f, S& s) { at(s) = static_cast<T>(f.Integer(min, max)); },
        [=](const S& s) { return YAML::Node(static_cast<long long>(at(const_cast<S&>(s)))); });
  }
  Fields& Flag(const char* key, Access<bool> at, const char* meaning) {
    return Add(
        {key, "boolean", "", "", "", meaning}, [=](const Field& f, S& s) { at(s) = f.Bool(); },
        [=](const S& s) { return YAML::Node(at(const_cast<S&>(s))); });
  }
  template <typename E>
  Fields& Choice(const char* key, Access<E> at, std::vector<std::pair<std::string, E>> choices, const char* meaning) {
    std::string range;
    for (const auto& [name, value] : choices) range += (range.empty() ? "`" : ", `") + name + "`";
    return Add(
        {key, "text", "", "", range, meaning},
        [=](const Field& f, S& s) {
          const std::string text = f.Text();
          for (const auto& [name, value] : choices)
            if (text == name) return void(at(s) = value);
          f.Fail("unknown value '" + text + "' (expected one of: " + PlainList(choices) + ")");
        },
        [=](const S& s) {
          for (const auto& [name, value] : choices)
            if (value == at(const_cast<S&>(s))) return YAML::Node(name);
          return YAML::Node();
        });
  }
  // Anything else: its own reader (null: the section's code reads it) and printer (a null node
  // prints nothing).
  Fields& Custom(FieldInfo info, std::function<void(const Field&, S&)> read,
                 std::function<YAML::Node(const S&)> print) {
    return Add(std::move(info), std::move(read), std::move(print));
  }

  // The field declared last must be given.
  Fields& Required() {
    entries_.back().info.default_text = kRequired;
    return *this;
  }
  // The field declared last has a default that depends on more than its settings (the model's
  // body): the docs say it in words.
  Fields& DefaultSaid(std::string text) {
    entries_.back().info.default_text = std::move(text);
    return *this;
  }

  std::vector<std::string> Keys() const {
    std::vector<std::string> keys;
    for (const Entry& e : entries_) keys.push_back(e.info.key);
    return keys;
  }
  // Reads every declared key present in the mapping `f` (after checking that it has no others).
  // A field whose default is "required" must be there.
  // `also_allowed`: keys the caller reads itself (a sensor instance's `kind`).
  void Read(const Field& f, S& s, const std::vector<std::string>& also_allowed = {}) const {
    std::vector<std::string> keys = Keys();
    keys.insert(keys.end(), also_allowed.begin(), also_allowed.end());
    f.ExpectKeys(keys);
    for (const Entry& e : entries_)
      if (e.info.default_text == kRequired) f.Require(e.info.key);
    ReadPresent(f, s);
  }
  // Reads the declared keys present in `f`, leaving the check of the others to the caller.
  void ReadPresent(const Field& f, S& s) const {
    for (const Entry& e : entries_)
      if (e.read)  // fields without a reader are read by the section's own code
        if (auto value = f.Get(e.info.key)) e.read(*value, s);
  }
  // The effective values, every field filled in.
  YAML::Node Print(const S& s) const {
    YAML::Node out(YAML::NodeType::Map);
    for (const Entry& e : entries_) {
      YAML::Node value = e.print(s);
      if (value.IsDefined() && !value.IsNull()) out[e.info.key] = value;
    }
    return out;
  }
  // The fields as the docs show them, with the defaults of `defaults`.
  std::vector<FieldInfo> Describe(const S& defaults) const {
    std::vector<FieldInfo> out;
    for (const Entry& e : entries_) {
      FieldInfo info = e.info;
      if (info.default_text.empty()) info.default_text = DefaultText(e.print(defaults));
      out.push_back(info);
    }
    return out;
  }

 private:
  struct Entry {
    FieldInfo info;
    std::function<void(const Field&, S&)> read;
    std::function<YAML::Node(const S&)> print;
  };
  Fields& Add(FieldInfo info, std::function<void(const Field&, S&)> read, std::function<YAML::Node(const S&)> print) {
    entries_.push_back({std::move(info), std::move(read), std::move(print)});
    return *this;
  }
  template <typename E>
  static std::string PlainList(const std::vector<std::pair<std::string, E>>& choices) {
    std::string list;
    for (const auto& [name, value] : choices) list += (list.empty() ? "" : ", ") + name;
    return list;
  }
  static std::string DefaultText(const YAML::Node& value) {
    if (!value.IsDefined() || value.IsNull()) return "none";
    YAML::Emitter e;
    e << YAML::Flow << value;
    return std::string("`") + e.c_str() + "`";
  }
  std::vector<Entry> entries_;
};

}  // namespace sanet::scenario
