// How far the server's clock is from this computer's, estimated as NTP does (RFC 5905, section
// 8): each exchange of timestamps gives an offset and a round trip, and the offset is wrong by
// at most half the round trip (the two directions may take unequal times). Of each burst of
// exchanges only the one with the shortest round trip counts (the least queued); over the run a
// line through those samples, weighted by how sharp each is, gives the offset and the drift of
// this computer's oscillator against the server's. Pure arithmetic: hil/clock_sync does the
// exchanges.
#pragma once

#include <deque>
#include <optional>

namespace sanet::hil {

// One exchange: t1 sent here, t2 received there, t3 sent there, t4 received here (s; t1 and t4
// on this computer's clock, t2 and t3 on the server's).
struct ClockExchange {
  double sent = 0, server_received = 0, server_sent = 0, received = 0;
};

struct ClockSample {
  double at = 0;          // this computer's clock, midway through the exchange
  double offset = 0;      // server's clock minus this computer's
  double round_trip = 0;  // network time there and back, without the server's own time
};

ClockSample SampleOf(const ClockExchange& e);

class ClockEstimate {
 public:
  // The best exchange of a burst (see Best).
  void Add(const ClockSample& sample);
  bool Known() const { return !samples_.empty(); }
  // The server's clock minus this computer's, at `local` on this computer's clock.
  double Offset(double local) const { return intercept_ + slope_ * (local - reference_); }
  // How wrong Offset(local) may be: half the sharpest recent round trip, plus how far the latest
  // sample strays from the line (what the line does not explain), plus what the drift's
  // uncertainty adds since the latest sample.
  double ErrorBound(double local) const;
  double Drift() const { return slope_; }  // s per s (1e-6 is 1 ppm)
  const ClockSample& Latest() const { return samples_.back(); }

  // Samples kept for the line (about a minute at one burst a second).
  static constexpr std::size_t kKept = 64;
  // Until the samples span enough time to measure the drift better than this, it is taken as 0
  // and this is its uncertainty: the tolerance of a computer's quartz oscillator (tens of ppm).
  static constexpr double kUnknownDrift = 100e-6;  // s per s

 private:
  void Fit();
  std::deque<ClockSample> samples_;
  double reference_ = 0, intercept_ = 0, slope_ = 0, error_bound_ = 0, drift_uncertainty_ = kUnknownDrift;
};

// The exchange of a burst with the shortest round trip; nullopt for an empty burst.
template <typename Exchanges>
std::optional<ClockSample> Best(const Exchanges& burst) {
  std::optional<ClockSample> best;
  for (const ClockExchange& e : burst) {
    const ClockSample s = SampleOf(e);
    if (!best || s.round_trip < best->round_trip) best = s;
  }
  return best;
}

}  // namespace sanet::hil
