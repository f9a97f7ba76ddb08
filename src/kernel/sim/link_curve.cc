#include "sim/link_curve.h"

#include <ns3/constant-position-mobility-model.h>
#include <ns3/node-container.h>
#include <ns3/rng-seed-manager.h>
#include <ns3/simulator.h>
#include <ns3/wifi-net-device.h>
#include <ns3/wifi-phy.h>

#include <algorithm>
#include <cmath>

#include "core/counter_random.h"
#include "core/statistics.h"
#include "net/fading.h"
#include "net/path_loss.h"
#include "net/wireless_network.h"
#include "sim/radio_walls.h"
#include "trace/figure_svg.h"

namespace sanet::sim {
namespace {

constexpr std::uint64_t kSetKey = 0x4c494e4b43ull;  // "LINKC"
constexpr double kStart = 0.01;                     // s: the first frame, once the stacks are up
constexpr double kRegionShare = 0.95;               // of links, for the regions' bounds
constexpr double kHeight = 0.05;                    // m: radios stand where a default mote's centre is

// What one set heard: the frames its sender put on the air, and per receiver (by distance)
// the frames received, their strengths and delays.
struct SetHeard {
  int sent = 0;
  std::vector<int> received;
  std::vector<std::vector<double>> rssi_dbm, delay_ms;
  explicit SetHeard(std::size_t n) : received(n, 0), rssi_dbm(n), delay_ms(n) {}
};

std::vector<double> Distances(const LinkCurveOptions& o) {
  std::vector<double> out;
  for (std::size_t i = 0; i < DistanceCount(o); ++i) out.push_back(o.from + i * o.step);
  return out;
}

// The sender, then a receiver at each distance along the line.
ns3::NodeContainer PlaceSet(const LinkCurveOptions& o, const std::vector<double>& distances) {
  double x0 = 0, y0 = 0, ux = 1, uy = 0;
  if (o.along) {
    const auto [ax, ay, bx, by] = *o.along;
    const double length = std::hypot(bx - ax, by - ay);
    x0 = ax, y0 = ay, ux = (bx - ax) / length, uy = (by - ay) / length;
  }
  ns3::NodeContainer nodes;
  nodes.Create(distances.size() + 1);
  for (std::size_t i = 0; i < nodes.GetN(); ++i) {
    const double d = i == 0 ? 0 : distances[i - 1];
    auto at = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
    at->SetPosition({x0 + ux * d, y0 + uy * d, kHeight});
    nodes.Get(i)->AggregateObject(at);
  }
  return nodes;
}

// The scenario's network as a set measures it: no routing, no jitter, no files, the set's seed.
net::NetworkSpec SetNetwork(const RunSpec& spec, int set) {
  net::NetworkSpec network = *spec.network;
  network.routing = net::Routing::kNone;
  network.broadcast_jitter = 0;
  network.packet_log = network.pcap = network.flow_monitor = false;
  network.wifi_in_use = network.radios.wifi, network.lr_wpan_in_use = network.radios.lr_wpan;
  network.seed = CounterRandom(spec.seed, {kSetKey, static_cast<std::uint64_t>(set)})();
  return network;
}

// Frames the sender put on the air: a sender asked for frames faster than they take to send
// drops some from its queue, and those were never sent.
void CountSent(net::WirelessNetwork& wireless, SetHeard& heard) {
  if (!wireless.Device(0)) return;  // no 802.11 PHY: counted by CountFrameEvents
  ns3::DynamicCast<ns3::WifiNetDevice>(wireless.Device(0))
      ->GetPhy()
      ->TraceConnectWithoutContext("PhyTxBegin", ns3::Callback<void, ns3::Ptr<const ns3::Packet>, double>(
                                                     [&heard](ns3::Ptr<const ns3::Packet>, double) { ++heard.sent; }));
}

// 802.15.4 and the abstract radio: neither reports a frame's signal strength (ns-3's lr-wpan PHY
// does not; the abstract radio has none), so a frame received whole counts with the mean power
// the channel computes for the pair (without its fading).
void CountFrameEvents(net::WirelessNetwork& wireless, SetHeard& heard) {
  wireless.ObserveFrames([&wireless, &heard](const net::FrameEvent& e) {
    if (e.node == 0 && e.sent) ++heard.sent;
    if (e.node > 0 && !e.sent && e.peer == NodeId{0})
      heard.rssi_dbm[e.node - 1].push_back(wireless.ReceivedPower(0, e.node));
  });
}

void ListenToStrengths(net::WirelessNetwork& wireless, std::size_t receivers, SetHeard& heard) {
  if (!wireless.Device(0)) return CountFrameEvents(wireless, heard);
  for (std::size_t i = 0; i < receivers; ++i) {
    auto phy = ns3::DynamicCast<ns3::WifiNetDevice>(wireless.Device(i + 1))->GetPhy();
    phy->TraceConnectWithoutContext(
        "MonitorSnifferRx",
        ns3::Callback<void, ns3::Ptr<const ns3::Packet>, uint16_t, ns3::WifiTxVector, ns3::MpduInfo,
                      ns3::SignalNoiseDbm, uint16_t>(
            [&heard, i](ns3::Ptr<const ns3::Packet>, uint16_t, ns3::WifiTxVector, ns3::MpduInfo,
                        ns3::SignalNoiseDbm signal, uint16_t) { heard.rssi_dbm[i].push_back(signal.signal); }));
  }
}

SetHeard MeasureSet(const RunSpec& spec, const LinkCurveOptions& o, const std::vector<double>& distances, int set) {
  const net::NetworkSpec network = SetNetwork(spec, set);
  ns3::RngSeedManager::SetSeed(net::Ns3Seed(network.seed));
  const ns3::NodeContainer nodes = PlaceSet(o, distances);
  std::vector<std::string> names = {"sender"};
  for (std::size_t i = 0; i < distances.size(); ++i) names.push_back("receiver" + std::to_string(i));
  SetHeard heard(distances.size());
  {
    const double frequency = net::DefaultFrequencyHz(network);
    const std::vector<net::RadioObstacle> walls =
        o.along ? RadioWalls(spec, frequency) : std::vector<net::RadioObstacle>{};
    net::WirelessNetwork wireless(network, nodes, names, std::vector<net::NodeRadio>(nodes.GetN()), walls, walls);
    wireless.SetReceiver([&heard](NodeId to, const Message& m) {
      if (to == 0) return;
      ++heard.received[to - 1];
      heard.delay_ms[to - 1].push_back((m.time_received - m.time_sent) * 1e3);
    });
    CountSent(wireless, heard);
    ListenToStrengths(wireless, distances.size(), heard);
    const Bytes payload(o.size, 0);
    for (int f = 0; f < o.frames; ++f)
      ns3::Simulator::Schedule(ns3::Seconds(kStart + f * o.interval),
                               [&wireless, &payload] { wireless.Broadcast(0, payload); });
    ns3::Simulator::Stop(ns3::Seconds(kStart + o.frames * o.interval + 1));
    ns3::Simulator::Run();
  }
  ns3::Simulator::Destroy();
  return heard;
}

Quartiles QuartilesOf(const std::vector<double>& samples) {
  if (samples.empty()) return {};
  return {Quantile(samples, 0.25), Quantile(samples, 0.5), Quantile(samples, 0.75), true};
}

// Each distance's row from every set's record of it.
std::vector<LinkCurveRow> Rows(const std::vector<double>& distances, const std::vector<SetHeard>& sets,
                               const net::NetworkSpec& network) {
  std::vector<LinkCurveRow> rows;
  for (std::size_t i = 0; i < distances.size(); ++i) {
    LinkCurveRow row;
    row.distance = distances[i];
    row.mean_dbm = MeanPower(network, distances[i]);
    std::vector<double> rssi, delay;
    for (const SetHeard& set : sets) {
      const double prr = set.sent ? double(set.received[i]) / set.sent : 0;
      row.sent += set.sent;
      row.received += set.received[i];
      row.share_90 += prr >= 0.9, row.share_50 += prr >= 0.5, row.share_10 += prr > 0.1;
      rssi.insert(rssi.end(), set.rssi_dbm[i].begin(), set.rssi_dbm[i].end());
      delay.insert(delay.end(), set.delay_ms[i].begin(), set.delay_ms[i].end());
    }
    for (double* share : {&row.share_90, &row.share_50, &row.share_10}) *share /= std::max<std::size_t>(1, sets.size());
    row.rssi_dbm = QuartilesOf(rssi);
    row.delay_ms = QuartilesOf(delay);
    rows.push_back(row);
  }
  return rows;
}

void FindRegions(LinkCurve& curve) {
  if (curve.sets_done == 0) return;  // stopped before the first set: nothing to say
  const auto& rows = curve.rows;
  for (const LinkCurveRow& row : rows) {
    if (row.share_90 < kRegionShare) break;
    curve.connected_to = row.distance;
  }
  for (auto row = rows.rbegin(); row != rows.rend(); ++row) {
    if (row->share_10 > 1 - kRegionShare) break;
    curve.disconnected_from = row->distance;
  }
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double a = rows[i - 1].Prr(), b = rows[i].Prr();
    if (a >= 0.5 && b < 0.5) {
      curve.p50_dbm = rows[i - 1].mean_dbm + (a - 0.5) / (a - b) * (rows[i].mean_dbm - rows[i - 1].mean_dbm);
      break;
    }
  }
}

}  // namespace

double MeanPower(const net::NetworkSpec& network, double distance) {
  auto from = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  auto to = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  from->SetPosition({0, 0, kHeight});
  to->SetPosition({distance, 0, kHeight});
  return net::PathLoss(network, net::DefaultFrequencyHz(network))->CalcRxPower(net::DefaultTxPower(network), from, to);
}

void DefaultDistances(const net::NetworkSpec& network, LinkCurveOptions& o) {
  constexpr double kSigmas = 2.5, kFadingShare = 0.99;  // of the links and frames a curve shows
  const double lift = kSigmas * (network.shadowing.sigma_db + network.spread.tx_power_db) +
                      (network.fading.model == net::FadingModel::kNone
                           ? 0
                           : net::NakagamiFading(0, network.fading).GainQuantileDb(kFadingShare));
  const double target = net::DefaultThreshold(network) - lift - 3;
  double far = 1;
  while (MeanPower(network, far) >= target && far < 1e6) far *= 2;
  for (double near = far / 2, i = 0; i < 50; ++i) {
    const double middle = 0.5 * (near + far);
    (MeanPower(network, middle) >= target ? near : far) = middle;
  }
  const bool to_given = o.to > 0;
  if (!to_given) o.to = far;
  if (o.step <= 0) o.step = trace::svg::NiceStep(o.to, 40);
  if (o.from <= 0) o.from = o.step;
  if (!to_given) o.to = std::ceil(o.to / o.step - 1e-9) * o.step;  // a whole number of steps
}

std::size_t DistanceCount(const LinkCurveOptions& o) {
  if (o.from > o.to) return 0;
  const double count = std::floor((o.to - o.from) / o.step + 1e-9) + 1;
  return count > kMostDistances ? kMostDistances + 1 : static_cast<std::size_t>(count);  // more: "too many"
}

LinkCurve MeasureLinkCurve(const RunSpec& spec, const LinkCurveOptions& o,
                           const std::function<void(int, int)>& progress, const std::function<bool()>& stop) {
  const std::vector<double> distances = Distances(o);
  std::vector<SetHeard> sets;
  LinkCurve curve;
  for (int set = 0; set < o.sets; ++set) {
    if (stop && stop()) {
      curve.interrupted = true;
      break;
    }
    sets.push_back(MeasureSet(spec, o, distances, set));
    for (std::size_t i = 0; i < distances.size(); ++i)
      curve.links.push_back({set, distances[i], sets.back().sent, sets.back().received[i]});
    if (progress) progress(set + 1, o.sets);
  }
  curve.sets_done = static_cast<int>(sets.size());
  curve.rows = Rows(distances, sets, *spec.network);
  FindRegions(curve);
  return curve;
}

}  // namespace sanet::sim
