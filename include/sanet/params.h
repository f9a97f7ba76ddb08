// Parameters of a controller, as written in the scenario. Header-only so that a controller
// library needs nothing but these headers. Every getter checks type and range and throws
// ParamError naming the key and its line; keys that no getter asked for are reported by
// CheckAllUsed() as unknown, so a typo in a scenario never passes silently.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace sanet {

class ParamError : public std::runtime_error {
 public:
  ParamError(std::string key, int line, const std::string& what)
      : std::runtime_error(what), key_(std::move(key)), line_(line) {}
  const std::string& key() const { return key_; }
  int line() const { return line_; }  // 1-based line in the scenario file, 0 if unknown

 private:
  std::string key_;
  int line_;
};

// What a controller asked of its parameters: sanet lists a controller's parameters by creating
// it once with none and noting each read (name, kind, default, range).
struct ParamRead {
  std::string key, kind, fallback;
  double min = -HUGE_VAL, max = HUGE_VAL;
};

// One parameter value: a scalar, a list of scalars, or a list of lists (e.g. way points).
struct ParamValue {
  enum class Shape { kScalar, kList, kTable };
  Shape shape = Shape::kScalar;
  std::vector<std::vector<std::string>> rows;  // kScalar: 1x1; kList: 1xN; kTable: MxN
  int line = 0;
};

class Params {
 public:
  Params() = default;
  void Set(const std::string& key, ParamValue value) { values_[key] = std::move(value); }
  bool Has(const std::string& key) const { return values_.count(key) != 0; }
  // Every parameter as written, by key.
  const std::map<std::string, ParamValue>& All() const { return values_; }
  // Line of `key` in the scenario (0 if absent).
  int Line(const std::string& key) const {
    auto it = values_.find(key);
    return it == values_.end() ? 0 : it->second.line;
  }

  double Number(const std::string& key, double fallback, double min = -HUGE_VAL, double max = HUGE_VAL) const {
    Note(key, "number", NumberText(fallback), min, max);
    const ParamValue* v = Find(key);
    if (!v) return fallback;
    return CheckRange(key, *v, ToNumber(key, *v, Scalar(key, *v)), min, max);
  }

  int Integer(const std::string& key, int fallback, int min = -2147483647, int max = 2147483647) const {
    Note(key, "whole number", std::to_string(fallback), min, max);
    const ParamValue* v = Find(key);
    if (!v) return fallback;
    const double d = ToNumber(key, *v, Scalar(key, *v));
    if (d != std::floor(d)) Fail(key, *v, "must be a whole number");
    return static_cast<int>(CheckRange(key, *v, d, min, max));
  }

  bool Flag(const std::string& key, bool fallback) const {
    Note(key, "boolean", fallback ? "true" : "false");
    const ParamValue* v = Find(key);
    if (!v) return fallback;
    const std::string& s = Scalar(key, *v);
    if (s == "true" || s == "True" || s == "yes") return true;
    if (s == "false" || s == "False" || s == "no") return false;
    Fail(key, *v, "must be true or false, not '" + s + "'");
  }

  std::string Text(const std::string& key, const std::string& fallback) const {
    Note(key, "text", fallback);
    const ParamValue* v = Find(key);
    return v ? Scalar(key, *v) : fallback;
  }

  // A word or a list of words, e.g. node names.
  std::vector<std::string> Words(const std::string& key, std::vector<std::string> fallback) const {
    Note(key, "word or list of words", List(fallback));
    const ParamValue* v = Find(key);
    if (!v) return fallback;
    if (v->shape == ParamValue::Shape::kTable) Fail(key, *v, "must be a word or a list of words");
    return v->rows.at(0);
  }

  std::vector<double> Numbers(const std::string& key, std::vector<double> fallback) const {
    std::vector<std::string> texts;
    for (double d : fallback) texts.push_back(NumberText(d));
    Note(key, "list of numbers", List(texts));
    const ParamValue* v = Find(key);
    if (!v) return fallback;
    if (v->shape == ParamValue::Shape::kTable) Fail(key, *v, "must be a list of numbers");
    std::vector<double> out;
    for (const auto& s : v->rows.at(0)) out.push_back(ToNumber(key, *v, s));
    return out;
  }

  // A list of rows of `width` numbers each, e.g. way points [[x, y], [x, y]].
  std::vector<std::vector<double>> Table(const std::string& key, std::size_t width,
                                         std::vector<std::vector<double>> fallback) const {
    Note(key, "list of [" + std::to_string(width) + " numbers]", fallback.empty() ? "none" : "given");
    const ParamValue* v = Find(key);
    if (!v) return fallback;
    if (v->shape != ParamValue::Shape::kTable)
      Fail(key, *v, "must be a list of [" + std::to_string(width) + " numbers] lists");
    std::vector<std::vector<double>> out;
    for (const auto& row : v->rows) {
      if (row.size() != width) Fail(key, *v, "each entry must hold " + std::to_string(width) + " numbers");
      std::vector<double> numbers;
      for (const auto& s : row) numbers.push_back(ToNumber(key, *v, s));
      out.push_back(numbers);
    }
    return out;
  }

  // A read of any kind, for controllers in other languages that convert values themselves
  // (Python's): noted as the getters note theirs (`kind`, `fallback` as `sanet list` shows them);
  // the value as written, or null when absent.
  const ParamValue* Read(const std::string& key, std::string kind, std::string fallback) const {
    Note(key, std::move(kind), std::move(fallback));
    return Find(key);
  }

  // Every read so far, in order, each key once.
  const std::vector<ParamRead>& Reads() const { return reads_; }

  // Throws for the first key that no getter has read: an unknown parameter.
  void CheckAllUsed() const {
    for (const auto& [key, value] : values_) {
      if (used_.count(key)) continue;
      std::string known;
      for (const ParamRead& r : reads_) known += (known.empty() ? "" : ", ") + r.key;
      throw ParamError(
          key, value.line,
          "unknown parameter '" + key + "'" +
              (known.empty() ? " (this controller takes none)" : " (this controller reads: " + known + ")"));
    }
  }

 private:
  void Note(const std::string& key, std::string kind, std::string fallback, double min = -HUGE_VAL,
            double max = HUGE_VAL) const {
    for (const ParamRead& r : reads_)
      if (r.key == key) return;
    reads_.push_back({key, std::move(kind), std::move(fallback), min, max});
  }
  static std::string NumberText(double d) {
    char s[32];
    std::snprintf(s, sizeof s, "%g", d);
    return s;
  }
  static std::string List(const std::vector<std::string>& items) {
    if (items.empty()) return "none";
    std::string out = "[";
    for (const std::string& i : items) out += (out.size() > 1 ? ", " : "") + i;
    return out + "]";
  }
  const ParamValue* Find(const std::string& key) const {
    auto it = values_.find(key);
    if (it == values_.end()) return nullptr;
    used_.insert(key);
    return &it->second;
  }
  [[noreturn]] static void Fail(const std::string& key, const ParamValue& v, const std::string& why) {
    throw ParamError(key, v.line, "parameter '" + key + "' " + why);
  }
  static const std::string& Scalar(const std::string& key, const ParamValue& v) {
    if (v.shape != ParamValue::Shape::kScalar) Fail(key, v, "must be a single value, not a list");
    return v.rows.at(0).at(0);
  }
  static double ToNumber(const std::string& key, const ParamValue& v, const std::string& s) {
    char* end = nullptr;
    errno = 0;
    const double d = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(d))
      Fail(key, v, "must be a number, not '" + s + "'");
    return d;
  }
  static double CheckRange(const std::string& key, const ParamValue& v, double d, double min, double max) {
    if (d < min || d > max) {
      auto fmt = [](double x) {
        std::string s = std::to_string(x);
        s.erase(s.find_last_not_of('0') + 1);
        if (!s.empty() && s.back() == '.') s.pop_back();
        return s;
      };
      std::string range = (min == -HUGE_VAL ? "" : ">= " + fmt(min)) +
                          (min != -HUGE_VAL && max != HUGE_VAL ? " and " : "") +
                          (max == HUGE_VAL ? "" : "<= " + fmt(max));
      Fail(key, v, "is " + fmt(d) + ", must be " + range);
    }
    return d;
  }

  std::map<std::string, ParamValue> values_;
  mutable std::set<std::string> used_;
  mutable std::vector<ParamRead> reads_;
};

}  // namespace sanet
