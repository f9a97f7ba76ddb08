// An agent's estimate of the server's clock when the two do not share one (another computer):
// timestamp exchanges with the server's time service (wire/time_service.h), a first burst before
// the agent starts, then a burst every second from a thread of its own, so that the estimate
// follows the drift of this computer's oscillator through the run.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "wire/clock_estimate.h"

namespace sanet::usarsim_agent {

struct ClockFigures {
  double offset = 0;           // s, the server's clock minus this computer's
  double error_bound = 0;      // s, how wrong the estimate may be now
  double error_bound_max = 0;  // s, the largest bound since the first burst
  double round_trip = 0;       // s, of the latest burst's best exchange
  double drift = 0;            // s per s
  std::uint64_t bursts = 0, exchanges = 0, unanswered = 0;
};

class ClockSync {
 public:
  // `skew`: added to this computer's clock (tests: an agent whose clock is far off). Throws
  // std::runtime_error when the server does not answer within a few seconds.
  ClockSync(const std::string& host, std::uint16_t port, double skew = 0);
  ~ClockSync();
  ClockSync(const ClockSync&) = delete;
  ClockSync& operator=(const ClockSync&) = delete;
  // The server's clock now (s since simulated time 0), never going back.
  double ServerNow() const;
  ClockFigures figures() const;

  static constexpr int kFirstBurst = 16, kBurst = 4;
  static constexpr double kRefreshPeriod = 1.0;  // s

 private:
  double Local() const;
  std::optional<wire::ClockSample> Burst(int exchanges);
  void Take(const wire::ClockSample& best);
  void Refresh();

  int fd_ = -1;
  std::string server_;
  double skew_;
  mutable std::mutex mutex_;
  wire::ClockEstimate estimate_;
  ClockFigures figures_;
  mutable double last_read_ = -1e300;
  bool stop_ = false;
  std::condition_variable wake_;
  std::thread thread_;
};

}  // namespace sanet::usarsim_agent
