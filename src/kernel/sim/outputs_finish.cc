// The end of a run's outputs: network files, figures, summary.json and the fingerprint.
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "core/json_text.h"
#include "core/statistics.h"
#include "sim/outputs.h"
#include "trace/png_export.h"

namespace sanet::sim {
namespace {

std::string PacketRow(const std::string& node, const net::PacketCounts& c) {
  char row[256];
  std::snprintf(row, sizeof row, "%s,%llu,%llu,%llu,%llu,%llu,%llu", node.c_str(), (unsigned long long)c.sent,
                (unsigned long long)c.received, (unsigned long long)c.forwarded, (unsigned long long)c.dropped,
                (unsigned long long)c.messages_sent, (unsigned long long)c.messages_received);
  return row;
}

std::string RouteRow(const std::string& node, const std::string& destination, const net::Discovery& d) {
  char row[256];
  if (d.established)
    std::snprintf(row, sizeof row, "%s,%s,%.6f,%.6f,%.6f", node.c_str(), destination.c_str(), d.started, *d.established,
                  *d.established - d.started);
  else
    std::snprintf(row, sizeof row, "%s,%s,%.6f,,", node.c_str(), destination.c_str(), d.started);
  return row;
}

// Frames the radios sent and received whole; with walls, how often a pair's wall loss was asked
// for and how often it had to be computed (the rest came from the cache), and the same of the
// links' shadowing; with the indexed
// channel also how many radios a frame was offered and handed to, on average.
nlohmann::ordered_json ChannelSummary(const net::ChannelCounts& c) {
  nlohmann::ordered_json out = {
      {"model", c.model}, {"frames_sent", c.frames_sent}, {"frames_received", c.frames_received}};
  if (c.walls > 0)
    out["walls"] = {{"obstacles", c.walls}, {"losses_asked", c.wall_losses}, {"losses_computed", c.wall_walks}};
  if (c.shadowing) out["shadowing"] = {{"asked", c.shadowing_asked}, {"computed", c.shadowing_computed}};
  if (!c.calibration.empty()) out["calibration"] = c.calibration;
  if (!c.floor_dbm) return out;
  const double frames = c.frames_sent ? static_cast<double>(c.frames_sent) : 1.0;
  out["floor_dbm"] = *c.floor_dbm;
  out["receivers_considered_per_frame"] = c.candidates / frames;
  out["receivers_per_frame"] = c.handed / frames;
  return out;
}

nlohmann::ordered_json NetworkSummary(const net::NetworkTraces& n) {
  net::PacketCounts total;
  for (const net::PacketCounts& c : n.counts) {
    total.sent += c.sent, total.received += c.received, total.forwarded += c.forwarded;
    total.dropped += c.dropped, total.messages_sent += c.messages_sent;
    total.messages_received += c.messages_received;
  }
  std::vector<double> discovery_times;
  for (const net::Discovery& d : n.discoveries)
    if (d.established) discovery_times.push_back(*d.established - d.started);
  return {{"radio", n.radio},
          {"data_rate_mbps", n.data_rate_mbps},
          {"tx_power_dbm", n.tx_power_dbm},
          {"routing", n.routing},
          {"channel", ChannelSummary(n.channel)},
          {"packets",
           {{"sent", total.sent},
            {"received", total.received},
            {"forwarded", total.forwarded},
            {"dropped", total.dropped},
            {"messages_sent", total.messages_sent},
            {"messages_received", total.messages_received}}},
          {"route_discoveries",
           {{"started", n.discoveries.size()},
            {"established", discovery_times.size()},
            {"time_s", Quartiles(discovery_times)}}}};
}

// Delays are left empty for a tap that received nothing.
std::string TapRow(const std::string& node, const net::TapCounts& c) {
  char row[320], delays[64] = ",";
  if (!c.delays.empty())
    std::snprintf(delays, sizeof delays, "%.6f,%.6f", Quantile(c.delays, 0.5), Quantile(c.delays, 0.99));
  std::snprintf(row, sizeof row, "%s,%llu,%llu,%llu,%llu,%llu,%llu,%s", node.c_str(),
                (unsigned long long)c.packets_sent, (unsigned long long)c.bytes_sent,
                (unsigned long long)c.packets_received, (unsigned long long)c.bytes_received,
                (unsigned long long)c.unicast_sent, (unsigned long long)(c.unicast_sent - c.unicast_arrived), delays);
  return row;
}

nlohmann::ordered_json TapSummary(const net::TapCounts& c) {
  return {
      {"packets_sent", c.packets_sent},
      {"bytes_sent", c.bytes_sent},
      {"packets_received", c.packets_received},
      {"bytes_received", c.bytes_received},
      {"unicast_sent", c.unicast_sent},
      {"unicast_lost", c.unicast_sent - c.unicast_arrived},
      {"delay_s", Quartiles(c.delays)},
      {"delay_p99_s", c.delays.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(Quantile(c.delays, 0.99))}};
}

}  // namespace

// taps.csv: what real programs sent and received over the simulated radio (not fingerprinted:
// real traffic follows the wall clock).
void Outputs::AddTapFiles(const net::NetworkTraces& network, nlohmann::ordered_json& summary) {
  if (network.taps.empty()) return;
  trace::CsvSink& taps = folder_.Csv("taps.csv",
                                     "node,packets_sent,bytes_sent,packets_received,bytes_received,unicast_sent,"
                                     "unicast_lost,delay_p50_s,delay_p99_s");
  for (const auto& [id, counts] : network.taps) {
    taps.Row(TapRow(Name(id), counts));
    summary[Name(id)] = TapSummary(counts);
  }
  folder_.Commit();
}

// packets.csv and routes.csv, then the packet logs the network wrote through the folder.
void Outputs::AddNetworkFiles(const net::NetworkTraces& network, Fingerprint& fp) {
  trace::CsvSink& packets =
      folder_.Csv("packets.csv", "node,sent,received,forwarded,dropped,messages_sent,messages_received");
  for (NodeId id = 0; id < network.counts.size(); ++id) packets.Row(PacketRow(Name(id), network.counts[id]));
  trace::CsvSink& routes = folder_.Csv("routes.csv", "node,destination,started,established,duration");
  for (const net::Discovery& d : network.discoveries) routes.Row(RouteRow(Name(d.node), Name(d.destination), d));
  folder_.Commit();
  fp.Add(packets.hash());
  fp.Add(routes.hash());
  if (network.packet_logs)
    for (const NodeSpec& n : nodes_) fp.Add(folder_.CsvHash("packets/" + n.name + ".csv"));
}

void Outputs::Finish(RunResult& result, const std::optional<net::NetworkTraces>& network,
                     const std::string& scenario_file, const std::vector<Pose2D>& final_poses,
                     nlohmann::ordered_json extra) {
  subscriptions_.clear();  // the run is over: nothing more is recorded
  energy_.Stop();
  radio_contacts_.Stop();
  if (sqlite_) sqlite_->Close();
  for (const auto& file : trace_files_) file->Close();
  folder_.Commit();
  Fingerprint fp;
  fp.Add(spec_.seed);
  fp.Add(trajectories_.hash());
  fp.Add(log_.hash());
  fp.Add(messages_.hash());
  fp.Add(transitions_.hash());
  fp.Add(metric_rows_.hash());
  if (min_distance_) fp.Add(min_distance_->hash());
  energy_.AddTo(fp);
  if (network) {
    AddNetworkFiles(*network, fp);
    extra["network"] = NetworkSummary(*network);
    nlohmann::ordered_json taps = nlohmann::ordered_json::object();
    AddTapFiles(*network, taps);
    if (!taps.empty()) extra["network"]["taps"] = taps;
  }
  if (auto contacts = radio_contacts_.Write(result.simulated)) {  // not fingerprinted, as the trace
    folder_.Commit();
    extra["radio_contacts"] = *contacts;
  }
  result.fingerprint = fp.Hex();
  const nlohmann::ordered_json moved_motes = RunWarnings::MovedMotes(nodes_, final_poses);
  result.warnings = warnings_.Sentences(moved_motes);
  for (const auto& file : trace_files_) file->Report(trace_profile_, result.warnings);
  if (!moved_motes.empty()) extra["motes_moved"] = moved_motes;
  std::vector<std::string> all = said_before_;
  // The front end's own (RunOptions::add_results), after the run's.
  if (extra.contains("warnings"))
    for (const auto& w : extra["warnings"]) result.warnings.push_back(w.get<std::string>());
  all.insert(all.end(), result.warnings.begin(), result.warnings.end());
  extra["warnings"] = all;
  if (!folder_.writes()) return;
  if (spec_.figures) {
    WriteFigures(final_poses, network);
    folder_.Commit();  // the PNG copies
  }
  nlohmann::ordered_json summary = Summary(result, scenario_file, final_poses);
  for (const auto& [key, value] : extra.items()) summary[key] = value;
  folder_.Listed("summary.json");
  summary["files"] = folder_.files();
  folder_.WriteWhole("summary.json", JsonText(summary, 2) + "\n");
  result.files = folder_.files();
}

void Outputs::WriteFigures(const std::vector<Pose2D>& final_poses, const std::optional<net::NetworkTraces>& network) {
  trace::FigureInput in;
  in.title = spec_.name;
  for (const Obstacle& o : spec_.obstacles)
    in.obstacles.push_back({o.kind, {o.box.center.x, o.box.center.y}, {o.box.size.x, o.box.size.y}, o.box.yaw});
  for (NodeId id = 0; id < nodes_.size(); ++id) {
    const NodeSpec& n = nodes_[id];
    const bool mote = !robots::HasDrive(n.model);
    const bool pushed = mote && Norm(final_poses.at(id).position() - n.pose.position()) > RunWarnings::kMoteMoved;
    in.nodes.push_back({n.name, mote, n.pose, final_poses.at(id), pushed});
  }
  for (auto& [id, track] : tracks_) {
    track.node = Name(id);
    in.tracks.push_back(track);
  }
  if (network)
    for (const net::PacketCounts& c : network->counts) in.received.push_back(c.received);
  std::vector<std::string> figures = {"map"};
  folder_.WriteWhole("map.svg", trace::MapSvg(in, spec_.figure_tick));
  if (!min_distances_.empty()) {
    folder_.WriteWhole("min_distance.svg", trace::LineSvg(spec_.name + ": smallest distance between robots", "time (s)",
                                                          "distance (m)", min_distances_, spec_.distance_reference));
    figures.push_back("min_distance");
  }
  if (!in.received.empty()) {
    folder_.WriteWhole("packets.svg", trace::PacketsSvg(in));
    figures.push_back("packets");
  }
  if (const auto energy = energy_.Figure(spec_.name)) {
    folder_.WriteWhole("energy.svg", *energy);
    figures.push_back("energy");
  }
  // PNG copies where rsvg-convert is installed (./setup installs it).
  if (trace::PngExportAvailable())
    for (const std::string& name : figures)
      trace::SvgToPng(folder_.dir() + "/" + name + ".svg", folder_.TempFile(name + ".png"));
}

namespace {
// The process's peak resident set (getrusage reports it in KiB on Linux).
double PeakMemoryMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}
}  // namespace

nlohmann::ordered_json Outputs::Summary(const RunResult& result, const std::string& scenario_file,
                                        const std::vector<Pose2D>& final_poses) const {
  nlohmann::ordered_json j;
  j["scenario"] = scenario_file;
  if (!scenario_fingerprint_.empty()) j["scenario_fingerprint"] = scenario_fingerprint_;
  j["name"] = spec_.name;
  j["status"] = !failure_.empty() ? "failed: " + failure_ : interrupted_ ? "interrupted" : "completed";
  j["seed"] = spec_.seed;
  j["duration_s"] = spec_.duration;
  j["simulated_s"] = result.simulated;
  j["wall_time_s"] = result.wall;
  j["real_time_factor"] = result.real_time_factor;
  j["peak_memory_mb"] = PeakMemoryMb();
  j["events"] = result.events;
  j["physics_steps"] = result.physics_steps;
  j["quiet_physics_steps"] = result.quiet_physics_steps;
  j["threads"] = result.threads;
  j["physics_step_s"] = spec_.physics_step;
  j["world_size_m"] = {spec_.world_size.x, spec_.world_size.y};
  j["fingerprint"] = result.fingerprint;
  j["profile_s"] = {{"physics", result.profile.physics},
                    {"sensing", result.profile.sensing},
                    {"controllers", result.profile.controllers},
                    {"recording", result.profile.recording},
                    {"physics_wait", result.profile.physics_wait}};
  if (sqlite_) {
    j["profile_s"]["trace"] = {{"sqlite", sqlite_->seconds()}};
    j["profile_s"]["trace"].update(trace_profile_);
  }
  nlohmann::ordered_json nodes = nlohmann::ordered_json::array();
  for (NodeId id = 0; id < nodes_.size(); ++id) {
    const Pose2D p = final_poses.at(id);
    nodes.push_back({{"name", Name(id)},
                     {"model", robots::ModelName(nodes_[id].model.kind)},
                     {"controller", nodes_[id].controller ? nodes_[id].controller->name : ""},
                     {"final_pose", {p.x, p.y, p.theta}}});
    if (auto it = spawned_as_.find(id); it != spawned_as_.end()) nodes.back()["spawned_as"] = it->second;
  }
  j["nodes"] = nodes;
  j["rows"] = {{"trajectories", trajectories_.rows()}, {"log", log_.rows()}, {"messages", messages_.rows()}};
  j["ended_by"] = ended_by_.empty() ? "duration" : ended_by_;
  j["ended_at_s"] = ended_by_.empty() ? result.simulated : ended_at_;
  j["message_delay_s"] = Quartiles(delays_);
  j["messages_dropped_by_impairment"] = messages_lost_;
  j["messages_lost_before_their_controller"] = messages_undelivered_;
  nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
  for (const auto& [node, named] : metrics_)
    for (const auto& [metric, values] : named) {
      metrics[node][metric] = Quartiles(values);
      // A controller's counts come one Metric call at a time, or as running totals: the sum says
      // what the first kind adds up to.
      metrics[node][metric]["sum"] = std::accumulate(values.begin(), values.end(), 0.0);
    }
  j["metrics"] = metrics;
  j["transitions_to"] = transitions_to_;
  if (!min_distances_.empty()) j["min_distance"] = MinDistanceSummary();
  return j;
}

nlohmann::ordered_json Outputs::MinDistanceSummary() const {
  auto lowest = std::min_element(min_distances_.begin(), min_distances_.end(),
                                 [](const auto& a, const auto& b) { return a.second < b.second; });
  nlohmann::ordered_json md = {{"min_m", lowest->second}, {"at_s", lowest->first}};
  if (spec_.distance_reference > 0) {
    std::size_t near = 0;
    for (const auto& [t, d] : min_distances_)
      near += std::fabs(d - spec_.distance_reference) <= 0.1 * spec_.distance_reference;
    md["reference_m"] = spec_.distance_reference;
    md["fraction_within_10_percent"] = double(near) / min_distances_.size();
  }
  return md;
}

}  // namespace sanet::sim
