// Cost of the network in sanet, against ns-3 alone. For 25, 100 and 400 static motes on a grid
// (40 m apart, so routes are multi-hop) with AODV and light traffic (a tenth of the motes send 64
// bytes to a far mote every 2 s), it times
//   ns-3:           the wireless network alone with ns-3's YansWifiChannel, sockets fed by plain
//                   ns-3 events (the baseline)
//   sanet yans:     a whole sanet run (physics world, controllers, recording, outputs in memory)
//                   on the same channel: the coupling's own overhead
//   sanet indexed:  the same run on sanet's default channel (net/indexed_channel.h, floor at
//                   -85 dBm), which hands each frame only to the radios it reaches
// and prints real-time factors and wall-time ratios against the baseline, all measured in the
// same process so that machine noise affects them alike.
//
//   bench/network_bench [simulated seconds, default 30]
#include <ns3/constant-position-mobility-model.h>
#include <ns3/node-container.h>
#include <ns3/rng-seed-manager.h>
#include <ns3/simulator.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <nlohmann/json.hpp>

#include "builtin.h"
#include "hosting/controller_registry.h"
#include "net/wireless_network.h"
#include "sensors/sensor_registry.h"
#include "sim/world.h"

namespace {

using namespace sanet;
constexpr double kSpacing = 40;
constexpr double kInterval = 2;

struct Layout {
  int side;
  std::vector<std::pair<NodeId, NodeId>> flows;  // (source, destination)
};

Layout MakeLayout(int count) {
  Layout l{static_cast<int>(std::lround(std::sqrt(count))), {}};
  for (int s = 0; s < count; s += 10) l.flows.push_back({static_cast<NodeId>(s), static_cast<NodeId>(count - 1 - s)});
  return l;
}

double WallSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double RunSanet(int count, double duration, hosting::Registry& registry, net::ChannelModel channel) {
  const Layout layout = MakeLayout(count);
  sim::RunSpec spec;
  spec.duration = duration;
  spec.network = net::NetworkSpec{};
  spec.network->packet_log = false;
  spec.network->channel = channel;
  for (int i = 0; i < count; ++i)
    spec.nodes.push_back({"m" + std::to_string(i),
                          sensors::DefaultModel(robots::ModelKind::kMote),
                          {kSpacing * (i % layout.side), kSpacing * (i / layout.side), 0},
                          std::nullopt,
                          {},
                          std::nullopt});
  for (const auto& [source, destination] : layout.flows) {
    sim::ControllerSpec c;
    c.name = "pinger";
    for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
             {"to", "m" + std::to_string(destination)}, {"interval", "2"}, {"size", "64"}, {"start", "1"}}) {
      ParamValue v;
      v.rows = {{value}};
      c.params.Set(key, v);
    }
    spec.nodes[source].controller = c;
  }
  sim::World world(spec, registry);
  return world.Run({}).wall;
}

double RunNs3Alone(int count, double duration) {
  const Layout layout = MakeLayout(count);
  ns3::RngSeedManager::SetSeed(2);
  ns3::NodeContainer nodes;
  nodes.Create(count);
  std::vector<std::string> names;
  for (int i = 0; i < count; ++i) {
    auto mobility = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
    mobility->SetPosition(ns3::Vector(kSpacing * (i % layout.side), kSpacing * (i / layout.side), 0.05));
    nodes.Get(i)->AggregateObject(mobility);
    names.push_back("m" + std::to_string(i));
  }
  net::NetworkSpec spec;
  spec.packet_log = false;
  spec.channel = net::ChannelModel::kYans;
  {
    net::WirelessNetwork network(spec, nodes, names, std::vector<net::NodeRadio>(count));
    trace::ResultsFolder nowhere("");
    network.Open(nowhere);
    const Bytes payload(64, 0);
    std::vector<std::function<void()>> senders(layout.flows.size());
    for (std::size_t i = 0; i < layout.flows.size(); ++i) {
      senders[i] = [&, i] {
        network.Send(layout.flows[i].first, layout.flows[i].second, payload);
        ns3::Simulator::Schedule(ns3::Seconds(kInterval), senders[i]);
      };
      ns3::Simulator::Schedule(ns3::Seconds(1), senders[i]);
    }
    const auto start = std::chrono::steady_clock::now();
    ns3::Simulator::Stop(ns3::Seconds(duration));
    ns3::Simulator::Run();
    const double wall = WallSince(start);
    ns3::Simulator::Destroy();
    return wall;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const double duration = argc > 1 ? std::atof(argv[1]) : 30;
  hosting::Registry registry;
  controllers::RegisterBuiltinControllers(registry);
  std::printf(
      "sanet network benchmark: static motes 40 m apart, AODV, 802.11b 1 Mbps, a tenth of the\n"
      "motes send 64 B to a far mote every 2 s; %.0f s simulated per case\n",
      duration);
  std::printf("%-6s %10s %8s | %10s %8s | %12s %8s %8s\n", "motes", "ns-3 wall", "RTF", "sanet yans", "ratio",
              "sanet indexed", "RTF", "ratio");
  for (int count : {25, 100, 400}) {
    const double ns3_wall = RunNs3Alone(count, duration);
    const double yans_wall = RunSanet(count, duration, registry, net::ChannelModel::kYans);
    const double indexed_wall = RunSanet(count, duration, registry, net::ChannelModel::kIndexed);
    std::printf("%-6d %9.3fs %8.1f | %9.3fs %7.2fx | %11.3fs %8.1f %7.3fx\n", count, ns3_wall, duration / ns3_wall,
                yans_wall, yans_wall / ns3_wall, indexed_wall, duration / indexed_wall, indexed_wall / ns3_wall);
    std::fflush(stdout);
  }
  return 0;
}
