// The abstract radio's channel against its calibration: shares of frames delivered at each
// receiver's mean power, nothing under the weakest power heard, unicasts only at their addressee,
// the access delay, and the same draws whatever else happens.
#include "net/abstract_channel.h"

#include <gtest/gtest.h>
#include <ns3/constant-position-mobility-model.h>
#include <ns3/node-container.h>
#include <ns3/propagation-loss-model.h>
#include <ns3/simple-net-device.h>
#include <ns3/simulator.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "net/wireless_network.h"
#include "scenario/scenario_loader.h"
#include "sim/world.h"
#include "support/test_world.h"

namespace sanet::net {
namespace {

constexpr double kTxPower = 10;  // dBm
constexpr int kFrames = 2000;
constexpr int kBytes = 20;  // each frame's packet
// The devices set no data rate (no serialization): the channel adds the whole frame's airtime
// beyond it, the preamble and the MAC's bytes, and for a broadcast its bytes at the lower rate.
constexpr double kPreamble = 192e-6, kDataRate = 2e6, kBroadcastRate = 1e6;
double UnicastAirtime() { return kPreamble + AbstractChannel::kMacOverhead * 8 / kDataRate; }
double BroadcastAirtime() {
  return kPreamble + AbstractChannel::kMacOverhead * 8 / kBroadcastRate +
         kBytes * 8 * (1 / kBroadcastRate - 1 / kDataRate);
}

// PRR 1 at -70 dBm and above, falling linearly to 0 at -90 dBm; 2 ms of access delay at -70,
// 4 ms at -90. Unicasts (at a higher rate) need 5 dB more.
LinkCalibration Calibration() {
  LinkCalibration c;
  c.rows = {{-100, 0, 0.004, 0},   {-90, 0, 0.004, 0}, {-85, 0.25, 0.0035, 0}, {-80, 0.5, 0.003, 0.25},
            {-70, 1, 0.002, 0.75}, {-65, 1, 0.002, 1}, {-40, 1, 0.002, 1}};
  return c;
}

// The mean power at `d` m from the sender, by ns-3's log-distance default (46.6777 dB at 1 m, n 3).
double MeanPower(double d) { return kTxPower - 46.6777 - 30 * std::log10(d); }

struct Field {
  ns3::NodeContainer nodes;
  ns3::Ptr<AbstractChannel> channel = ns3::CreateObject<AbstractChannel>();
  std::vector<ns3::Ptr<ns3::SimpleNetDevice>> devices;
  std::vector<std::vector<double>> arrivals;  // per node, when frames arrived

  Field(const std::vector<double>& distances, std::uint64_t seed, AbstractChannel::Settings::Retries retries = {})
      : arrivals(distances.size() + 1) {
    nodes.Create(distances.size() + 1);
    AbstractChannel::Settings s;
    s.calibration = Calibration();
    s.mean_loss = ns3::CreateObject<ns3::LogDistancePropagationLossModel>();
    s.tx_power_dbm = [](std::uint32_t) { return kTxPower; };
    s.seed = seed;
    s.range_m = 200;
    s.preamble_s = kPreamble, s.data_rate_bps = kDataRate, s.broadcast_rate_bps = kBroadcastRate;
    s.unicast = retries;
    channel->Configure(s);
    for (std::uint32_t i = 0; i < nodes.GetN(); ++i) {
      auto at = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
      at->SetPosition(ns3::Vector(i == 0 ? 0 : distances[i - 1], 0, 0));
      nodes.Get(i)->AggregateObject(at);
      auto device = ns3::CreateObject<ns3::SimpleNetDevice>();
      device->SetAddress(ns3::Mac48Address::Allocate());
      nodes.Get(i)->AddDevice(device);
      device->SetChannel(channel);
      device->SetReceiveCallback(
          [this, i](ns3::Ptr<ns3::NetDevice>, ns3::Ptr<const ns3::Packet>, uint16_t, const ns3::Address&) {
            arrivals[i].push_back(ns3::Simulator::Now().GetSeconds());
            return true;
          });
      devices.push_back(device);
    }
  }
  // Frame k leaves node 0 at k times `every_ms` ms, to `to` (broadcast unless given).
  void SendAll(std::optional<std::uint32_t> to = std::nullopt, int every_ms = 1) {
    const ns3::Address dst = to ? devices[*to]->GetAddress() : devices[0]->GetBroadcast();
    for (int k = 0; k < kFrames; ++k)
      ns3::Simulator::Schedule(ns3::MilliSeconds(k * every_ms),
                               [this, dst] { devices[0]->Send(ns3::Create<ns3::Packet>(kBytes), dst, 0x800); });
    ns3::Simulator::Stop(ns3::Seconds(kFrames * every_ms * 0.001 + 1));
    ns3::Simulator::Run();
  }
};

TEST(AbstractChannel, DeliversTheCalibrationsShareAtEachLinksMeanPower) {
  // Mean powers from -60 dBm (all) through -80 (half) to under -90 (none).
  const std::vector<double> distances = {12.5, 26.9, 36.0, 46.4, 58.0, 80.0, 120.0};
  std::vector<std::size_t> heard;
  {
    Field field(distances, 7);
    field.SendAll();
    for (std::size_t i = 1; i < field.arrivals.size(); ++i) heard.push_back(field.arrivals[i].size());
    EXPECT_EQ(field.channel->counters().frames, static_cast<std::uint64_t>(kFrames));
  }
  ns3::Simulator::Destroy();
  const LinkCalibration c = Calibration();
  for (std::size_t i = 0; i < distances.size(); ++i) {
    const double p = c.Prr(MeanPower(distances[i]));
    const double sigma = std::sqrt(p * (1 - p) / kFrames);
    EXPECT_NEAR(static_cast<double>(heard[i]) / kFrames, p, 4 * sigma + 1e-9)
        << "at " << distances[i] << " m, " << MeanPower(distances[i]) << " dBm";
  }
  EXPECT_EQ(heard.back(), 0u) << "under the weakest power heard, nothing";
}

// Frame k left at k ms: each arrival is that much later than a whole millisecond.
void ExpectDelays(const std::vector<double>& arrivals, double delay) {
  for (double t : arrivals) {
    const double sent = std::round((t - delay) * 1000) / 1000;
    EXPECT_NEAR(t - sent, delay, 1e-9);
  }
}

TEST(AbstractChannel, AUnicastReachesOnlyItsAddresseeAfterItsAirtimeAndTheAccessDelay) {
  {
    Field field({5, 10}, 3);  // -68 and -77 dBm: node 1 would hear every frame, node 2 most
    field.SendAll(2);
    EXPECT_TRUE(field.arrivals[1].empty()) << "not the addressee";
    const double p = Calibration().UnicastPrr(MeanPower(10));
    EXPECT_NEAR(static_cast<double>(field.arrivals[2].size()) / kFrames, p, 4 * std::sqrt(p * (1 - p) / kFrames));
    ExpectDelays(field.arrivals[2], UnicastAirtime() + Calibration().AccessDelay(MeanPower(10)));
  }
  ns3::Simulator::Destroy();
}

// 802.11b's retries: a unicast reaches its addressee unless all seven attempts fail; one that
// needed more than one is late by at least a failed attempt's cost (the frame's airtime, the ACK
// timeout, a DIFS) and at most that and the largest backoffs for each.
TEST(AbstractChannel, AUnicastIsRetriedAsTheMacRetriesIt) {
  AbstractChannel::Settings::Retries r;
  r.attempts = 7, r.slot_s = 20e-6, r.sifs_s = 10e-6, r.ack_s = 192e-6, r.cw_min = 31, r.cw_max = 1023;
  constexpr int kEveryMs = 100;  // far more than seven attempts take
  std::vector<double> arrivals;
  {
    Field field({5, 20}, 3, r);  // -75.7 dBm: about half the attempts
    field.SendAll(2, kEveryMs);
    arrivals = field.arrivals[2];
  }
  ns3::Simulator::Destroy();
  const double p = Calibration().UnicastPrr(MeanPower(20)), all = 1 - std::pow(1 - p, 7);
  ASSERT_LT(p, 0.7);
  EXPECT_NEAR(static_cast<double>(arrivals.size()) / kFrames, all, 4 * std::sqrt(all * (1 - all) / kFrames));
  const double first = UnicastAirtime() + Calibration().AccessDelay(MeanPower(20));
  const double airtime = kPreamble + (kBytes + AbstractChannel::kMacOverhead) * 8 / kDataRate;
  const double failed = airtime + r.sifs_s + r.slot_s + r.ack_s + r.sifs_s + 2 * r.slot_s;
  double most = 0;
  for (int k = 1; k < r.attempts; ++k) most += failed + std::min(((r.cw_min + 1) << k) - 1, r.cw_max) * r.slot_s;
  int at_first = 0, retried = 0;
  for (double t : arrivals) {
    const double late = std::fmod(t - first + 1e-12, kEveryMs * 1e-3) - 1e-12;
    if (std::fabs(late) < 1e-9) {
      ++at_first;
      continue;
    }
    ++retried;
    EXPECT_GE(late, failed - 1e-9);
    EXPECT_LE(late, most + 1e-9);
  }
  EXPECT_NEAR(static_cast<double>(at_first) / kFrames, p, 4 * std::sqrt(p * (1 - p) / kFrames));
  EXPECT_GT(retried, kFrames / 10);
}

TEST(AbstractChannel, ABroadcastGoesAtTheLowerRate) {
  {
    Field field({5}, 3);
    field.SendAll();
    EXPECT_EQ(field.arrivals[1].size(), static_cast<std::size_t>(kFrames));
    ExpectDelays(field.arrivals[1], BroadcastAirtime() + Calibration().AccessDelay(MeanPower(5)));
  }
  ns3::Simulator::Destroy();
}

TEST(AbstractChannel, TheSameSeedGivesTheSameFramesAndAnotherOthers) {
  const auto run = [](std::uint64_t seed) {
    std::vector<double> got;
    {
      Field field({50}, seed);
      field.SendAll();
      got = field.arrivals[1];
    }
    ns3::Simulator::Destroy();
    return got;
  };
  const auto a = run(11), b = run(11), c = run(12);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_GT(a.size(), 0u);
  EXPECT_LT(a.size(), static_cast<std::size_t>(kFrames));
}

// Five radios 40 m apart on the abstract radio, each reaching only its neighbours: AODV finds the
// route from one end to the other, and the message arrives over its four hops.
TEST(AbstractRadio, AodvFindsRoutesAndMessagesArrive) {
  std::vector<Message> got;
  {
    ns3::NodeContainer nodes;
    nodes.Create(5);
    for (std::uint32_t i = 0; i < 5; ++i) {
      auto at = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
      at->SetPosition(ns3::Vector(40.0 * i, 0, 0.05));
      nodes.Get(i)->AggregateObject(at);
    }
    NetworkSpec spec;
    spec.radio_model = RadioModel::kAbstract;
    spec.packet_log = false;
    LinkCalibration c;  // 40 m at 16 dBm: -78.7 dBm, every frame; 80 m: -87.8 dBm, none
    c.rows = {{-90, 0, 0.002, 0}, {-85, 0, 0.002, 0}, {-80, 1, 0.001, 1}, {-30, 1, 0.001, 1}};
    spec.calibration = c;
    WirelessNetwork network(spec, nodes, {"a", "b", "c", "d", "e"}, std::vector<NodeRadio>(5));
    network.SetReceiver([&got](NodeId to, const Message& m) {
      if (to == 4) got.push_back(m);
    });
    for (int k = 0; k < 3; ++k)
      ns3::Simulator::Schedule(ns3::Seconds(1 + k), [&network] { network.Send(0, 4, Bytes(32, 1)); });
    ns3::Simulator::Stop(ns3::Seconds(6));
    ns3::Simulator::Run();
    EXPECT_GE(network.View(0).RoutingTable().size(), 1u) << "a route to e, through b";
    const auto traces = network.Traces();
    ASSERT_TRUE(traces);
    EXPECT_EQ(traces->channel.model, "abstract");
    EXPECT_GT(traces->channel.frames_received, 0u);
  }
  ns3::Simulator::Destroy();
  ASSERT_EQ(got.size(), 3u);
  for (const Message& m : got) {
    EXPECT_EQ(m.from, 0u);
    EXPECT_EQ(m.hops, 4);
  }
}

// A scenario on the abstract radio: the calibration is measured once and then read from the
// cache, and the same seed gives the same run whichever, with one physics thread or two.
TEST(AbstractRadio, AScenarioRunsTheSameFromAMeasuredOrACachedCalibration) {
  const std::string cache = ::testing::TempDir() + "/sanet-calibration-cache";
  std::filesystem::remove_all(cache);
  setenv("SANET_CACHE", cache.c_str(), 1);
  const auto run = [](int threads, const std::string& tag) {
    const std::string yaml = "duration: 8\nworld: {threads: " + std::to_string(threads) +
                             "}\nnetwork: {radio_model: abstract, routing: aodv}\nnodes:\n"
                             "  - grid: {name: m, rows: 1, cols: 4, origin: [0, 0], spacing: 40}\n"
                             "    model: mote\n"
                             "  - {name: s, model: mote, pose: [0, 5, 0], controller: {name: pinger, params: {to: m3, "
                             "interval: 1}}}\n";
    sim::World world(scenario::LoadScenarioText(yaml, tag + ".yaml").run, testing::BuiltinRegistry());
    const std::string dir = ::testing::TempDir() + "/sanet-abstract-" + tag;
    std::filesystem::remove_all(dir);
    const sim::RunResult result = world.Run({dir, ""});
    std::ifstream in(dir + "/summary.json");
    return std::pair{result.fingerprint, nlohmann::json::parse(in)["network"]};
  };
  const auto [first, measured] = run(1, "measured");
  const auto [second, cached] = run(1, "cached");
  const auto [threaded, ignored] = run(2, "threads");
  unsetenv("SANET_CACHE");
  EXPECT_EQ(measured["channel"]["calibration"], "measured");
  EXPECT_EQ(cached["channel"]["calibration"], "cached");
  EXPECT_EQ(first, second);
  EXPECT_EQ(first, threaded);
  EXPECT_GE(measured["packets"]["messages_received"].get<int>(), 5) << "over three hops of AODV";
}

}  // namespace
}  // namespace sanet::net
