#include "sanet/params.h"

#include <gtest/gtest.h>

namespace sanet {
namespace {

ParamValue Value(std::string text, int line) {
  ParamValue v;
  v.rows = {{std::move(text)}};
  v.line = line;
  return v;
}

TEST(Params, ReadsTypedValuesAndDefaults) {
  Params p;
  p.Set("speed", Value("0.5", 3));
  p.Set("loop", Value("true", 4));
  EXPECT_DOUBLE_EQ(p.Number("speed", 1, 0, 2), 0.5);
  EXPECT_TRUE(p.Flag("loop", false));
  EXPECT_EQ(p.Text("mode", "fast"), "fast");
  EXPECT_NO_THROW(p.CheckAllUsed());
}

TEST(Params, OutOfRangeNamesKeyAndLine) {
  Params p;
  p.Set("speed", Value("-3", 7));
  try {
    p.Number("speed", 1, 0, 2);
    FAIL() << "no error";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "speed");
    EXPECT_EQ(e.line(), 7);
    EXPECT_NE(std::string(e.what()).find(">= 0"), std::string::npos) << e.what();
  }
}

TEST(Params, NotANumberIsRejected) {
  Params p;
  p.Set("speed", Value("fast", 2));
  EXPECT_THROW(p.Number("speed", 1), ParamError);
}

TEST(Params, UnreadKeyIsUnknown) {
  Params p;
  p.Set("sped", Value("1", 9));
  p.Number("speed", 1);
  try {
    p.CheckAllUsed();
    FAIL() << "no error";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "sped");
    EXPECT_EQ(e.line(), 9);
  }
}

TEST(Params, TableNeedsRowsOfTheRightWidth) {
  Params p;
  ParamValue v;
  v.shape = ParamValue::Shape::kTable;
  v.rows = {{"1", "2"}, {"3"}};
  p.Set("waypoints", v);
  EXPECT_THROW(p.Table("waypoints", 2, {}), ParamError);
}

}  // namespace
}  // namespace sanet
