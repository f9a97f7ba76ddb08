// What `sanet link-curve` leaves in its folder (sim/link_curve.h), each file written whole.
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/atomic_file.h"
#include "sim/link_curve.h"
#include "sim/radio_calibration.h"
#include "trace/figures.h"

namespace sanet::sim {
namespace {

std::string Number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

std::string QuartileCells(const Quartiles& q) {
  if (!q.any) return ",,";
  return Number(q.q1) + "," + Number(q.median) + "," + Number(q.q3);
}

// What the figure's title says of the radio (the y axis says it is a link curve): power,
// shadowing, fading, spread.
std::string RadioText(const net::NetworkSpec& n) {
  std::string text = (n.radios.wifi ? "" : "802.15.4, ") + Number(net::DefaultTxPower(n)) + " dBm";
  if (n.shadowing.sigma_db > 0)
    text += ", shadowing " + Number(n.shadowing.sigma_db) + " dB/" + Number(n.shadowing.correlation_m) + " m";
  if (n.fading.model != net::FadingModel::kNone) text += ", Nakagami " + Number(n.fading.m);
  if (n.spread.tx_power_db > 0 || n.spread.noise_figure_db > 0)
    text += ", spread " + Number(n.spread.tx_power_db) + "/" + Number(n.spread.noise_figure_db) + " dB";
  return text;
}

std::string CurveCsv(const LinkCurve& curve) {
  std::ostringstream csv;
  csv << "distance_m,mean_dbm,links,frames_sent,frames_received,prr,share_prr_ge_90,share_prr_ge_50,"
         "share_prr_gt_10,rssi_q1_dbm,rssi_median_dbm,rssi_q3_dbm,delay_q1_ms,delay_median_ms,delay_q3_ms\n";
  for (const LinkCurveRow& r : curve.rows)
    csv << Number(r.distance) << "," << Number(r.mean_dbm) << "," << curve.sets_done << "," << r.sent << ","
        << r.received << "," << Number(r.Prr()) << "," << Number(r.share_90) << "," << Number(r.share_50) << ","
        << Number(r.share_10) << "," << QuartileCells(r.rssi_dbm) << "," << QuartileCells(r.delay_ms) << "\n";
  return csv.str();
}

std::string LinksCsv(const LinkCurve& curve) {
  std::ostringstream csv;
  csv << "set,distance_m,frames_sent,frames_received,prr\n";
  for (const LinkRecord& l : curve.links)
    csv << l.set << "," << Number(l.distance) << "," << l.sent << "," << l.received << ","
        << Number(double(l.received) / l.sent) << "\n";
  return csv.str();
}

std::string CurveSvg(const LinkCurve& curve, const std::string& title) {
  trace::Series prr{"PRR (all frames)", {}}, good{"links with PRR >= 0.9", {}}, some{"links with PRR > 0.1", {}};
  for (const LinkCurveRow& r : curve.rows) {
    prr.points.push_back({r.distance, r.Prr()});
    good.points.push_back({r.distance, r.share_90});
    some.points.push_back({r.distance, r.share_10});
  }
  const double last = curve.rows.empty() ? 0 : curve.rows.back().distance;
  const double connected = curve.connected_to.value_or(0), disconnected = curve.disconnected_from.value_or(last);
  std::vector<trace::Band> bands = {{0, connected, "connected", "#b7e4b0"},
                                    {connected, disconnected, "transitional", "#fde7a9"},
                                    {disconnected, last, "disconnected", "#e0e0e0"}};
  return trace::LinesSvg(title, "distance (m)", "reception ratio, share of links", {prr, good, some}, bands);
}

nlohmann::ordered_json Summary(const LinkCurve& curve, const RunSpec& spec, const LinkCurveOptions& o) {
  nlohmann::ordered_json j;
  j["scenario"] = spec.name;
  j["seed"] = spec.seed;
  j["status"] = curve.interrupted ? "interrupted" : "completed";
  j["sets"] = {{"asked", o.sets}, {"done", curve.sets_done}};
  j["frames_per_link"] = o.frames;
  j["interval_s"] = o.interval;
  j["size_bytes"] = o.size;
  j["distances_m"] = {{"from", o.from}, {"to", o.to}, {"step", o.step}};
  if (o.along) j["along"] = *o.along;
  auto or_null = [](const std::optional<double>& v) { return v ? nlohmann::ordered_json(*v) : nullptr; };
  j["regions"] = {{"connected_to_m", or_null(curve.connected_to)},
                  {"disconnected_from_m", or_null(curve.disconnected_from)},
                  {"share_of_links", 0.95}};
  j["p50_dbm"] = or_null(curve.p50_dbm);
  return j;
}

}  // namespace

void WriteLinkCurve(const LinkCurve& curve, const RunSpec& spec, const LinkCurveOptions& options,
                    const std::string& folder) {
  std::filesystem::create_directories(folder);
  WriteFileAtomically(folder + "/link_curve.csv", CurveCsv(curve));
  WriteFileAtomically(folder + "/link_curve_links.csv", LinksCsv(curve));
  WriteFileAtomically(folder + "/link_curve.svg", CurveSvg(curve, spec.name + ": " + RadioText(*spec.network)));
  WriteFileAtomically(folder + "/link_curve.json", Summary(curve, spec, options).dump(2) + "\n");
  if (WhyNoCalibration(spec, options).empty())
    WriteFileAtomically(
        folder + "/calibration.csv",
        net::LinkCalibrationCsv(CalibrationFromCurve(curve, *spec.network, options.size),
                                "sanet link-curve of " + spec.name + ", " + std::to_string(curve.sets_done) +
                                    " links x " + std::to_string(options.frames) + " frames of " +
                                    std::to_string(options.size) + " B; " + CalibrationKey(*spec.network)));
}

std::string WhyNoCalibration(const RunSpec& spec, const LinkCurveOptions& options) {
  const net::NetworkSpec& n = *spec.network;
  if (n.radio_model != net::RadioModel::kFull) return "it measures the abstract radio, not the full model";
  if (!n.radios.wifi || n.radios.lr_wpan) return "the abstract radio stands for 802.11 radios only";
  if (n.shadowing.sigma_db != 0) return "the curve has shadowing, which the abstract radio adds to each link itself";
  if (n.spread.tx_power_db != 0)
    return "the curve has a transmit-power spread, which the abstract radio applies to each sender itself";
  if (n.data_rate != net::DataRates(n.standard).front())
    return "its broadcasts go at the lowest rate, not network.data_rate (the `measure` calibration measures both)";
  if (options.along) return "its lines cross the scenario's walls, which the abstract radio adds to each link itself";
  return "";
}

}  // namespace sanet::sim
