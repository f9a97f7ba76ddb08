// The server's clock for agents on other computers (a sanet extension): a UDP socket, served by
// a thread of its own so that a request is stamped the moment it arrives, not at the server's
// next poll (which would add up to a poll period to the error). A request carries the agent's
// send time; the reply adds the server's receive and send times on the run's clock (s since
// simulated time 0). hil/clock_sync is the agent's side; hil/clock_estimate the arithmetic.
//
//   request  (12 bytes): magic "sTQ1", t1 (f64, little-endian)
//   reply    (28 bytes): magic "sTR1", t1, t2, t3 (f64)
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <thread>

#include "sanet/message.h"
#include "wire/clock_estimate.h"

namespace sanet::wire {

Bytes TimeRequest(double sent);
std::optional<double> ReadTimeRequest(const std::uint8_t* data, std::size_t size);  // t1
Bytes TimeReply(double sent, double server_received, double server_sent);
// The exchange when `data` is a reply to a request sent at `sent`; nullopt otherwise.
std::optional<ClockExchange> ReadTimeReply(const std::uint8_t* data, std::size_t size, double sent, double received);

// This machine's monotonic clock, s.
double MonotonicSeconds();

class TimeService {
 public:
  // Listens on `bind`:`port` (UDP; 0 or a port taken: any free one). `origin`: the monotonic
  // clock at simulated time 0. Throws std::runtime_error naming the address and the reason.
  TimeService(const std::string& bind, std::uint16_t port, double origin);
  ~TimeService();
  TimeService(const TimeService&) = delete;
  TimeService& operator=(const TimeService&) = delete;
  std::uint16_t port() const { return port_; }
  std::uint64_t served() const { return served_; }

 private:
  void Serve();
  int fd_ = -1;
  std::uint16_t port_ = 0;
  double origin_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> served_{0};
  std::thread thread_;
};

}  // namespace sanet::wire
