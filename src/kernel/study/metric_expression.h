// Derived metrics of a study's runs (`sanet report --derive NAME=EXPR`): arithmetic over a run's
// metrics, with aggregates over every metric a pattern matches (the per-node ones, mostly):
//
//   expr    := term (('+' | '-') term)*
//   term    := unary (('*' | '/') unary)*
//   unary   := '-' unary | primary
//   primary := NUMBER | NAME | AGG '(' PATTERN ')' | '(' expr ')'
//   AGG     := sum | mean | min | max | count
//
// A NAME is a metric's dotted name (`ended_at_s`, `metrics.mule.delivered.sum`) or an earlier
// derived metric's name: letters, digits, `_` and `.`, or anything but a backquote between
// backquotes (`` `metrics.robot-1.hop time.mean` ``). A PATTERN is a name holding `*`, which
// matches any characters, dots included: `metrics.m*.created.count` matches
// `metrics.m7.created.count`. Each run is evaluated alone: an aggregate takes the run's matches,
// so `sum(metrics.*.created.count)` is that run's total over its nodes.
//
// A run has no value when a NAME it needs is missing from it, when mean, min or max match nothing
// in it, or when it divides by zero; sum and count of nothing are 0.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sanet::study {

class ExpressionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One run's metrics by name.
using RunMetrics = std::map<std::string, double>;

// Whether `name` matches `pattern` (`*`: any characters).
bool MatchesPattern(const std::string& pattern, const std::string& name);
// Whether an expression reads `name` without backquotes: a letter or `_`, then letters, digits,
// `_`, `.` (and `*`, a pattern's).
bool IsPlainName(const std::string& name);
// `name` as an expression reads it: as it is, or between backquotes when it holds other characters.
std::string QuotedName(const std::string& name);

class MetricExpression {
 public:
  // Throws ExpressionError naming the place in `text` that is wrong.
  static MetricExpression Parse(const std::string& text);
  ~MetricExpression();
  MetricExpression(MetricExpression&&) noexcept;
  MetricExpression& operator=(MetricExpression&&) noexcept;

  // `derived` gives the value of an earlier derived metric for this run (nullopt: none).
  using Derived = std::function<std::optional<double>(const std::string& name, const RunMetrics& run)>;
  std::optional<double> Evaluate(const RunMetrics& run, const Derived& derived) const;

  // The plain names and the aggregates' patterns the expression reads.
  const std::vector<std::string>& names() const;
  const std::vector<std::string>& patterns() const;

  struct Node;

 private:
  explicit MetricExpression(std::unique_ptr<Node> root);
  std::unique_ptr<Node> root_;
  std::vector<std::string> names_, patterns_;
};

}  // namespace sanet::study
