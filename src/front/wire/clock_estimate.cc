#include "wire/clock_estimate.h"

#include <algorithm>
#include <cmath>

namespace sanet::wire {

ClockSample SampleOf(const ClockExchange& e) {
  ClockSample s;
  s.at = (e.sent + e.received) / 2;
  s.offset = ((e.server_received - e.sent) + (e.server_sent - e.received)) / 2;
  s.round_trip = std::max(0.0, (e.received - e.sent) - (e.server_sent - e.server_received));
  return s;
}

void ClockEstimate::Add(const ClockSample& sample) {
  samples_.push_back(sample);
  if (samples_.size() > kKept) samples_.pop_front();
  Fit();
}

// Each sample weighted by the inverse square of its round trip: a queued exchange counts little.
// A floor of 10 us keeps one lucky sample from outweighing all the others.
double ClockEstimate::Weight(const ClockSample& s) const {
  constexpr double kFloor = 10e-6;
  return 1 / std::pow(std::max(s.round_trip, kFloor), 2);
}

double ClockEstimate::ValueCoefficient(const ClockSample& s, double x) const {
  const double xi = s.at - reference_;
  if (!fitted_) return Weight(s) / sums_.w;
  return Weight(s) * ((sums_.xx - sums_.x * xi) + x * (sums_.w * xi - sums_.x)) / sums_.Spread();
}

double ClockEstimate::SlopeCoefficient(const ClockSample& s) const {
  return Weight(s) * (sums_.w * (s.at - reference_) - sums_.x) / sums_.Spread();
}

// Weighted least squares; the slope is fitted only once the samples pin it down better than
// kUnknownDrift (its error is at most the sum of its coefficients times the half round trips).
void ClockEstimate::Fit() {
  reference_ = samples_.back().at;
  sums_ = {};
  for (const ClockSample& s : samples_) {
    const double w = Weight(s), x = s.at - reference_;
    sums_.w += w, sums_.x += w * x, sums_.y += w * s.offset, sums_.xx += w * x * x, sums_.xy += w * x * s.offset;
  }
  fitted_ = false;
  if (samples_.size() >= 2 && sums_.Spread() > 0) {
    double slope_error = 0;
    for (const ClockSample& s : samples_) slope_error += std::abs(SlopeCoefficient(s)) * s.round_trip / 2;
    fitted_ = slope_error < kUnknownDrift;
  }
  slope_ = fitted_ ? (sums_.w * sums_.xy - sums_.x * sums_.y) / sums_.Spread() : 0;
  intercept_ = (sums_.y - slope_ * sums_.x) / sums_.w;
}

double ClockEstimate::ErrorBound(double local) const {
  const double x = local - reference_;
  double bound = 0;
  for (const ClockSample& s : samples_) bound += std::abs(ValueCoefficient(s, x)) * s.round_trip / 2;
  if (!fitted_) bound += kUnknownDrift * std::abs(x - sums_.x / sums_.w);
  return bound;
}

}  // namespace sanet::wire
