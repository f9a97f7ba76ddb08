#include "sim/radio_calibration.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.h"
#include "core/fingerprint.h"
#include "core/version.h"
#include "net/message_header.h"
#include "sim/link_curve.h"

namespace sanet::sim {
namespace {

namespace fs = std::filesystem;

constexpr int kLinks = 20, kFrames = 50, kBytes = 64;
constexpr std::uint64_t kSeed = 1;

std::string CacheFolder() {
  if (const char* own = std::getenv("SANET_CACHE"); own && *own) return own;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/sanet";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/sanet";
  return "";
}

// A broadcast frame's time on the air at the lowest rate (the link curve's frames): PLCP preamble
// and header, then the MAC frame (header and FCS, LLC/SNAP, IP, UDP, sanet's header, the payload).
double BroadcastAirtime(const net::NetworkSpec& n) {
  const double rate = net::DataRates(n.standard).front() * 1e6;
  const double preamble = n.standard == net::WifiStandard::k80211b ? 192e-6 : 20e-6;
  const int bytes = kBytes + static_cast<int>(net::MessageHeader().GetSerializedSize()) + 8 + 20 + 8 + 28;
  return preamble + bytes * 8 / rate;
}

// The curve's rows in ascending power; a row where nothing arrived takes the access delay of the
// nearest row where something did.
net::LinkCalibration FromCurve(const LinkCurve& curve, const net::NetworkSpec& n) {
  net::LinkCalibration c;
  for (auto row = curve.rows.rbegin(); row != curve.rows.rend(); ++row)
    c.rows.push_back({row->mean_dbm, row->Prr(),
                      row->delay_ms.any ? std::max(0.0, row->delay_ms.median / 1e3 - BroadcastAirtime(n)) : -1});
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

Calibration Measure(const RunSpec& spec) {
  RunSpec measured = spec;
  net::NetworkSpec& n = *measured.network;
  n.radio_model = net::RadioModel::kFull;
  n.radios = {true, false};
  n.shadowing.sigma_db = 0;
  measured.seed = kSeed;
  LinkCurveOptions o;
  o.sets = kLinks, o.frames = kFrames, o.size = kBytes;
  DefaultDistances(n, o);
  const LinkCurve curve = MeasureLinkCurve(measured, o, nullptr, [] { return false; });
  return {FromCurve(curve, n), "measured", ""};
}

std::string Text(const net::LinkCalibration& c, const std::string& key) {
  std::ostringstream out;
  out.precision(17);
  out << "# " << key << "\nmean_dbm,prr,access_delay_s\n";
  for (const auto& r : c.rows) out << r.mean_dbm << ',' << r.prr << ',' << r.access_delay_s << '\n';
  return out.str();
}

// The cached table, if the file exists and holds the same key.
std::optional<net::LinkCalibration> Read(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line) || line != "# " + key || !std::getline(in, line)) return std::nullopt;
  net::LinkCalibration c;
  net::LinkCalibration::Row r;
  char comma = 0;
  while (in >> r.mean_dbm >> comma >> r.prr >> comma >> r.access_delay_s) c.rows.push_back(r);
  if (c.rows.empty()) return std::nullopt;
  return c;
}

}  // namespace

std::string CalibrationKey(const net::NetworkSpec& n) {
  std::ostringstream text;
  text.precision(17);
  text << "sanet " << SanetVersion() << "; " << net::StandardName(n.standard) << " " << n.data_rate << " Mbps, rx "
       << n.rx_threshold << " dBm, channel " << net::ChannelName(n.channel) << " " << n.ChannelFloor() << ", fading "
       << static_cast<int>(n.fading.model) << " " << n.fading.m << ", spread " << n.spread.tx_power_db << "/"
       << n.spread.noise_figure_db << ", delay " << static_cast<int>(n.delay) << " " << n.random_delay_max;
  for (const auto& [name, value] : n.ns3) text << ", " << name << "=" << value;
  text << "; " << kLinks << " links x " << kFrames << " frames of " << kBytes << " B";
  return text.str();
}

Calibration CalibrationFor(const RunSpec& spec) {
  const std::string key = CalibrationKey(*spec.network);
  Fingerprint hash;
  hash.Add(key);
  const std::string folder = CacheFolder();
  const std::string path = folder.empty() ? "" : folder + "/calibrations/" + hash.Hex() + ".csv";
  if (!path.empty())
    if (auto cached = Read(path, key)) return {*cached, "cached", path};
  Calibration c = Measure(spec);
  if (path.empty()) return c;
  try {
    fs::create_directories(fs::path(path).parent_path());
    AtomicFile file(path);
    file.Write(Text(c.table, key));
    file.Commit();
    c.path = path;
  } catch (const std::exception&) {  // a cache that cannot be written: measured again next time
  }
  return c;
}

}  // namespace sanet::sim
