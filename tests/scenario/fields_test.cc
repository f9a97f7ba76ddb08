// Field declarations: numbers print short and read back exactly; a section reads only its
// declared keys, with the declared ranges, and prints every field.
#include "scenario/fields.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "scenario/declarations.h"

namespace sanet::scenario {
namespace {

TEST(Fields, NumbersPrintShortAndReadBackExactly) {
  EXPECT_EQ(ShortNumber(0.005), "0.005");
  EXPECT_EQ(ShortNumber(10000), "10000");
  EXPECT_EQ(ShortNumber(1e6), "1e6");
  EXPECT_EQ(ShortNumber(1e-6), "1e-6");
  EXPECT_EQ(ShortNumber(-82), "-82");
  EXPECT_EQ(ShortNumber(0), "0");
  for (double v : {kPi, 46.6777, 0.1 + 0.2, -1.0 / 3, 123456.789, 2.5e-7, 0.4475})
    EXPECT_EQ(std::strtod(ShortNumber(v).c_str(), nullptr), v) << ShortNumber(v);
}

struct Sample {
  double a = 1;
  bool b = false;
};

Fields<Sample> SampleFields() {
  Fields<Sample> f;
  f.Number(
      "a", [](Sample& s) -> double& { return s.a; }, "m", 0, 5, "a length", true);
  f.Flag(
      "b", [](Sample& s) -> bool& { return s.b; }, "a switch");
  return f;
}

Field Yaml(const std::string& text) {
  const std::string path = ::testing::TempDir() + "/fields.yaml";
  std::ofstream(path) << text;
  return ParseYamlFile(path);
}

TEST(Fields, ReadsDeclaredKeysWithTheirRanges) {
  Sample s;
  SampleFields().Read(Yaml("a: 2.5\nb: true\n"), s);
  EXPECT_EQ(s.a, 2.5);
  EXPECT_TRUE(s.b);
  EXPECT_THROW(SampleFields().Read(Yaml("a: 0\n"), s), ScenarioError) << "the range is (0, 5]";
  try {
    SampleFields().Read(Yaml("c: 1\n"), s);
    FAIL() << "an undeclared key must be refused";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.field(), "c");
    EXPECT_NE(e.message().find("expected one of: a, b"), std::string::npos);
  }
}

TEST(Fields, DescribeAndPrintUseTheDeclaration) {
  const auto info = SampleFields().Describe(Sample{});
  ASSERT_EQ(info.size(), 2u);
  EXPECT_EQ(info[0].default_text, "`1`");
  EXPECT_EQ(info[0].range, "(0, 5]");
  EXPECT_EQ(info[1].type, "boolean");
  const YAML::Node printed = SampleFields().Print(Sample{3, true});
  EXPECT_EQ(printed["a"].as<double>(), 3);
  EXPECT_TRUE(printed["b"].as<bool>());
}

TEST(Fields, EveryDeclaredTableHasItsDefaults) {
  for (const SectionTable& t : SectionTables())
    for (const FieldInfo& f : t.fields) {
      EXPECT_FALSE(f.default_text.empty()) << t.name << "." << f.key;
      EXPECT_FALSE(f.type.empty()) << t.name << "." << f.key;
    }
}

}  // namespace
}  // namespace sanet::scenario
