#include "hil/clock_estimate.h"

#include <algorithm>
#include <cmath>

namespace sanet::hil {

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

// Weighted least squares, each sample weighted by the inverse square of its round trip (a
// sample from a queued exchange counts little); a floor of 10 us keeps one lucky sample from
// outweighing the rest. The slope is fitted only once two samples, each wrong by up to half the
// sharpest round trip, pin it down better than kUnknownDrift.
void ClockEstimate::Fit() {
  constexpr double kFloor = 10e-6;
  const ClockSample& latest = samples_.back();
  double sharpest = latest.round_trip;
  const std::size_t recent = std::min<std::size_t>(samples_.size(), 8);
  for (std::size_t i = samples_.size() - recent; i < samples_.size(); ++i)
    sharpest = std::min(sharpest, samples_[i].round_trip);
  reference_ = latest.at;
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ClockSample& s : samples_) {
    const double w = 1 / std::pow(std::max(s.round_trip, kFloor), 2), x = s.at - reference_;
    sw += w, sx += w * x, sy += w * s.offset, sxx += w * x * x, sxy += w * x * s.offset;
  }
  const double span = latest.at - samples_.front().at, spread = sw * sxx - sx * sx;
  const double measured = span > 0 ? std::max(sharpest, kFloor) / span : kUnknownDrift;
  const bool fitted = measured < kUnknownDrift && spread > 0;
  slope_ = fitted ? (sw * sxy - sx * sy) / spread : 0;
  drift_uncertainty_ = fitted ? measured : kUnknownDrift;
  intercept_ = (sy - slope_ * sx) / sw;
  error_bound_ = sharpest / 2 + std::abs(latest.offset - intercept_);
}

double ClockEstimate::ErrorBound(double local) const {
  return error_bound_ + drift_uncertainty_ * std::abs(local - reference_);
}

}  // namespace sanet::hil
