// Energy (docs/energy.md): a battery runs down at the rate its formula says and the node dies at
// that instant; the radio's energy by state is each state's time in the PHY's own trace times its
// current and the voltage; a dead node is silent and routes through it break until it is
// recharged; its controller reads the battery as it drains.
#include <gtest/gtest.h>
#include <ns3/callback.h>
#include <ns3/node-list.h>
#include <ns3/wifi-net-device.h>
#include <ns3/wifi-phy-state-helper.h>

#include <array>
#include <map>
#include <optional>
#include <vector>

#include "sim/assembly.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

constexpr double kVoltage = 3;
constexpr double kIdleWatts = kVoltage * 0.273;  // ns-3's WifiRadioEnergyModel idle current

energy::EnergySpec Battery(double joules, double electronics_w = 0, double initial_fraction = 1, double cutoff = 0) {
  energy::EnergySpec e;
  e.battery_j = joules;
  e.voltage = kVoltage;
  e.electronics_w = electronics_w;
  e.initial_fraction = initial_fraction;
  e.cutoff = cutoff;
  return e;
}

sim::NodeSpec Mote(std::string name, Vec2 at, std::optional<energy::EnergySpec> energy,
                   std::optional<sim::ControllerSpec> controller = std::nullopt) {
  sim::NodeSpec n = Robot(std::move(name), ModelKind::kMote, {at.x, at.y, 0}, std::move(controller));
  n.energy = energy;
  if (energy) n.model.sensors["battery"] = {"battery", sensors::FindKind("battery")->DefaultSettings(n.model)};
  return n;
}

// Motes 125 m apart hear only their neighbours (30 dBm, log-distance with exponent 3).
sim::RunSpec WithRadio(double duration, std::vector<sim::NodeSpec> nodes, net::Routing routing) {
  sim::RunSpec spec = Spec(duration, std::move(nodes));
  spec.network = net::NetworkSpec{};
  spec.network->tx_power = 30;
  spec.network->routing = routing;
  return spec;
}

std::map<NodeId, std::vector<double>> Deaths(sim::World& world, std::vector<Subscription>& keep) {
  auto deaths = std::make_shared<std::map<NodeId, std::vector<double>>>();
  keep.push_back(world.bus().On<sim::Died>(sim::RunStage::kRecord,
                                           [deaths](const sim::Died& e) { (*deaths)[e.node].push_back(e.t); }));
  world.Run({});
  return *deaths;
}

TEST(Energy, ANodeDiesWhenItsChargeReachesTheCutoffAtTheTimeTheFormulaSays) {
  // Idle radios (no routing, no traffic) and the electronics: P = V * idle_a + electronics_w.
  const double watts = kIdleWatts + 0.05;
  sim::World world(WithRadio(30,
                             {Mote("full", {0, 0}, Battery(10, 0.05)), Mote("half", {10, 0}, Battery(10, 0.05, 0.5)),
                              Mote("cut", {20, 0}, Battery(10, 0.05, 1, 0.2)), Mote("mains", {30, 0}, std::nullopt)},
                             net::Routing::kNone),
                   BuiltinRegistry());
  std::vector<Subscription> keep;
  const auto deaths = Deaths(world, keep);
  ASSERT_EQ(deaths.size(), 3u) << "the node without energy lives on";
  EXPECT_NEAR(deaths.at(0).at(0), 10 / watts, 1e-6);
  EXPECT_NEAR(deaths.at(1).at(0), 5 / watts, 1e-6) << "half charged at the start: half the time";
  EXPECT_NEAR(deaths.at(2).at(0), 8 / watts, 1e-6) << "a cutoff of 0.2 leaves a fifth unused";
  const energy::NodeEnergy& cut = *world.parts().batteries().Of(2);
  EXPECT_NEAR(cut.remaining_j(), 2, 1e-6) << "a dead node draws nothing more";
  EXPECT_DOUBLE_EQ(cut.power_w(), 0);
  const auto summary = world.parts().batteries().Summary(world.nodes());
  EXPECT_NEAR(summary["lifetime"]["first_death_s"].get<double>(), 5 / watts, 1e-6);
  EXPECT_NEAR(summary["lifetime"]["half_dead_s"].get<double>(), 8 / watts, 1e-6);
  EXPECT_NEAR(summary["lifetime"]["last_alive_s"].get<double>(), 10 / watts, 1e-6);
  EXPECT_FALSE(summary["nodes"].contains("mains")) << "only nodes with energy are listed";
  EXPECT_NEAR(summary["nodes"]["full"]["used_j"]["electronics"].get<double>(), 0.05 * 10 / watts, 1e-6);
}

struct StateSeconds {
  std::array<double, 8> seconds{};
  double end = 0;     // the run's end: a frame logged ahead is counted up to it
  double logged = 0;  // the end of the last period logged
};

void AddPeriod(StateSeconds* out, ns3::Time start, ns3::Time duration, WifiPhyState state) {
  const double from = start.GetSeconds(), to = std::min(from + duration.GetSeconds(), out->end);
  if (to > from) out->seconds.at(state) += to - from;
  out->logged = std::max(out->logged, to);
}

TEST(Energy, TheRadiosEnergyByStateIsEachStatesTimeInThePhysTraceTimesItsCurrent) {
  constexpr double kDuration = 20;
  energy::EnergySpec e = Battery(1000);
  e.radio.tx_a = 0.5, e.radio.rx_a = 0.3, e.radio.idle_a = 0.2, e.radio.cca_busy_a = 0.25;
  sim::World world(WithRadio(kDuration,
                             {Mote("talker", {0, 0}, e,
                                   UseController("pinger", {{"to", Text("listener")},
                                                            {"interval", Scalar(0.05)},
                                                            {"size", Scalar(1200)},
                                                            {"start", Scalar(0.5)}})),
                              Mote("listener", {50, 0}, e)},
                             net::Routing::kNone),
                   BuiltinRegistry());
  world.parts().node(0);  // built
  std::array<StateSeconds, 2> trace;
  for (NodeId id : {0u, 1u}) {
    trace[id].end = kDuration;
    auto phy = ns3::DynamicCast<ns3::WifiNetDevice>(ns3::NodeList::GetNode(id)->GetDevice(0))->GetPhy();
    phy->GetState()->TraceConnectWithoutContext("State", ns3::MakeBoundCallback(&AddPeriod, &trace[id]));
  }
  world.Run({});
  for (NodeId id : {0u, 1u}) {
    // The trace logs idle time when it ends: the last stretch is in the state the PHY is in now.
    auto phy = ns3::DynamicCast<ns3::WifiNetDevice>(ns3::NodeList::GetNode(id)->GetDevice(0))->GetPhy();
    trace[id].seconds.at(phy->GetState()->GetState()) += kDuration - trace[id].logged;
    const energy::NodeEnergy& energy = *world.parts().batteries().Of(id);
    std::map<std::string, double> used;
    for (const auto& [component, joules] : energy.Used()) used[component] = joules;
    const auto& s = trace[id].seconds;
    EXPECT_NEAR(used["radio_tx"], s[WifiPhyState::TX] * 0.5 * kVoltage, 1e-9);
    EXPECT_NEAR(used["radio_rx"], s[WifiPhyState::RX] * 0.3 * kVoltage, 1e-9);
    EXPECT_NEAR(used["radio_cca_busy"], s[WifiPhyState::CCA_BUSY] * 0.25 * kVoltage, 1e-9);
    EXPECT_NEAR(used["radio_idle"], s[WifiPhyState::IDLE] * 0.2 * kVoltage, 1e-9);
    EXPECT_GT(used[id == 0 ? "radio_tx" : "radio_rx"], 0.5) << "the traffic cost something";
    std::map<std::string, double> seconds;
    for (const auto& [state, in_state] : energy.RadioSeconds()) seconds[state] = in_state;
    EXPECT_NEAR(seconds["tx"], s[WifiPhyState::TX], 1e-6);  // the run stops 1 ns past its end
    EXPECT_NEAR(seconds["idle"], s[WifiPhyState::IDLE], 1e-6);
    double total = 0;
    for (const auto& [component, joules] : used) total += joules;
    // The battery drained by ns-3's models as they changed state, in step with the split by state.
    EXPECT_NEAR(1000 - energy.remaining_j(), total, 1e-6 * total);
  }
}

TEST(Energy, ADeadNodeIsSilentAndRoutesThroughItBreakUntilItIsRechargedAndHeardAgain) {
  // a -- relay -- c, 125 m apart: a reaches c only through the relay, which dies at about 20 s
  // and is recharged at 40 s.
  sim::RunSpec spec =
      WithRadio(70,
                {Mote("a", {0, 0}, std::nullopt,
                      UseController("pinger", {{"to", Text("c")}, {"interval", Scalar(1)}, {"start", Scalar(2)}})),
                 Mote("relay", {125, 0}, Battery(20 * kIdleWatts)), Mote("c", {250, 0}, std::nullopt)},
                net::Routing::kAodv);
  spec.events.push_back({40, 1, sim::NodeEvent::Action::kRecharge, std::nullopt});
  sim::World world(spec, BuiltinRegistry());
  std::vector<double> delivered, relay_frames;
  std::vector<std::pair<double, std::optional<NodeId>>> a_to_c;
  std::vector<Subscription> keep;
  keep.push_back(world.bus().On<sim::MessageDelivered>(sim::RunStage::kRecord, [&](const sim::MessageDelivered& e) {
    if (e.to == 2) delivered.push_back(e.message.time_received);
  }));
  keep.push_back(world.bus().On<net::FrameEvent>(sim::RunStage::kRecord, [&](const net::FrameEvent& f) {
    if (f.node == 1) relay_frames.push_back(f.t);
  }));
  keep.push_back(world.bus().On<sim::RouteChange>(sim::RunStage::kRecord, [&](const sim::RouteChange& r) {
    if (r.node == 0 && r.destination == 2) a_to_c.emplace_back(r.time, r.next_hop);
  }));
  const auto deaths = Deaths(world, keep);
  ASSERT_EQ(deaths.count(1), 1u);
  const double died = deaths.at(1).front();
  EXPECT_GT(died, 15);
  EXPECT_LT(died, 21);
  const auto count = [](const std::vector<double>& times, double from, double to) {
    return std::count_if(times.begin(), times.end(), [&](double t) { return t > from && t < to; });
  };
  EXPECT_GT(count(delivered, 0, died), 10);
  EXPECT_EQ(count(delivered, died + 0.1, 40), 0) << "nothing crosses a dead relay";
  EXPECT_EQ(count(relay_frames, died + 1e-3, 40), 0) << "a dead radio neither sends nor receives";
  EXPECT_GT(count(relay_frames, 40, 70), 10) << "recharged, it is heard again";
  EXPECT_GT(count(delivered, 40, 70), 10) << "and carries a's messages again";
  // a's route to c went through the relay, and was gone before the relay came back.
  const auto route_before = [&](double time) {
    std::optional<NodeId> next_hop;
    for (const auto& [t, hop] : a_to_c)
      if (t < time) next_hop = hop;
    return next_hop;
  };
  EXPECT_EQ(route_before(died), std::optional<NodeId>(1));
  EXPECT_NE(route_before(40), std::optional<NodeId>(1)) << "the route through the dead relay broke";
  // Revived on a busy channel, it accounts for every joule: what it had and got is what it used
  // and has.
  const energy::NodeEnergy& relay = *world.parts().batteries().Of(1);
  double used = 0;
  for (const auto& [component, joules] : relay.Used()) used += joules;
  EXPECT_NEAR(20 * kIdleWatts + relay.charged_j() - relay.remaining_j(), used, 1e-6);
}

TEST(Energy, ANodeThatDiesMidFrameOrAsleepAccountsForEveryJouleAndTheRunGoesOn) {
  // A talker that keeps its radio busy dies most likely while it transmits; a mote that sleeps
  // dies asleep (ns-3 cannot switch a sleeping radio off: it wakes first).
  sim::World world(WithRadio(30,
                             {Mote("talker", {0, 0}, Battery(3, 0.05),
                                   UseController("pinger", {{"to", Text("broadcast")},
                                                            {"interval", Scalar(0.01)},
                                                            {"size", Scalar(1400)},
                                                            {"start", Scalar(0.1)}})),
                              Mote("sleeper", {2000, 0}, Battery(1, 0.05))},  // out of the talker's range
                             net::Routing::kNone),
                   BuiltinRegistry());
  world.Every(0.5, [&] {
    if (world.Now() > 0.25 && world.Now() < 0.75) world.parts().node(1).SetRadioSleep(true);
  });
  std::vector<Subscription> keep;
  const auto deaths = Deaths(world, keep);
  ASSERT_EQ(deaths.size(), 2u);
  // Idle for 0.5 s, then asleep (ns-3's 33 mA): 1 J at 0.869 W, then at 0.149 W.
  EXPECT_NEAR(deaths.at(1).at(0), 0.5 + (1 - 0.5 * (kIdleWatts + 0.05)) / (kVoltage * 0.033 + 0.05), 1e-3);
  for (NodeId id : {0u, 1u}) {
    const energy::NodeEnergy& e = *world.parts().batteries().Of(id);
    double used = 0;
    for (const auto& [component, joules] : e.Used()) used += joules;
    EXPECT_NEAR(e.spec().battery_j - e.remaining_j(), used, 1e-6) << world.NameOf(id) << ": no frame counted twice";
  }
}

TEST(Energy, TheLastSampleAndTheSummaryHoldTheChargeAtTheRunsEnd) {
  const double watts = kIdleWatts + 0.1;
  sim::RunSpec spec = WithRadio(12.5, {Mote("m", {0, 0}, Battery(100, 0.1))}, net::Routing::kNone);
  spec.energy_interval = 10;
  std::vector<std::pair<double, double>> samples;
  double summary_remaining = 0;
  {
    sim::World world(spec, BuiltinRegistry());
    std::vector<Subscription> keep;
    keep.push_back(world.bus().On<sim::EnergySampled>(sim::RunStage::kRecord, [&](const sim::EnergySampled& e) {
      samples.emplace_back(e.t, e.levels.at(0).battery.remaining_j);
    }));
    world.Run({});
    summary_remaining = world.parts().batteries().Summary(world.nodes())["nodes"]["m"]["remaining_j"];
  }
  ASSERT_EQ(samples.size(), 3u) << "at 0, 10 and the end";
  EXPECT_NEAR(samples.back().first, 12.5, 1e-6);
  EXPECT_NEAR(samples.back().second, 100 - watts * 12.5, 1e-6) << "not the charge of the last update";
  EXPECT_NEAR(summary_remaining, 100 - watts * 12.5, 1e-6);
}

TEST(Energy, ARobotSpawnedLaterStartsItsPackFull) {
  energy::EnergySpec cell = Battery(20000, 0.1);
  cell.source = energy::Chemistry::kLiIon;
  sim::RunSpec spec = Spec(1100, {Mote("m", {0, 0}, std::nullopt)});
  double remaining = 0;
  {
    sim::World world(spec, BuiltinRegistry());
    world.Every(1000, [&] {
      if (world.Now() > 999) world.parts().Spawn(Mote("late", {5, 0}, cell), "Mote", "spawned by the test");
    });
    world.Run({});
    remaining = world.parts().batteries().Of(1)->remaining_j();
  }
  EXPECT_NEAR(remaining, 20000 - 0.1 * 100, 0.5) << "it drew for 100 s, not since the run began";
}

TEST(Energy, ALiIonPacksVoltageFallsAlongItsCurveUntilItDiesAndARechargeRaisesIt) {
  energy::EnergySpec cell = Battery(20000, 0.1);
  cell.source = energy::Chemistry::kLiIon;
  sim::RunSpec spec = WithRadio(26000, {Mote("m", {0, 0}, cell)}, net::Routing::kNone);
  spec.events.push_back({25000, 0, sim::NodeEvent::Action::kRecharge, std::nullopt});
  std::vector<std::pair<double, BatteryReading>> readings;
  std::vector<double> died, revived;
  {
    sim::World world(spec, BuiltinRegistry());
    std::vector<Subscription> keep;
    keep.push_back(
        world.bus().On<sim::Revived>(sim::RunStage::kRecord, [&](const sim::Revived& e) { revived.push_back(e.t); }));
    keep.push_back(world.bus().On<sim::Died>(sim::RunStage::kRecord, [&](const sim::Died& e) { died.push_back(e.t); }));
    world.Every(500, [&] {
      readings.emplace_back(world.Now(), std::get<BatteryReading>(*world.parts().node(0).Sensor("battery")));
    });
    world.Run({});
  }
  ASSERT_EQ(died.size(), 1u);
  ASSERT_EQ(revived, std::vector<double>{25000});
  const BatteryReading& start = readings.front().second;
  // Full: ns-3's default cell gives 4.05 V at its typical current, a little more at a light load.
  EXPECT_GT(start.voltage, 4.0);
  EXPECT_LT(start.voltage, 4.3);
  BatteryReading last_alive = start;
  for (const auto& [t, b] : readings) {
    if (t >= died[0]) break;
    EXPECT_LE(b.voltage, last_alive.voltage + 1e-9) << "the voltage falls as the pack drains, at " << t;
    EXPECT_NEAR(b.power_w, b.voltage * (0.273 + 0.1 / kVoltage), 0.2) << "the same currents at a lower voltage";
    last_alive = b;
  }
  EXPECT_GT(last_alive.voltage, 3.3);
  EXPECT_LT(last_alive.voltage, 3.9);
  EXPECT_GT(died[0], 15000) << "about 20 kJ at about 1.1 W";
  const BatteryReading& recharged = readings.back().second;
  EXPECT_NEAR(recharged.remaining_j, 20000 - 1000 * recharged.power_w, 200) << "full again, 1000 s before the end";
  EXPECT_GT(recharged.voltage, last_alive.voltage) << "and its voltage rose with its charge";
}

TEST(Energy, AControllerReadsItsBatteryAsItDrains) {
  const double watts = kIdleWatts + 0.1;
  std::vector<std::pair<double, BatteryReading>> readings;
  {
    sim::World world(WithRadio(12, {Mote("m", {0, 0}, Battery(100, 0.1))}, net::Routing::kNone), BuiltinRegistry());
    world.Every(5, [&] {
      const auto reading = world.parts().node(0).Sensor("battery");
      ASSERT_TRUE(reading.has_value());
      readings.emplace_back(world.Now(), std::get<BatteryReading>(*reading));
    });
    world.Run({});
  }
  ASSERT_EQ(readings.size(), 3u);
  for (const auto& [t, b] : readings) {
    EXPECT_NEAR(b.remaining_j, 100 - watts * t, 1e-6) << "at " << t;
    EXPECT_NEAR(b.fraction, b.remaining_j / 100, 1e-12);
    EXPECT_DOUBLE_EQ(b.voltage, kVoltage);
    EXPECT_DOUBLE_EQ(b.capacity_j, 100);
    EXPECT_NEAR(b.power_w, watts, 1e-9);
    EXPECT_FALSE(b.charging);
  }
  sim::World without(WithRadio(1, {Mote("n", {0, 0}, std::nullopt)}, net::Routing::kNone), BuiltinRegistry());
  EXPECT_FALSE(without.parts().node(0).Sensor("battery").has_value()) << "no energy, no battery";
}

}  // namespace
}  // namespace sanet
