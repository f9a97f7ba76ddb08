// Each radio's nominal range for the viewer: the distance at which the scenario's link curve
// (sim/link_curve.h, `sanet link-curve`) crosses a packet reception ratio of 0.5, one per
// distinct radio (nodes' transmit powers), and, where the world has walls that cost the radio
// something, the shape of that range around a point: per bearing, the distance at which the mean
// power through the walls falls to the mean power at the nominal range.
//
// The curve is measured in two passes with the same links: over the default distances (about
// 40), then at 20 distances between the two that bracket 0.5; the crossing is interpolated
// linearly in the second. Measuring starts when the viewer starts, on a thread of its own.
#pragma once

#include <atomic>
#include <future>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "net/obstacle_crossings.h"
#include "sim/run_spec.h"

namespace sanet::view {

constexpr int kRangeLinks = 20;          // links per distance (sanet link-curve --links)
constexpr int kRangeFineDistances = 20;  // steps of the second pass between the bracketing distances
constexpr int kRangeBearings = 180;      // of a shape through walls

struct RadioRange {
  double tx_power_dbm = 0;
  bool lr_wpan = false;              // an 802.15.4 radio's range, else an 802.11 one's
  std::vector<int> nodes;            // ids of the nodes with this radio
  std::optional<double> radius_m;    // unset: the curve never crosses 0.5 in its distances
  double precision_m = 0;            // half the fine step, plus the links' spread over the slope
  double power_dbm = 0;              // the path loss's mean power at radius_m
  std::vector<double> coarse, fine;  // the passes' distances (from, to, step)
};

class RadioRanges {
 public:
  // Starts measuring `spec`'s radios at once; a spec without a network has no ranges (`why`).
  explicit RadioRanges(std::optional<sim::RunSpec> spec, std::string why);
  ~RadioRanges();
  // {"radios": [{tx_power_dbm, radius_m, precision_m, power_dbm, nodes, coarse, fine}], "walls": bool,
  //  "links": n, "frames": n, "seconds": s}, or {"error": why}; waits for the measurement.
  nlohmann::json Ranges();
  // The range of radio `radio` from (x, y) through the walls: kRangeBearings points [x, y].
  nlohmann::json Shape(std::size_t radio, double x, double y);

 private:
  void Measure();
  std::optional<sim::RunSpec> spec_;
  std::string why_;
  std::vector<RadioRange> radios_;
  std::optional<net::ObstacleCrossings> walls_;
  double seconds_ = 0;
  std::mutex ns3_;  // ns-3's objects are made and used by one thread at a time
  std::atomic<bool> stopping_{false};
  std::shared_future<void> measured_;
};

}  // namespace sanet::view
