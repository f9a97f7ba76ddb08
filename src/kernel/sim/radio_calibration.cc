#include "sim/radio_calibration.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/fingerprint.h"
#include "core/version.h"
#include "net/abstract_channel.h"
#include "net/message_header.h"
#include "sim/link_curve.h"

namespace sanet::sim {
namespace {

namespace fs = std::filesystem;

constexpr int kLinks = 20, kFrames = 50, kBytes = 64;
// Raised whenever the measurement changes in a way its key's other words do not say, so that no
// cache measured the old way is read.
constexpr int kMethod = 3;
constexpr int kTransitionSteps = 40;  // the fall from full to no delivery is measured again in as many steps
constexpr std::uint64_t kSeed = 1;

std::string CacheFolder() {
  if (const char* own = std::getenv("SANET_CACHE"); own && *own) return own;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/sanet";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/sanet";
  return "";
}

// A broadcast frame's time on the air at the lowest rate (the link curve's frames): PLCP preamble
// and header, then the MAC frame (header and FCS, LLC/SNAP, IP, UDP, sanet's header, the payload).
double BroadcastAirtime(const net::NetworkSpec& n, int size) {
  const double rate = net::DataRates(n.standard).front() * 1e6;
  const int bytes = size + static_cast<int>(net::MessageHeader().GetSerializedSize()) + 8 + 20 +
                    static_cast<int>(net::AbstractChannel::kMacOverhead);
  return net::PreambleSeconds(n.standard) + bytes * 8 / rate;
}

}  // namespace

net::LinkCalibration CalibrationFromCurve(const LinkCurve& curve, const net::NetworkSpec& n, int size) {
  net::LinkCalibration c;
  for (auto row = curve.rows.rbegin(); row != curve.rows.rend(); ++row)
    c.rows.push_back({row->mean_dbm, row->Prr(),
                      row->delay_ms.any ? std::max(0.0, row->delay_ms.median / 1e3 - BroadcastAirtime(n, size)) : -1,
                      row->Prr()});
  // Distances within the path loss's reference distance share its power: one row for each power.
  c.rows.erase(std::unique(c.rows.begin(), c.rows.end(), [](auto& a, auto& b) { return a.mean_dbm == b.mean_dbm; }),
               c.rows.end());
  // Rows without a delay are the weak ones, first: each takes the first measured delay above it.
  double above = 0;
  for (auto it = c.rows.rbegin(); it != c.rows.rend(); ++it) {
    if (it->access_delay_s < 0)
      it->access_delay_s = above;
    else
      above = it->access_delay_s;
  }
  return c;
}

namespace {

// Where the PRR falls from (nearly) every frame to none: from the farthest distance still at 0.99
// or more before the fall to the first distance beyond the last that delivered anything. The
// table interpolates between rows, so a radio whose PRR falls within one step of the default
// distances (a threshold without fading) would be half wrong there without rows of its own.
std::optional<std::pair<double, double>> Transition(const LinkCurve& curve) {
  const auto& rows = curve.rows;
  std::size_t last_heard = rows.size(), last_full = 0;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].Prr() > 0) last_heard = i;
  if (last_heard == rows.size() || last_heard + 1 == rows.size()) return std::nullopt;
  for (std::size_t i = 0; i <= last_heard; ++i)
    if (rows[i].Prr() >= 0.99) last_full = i;
  return std::pair(rows[last_full].distance, rows[last_heard + 1].distance);
}

// A link curve of `measured`'s network, with the fall from full to no delivery measured again.
LinkCurve CurveWithItsFall(const RunSpec& measured) {
  LinkCurveOptions o;
  o.sets = kLinks, o.frames = kFrames, o.size = kBytes;
  DefaultDistances(*measured.network, o);
  LinkCurve curve = MeasureLinkCurve(measured, o, nullptr, [] { return false; });
  if (const auto fall = Transition(curve)) {
    o.from = fall->first, o.to = fall->second, o.step = (o.to - o.from) / kTransitionSteps;
    const LinkCurve detail = MeasureLinkCurve(measured, o, nullptr, [] { return false; });
    curve.rows.insert(curve.rows.end(), detail.rows.begin(), detail.rows.end());
    std::sort(curve.rows.begin(), curve.rows.end(), [](auto& a, auto& b) { return a.distance < b.distance; });
    curve.rows.erase(
        std::unique(curve.rows.begin(), curve.rows.end(), [](auto& a, auto& b) { return a.distance == b.distance; }),
        curve.rows.end());
  }
  return curve;
}

// Broadcasts go at the lowest rate; unicasts at the data rate, which needs a stronger signal: where
// the two differ, a second curve with broadcasts sent at the data rate gives the unicasts' PRR per
// attempt, and the table has a row at every power either curve measured.
Calibration Measure(const RunSpec& spec) {
  RunSpec measured = spec;
  net::NetworkSpec& n = *measured.network;
  n.radio_model = net::RadioModel::kFull;
  n.radios = {true, false};
  n.shadowing.sigma_db = 0;
  n.spread.tx_power_db = 0;  // the abstract channel applies each sender's own offset
  measured.seed = kSeed;
  const net::LinkCalibration broadcast = CalibrationFromCurve(CurveWithItsFall(measured), n, kBytes);
  if (n.data_rate == net::DataRates(n.standard).front()) return {broadcast, "measured", ""};
  n.broadcast_at_data_rate = true;
  const net::LinkCalibration unicast = CalibrationFromCurve(CurveWithItsFall(measured), n, kBytes);
  std::vector<double> powers;
  for (const auto* table : {&broadcast, &unicast})
    for (const auto& r : table->rows) powers.push_back(r.mean_dbm);
  std::sort(powers.begin(), powers.end());
  powers.erase(std::unique(powers.begin(), powers.end()), powers.end());
  net::LinkCalibration both;
  for (double p : powers) both.rows.push_back({p, broadcast.Prr(p), broadcast.AccessDelay(p), unicast.Prr(p)});
  return {both, "measured", ""};
}

// The cached table, if the file exists, holds the same key and reads as a whole table.
std::optional<net::LinkCalibration> Read(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line) || line != "# " + key) return std::nullopt;
  std::stringstream rest;
  rest << in.rdbuf();
  try {
    return net::ParseLinkCalibrationCsv(rest.str());
  } catch (const net::CalibrationCsvError&) {  // damaged: measured again
    return std::nullopt;
  }
}

}  // namespace

std::string CalibrationKey(const net::NetworkSpec& n) {
  std::ostringstream text;
  text.precision(17);
  text << "sanet " << SanetVersion() << ", calibration method " << kMethod << "; " << net::StandardName(n.standard)
       << " " << n.data_rate << " Mbps, rx " << n.rx_threshold << " dBm, channel " << net::ChannelName(n.channel) << " "
       << n.ChannelFloor() << ", fading " << static_cast<int>(n.fading.model) << " " << n.fading.m
       << ", noise figure spread " << n.spread.noise_figure_db << ", delay " << static_cast<int>(n.delay) << " "
       << n.random_delay_max;
  for (const auto& [name, value] : n.ns3) text << ", " << name << "=" << value;
  text << "; " << kLinks << " links x " << kFrames << " frames of " << kBytes << " B, the fall again in "
       << kTransitionSteps << " steps, unicasts at the data rate";
  return text.str();
}

namespace {

// Where the calibration of `n` is cached: the key's hash in the cache folder.
std::string CachePath(const net::NetworkSpec& n) {
  Fingerprint hash;
  hash.Add(CalibrationKey(n));
  const std::string folder = CacheFolder();
  return folder.empty() ? "" : folder + "/calibrations/" + hash.Hex() + ".csv";
}

}  // namespace

std::string DescribeCalibration(const net::NetworkSpec& n) {
  if (n.calibration) return "from " + (n.calibration_file.empty() ? "the scenario's rows" : n.calibration_file);
  const std::string path = CachePath(n);
  if (!path.empty() && Read(path, CalibrationKey(n))) return "measured earlier, cached in " + path;
  return "not measured yet: the first run measures the full model's link curve (" + std::to_string(kLinks) +
         " links x " + std::to_string(kFrames) + " frames), then caches it" + (path.empty() ? "" : " in " + path);
}

Calibration CalibrationFor(const RunSpec& spec) {
  if (spec.network->calibration) return {*spec.network->calibration, "file", spec.network->calibration_file};
  const std::string key = CalibrationKey(*spec.network);
  const std::string path = CachePath(*spec.network);
  if (!path.empty())
    if (auto cached = Read(path, key)) return {*cached, "cached", path};
  Calibration c = Measure(spec);
  if (path.empty()) return c;
  // Runs of a sweep may measure the same radio at once: each writes a file of its own and renames
  // it into place, so that a reader sees one whole table (the same, whoever wrote it last).
  const std::string own = path + "." + std::to_string(::getpid()) + ".tmp";
  std::error_code error;
  fs::create_directories(fs::path(path).parent_path(), error);
  std::ofstream(own) << net::LinkCalibrationCsv(c.table, key);
  fs::rename(own, path, error);
  if (!error) c.path = path;  // else: a cache that cannot be written, measured again next time
  fs::remove(own, error);
  return c;
}

}  // namespace sanet::sim
