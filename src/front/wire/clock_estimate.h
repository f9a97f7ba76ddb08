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

namespace sanet::wire {

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
  // How wrong Offset(local) may be. Each sample's offset is wrong by at most half its round trip
  // (however unequal the two directions); the line's value at `local` is a sum of the samples'
  // offsets with known coefficients, so its error is at most the same sum of those half round
  // trips, taken absolutely. Without a fitted drift, the oscillator's possible drift since the
  // samples' weighted mean time is added.
  double ErrorBound(double local) const;
  double Drift() const { return slope_; }  // s per s (1e-6 is 1 ppm)
  const ClockSample& Latest() const { return samples_.back(); }

  // Samples kept for the line (about a minute at one burst a second).
  static constexpr std::size_t kKept = 64;
  // Until the samples pin the drift down better than this, it is taken as 0 and this is its
  // uncertainty: the tolerance of a computer's quartz oscillator (tens of ppm).
  static constexpr double kUnknownDrift = 100e-6;  // s per s

 private:
  struct Sums {  // of the weighted least squares, x measured from reference_
    double w = 0, x = 0, y = 0, xx = 0, xy = 0;
    double Spread() const { return w * xx - x * x; }
  };
  double Weight(const ClockSample& s) const;
  // The coefficient of sample `s` in the line's value at x (from reference_), and in its slope.
  double ValueCoefficient(const ClockSample& s, double x) const;
  double SlopeCoefficient(const ClockSample& s) const;
  void Fit();
  std::deque<ClockSample> samples_;
  Sums sums_;
  bool fitted_ = false;  // the slope is measured, not taken as 0
  double reference_ = 0, intercept_ = 0, slope_ = 0;
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

}  // namespace sanet::wire
