#include "study/metric_expression.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace sanet::study {

struct MetricExpression::Node {
  enum class Kind { kNumber, kName, kAggregate, kNegate, kBinary } kind = Kind::kNumber;
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

// `*` matches any run of characters (none included). Greedy with one backtrack point, so
// linear in practice whatever the stars.
bool GlobMatches(const std::string& pattern, const std::string& text) {
  std::size_t p = 0, t = 0, star = std::string::npos, resume = 0;
  while (t < text.size()) {
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++, resume = t;
    } else if (p < pattern.size() && pattern[p] == text[t]) {
      ++p, ++t;
    } else if (star != std::string::npos) {
      p = star + 1, t = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::unique_ptr<Node> Make(Kind kind) {
  auto node = std::make_unique<Node>();
  node->kind = kind;
  return node;
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
    auto node = Make(Kind::kNegate);
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
    const bool quoted = at_ < text_.size() && text_[at_] == '`';
    const std::string word = Word("a metric, a number, an aggregate or '('", /*pattern=*/false);
    if (!quoted && Next('(')) {
      if (std::find(kAggregates.begin(), kAggregates.end(), word) == kAggregates.end())
        Fail("'" + word + "' is not an aggregate: sum, mean, min, max or count");
      return Aggregate(word);
    }
    if (word.find('*') != std::string::npos)
      Fail("the pattern '" + word + "' stands for several metrics: aggregate it, e.g. sum(" + word + ")");
    names.push_back(word);
    auto node = Make(Kind::kName);
    node->text = word;
    return node;
  }

  std::unique_ptr<Node> Aggregate(const std::string& function) {
    const std::string pattern = Word("a metric's name or pattern inside " + function + "()", /*pattern=*/true);
    Expect(')');
    patterns.push_back(pattern);
    auto node = Make(Kind::kAggregate);
    node->text = pattern;
    node->function = function;
    return node;
  }

  std::unique_ptr<Node> Number() {
    const char* start = text_.c_str() + at_;
    char* end = nullptr;
    const double value = std::strtod(start, &end);
    if (end == start) Fail("a number");
    at_ += static_cast<std::size_t>(end - start);
    auto node = Make(Kind::kNumber);
    node->number = value;
    return node;
  }

  static std::unique_ptr<Node> Binary(char op, std::unique_ptr<Node> left, std::unique_ptr<Node> right) {
    auto node = Make(Kind::kBinary);
    node->op = op;
    node->left = std::move(left);
    node->right = std::move(right);
    return node;
  }

  // In a pattern every `*` is a wildcard; elsewhere only one beside a dot (`metrics.*.x`,
  // `metrics.m*.x`), so that `a*b` and `a*2` multiply.
  std::string Word(const std::string& wanted, bool pattern) {
    Skip();
    if (at_ < text_.size() && text_[at_] == '`') {
      const std::size_t close = text_.find('`', at_ + 1);
      if (close == std::string::npos) Fail("a name opened with ` is not closed");
      if (close == at_ + 1) Fail("an empty name between backquotes");
      const std::string quoted = text_.substr(at_ + 1, close - at_ - 1);
      at_ = close + 1;
      return quoted;
    }
    const std::size_t start = at_;
    const auto wildcard = [&](std::size_t i) {
      return pattern || (i > start && text_[i - 1] == '.') || (i + 1 < text_.size() && text_[i + 1] == '.');
    };
    while (at_ < text_.size() && NameChar(text_[at_]) && (text_[at_] != '*' || wildcard(at_))) ++at_;
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

bool MatchesPattern(const std::string& pattern, const std::string& name) { return GlobMatches(pattern, name); }

bool IsPlainName(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), NameChar) &&
         (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_' || name[0] == '*');
}

std::string QuotedName(const std::string& name) { return IsPlainName(name) ? name : "`" + name + "`"; }

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

}  // namespace sanet::study
