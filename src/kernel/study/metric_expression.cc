#include "study/metric_expression.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace sanet::study {

struct MetricExpression::Node {
  enum class Kind { kNumber, kName, kAggregate, kNegate, kBinary } kind;
  double number = 0;
  std::string text;      // a name, or an aggregate's pattern
  char op = 0;           // + - * /
  std::string function;  // an aggregate's: sum, mean, min, max, count
  std::unique_ptr<Node> left, right;
};

namespace {

using Node = MetricExpression::Node;
using Kind = Node::Kind;

const std::vector<std::string> kAggregates = {"sum", "mean", "min", "max", "count"};

bool NameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '*'; }

std::vector<std::string> Parts(const std::string& dotted) {
  std::vector<std::string> parts(1);
  for (char c : dotted)
    if (c == '.')
      parts.emplace_back();
    else
      parts.back() += c;
  return parts;
}

// `*` matches any run of characters (none included).
bool GlobMatches(const char* pattern, const char* text) {
  if (*pattern == '\0') return *text == '\0';
  if (*pattern == '*') return GlobMatches(pattern + 1, text) || (*text != '\0' && GlobMatches(pattern, text + 1));
  return *text == *pattern && GlobMatches(pattern + 1, text + 1);
}

// Recursive descent over the grammar in the header, keeping what the expression reads.
class Parser {
 public:
  explicit Parser(const std::string& text) : text_(text) {}

  std::unique_ptr<Node> Whole() {
    auto root = Sum();
    Skip();
    if (at_ < text_.size()) Fail("'" + std::string(1, text_[at_]) + "' where an operator or the end belongs");
    return root;
  }
  std::vector<std::string> names, patterns;

 private:
  std::unique_ptr<Node> Sum() {
    auto left = Product();
    while (Next('+') || Next('-')) {
      const char op = text_[at_ - 1];  // before the right side moves on
      left = Binary(op, std::move(left), Product());
    }
    return left;
  }

  std::unique_ptr<Node> Product() {
    auto left = Unary();
    while (Next('*') || Next('/')) {
      const char op = text_[at_ - 1];
      left = Binary(op, std::move(left), Unary());
    }
    return left;
  }

  std::unique_ptr<Node> Unary() {
    if (!Next('-')) return Primary();
    auto node = std::make_unique<Node>(Node{Kind::kNegate});
    node->left = Unary();
    return node;
  }

  std::unique_ptr<Node> Primary() {
    Skip();
    if (Next('(')) {
      auto inner = Sum();
      Expect(')');
      return inner;
    }
    if (at_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[at_])) || text_[at_] == '.'))
      return Number();
    const std::string word = Word("a metric, a number, an aggregate or '('");
    if (std::find(kAggregates.begin(), kAggregates.end(), word) != kAggregates.end() && Next('('))
      return Aggregate(word);
    if (word.find('*') != std::string::npos)
      Fail("the pattern '" + word + "' stands for several metrics: aggregate it, e.g. sum(" + word + ")");
    names.push_back(word);
    return std::make_unique<Node>(Node{Kind::kName, 0, word});
  }

  std::unique_ptr<Node> Aggregate(const std::string& function) {
    const std::string pattern = Word("a metric's name or pattern inside " + function + "()");
    Expect(')');
    patterns.push_back(pattern);
    auto node = std::make_unique<Node>(Node{Kind::kAggregate, 0, pattern});
    node->function = function;
    return node;
  }

  std::unique_ptr<Node> Number() {
    const char* start = text_.c_str() + at_;
    char* end = nullptr;
    const double value = std::strtod(start, &end);
    if (end == start) Fail("a number");
    at_ += static_cast<std::size_t>(end - start);
    return std::make_unique<Node>(Node{Kind::kNumber, value});
  }

  static std::unique_ptr<Node> Binary(char op, std::unique_ptr<Node> left, std::unique_ptr<Node> right) {
    auto node = std::make_unique<Node>(Node{Kind::kBinary});
    node->op = op;
    node->left = std::move(left);
    node->right = std::move(right);
    return node;
  }

  std::string Word(const std::string& wanted) {
    Skip();
    const std::size_t start = at_;
    while (at_ < text_.size() && NameChar(text_[at_])) ++at_;
    if (at_ == start) Fail(wanted + " expected");
    return text_.substr(start, at_ - start);
  }

  bool Next(char c) {
    Skip();
    if (at_ >= text_.size() || text_[at_] != c) return false;
    ++at_;
    return true;
  }

  void Expect(char c) {
    if (!Next(c)) Fail(std::string("'") + c + "' expected");
  }

  void Skip() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }

  [[noreturn]] void Fail(const std::string& why) const {
    throw ExpressionError("in '" + text_ + "' at character " + std::to_string(at_ + 1) + ": " + why);
  }

  const std::string& text_;
  std::size_t at_ = 0;
};

using Value = std::optional<double>;

Value Aggregate(const std::string& function, const std::string& pattern, const RunMetrics& run) {
  double sum = 0, low = std::numeric_limits<double>::infinity(), high = -low;
  int count = 0;
  for (const auto& [name, value] : run)
    if (MatchesPattern(pattern, name)) ++count, sum += value, low = std::min(low, value), high = std::max(high, value);
  if (function == "sum") return sum;
  if (function == "count") return count;
  if (count == 0) return std::nullopt;
  return function == "mean" ? sum / count : function == "min" ? low : high;
}

Value Combine(char op, Value a, Value b) {
  if (!a || !b) return std::nullopt;
  switch (op) {
    case '+':
      return *a + *b;
    case '-':
      return *a - *b;
    case '*':
      return *a * *b;
    default:
      return *b == 0 ? Value{} : Value{*a / *b};
  }
}

Value Evaluate(const Node& n, const RunMetrics& run, const MetricExpression::Derived& derived) {
  switch (n.kind) {
    case Kind::kNumber:
      return n.number;
    case Kind::kName: {
      if (auto it = run.find(n.text); it != run.end()) return it->second;
      return derived ? derived(n.text, run) : std::nullopt;
    }
    case Kind::kAggregate:
      return Aggregate(n.function, n.text, run);
    case Kind::kNegate: {
      const Value v = Evaluate(*n.left, run, derived);
      return v ? Value{-*v} : v;
    }
    case Kind::kBinary:
      return Combine(n.op, Evaluate(*n.left, run, derived), Evaluate(*n.right, run, derived));
  }
  return std::nullopt;
}

}  // namespace

bool MatchesPattern(const std::string& pattern, const std::string& name) {
  const std::vector<std::string> want = Parts(pattern), have = Parts(name);
  if (want.size() != have.size()) return false;
  for (std::size_t i = 0; i < want.size(); ++i)
    if (!GlobMatches(want[i].c_str(), have[i].c_str())) return false;
  return true;
}

MetricExpression MetricExpression::Parse(const std::string& text) {
  Parser parser(text);
  MetricExpression e(parser.Whole());
  e.names_ = std::move(parser.names);
  e.patterns_ = std::move(parser.patterns);
  return e;
}

MetricExpression::MetricExpression(std::unique_ptr<Node> root) : root_(std::move(root)) {}
MetricExpression::~MetricExpression() = default;
MetricExpression::MetricExpression(MetricExpression&&) noexcept = default;
MetricExpression& MetricExpression::operator=(MetricExpression&&) noexcept = default;

std::optional<double> MetricExpression::Evaluate(const RunMetrics& run, const Derived& derived) const {
  const Value v = study::Evaluate(*root_, run, derived);
  return v && std::isfinite(*v) ? v : std::nullopt;
}

const std::vector<std::string>& MetricExpression::names() const { return names_; }
const std::vector<std::string>& MetricExpression::patterns() const { return patterns_; }
bool MetricExpression::IsPlainName() const { return root_->kind == Kind::kName; }

}  // namespace sanet::study
