#include "core/random_stream.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sanet {
namespace {

TEST(RandomStream, SameSeedAndNameGiveTheSameNumbers) {
  RandomStream a(7, "node/1/ir"), b(7, "node/1/ir");
  for (int i = 0; i < 100; ++i) ASSERT_EQ(a.NextU64(), b.NextU64());
}

TEST(RandomStream, OtherNameOrSeedGivesOtherNumbers) {
  RandomStream a(7, "node/1/ir"), b(7, "node/2/ir"), c(8, "node/1/ir");
  const auto x = a.NextU64();
  EXPECT_NE(x, b.NextU64());
  EXPECT_NE(x, c.NextU64());
}

TEST(RandomStream, GaussianHasTheRequestedMeanAndDeviation) {
  RandomStream r(1, "g");
  double sum = 0, sq = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double g = r.Gaussian(2.0, 0.5);
    sum += g;
    sq += g * g;
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, 2.0, 0.01);
  EXPECT_NEAR(std::sqrt(sq / n - mean * mean), 0.5, 0.01);
}

TEST(RandomStream, UniformStaysInUnitInterval) {
  RandomStream r(3, "u");
  for (int i = 0; i < 10000; ++i) {
    const double u = r.Uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
}

}  // namespace
}  // namespace sanet
