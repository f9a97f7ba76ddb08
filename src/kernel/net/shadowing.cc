#include "net/shadowing.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/counter_random.h"

namespace sanet::net {
namespace {

constexpr std::uint64_t kShadowingKey = 0x5348414457ull;  // "SHADW": keeps these draws apart from others

struct WaveVector {
  double x, y;
};

// A wave vector of the isotropic spectrum of exp(-r / d) in the plane: its length from the
// inverse CDF, its direction a point of the unit disc drawn by rejection and scaled (no sine
// or cosine: this runs for every term of every evaluation).
WaveVector DrawWaveVector(CounterRandom& random, double d) {
  const double u = random.Uniform();
  const double k = std::sqrt(1 / ((1 - u) * (1 - u)) - 1) / d;
  double x, y, r2;
  do {
    x = 2 * random.Uniform() - 1;
    y = 2 * random.Uniform() - 1;
    r2 = x * x + y * y;
  } while (r2 > 1 || r2 == 0);
  const double scale = k / std::sqrt(r2);
  return {x * scale, y * scale};
}

}  // namespace

double ShadowingField::GainDb(std::uint32_t from, double ax, double ay, std::uint32_t to, double bx, double by) const {
  if (spec_.sigma_db <= 0) return 0;
  std::uint64_t direction = 0;
  if (spec_.symmetric && to < from) {
    std::swap(from, to);
    std::swap(ax, bx);
    std::swap(ay, by);
  } else if (!spec_.symmetric) {
    direction = 1;
  }
  CounterRandom random(seed_, {kShadowingKey, from, to, direction});
  const double d = spec_.correlation_m;
  double sum = 0;
  for (int i = 0; i < kTerms; ++i) {
    const WaveVector ka = DrawWaveVector(random, d), kb = DrawWaveVector(random, d);
    const double phase = 2 * M_PI * random.Uniform();
    sum += std::cos(ka.x * ax + ka.y * ay + kb.x * bx + kb.y * by + phase);
  }
  const double gain = spec_.sigma_db * std::sqrt(2.0 / kTerms) * sum;
  return std::clamp(gain, -MaxGainDb(), MaxGainDb());
}

}  // namespace sanet::net
