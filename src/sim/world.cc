#include "sim/world.h"

#include <ns3/core-module.h>
#include <ns3/mobility-model.h>
#include <ns3/node-container.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "core/atomic_file.h"
#include "core/fingerprint.h"
#include "net/body_mobility_model.h"
#include "core/statistics.h"
#include "net/local_transport.h"
#include "net/wireless_network.h"
#include "trace/figures.h"

namespace sanet::sim {
namespace {

bool g_world_exists = false;

ns3::Time Period(double seconds) { return ns3::NanoSeconds(std::llround(seconds * 1e9)); }

double Since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Adds the wall time of a scope to one stage of the profile.
class StageTimer {
 public:
  explicit StageTimer(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~StageTimer() { total_ += Since(start_); }

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

std::string Format(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string Format(const char* format, ...) {
  char line[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  return line;
}

}  // namespace

std::unique_ptr<Controller> MakeController(const ControllerSpec& spec, agents::Registry& registry) {
  if (!spec.library.empty()) registry.LoadLibrary(spec.library);
  const ControllerInfo* info = registry.Find(spec.name);
  if (!info) throw agents::RegistryError("unknown controller '" + spec.name + "'");
  std::unique_ptr<Controller> controller = info->create(spec.params);
  spec.params.CheckAllUsed();
  return controller;
}

struct World::Outputs {
  trace::CsvSink trajectories, log, messages, transitions, min_distance;
  std::vector<std::pair<double, double>> min_distances;  // (time, smallest distance between robots)
  std::vector<double> delays;  // of every message delivered, s
  std::uint64_t messages_lost = 0;  // dropped by the added message_loss
  std::map<std::string, std::map<std::string, std::vector<double>>> metrics;  // node -> name -> values
  std::string ended_by;  // the end condition met, if any
  double ended_at = 0;   // s, when it was met
  std::map<NodeId, trace::Track> tracks;  // of robots, for the figures
  std::map<std::string, int> transitions_to;  // state -> transitions into it
  std::string failure;  // first controller error, which ends the run early
  Outputs(const std::string& dir)
      : trajectories(dir.empty() ? std::nullopt : std::optional(dir + "/trajectories.csv"),
                     "time,node,x,y,theta"),
        log(dir.empty() ? std::nullopt : std::optional(dir + "/log.csv"), "time,node,text"),
        messages(dir.empty() ? std::nullopt : std::optional(dir + "/messages.csv"),
                 "time_sent,from,to,delivery,bytes,time_received,delay,hops"),
        transitions(dir.empty() ? std::nullopt : std::optional(dir + "/transitions.csv"), "time,node,from,to,why"),
        min_distance(std::nullopt, "time,min_distance,a,b") {}
};

World::World(const RunSpec& spec, agents::Registry& registry)
    : spec_(spec), impairments_(spec.seed, "messages/impairments") {
  if (g_world_exists) throw WorldError("only one World may exist at a time (ns-3 is process-wide)");
  if (spec.physics_step <= 0) throw WorldError("physics step must be positive");
  g_world_exists = true;
  try {
    ns3::RngSeedManager::SetSeed(static_cast<std::uint32_t>(spec.seed % 4294967295u) + 1);
    physics_ = physics::CreateOdeWorld(spec.physics);
    for (const Obstacle& o : spec.obstacles) physics_->add_static_box(o.box);

    ns3::NodeContainer ns3_nodes;
    ns3_nodes.Create(spec.nodes.size());
    for (NodeId id = 0; id < spec.nodes.size(); ++id) {
      const NodeSpec& n = spec.nodes[id];
      models_.push_back(std::make_unique<robots::NodeModel>(*physics_, n.model, n.pose, spec.seed,
                                                            "node/" + n.name));
      const physics::Body& body = models_.back()->body();
      auto mobility = ns3::CreateObject<net::BodyMobilityModel>();
      mobility->Bind(
          [&body] {
            const physics::Vec3 p = body.position3();
            return ns3::Vector(p.x, p.y, p.z);
          },
          [&body] {
            const Twist2D v = body.velocity();
            return ns3::Vector(v.vx, v.vy, 0);
          });
      ns3_nodes.Get(id)->AggregateObject(mobility);
    }
    if (spec.network) {
      std::vector<std::string> names;
      std::vector<net::NodeRadio> radios;
      for (const NodeSpec& n : spec.nodes) {
        names.push_back(n.name);
        radios.push_back(n.radio);
      }
      transport_ = std::make_unique<net::WirelessNetwork>(*spec.network, ns3_nodes, names, radios);
    } else {
      transport_ = std::make_unique<net::LocalTransport>(spec.nodes.size(), spec.message_latency);
    }
    transport_->SetReceiver([this](NodeId to, const Message& m) { Receive(to, m); });
    for (NodeId id = 0; id < spec.nodes.size(); ++id) {
      const NodeSpec& n = spec.nodes[id];
      nodes_.push_back(std::make_unique<agents::SimulatedNode>(
          id, n.name, *models_[id], *transport_, *this, RandomStream(spec.seed, "node/" + n.name + "/controller")));
      const bool remote = spec.robots_remote && n.model.kind != robots::ModelKind::kMote;
      controllers_.push_back(n.controller && !remote ? MakeController(*n.controller, registry) : nullptr);
    }
  } catch (...) {
    ns3::Simulator::Destroy();
    g_world_exists = false;
    throw;
  }
  last_recorded_.resize(spec.nodes.size());
  switched_off_.assign(spec.nodes.size(), false);
}

World::~World() {
  // Controllers may hold code from libraries and state tied to nodes: drop them first.
  controllers_.clear();
  ns3::Simulator::Destroy();
  g_world_exists = false;
}

std::optional<NodeId> World::Lookup(const std::string& name) const {
  for (NodeId id = 0; id < spec_.nodes.size(); ++id)
    if (spec_.nodes[id].name == name) return id;
  return std::nullopt;
}

Pose2D World::TruePose(NodeId node) const { return models_.at(node)->body().pose(); }

void World::Log(NodeId node, const std::string& text) {
  if (!out_) return;
  const double now = ns3::Simulator::Now().GetSeconds();
  const std::string& name = spec_.nodes.at(node).name;
  out_->log.Row(Format("%.6f,", now) + trace::CsvField(name) + "," + trace::CsvField(text));
  // "transition FROM -> TO: why"
  if (text.rfind("transition ", 0) == 0) {
    const auto arrow = text.find(" -> "), colon = text.find(": ", text.find(" -> ") + 4);
    if (arrow != std::string::npos) {
      const std::string from = text.substr(11, arrow - 11);
      const std::string to = text.substr(arrow + 4, colon == std::string::npos ? std::string::npos : colon - arrow - 4);
      const std::string why = colon == std::string::npos ? "" : text.substr(colon + 2);
      ++out_->transitions_to[to];
      out_->transitions.Row(Format("%.6f,", now) + trace::CsvField(name) + "," + trace::CsvField(from) + "," +
                            trace::CsvField(to) + "," + trace::CsvField(why));
    }
  }
  // "metric NAME VALUE"
  if (text.rfind("metric ", 0) == 0) {
    std::istringstream words(text.substr(7));
    std::string metric;
    double value;
    if (words >> metric >> value) out_->metrics[name][metric].push_back(value);
  }
  for (const std::string& end : spec_.end_when_logged)
    if (text == end && out_->ended_by.empty()) {
      out_->ended_by = "'" + end + "' logged by " + name;
      out_->ended_at = now;
      ns3::Simulator::Stop(Period(spec_.end_grace));  // let the last messages arrive
    }
}

void World::SwitchOff(NodeId node) {
  switched_off_.at(node) = true;
  models_[node]->Drive({});
  transport_->SwitchOff(node);
  Log(node, "switched off");
}

// Impairments added on top of the network, as the receiving controller sees them: a message is
// lost with probability `message_loss`, or reaches the controller `message_delay` later.
void World::Receive(NodeId to, const Message& m) {
  if (spec_.message_loss > 0 && impairments_.Uniform() < spec_.message_loss) {
    ++out_->messages_lost;
    return;
  }
  if (spec_.message_delay > 0) {
    Message later = m;
    ns3::Simulator::Schedule(Period(spec_.message_delay), [this, to, later]() mutable {
      later.time_received = ns3::Simulator::Now().GetSeconds();
      Deliver(to, later);
    });
    return;
  }
  Deliver(to, m);
}

void World::Deliver(NodeId to, const Message& m) {
  static const char* kDelivery[] = {"unicast", "broadcast", "flood"};
  const double delay = m.time_received - m.time_sent;
  out_->delays.push_back(delay);
  out_->messages.Row(Format("%.6f,%s,%s,%s,%zu,%.6f,%.6f,%s", m.time_sent, spec_.nodes.at(m.from).name.c_str(),
                            spec_.nodes.at(to).name.c_str(), kDelivery[static_cast<int>(m.delivery)],
                            m.payload.size(), m.time_received, delay,
                            m.hops ? std::to_string(*m.hops).c_str() : ""));
  if (!controllers_.at(to) || switched_off_[to]) return;
  StageTimer timer(profile_.controllers);
  try {
    controllers_[to]->OnMessage(*nodes_[to], m);
  } catch (const std::exception& e) {
    out_->failure = "controller of " + spec_.nodes[to].name + " failed on a message: " + e.what();
    ns3::Simulator::Stop();
  }
}

void World::PhysicsStep() {
  {
    StageTimer timer(profile_.physics);
    physics_->step(spec_.physics_step);
  }
  {
    StageTimer timer(profile_.sensing);
    for (robots::NodeModel* m : vehicles_) m->AfterPhysicsStep();
  }
  ++physics_steps_;
  if (step_observer_) step_observer_(ns3::Simulator::Now().GetSeconds());
  ns3::Simulator::Schedule(Period(spec_.physics_step), &World::PhysicsStep, this);
}

void World::ControlStep(std::size_t index) {
  if (switched_off_[index]) return;
  {
    StageTimer timer(profile_.controllers);
    try {
      controllers_[index]->ControlStep(*nodes_[index]);
    } catch (const std::exception& e) {
      out_->failure = "controller of " + spec_.nodes[index].name + " failed: " + e.what();
      ns3::Simulator::Stop();
      return;
    }
  }
  ns3::Simulator::Schedule(Period(1.0 / spec_.nodes[index].controller->rate), &World::ControlStep,
                           this, index);
}

// The smallest distance between any two robots (centre to centre), with the pair.
void World::RecordMinDistance(double now) {
  double best = HUGE_VAL;
  std::size_t a = 0, b = 0;
  for (std::size_t i = 0; i < vehicles_.size(); ++i)
    for (std::size_t j = i + 1; j < vehicles_.size(); ++j) {
      const double d = Norm(vehicles_[i]->body().pose().position() - vehicles_[j]->body().pose().position());
      if (d < best) best = d, a = i, b = j;
    }
  if (best == HUGE_VAL) return;
  out_->min_distances.push_back({now, best});
  out_->min_distance.Row(Format("%.3f,%.4f,%s,%s", now, best, vehicle_names_[a].c_str(), vehicle_names_[b].c_str()));
}

void World::Record(bool final_row) {
  StageTimer timer(profile_.recording);
  if (spec_.min_distance && !final_row) RecordMinDistance(std::min(ns3::Simulator::Now().GetSeconds(), spec_.duration));
  const double now = std::min(ns3::Simulator::Now().GetSeconds(), spec_.duration);
  for (NodeId id = 0; id < models_.size(); ++id) {
    const Pose2D p = models_[id]->body().pose();
    auto& last = last_recorded_[id];
    // Nodes at rest add no rows (a mote appears at the start and the end unless something moves
    // it); the last row of every node is its final pose.
    if (last && (final_row ? last->time >= spec_.duration
                           : std::fabs(p.x - last->pose.x) < 5e-5 && std::fabs(p.y - last->pose.y) < 5e-5 &&
                                 std::fabs(WrapAngle(p.theta - last->pose.theta)) < 5e-5))
      continue;
    last = Recorded{p, now};
    if (spec_.figures && models_[id]->mobile()) {
      trace::Track& track = out_->tracks[id];
      track.t.push_back(now), track.x.push_back(p.x), track.y.push_back(p.y);
    }
    out_->trajectories.Row(Format("%.3f,%s,%.4f,%.4f,%.4f", now, spec_.nodes[id].name.c_str(), p.x,
                                  p.y, p.theta));
  }
}

void World::ShowProgress() {
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_progress_).count() >= 0.5) {
    last_progress_ = now;
    const double t = ns3::Simulator::Now().GetSeconds();
    const double wall = Since(wall_start_);
    const double rtf = wall > 0 ? t / wall : 0;
    const double eta = rtf > 0 ? (spec_.duration - t) / rtf : 0;
    std::fprintf(stderr, "\r  t = %.1f / %.1f s   %.1fx real time   ETA %.0f s   ", t,
                 spec_.duration, rtf, eta);
    std::fflush(stderr);
  }
  ns3::Simulator::Schedule(ns3::Seconds(1), &World::ShowProgress, this);
}

RunResult World::Run(const RunOptions& options) {
  if (ran_) throw WorldError("a World runs once");
  ran_ = true;
  if (!options.output_dir.empty()) std::filesystem::create_directories(options.output_dir);
  out_ = std::make_unique<Outputs>(options.output_dir);
  if (spec_.min_distance && !options.output_dir.empty())
    out_->min_distance = trace::CsvSink(options.output_dir + "/min_distance.csv", "time,min_distance,a,b");

  // Order at equal times follows scheduling order: controllers start, then record, physics.
  ns3::Simulator::ScheduleNow([this] {
    StageTimer timer(profile_.controllers);
    for (std::size_t i = 0; i < controllers_.size(); ++i) {
      if (!controllers_[i]) continue;
      try {
        controllers_[i]->Start(*nodes_[i]);
      } catch (const std::exception& e) {
        out_->failure = "controller of " + spec_.nodes[i].name + " failed to start: " + e.what();
        ns3::Simulator::Stop();
        return;
      }
    }
  });
  for (std::size_t i = 0; i < controllers_.size(); ++i)
    if (controllers_[i]) ns3::Simulator::ScheduleNow(&World::ControlStep, this, i);
  for (const NodeEvent& e : spec_.events)
    ns3::Simulator::Schedule(Period(e.time), &World::SwitchOff, this, static_cast<NodeId>(e.node));
  std::function<void()> record = [this, &record] {
    Record(false);
    ns3::Simulator::Schedule(Period(spec_.trajectory_interval), record);
  };
  ns3::Simulator::ScheduleNow(record);
  // A world without vehicles has nothing to integrate: motes rest until a vehicle pushes them.
  for (NodeId id = 0; id < models_.size(); ++id)
    if (models_[id]->mobile()) vehicles_.push_back(models_[id].get()), vehicle_names_.push_back(spec_.nodes[id].name);
  if (!vehicles_.empty()) ns3::Simulator::Schedule(Period(spec_.physics_step), &World::PhysicsStep, this);
  transport_->Open(options.output_dir);
  wall_start_ = last_progress_ = std::chrono::steady_clock::now();
  if (options.progress) ns3::Simulator::ScheduleNow(&World::ShowProgress, this);

  // Events at exactly `duration` still run: the run covers [0, duration].
  ns3::Simulator::Stop(Period(spec_.duration) + ns3::NanoSeconds(1));
  ns3::Simulator::Run();
  if (options.progress) std::fprintf(stderr, "\r%78s\r", "");

  RunResult result;
  result.simulated = std::min(ns3::Simulator::Now().GetSeconds(), spec_.duration);
  Record(/*final_row=*/true);
  ended_by_ = out_->ended_by;
  ended_at_ = out_->ended_at;
  result.wall = Since(wall_start_);
  result.real_time_factor = result.wall > 0 ? result.simulated / result.wall : 0;
  result.events = ns3::Simulator::GetEventCount();
  result.physics_steps = physics_steps_;
  out_->trajectories.Commit();
  out_->log.Commit();
  out_->messages.Commit();
  out_->transitions.Commit();
  out_->min_distance.Commit();
  Fingerprint fp;
  fp.Add(spec_.seed);
  fp.Add(out_->trajectories.hash());
  fp.Add(out_->log.hash());
  fp.Add(out_->messages.hash());
  fp.Add(out_->transitions.hash());
  if (spec_.min_distance) fp.Add(out_->min_distance.hash());
  nlohmann::ordered_json network_summary;
  transport_->Finish(fp, network_summary, result.files);
  result.fingerprint = fp.Hex();
  result.profile = profile_;
  if (!options.output_dir.empty()) {
    for (const char* f : {"trajectories.csv", "log.csv", "messages.csv", "transitions.csv", "summary.json"})
      result.files.push_back(f);
    if (spec_.min_distance) result.files.push_back("min_distance.csv");
    if (spec_.figures) WriteFigures(options.output_dir, result);
    WriteSummary(options, result, network_summary);
  }
  if (!out_->failure.empty()) throw WorldError(out_->failure);
  return result;
}

void World::WriteFigures(const std::string& dir, RunResult& result) {
  trace::FigureInput in{spec_, {}, {}, transport_->PacketsReceived()};
  for (const auto& m : models_) in.final_poses.push_back(m->body().pose());
  for (auto& [id, track] : out_->tracks) {
    track.node = spec_.nodes[id].name;
    in.tracks.push_back(track);
  }
  WriteFileAtomically(dir + "/map.svg", trace::MapSvg(in, spec_.figure_tick));
  result.files.push_back("map.svg");
  if (!out_->min_distances.empty()) {
    WriteFileAtomically(dir + "/min_distance.svg",
                        trace::LineSvg(spec_.name + ": smallest distance between robots", "time (s)", "distance (m)",
                                       out_->min_distances, spec_.distance_reference));
    result.files.push_back("min_distance.svg");
  }
  if (!in.received.empty()) {
    WriteFileAtomically(dir + "/packets.svg", trace::PacketsSvg(in));
    result.files.push_back("packets.svg");
  }
}

void World::WriteSummary(const RunOptions& options, RunResult& result, const nlohmann::ordered_json& extra) {
  nlohmann::ordered_json j;
  j["scenario"] = options.scenario_file;
  j["name"] = spec_.name;
  j["status"] = out_->failure.empty() ? "completed" : "failed: " + out_->failure;
  j["seed"] = spec_.seed;
  j["duration_s"] = spec_.duration;
  j["simulated_s"] = result.simulated;
  j["wall_time_s"] = result.wall;
  j["real_time_factor"] = result.real_time_factor;
  j["events"] = result.events;
  j["physics_steps"] = result.physics_steps;
  j["physics_step_s"] = spec_.physics_step;
  j["world_size_m"] = {spec_.world_size.x, spec_.world_size.y};
  j["fingerprint"] = result.fingerprint;
  j["profile_s"] = {{"physics", profile_.physics},
                    {"sensing", profile_.sensing},
                    {"controllers", profile_.controllers},
                    {"recording", profile_.recording}};
  nlohmann::ordered_json nodes = nlohmann::ordered_json::array();
  for (NodeId id = 0; id < models_.size(); ++id) {
    const Pose2D p = models_[id]->body().pose();
    nodes.push_back({{"name", spec_.nodes[id].name},
                     {"model", robots::ModelName(spec_.nodes[id].model.kind)},
                     {"controller", spec_.nodes[id].controller ? spec_.nodes[id].controller->name : ""},
                     {"final_pose", {p.x, p.y, p.theta}}});
  }
  j["nodes"] = nodes;
  j["rows"] = {{"trajectories", out_->trajectories.rows()},
               {"log", out_->log.rows()},
               {"messages", out_->messages.rows()}};
  j["ended_by"] = out_->ended_by.empty() ? "duration" : out_->ended_by;
  j["ended_at_s"] = out_->ended_by.empty() ? result.simulated : out_->ended_at;
  j["message_delay_s"] = Quartiles(out_->delays);
  j["messages_dropped_by_impairment"] = out_->messages_lost;
  nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
  for (const auto& [node, named] : out_->metrics)
    for (const auto& [metric, values] : named) metrics[node][metric] = Quartiles(values);
  j["metrics"] = metrics;
  j["transitions_to"] = out_->transitions_to;
  if (spec_.min_distance && !out_->min_distances.empty()) {
    auto lowest = std::min_element(out_->min_distances.begin(), out_->min_distances.end(),
                                   [](const auto& a, const auto& b) { return a.second < b.second; });
    nlohmann::ordered_json md = {{"min_m", lowest->second}, {"at_s", lowest->first}};
    if (spec_.distance_reference > 0) {
      std::size_t near = 0;
      for (const auto& [t, d] : out_->min_distances) near += std::fabs(d - spec_.distance_reference) <= 0.1 * spec_.distance_reference;
      md["reference_m"] = spec_.distance_reference;
      md["fraction_within_10_percent"] = double(near) / out_->min_distances.size();
    }
    j["min_distance"] = md;
  }
  for (const auto& [key, value] : extra.items()) j[key] = value;
  if (options.add_to_summary) options.add_to_summary(j);
  j["files"] = result.files;
  WriteFileAtomically(options.output_dir + "/summary.json", j.dump(2) + "\n");
}

}  // namespace sanet::sim
