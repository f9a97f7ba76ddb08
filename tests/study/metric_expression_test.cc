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
  // A star between names multiplies; only one beside a dot is a wildcard.
  EXPECT_DOUBLE_EQ(*Eval("metrics.mule.delivered.sum*2"), 90);
  EXPECT_DOUBLE_EQ(*Eval("ended_at_s*metrics.mule.delivered.sum"), 27000);
}

TEST(MetricExpression, AggregatesTakeTheMetricsAPatternMatchesWithinOneRun) {
  // `*` takes dots too: mule's metric "x.created" is one of them (node names may hold dots).
  EXPECT_DOUBLE_EQ(*Eval("sum(metrics.m*.created.count)"), 1060);
  EXPECT_DOUBLE_EQ(*Eval("mean(metrics.m1*.created.count)"), 25);
  EXPECT_DOUBLE_EQ(*Eval("min(metrics.m*.created.count)"), 10);
  EXPECT_DOUBLE_EQ(*Eval("max(metrics.m*.created.count)"), 1000);
  EXPECT_DOUBLE_EQ(*Eval("count(metrics.m*.created.count)"), 4);
  EXPECT_DOUBLE_EQ(*Eval("count(metrics.m1*.created.count)"), 2);
  EXPECT_DOUBLE_EQ(*Eval("count(*)"), 6);
  EXPECT_DOUBLE_EQ(*Eval("metrics.mule.delivered.sum / sum(metrics.m1*.created.count)"), 0.9);
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
  EXPECT_NE(message("avg(a.*)").find("'avg' is not an aggregate: sum, mean, min, max or count"), std::string::npos);
  EXPECT_NE(message("metrics.m*.x").find("aggregate it"), std::string::npos);
}

TEST(MetricExpression, ReadsAreListed) {
  const MetricExpression e = MetricExpression::Parse("a / sum(b.*.c) + mean(d.*)");
  EXPECT_EQ(e.names(), std::vector<std::string>{"a"});
  EXPECT_EQ(e.patterns(), (std::vector<std::string>{"b.*.c", "d.*"}));
}

TEST(MetricExpression, BackquotesHoldAnyName) {
  const RunMetrics run = {{"metrics.robot-1.hop time.mean", 4}, {"metrics.robot-2.hop time.mean", 6}, {"sum", 2}};
  EXPECT_DOUBLE_EQ(*Eval("`metrics.robot-1.hop time.mean` * 2", run), 8);
  EXPECT_DOUBLE_EQ(*Eval("mean(`metrics.*.hop time.mean`)", run), 5);
  EXPECT_DOUBLE_EQ(*Eval("`sum` + 1", run), 3) << "a quoted name is never an aggregate";
  EXPECT_EQ(QuotedName("metrics.m0.created.count"), "metrics.m0.created.count");
  EXPECT_EQ(QuotedName("metrics.robot-1.x"), "`metrics.robot-1.x`");
  EXPECT_EQ(QuotedName("2x"), "`2x`");
  EXPECT_THROW(MetricExpression::Parse("`open"), ExpressionError);
  EXPECT_THROW(MetricExpression::Parse("``"), ExpressionError);
}

TEST(NodeFold, ANodesPlaceBecomesAStarAndGetsItsStatisticsAggregate) {
  const std::set<std::string> nodes = {"m0", "mule", "q1", "nodes", "team", "team.a0", "robot-1"};
  EXPECT_EQ(NodePattern("metrics.m0.created.count", nodes), "metrics.*.created.count");
  EXPECT_EQ(NodePattern("energy.nodes.mule.used_j.total", nodes), "energy.nodes.*.used_j.total");
  // Only a node's place in the per-node sections: not a part that happens to be a node's name.
  EXPECT_EQ(NodePattern("message_delay_s.q1", nodes), "");
  EXPECT_EQ(NodePattern("metrics.mule.delay.q1", nodes), "metrics.*.delay.q1");
  EXPECT_EQ(NodePattern("energy.nodes.q1.remaining_j", nodes), "energy.nodes.*.remaining_j");
  EXPECT_EQ(NodePattern("network.packets.sent", nodes), "");
  // A node's name with dots: the longest that fits.
  EXPECT_EQ(NodePattern("metrics.team.a0.created.count", nodes), "metrics.*.created.count");
  EXPECT_EQ(NodePattern("metrics.team.created.count", nodes), "metrics.*.created.count");
  EXPECT_EQ(FoldedExpression(NodePattern("metrics.robot-1.hop time.mean", nodes)), "mean(`metrics.*.hop time.mean`)");
  EXPECT_EQ(FoldedExpression("metrics.*.created.count"), "sum(metrics.*.created.count)");
  EXPECT_EQ(FoldedExpression("metrics.*.created.sum"), "sum(metrics.*.created.sum)");
  EXPECT_EQ(FoldedExpression("metrics.*.delay.min"), "min(metrics.*.delay.min)");
  EXPECT_EQ(FoldedExpression("metrics.*.delay.max"), "max(metrics.*.delay.max)");
  EXPECT_EQ(FoldedExpression("metrics.*.delay.median"), "mean(metrics.*.delay.median)");
}

}  // namespace
}  // namespace sanet::study
