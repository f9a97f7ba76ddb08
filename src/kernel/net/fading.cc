#include "net/fading.h"

#include <algorithm>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/random/gamma_distribution.hpp>
#include <cmath>

#include "core/counter_random.h"

namespace sanet::net {
namespace {

constexpr std::uint64_t kFadingKey = 0x46414445ull;  // "FADE"

}  // namespace

NakagamiFading::NakagamiFading(std::uint64_t seed, const Fading& spec)
    : seed_(seed), m_(spec.model == FadingModel::kRayleigh ? 1.0 : spec.m) {
  // The power gain is Gamma(m, 1/m): its quantile is the regularised incomplete gamma's inverse over m.
  cap_db_ = GainQuantileDb(1 - kCapTail);
}

double NakagamiFading::GainQuantileDb(double q) const { return 10 * std::log10(boost::math::gamma_p_inv(m_, q) / m_); }

double NakagamiFading::Draw(std::uint32_t from, std::uint32_t to, std::int64_t instant) const {
  CounterRandom random(seed_, {kFadingKey, from, to, static_cast<std::uint64_t>(instant)});
  boost::random::gamma_distribution<double> gamma(m_, 1 / m_);
  return gamma(random);
}

double NakagamiFading::GainDb(std::uint32_t from, std::uint32_t to, std::int64_t instant) const {
  constexpr double kDeepestDb = -300;  // a draw of 0 would be -infinity
  return std::clamp(10 * std::log10(Draw(from, to, instant)), kDeepestDb, cap_db_);
}

}  // namespace sanet::net
