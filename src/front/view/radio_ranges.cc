#include "view/radio_ranges.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "sim/link_curve.h"
#include "sim/radio_walls.h"

namespace sanet::view {
namespace {

constexpr double kAntennaHeight = 0.05;  // m: as the link curve's radios (a default mote's centre)

// The first distance index whose PRR is under 0.5 after one at or over it (as sim::FindRegions).
std::optional<std::size_t> FirstDrop(const sim::LinkCurve& curve) {
  for (std::size_t i = 1; i < curve.rows.size(); ++i)
    if (curve.rows[i - 1].Prr() >= 0.5 && curve.rows[i].Prr() < 0.5) return i;
  return std::nullopt;
}

double Crossing(const sim::LinkCurve& curve, std::size_t i) {
  const sim::LinkCurveRow &a = curve.rows[i - 1], &b = curve.rows[i];
  return a.distance + (a.Prr() - 0.5) / (a.Prr() - b.Prr()) * (b.distance - a.distance);
}

// The standard error of a distance's PRR: the spread of its links' PRRs over the root of their number.
double StandardError(const sim::LinkCurve& curve, double distance) {
  std::vector<double> prr;
  for (const sim::LinkRecord& link : curve.links)
    if (link.distance == distance && link.sent > 0) prr.push_back(double(link.received) / link.sent);
  if (prr.size() < 2) return 0;
  double mean = 0, squares = 0;
  for (double p : prr) mean += p / prr.size();
  for (double p : prr) squares += (p - mean) * (p - mean);
  return std::sqrt(squares / (prr.size() - 1) / prr.size());
}

using Stop = std::function<bool()>;

sim::LinkCurve Curve(const sim::RunSpec& spec, sim::LinkCurveOptions& options, const Stop& stop) {
  if (options.step <= 0) sim::DefaultDistances(*spec.network, options);
  return sim::MeasureLinkCurve(spec, options, nullptr, stop);
}

// The two passes for one transmit power; `stop` cuts them short when the viewer closes.
void MeasureRange(const sim::RunSpec& spec, RadioRange& range, const Stop& stop) {
  sim::LinkCurveOptions coarse;
  coarse.sets = kRangeLinks;
  const sim::LinkCurve first = Curve(spec, coarse, stop);
  if (stop()) return;
  range.coarse = {coarse.from, coarse.to, coarse.step};
  const auto drop = FirstDrop(first);
  if (!drop) return;
  const sim::LinkCurveRow &a = first.rows[*drop - 1], &b = first.rows[*drop];
  sim::LinkCurveOptions fine = coarse;
  fine.from = a.distance, fine.to = b.distance, fine.step = (b.distance - a.distance) / kRangeFineDistances;
  range.fine = {fine.from, fine.to, fine.step};
  const sim::LinkCurve second = Curve(spec, fine, stop);
  const auto fine_drop = FirstDrop(second);
  range.radius_m = fine_drop ? Crossing(second, *fine_drop) : Crossing(first, *drop);
  const double slope = (a.Prr() - b.Prr()) / (b.distance - a.distance);
  range.precision_m = (fine_drop ? fine.step : coarse.step) / 2 +
                      std::max(StandardError(first, a.distance), StandardError(first, b.distance)) / slope;
  range.power_dbm = sim::MeanPower(*spec.network, *range.radius_m);
}

// The nodes grouped by their radio and its transmit power, in order of first appearance: a node
// with two radios by its 802.11 one (its team's).
std::vector<RadioRange> Radios(const sim::RunSpec& spec) {
  std::vector<RadioRange> radios;
  for (std::size_t id = 0; id < spec.nodes.size(); ++id) {
    const net::NodeRadio& radio = spec.nodes[id].radio;
    const bool lr_wpan = !radio.RadiosIn(*spec.network).wifi;
    const double power = lr_wpan ? radio.lr_wpan_tx_power.value_or(spec.network->lr_wpan.tx_power)
                                 : radio.tx_power.value_or(spec.network->tx_power);
    auto same = std::find_if(radios.begin(), radios.end(),
                             [&](const RadioRange& r) { return r.tx_power_dbm == power && r.lr_wpan == lr_wpan; });
    if (same == radios.end()) same = radios.insert(radios.end(), RadioRange{power, lr_wpan});
    same->nodes.push_back(static_cast<int>(id));
  }
  return radios;
}

// The network as a link curve measures `range`'s radio: that kind as the network's own, at its power.
net::NetworkSpec RangeNetwork(const net::NetworkSpec& network, const RadioRange& range) {
  net::NetworkSpec out = network;
  out.radios = {!range.lr_wpan, range.lr_wpan};
  net::SetDefaultTxPower(out, range.tx_power_dbm);
  return out;
}

nlohmann::json RangeJson(const RadioRange& r) {
  nlohmann::json radius = r.radius_m ? nlohmann::json(*r.radius_m) : nlohmann::json(nullptr);
  return {{"tx_power_dbm", r.tx_power_dbm},
          {"standard", r.lr_wpan ? net::kLrWpanName : "802.11"},
          {"radius_m", radius},
          {"precision_m", r.precision_m},
          {"power_dbm", r.power_dbm},
          {"nodes", r.nodes},
          {"coarse", r.coarse},
          {"fine", r.fine}};
}

}  // namespace

RadioRanges::RadioRanges(std::optional<sim::RunSpec> spec, std::string why) : spec_(std::move(spec)), why_(why) {
  if (spec_ && !spec_->network) why_ = "the scenario has no network: no radio to draw the range of";
  if (!spec_ || !spec_->network) spec_.reset();
  measured_ = std::async(std::launch::async, [this] {
                try {
                  Measure();
                } catch (const std::exception& e) {  // said by Ranges() instead of ranges
                  why_ = std::string("measuring the radio failed: ") + e.what();
                  spec_.reset();
                }
              }).share();
}

RadioRanges::~RadioRanges() {
  stopping_ = true;  // Ctrl-C on sanet view does not wait for the measurement to finish
  measured_.wait();
}

void RadioRanges::Measure() {
  if (!spec_) return;
  const std::lock_guard<std::mutex> lock(ns3_);
  const auto start = std::chrono::steady_clock::now();
  radios_ = Radios(*spec_);
  const Stop stop = [this] { return stopping_.load(); };
  for (RadioRange& range : radios_) {
    if (stop()) return;
    sim::RunSpec spec = *spec_;
    spec.network = RangeNetwork(*spec_->network, range);
    MeasureRange(spec, range, stop);
  }
  const auto walls = sim::RadioWalls(*spec_);
  if (!walls.empty()) walls_.emplace(walls);
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

nlohmann::json RadioRanges::Ranges() {
  measured_.wait();
  if (!spec_) return {{"error", why_}};
  nlohmann::json radios = nlohmann::json::array();
  for (const RadioRange& range : radios_) radios.push_back(RangeJson(range));
  return {{"radios", radios},
          {"walls", walls_.has_value()},
          {"links", kRangeLinks},
          {"frames", sim::LinkCurveOptions{}.frames},
          {"seconds", seconds_}};
}

nlohmann::json RadioRanges::Shape(std::size_t radio, double x, double y) {
  measured_.wait();
  if (!spec_ || radio >= radios_.size() || !radios_[radio].radius_m)
    throw std::invalid_argument("no radio " + std::to_string(radio) + " with a range");
  const RadioRange& range = radios_[radio];
  const std::lock_guard<std::mutex> lock(ns3_);
  const net::NetworkSpec network = RangeNetwork(*spec_->network, range);
  nlohmann::json points = nlohmann::json::array();
  const physics::Vec3 from{x, y, kAntennaHeight};
  for (int k = 0; k < kRangeBearings; ++k) {
    const double bearing = 2 * M_PI * k / kRangeBearings;
    const auto at = [&](double d) {
      return physics::Vec3{x + d * std::cos(bearing), y + d * std::sin(bearing), kAntennaHeight};
    };
    // The power through the walls only falls with distance: bisect for where it meets the range's.
    const auto above = [&](double d) {
      return sim::MeanPower(network, d) - (walls_ ? walls_->LossDb(from, at(d)) : 0) >= range.power_dbm;
    };
    double near = 0, far = *range.radius_m;
    if (above(far)) near = far;
    for (int i = 0; i < 40 && far - near > 1e-3; ++i) (above(0.5 * (near + far)) ? near : far) = 0.5 * (near + far);
    const physics::Vec3 edge = at(near);
    points.push_back({edge.x, edge.y});
  }
  return points;
}

}  // namespace sanet::view
