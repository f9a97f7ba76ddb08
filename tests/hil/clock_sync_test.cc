#include "usarsim_agent/clock_sync.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "wire/clock_estimate.h"
#include "wire/time_service.h"

namespace sanet::usarsim_agent {
namespace {

// A server whose clock is `offset` ahead of the agent's and gains `drift` s per s, reached over a
// path whose two directions take different, random times (exponential queueing on top of a base).
struct Path {
  double offset, drift, base_out, base_back, queueing;
  std::mt19937 random{7};
  double Server(double local) { return local + offset + drift * local; }
  double Delay(double base) { return base + std::exponential_distribution<double>(1 / queueing)(random); }
  wire::ClockExchange Exchange(double t1) {
    const double out = Delay(base_out), back = Delay(base_back), at_server = 20e-6;
    wire::ClockExchange e;
    e.sent = t1;
    e.server_received = Server(t1 + out);
    e.server_sent = e.server_received + at_server;
    e.received = t1 + out + at_server + back;
    return e;
  }
};

TEST(ClockEstimate, ASymmetricExchangeGivesTheOffsetExactly) {
  wire::ClockExchange e{10.0, 1010.0003, 1010.0004, 10.0007};  // 0.3 ms each way, 0.1 ms at the server
  const wire::ClockSample s = wire::SampleOf(e);
  EXPECT_NEAR(s.offset, 1000.0, 1e-9);
  EXPECT_NEAR(s.round_trip, 0.0006, 1e-9);
}

TEST(ClockEstimate, AnAsymmetricPathIsWrongByAtMostHalfTheRoundTrip) {
  wire::ClockExchange e{10.0, 1010.0009, 1010.0009, 10.001};  // 0.9 ms out, 0.1 ms back
  const wire::ClockSample s = wire::SampleOf(e);
  EXPECT_NEAR(s.offset, 1000.0004, 1e-9);
  EXPECT_LE(std::abs(s.offset - 1000.0), s.round_trip / 2 + 1e-12);
}

TEST(ClockEstimate, TheShortestRoundTripOfABurstCounts) {
  const std::vector<wire::ClockExchange> burst{{0, 5.004, 5.004, 0.005}, {1, 6.0001, 6.0001, 1.0002}};
  const auto best = wire::Best(burst);
  ASSERT_TRUE(best);
  EXPECT_NEAR(best->offset, 5.0, 1e-9);
  EXPECT_FALSE(wire::Best(std::vector<wire::ClockExchange>{}));
}

// A LAN: 0.1-0.2 ms each way, queueing 0.3 ms on average, an oscillator 40 ppm fast, a clock
// 1000 s off. After a minute of bursts the estimate is within its bound, the bound under 1 ms,
// and the drift found within a few ppm.
TEST(ClockEstimate, FollowsOffsetAndDriftWithinItsBound) {
  Path path{-1000.25, 40e-6, 100e-6, 200e-6, 300e-6};
  wire::ClockEstimate estimate;
  int outside = 0;
  for (int second = 0; second < 90; ++second) {
    std::vector<wire::ClockExchange> burst;
    for (int i = 0; i < 4; ++i) burst.push_back(path.Exchange(second + i * 0.001));
    estimate.Add(*wire::Best(burst));
    const double now = second + 0.9;  // just before the next burst
    const double error = std::abs(estimate.Offset(now) - (path.Server(now) - now));
    EXPECT_LT(estimate.ErrorBound(now), 1e-3) << "at " << second << " s";
    if (error > estimate.ErrorBound(now)) ++outside;
  }
  EXPECT_EQ(outside, 0);
  EXPECT_NEAR(estimate.Drift(), 40e-6, 5e-6);
}

TEST(ClockEstimate, WithoutDriftEstimateItsSlopeIsZeroUntilTheSamplesSpanEnoughTime) {
  wire::ClockEstimate estimate;
  estimate.Add({0, 3.0, 0.001});
  estimate.Add({1, 3.001, 0.001});
  EXPECT_EQ(estimate.Drift(), 0);
  EXPECT_NEAR(estimate.Offset(1), 3.0005, 1e-9);
}

// The service and an agent's sync over loopback: an agent clock 1000 s off is found to well
// under a millisecond, and the server's time read through it matches the server's clock.
TEST(ClockSync, FindsTheServersClockOverUdp) {
  const double origin = wire::MonotonicSeconds() - 5;  // the run started 5 s ago
  wire::TimeService service("127.0.0.1", 0, origin);
  ClockSync sync("127.0.0.1", service.port(), 1000);
  const ClockFigures f = sync.figures();
  EXPECT_NEAR(f.offset, -origin - 1000, f.error_bound + 1e-9);
  EXPECT_LT(f.error_bound, 1e-3);
  EXPECT_GE(f.exchanges, static_cast<std::uint64_t>(ClockSync::kFirstBurst));
  // The server's clock read through the estimate lies between two readings of the truth, give or
  // take the bound (however long the process was kept from running in between).
  const double before = wire::MonotonicSeconds() - origin;
  const double now = sync.ServerNow();
  const double after = wire::MonotonicSeconds() - origin;
  const double bound = sync.figures().error_bound;
  EXPECT_GE(now, before - bound);
  EXPECT_LE(now, after + bound);
  EXPECT_GE(service.served(), f.exchanges);
}

TEST(ClockSync, SaysWhenTheServerDoesNotAnswer) {
  std::uint16_t nobody = 0;
  {
    wire::TimeService closed("127.0.0.1", 0, 0);
    nobody = closed.port();
  }  // nothing listens there now
  try {
    ClockSync sync("127.0.0.1", nobody);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("does not answer"), std::string::npos) << e.what();
  }
}

TEST(TimePackets, AReplyToAnotherRequestIsNotTaken) {
  const Bytes reply = wire::TimeReply(1.5, 10, 10.1);
  EXPECT_TRUE(wire::ReadTimeReply(reply.data(), reply.size(), 1.5, 2));
  EXPECT_FALSE(wire::ReadTimeReply(reply.data(), reply.size(), 1.25, 2));
  EXPECT_FALSE(wire::ReadTimeReply(reply.data(), reply.size() - 1, 1.5, 2));
  const Bytes request = wire::TimeRequest(3.25);
  EXPECT_EQ(wire::ReadTimeRequest(request.data(), request.size()), 3.25);
  EXPECT_FALSE(wire::ReadTimeRequest(reply.data(), reply.size()));
}

}  // namespace
}  // namespace sanet::usarsim_agent
