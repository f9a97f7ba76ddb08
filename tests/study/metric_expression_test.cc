#include "study/metric_expression.h"

#include <gtest/gtest.h>

#include "study/node_fold.h"

namespace sanet::study {
namespace {

const RunMetrics kRun = {{"ended_at_s", 600},
                         {"metrics.m0.created.count", 10},
                         {"metrics.m1.created.count", 30},
                         {"metrics.m12.created.count", 20},
                         {"metrics.mule.delivered.sum", 45},
                         {"metrics.mule.x.created.count", 1000}};

std::optional<double> Eval(const std::string& text, const RunMetrics& run = kRun) {
  return MetricExpression::Parse(text).Evaluate(run, nullptr);
}

TEST(MetricExpression, ArithmeticKeepsPrecedenceAndOrder) {
  EXPECT_DOUBLE_EQ(*Eval("1 + 2 * 3"), 7);
  EXPECT_DOUBLE_EQ(*Eval("(1 + 2) * 3"), 9);
  EXPECT_DOUBLE_EQ(*Eval("10 - 4 - 3"), 3);
  EXPECT_DOUBLE_EQ(*Eval("12 / 4 / 3"), 1);
  EXPECT_DOUBLE_EQ(*Eval("-2 * -3"), 6);
  EXPECT_DOUBLE_EQ(*Eval("ended_at_s - 500"), 100);
  EXPECT_DOUBLE_EQ(*Eval("1/(ended_at_s-590)"), 0.1);
  EXPECT_DOUBLE_EQ(*Eval("2.5e1"), 25);
}

TEST(MetricExpression, AggregatesTakeTheMetricsAPatternMatchesWithinOneRun) {
  EXPECT_DOUBLE_EQ(*Eval("sum(metrics.m*.created.count)"), 60);  // not mule.x: one part each
  EXPECT_DOUBLE_EQ(*Eval("mean(metrics.m*.created.count)"), 20);
  EXPECT_DOUBLE_EQ(*Eval("min(metrics.m*.created.count)"), 10);
  EXPECT_DOUBLE_EQ(*Eval("max(metrics.m*.created.count)"), 30);
  EXPECT_DOUBLE_EQ(*Eval("count(metrics.m*.created.count)"), 3);
  EXPECT_DOUBLE_EQ(*Eval("count(metrics.m1*.created.count)"), 2);
  EXPECT_DOUBLE_EQ(*Eval("metrics.mule.delivered.sum / sum(metrics.*.created.count)"), 0.75);
}

TEST(MetricExpression, ARunWithoutWhatItNeedsHasNoValue) {
  EXPECT_FALSE(Eval("absent + 1"));
  EXPECT_FALSE(Eval("1 / (ended_at_s - 600)"));
  EXPECT_FALSE(Eval("mean(metrics.*.nothing.count)"));
  EXPECT_DOUBLE_EQ(*Eval("sum(metrics.*.nothing.count)"), 0);
  EXPECT_DOUBLE_EQ(*Eval("count(metrics.*.nothing.count)"), 0);
}

TEST(MetricExpression, DerivedNamesComeFromTheCaller) {
  const auto derived = [](const std::string& name, const RunMetrics& run) -> std::optional<double> {
    if (name == "total") return run.at("ended_at_s") * 2;
    return std::nullopt;
  };
  EXPECT_DOUBLE_EQ(*MetricExpression::Parse("total / 4").Evaluate(kRun, derived), 300);
}

TEST(MetricExpression, MistakesAreNamedWithTheirPlace) {
  const auto message = [](const std::string& text) {
    try {
      MetricExpression::Parse(text);
    } catch (const ExpressionError& e) {
      return std::string(e.what());
    }
    return std::string("parsed");
  };
  EXPECT_NE(message("sum(").find("at character 5"), std::string::npos);
  EXPECT_NE(message("a + ").find("expected"), std::string::npos);
  EXPECT_NE(message("metrics.*.x.count").find("aggregate it, e.g. sum(metrics.*.x.count)"), std::string::npos);
  EXPECT_NE(message("(a").find("')' expected"), std::string::npos);
  EXPECT_NE(message("a b").find("'b' where an operator or the end belongs"), std::string::npos);
}

TEST(MetricExpression, ReadsAreListed) {
  const MetricExpression e = MetricExpression::Parse("a / sum(b.*.c) + mean(d.*)");
  EXPECT_EQ(e.names(), std::vector<std::string>{"a"});
  EXPECT_EQ(e.patterns(), (std::vector<std::string>{"b.*.c", "d.*"}));
  EXPECT_FALSE(e.IsPlainName());
  EXPECT_TRUE(MetricExpression::Parse("ended_at_s").IsPlainName());
}

TEST(NodeFold, ANodesPartBecomesAStarAndGetsItsStatisticsAggregate) {
  const std::set<std::string> nodes = {"m0", "mule"};
  EXPECT_EQ(NodePattern("metrics.m0.created.count", nodes), "metrics.*.created.count");
  EXPECT_EQ(NodePattern("energy.nodes.mule.used_j.total", nodes), "energy.nodes.*.used_j.total");
  EXPECT_EQ(NodePattern("mule.x", nodes), "");  // the first part is never a node's
  EXPECT_EQ(NodePattern("network.packets.sent", nodes), "");
  EXPECT_EQ(FoldedExpression("metrics.*.created.count"), "sum(metrics.*.created.count)");
  EXPECT_EQ(FoldedExpression("metrics.*.created.sum"), "sum(metrics.*.created.sum)");
  EXPECT_EQ(FoldedExpression("metrics.*.delay.min"), "min(metrics.*.delay.min)");
  EXPECT_EQ(FoldedExpression("metrics.*.delay.max"), "max(metrics.*.delay.max)");
  EXPECT_EQ(FoldedExpression("metrics.*.delay.median"), "mean(metrics.*.delay.median)");
}

}  // namespace
}  // namespace sanet::study
