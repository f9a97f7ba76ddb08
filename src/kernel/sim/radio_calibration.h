// The abstract radio's calibration (net/link_calibration.h): what the full 802.11 model delivers
// against a link's mean received power, measured by its link curve (sim/link_curve.h) on the
// scenario's own 802.11 settings without shadowing (the abstract channel adds each link's
// shadowing and walls to its mean power), 20 links per distance of 50 frames of 64 bytes.
//
// PRR against mean power depends on the radio (standard, rates, threshold, fading, hardware spread,
// ns-3 attributes), not on the path loss, which only maps distance to power: the cache key leaves
// the propagation out, so one calibration serves every scenario with the same radio. Measured
// once per key, with seed 1, and kept in the cache folder ($SANET_CACHE, else
// $XDG_CACHE_HOME/sanet, else ~/.cache/sanet) as calibrations/<key>.csv; a folder that cannot be
// written is no error (the next run measures again).
#pragma once

#include <string>

#include "net/link_calibration.h"
#include "sim/link_curve.h"
#include "sim/run_spec.h"

namespace sanet::sim {

struct Calibration {
  net::LinkCalibration table;
  std::string source;  // "measured", "cached" (from `path`) or "file" (the scenario's)
  std::string path;    // the cache file or the scenario's; empty where none was written or named
};

// The scenario's own table (network.calibration), else the cached one, else measured and cached.
// Call it before the run touches ns-3: measuring runs simulations of its own.
Calibration CalibrationFor(const RunSpec& spec);
// Which of those a run of `network` would use, in words, without measuring.
std::string DescribeCalibration(const net::NetworkSpec& network);
// The cache key: the radio's settings that decide PRR against mean power.
std::string CalibrationKey(const net::NetworkSpec& network);
// A link curve's rows as a calibration: median delay less the airtime of a broadcast of `size`
// bytes at the lowest rate; rows where nothing arrived take the nearest measured delay above.
// Unicasts take the broadcasts' PRR (the curve measured one rate).
net::LinkCalibration CalibrationFromCurve(const LinkCurve& curve, const net::NetworkSpec& network, int size);

}  // namespace sanet::sim
