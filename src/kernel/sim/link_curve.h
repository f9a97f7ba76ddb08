// Link curves: how a scenario's radio delivers frames against distance (`sanet link-curve`).
//
// A *set* is one sender and a receiver at each distance, on a line: the sender broadcasts
// `frames` frames, `interval` apart, over the scenario's network (its radio, propagation,
// shadowing, fading and hardware spread; routing none, so the frames are the only traffic), and
// every receiver counts what it hears, with the signal strength and the delay of each frame. Each
// set is a simulation of its own with a seed of its own drawn from the scenario's, so the sets
// are independent links, as many per distance as there are sets. Lines lie in free space, or
// with `along` in the scenario's world, through its walls.
//
// Per distance the curve gives the packet reception ratio (PRR) over all frames, the shares of
// links whose PRR is at least 0.9, at least 0.5 and above 0.1, and quartiles of signal strength
// and delay. The regions are Zuniga and Krishnamachari's ("Analyzing the transitional region in
// low power wireless links", SECON 2004): connected while at least 95 % of the links have a PRR of
// at least 0.9, disconnected once at most 5 % have more than 0.1, transitional in between.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/run_spec.h"

namespace sanet::sim {

struct LinkCurveOptions {
  double from = 0, to = 0, step = 0;           // m; 0: chosen from the radio (DefaultDistances)
  int sets = 100;                              // links per distance
  int frames = 50;                             // per link
  double interval = 0.05;                      // s between a sender's frames
  int size = 64;                               // bytes of each message
  std::optional<std::array<double, 4>> along;  // x0, y0, x1, y1: from (x0, y0) towards (x1, y1)
};

struct Quartiles {
  double q1 = 0, median = 0, q3 = 0;
  bool any = false;
};

struct LinkCurveRow {
  double distance = 0;  // m
  double mean_dbm = 0;  // the path loss's mean received power (no walls, shadowing or fading)
  std::uint64_t sent = 0, received = 0;
  double share_90 = 0, share_50 = 0, share_10 = 0;  // of links with PRR >= 0.9, >= 0.5, > 0.1
  Quartiles rssi_dbm, delay_ms;
  double Prr() const { return sent ? double(received) / sent : 0; }
};

struct LinkRecord {
  int set = 0;
  double distance = 0;
  int sent = 0, received = 0;  // sent: the frames the set's sender put on the air
};

struct LinkCurve {
  std::vector<LinkCurveRow> rows;
  std::vector<LinkRecord> links;
  int sets_done = 0;
  bool interrupted = false;
  // The regions' bounds (m): connected up to `connected_to`, disconnected from
  // `disconnected_from`; unset when the curve never meets the condition.
  std::optional<double> connected_to, disconnected_from;
  // The mean received power at which half the frames arrive, interpolated along the curve.
  std::optional<double> p50_dbm;
};

// The mean power (dBm) the path loss alone leaves of the network's transmit power at `distance`.
double MeanPower(const net::NetworkSpec& network, double distance);
// Distances from the radio when the options leave them at 0, about 40 of them: up to where a link
// shadowed 2.5 sigma up, on a radio 2.5 sigma stronger, in a frame faded less than 99 % of frames,
// still arrives 3 dB under the detection threshold.
void DefaultDistances(const net::NetworkSpec& network, LinkCurveOptions& options);
constexpr std::size_t kMostDistances = 10000;
// How many distances the options ask for (from, from + step, ... up to to); kMostDistances + 1
// stands for any number over the most.
std::size_t DistanceCount(const LinkCurveOptions& options);
// Measures set by set; `progress(done, total)` after each, `stop()` asked between sets.
LinkCurve MeasureLinkCurve(const RunSpec& spec, const LinkCurveOptions& options,
                           const std::function<void(int, int)>& progress, const std::function<bool()>& stop);
// link_curve.csv, link_curve_links.csv, link_curve.svg and link_curve.json, each written whole;
// and calibration.csv, the abstract radio's table (`network.calibration`), unless WhyNoCalibration.
// The abstract channel adds each link's shadowing, walls and transmit-power spread to its mean
// power, so a curve calibrates only without them: the full 802.11 model alone, no shadowing and
// no transmit spread, in free space; and at the lowest rate, which broadcasts and (then) unicasts use.
// Why a curve of `spec` with `options` is no calibration (empty: it is one).
std::string WhyNoCalibration(const RunSpec& spec, const LinkCurveOptions& options);
void WriteLinkCurve(const LinkCurve& curve, const RunSpec& spec, const LinkCurveOptions& options,
                    const std::string& folder);

}  // namespace sanet::sim
