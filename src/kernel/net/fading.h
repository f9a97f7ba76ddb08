// Fast fading, frame by frame: the power a frame arrives with is its mean (path loss, walls,
// shadowing) times a gain drawn from Nakagami's distribution (M. Nakagami, "The m-distribution: a
// general formula of intensity distribution of rapid fading", 1960). In power, Nakagami-m is a
// Gamma distribution of shape m and mean 1; m = 1 is Rayleigh fading (an exponential power). It is
// the distribution ns-3's NakagamiPropagationLossModel draws (Gamma(m, P/m) in watts, one m here
// where ns-3 switches among three by distance), and a test checks the two draw alike.
//
// ns-3's model takes its draws from one sequential stream, so whoever asks first changes what the
// others get: YansWifiChannel asks for every radio, the indexed channel only for candidates. Here
// a frame's gain is drawn from (seed, sender, receiver, the instant the frame starts), which is
// the same whoever asks (core/counter_random.h): a sender starts at most one frame per instant.
//
// Gains above the (1 - kCapTail) quantile are capped, so that a frame never reaches farther than
// the indexed channel's ranges allow (MaxGainDb; docs/network.md#fading).
#pragma once

#include <cstdint>

#include "net/network_spec.h"

namespace sanet::net {

class NakagamiFading {
 public:
  static constexpr double kCapTail = 1e-4;  // the share of draws the cap cuts

  NakagamiFading(std::uint64_t seed, const Fading& spec);
  // The gain (dB) of the frame that `from` starts sending at `instant` (ns-3 time steps) to `to`.
  double GainDb(std::uint32_t from, std::uint32_t to, std::int64_t instant) const;
  // The gain (a power ratio, mean 1) before it is capped.
  double Draw(std::uint32_t from, std::uint32_t to, std::int64_t instant) const;
  double MaxGainDb() const { return cap_db_; }
  // The gain (dB) that a share `q` of the frames fade less than.
  double GainQuantileDb(double q) const;
  double m() const { return m_; }

 private:
  std::uint64_t seed_;
  double m_;
  double cap_db_;
};

}  // namespace sanet::net
