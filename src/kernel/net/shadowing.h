// Log-normal shadowing that is a property of places, not of moments: the shadowing of a link is
// a Gaussian random field over the positions of its two ends, drawn from the run's seed and the
// link, with Gudmundson's exponential correlation (M. Gudmundson, "Correlation model for shadow
// fading in mobile radio systems", Electronics Letters 27(23), 1991):
//
//   E[S(a, b) S(a', b')] = sigma^2 * exp(-|a - a'| / d) * exp(-|b - b'| / d)
//
// with d = `correlation_m`. One end moving is Gudmundson's case (the correlation decays with the
// distance it moved); both ends moving multiply the two decays. A link whose ends stand still
// keeps its shadowing; a robot driving past a mote sees it fade and return over about d metres.
//
// The field is a sum of kTerms random cosines whose wave vectors are drawn from the spectrum of
// that correlation (the spectral method of Shinozuka and Deodatis, "Simulation of stochastic
// processes by spectral representation", Applied Mechanics Reviews 44(4), 1991): in the plane, the
// spectrum of exp(-r/d) is proportional to (1 + d^2 k^2)^(-3/2), whose wave numbers have the
// inverse CDF k = sqrt((1 - u)^-2 - 1) / d. The sum's covariance is exactly the one above; its
// values are Gaussian to within the central limit theorem over kTerms cosines (excess kurtosis
// -1.5 / kTerms). Every term is drawn from the link and the seed alone (core/counter_random.h),
// so the value at a place never depends on who asked before. Values are clipped at
// +-`clip_sigmas` sigma. Positions are on the ground plane (x, y).
#pragma once

#include <cstdint>

#include "net/network_spec.h"

namespace sanet::net {

class ShadowingField {
 public:
  static constexpr int kTerms = 32;

  ShadowingField(std::uint64_t seed, const Shadowing& spec) : seed_(seed), spec_(spec) {}
  // dB added to what node `from` at (ax, ay) sends to node `to` at (bx, by). With a symmetric
  // spec the answer is the same both ways.
  double GainDb(std::uint32_t from, double ax, double ay, std::uint32_t to, double bx, double by) const;
  // The most the field ever adds (dB).
  double MaxGainDb() const { return spec_.sigma_db * spec_.clip_sigmas; }
  bool symmetric() const { return spec_.symmetric; }

 private:
  std::uint64_t seed_;
  Shadowing spec_;
};

}  // namespace sanet::net
