#include "view/live_view.h"

#include <httplib.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "core/json_text.h"
#include "view/page_routes.h"

namespace sanet::view {
namespace {

double Rounded(double v) { return std::round(v * 1e4) / 1e4; }  // 0.1 mm: enough for a picture

}  // namespace

LiveView::LiveView(const sim::RunSpec& spec, LiveSettings settings)
    : settings_(std::move(settings)), run_json_(JsonText(RunJson(spec))), server_(std::make_unique<httplib::Server>()) {
  CheckLibraries(settings_.javascript);
  AddPageRoutes(*server_, settings_.javascript);
  server_->Get("/api/run",
               [this](const httplib::Request&, httplib::Response& r) { r.set_content(run_json_, "application/json"); });
  // Server-sent events: each new frame once; a browser too slow for every frame gets the latest.
  server_->Get("/api/live", [this](const httplib::Request&, httplib::Response& r) {
    r.set_chunked_content_provider("text/event-stream",
                                   [this, seen = std::uint64_t{0}](std::size_t, httplib::DataSink& sink) mutable {
                                     std::string frame;
                                     const bool more = WaitForFrame(seen, &frame);
                                     if (!frame.empty()) {
                                       seen = sequence_;
                                       const std::string event = "data: " + frame + "\n\n";
                                       if (!sink.write(event.data(), event.size())) return false;
                                     }
                                     if (!more) {
                                       const std::string end = "event: end\ndata: {}\n\n";
                                       sink.write(end.data(), end.size());
                                       sink.done();
                                     }
                                     return true;
                                   });
  });
  ListenAlone(*server_);
  port_ = settings_.port == 0 ? server_->bind_to_any_port(settings_.bind)
                              : (server_->bind_to_port(settings_.bind, settings_.port) ? settings_.port : -1);
  if (port_ < 0) throw std::runtime_error("cannot listen on " + settings_.bind + ":" + std::to_string(settings_.port));
  thread_ = std::thread([this] { server_->listen_after_bind(); });
  // Until it runs, cpp-httplib's stop() does nothing and a destructor would wait on it for ever.
  for (int i = 0; i < 5000 && !server_->is_running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

LiveView::~LiveView() {
  Finish();
  server_->stop();
  if (thread_.joinable()) thread_.join();
}

// What the page needs before the first frame: as /api/run of a replay, marked live.
nlohmann::json LiveView::RunJson(const sim::RunSpec& spec) const {
  nlohmann::json run;
  run["info"] = {{"name", spec.name},
                 {"duration_s", std::to_string(spec.duration)},
                 {"world_size_m", std::to_string(spec.world_size.x) + " " + std::to_string(spec.world_size.y)},
                 {"live", true}};
  run["nodes"] = nlohmann::json::array();
  for (NodeId id = 0; id < spec.nodes.size(); ++id) {
    const sim::NodeSpec& n = spec.nodes[id];
    run["nodes"].push_back({{"id", id},
                            {"name", n.name},
                            {"model", robots::ModelName(n.model.kind)},
                            {"x", n.pose.x},
                            {"y", n.pose.y},
                            {"theta", n.pose.theta}});
  }
  run["obstacles"] = nlohmann::json::array();
  for (const sim::Obstacle& o : spec.obstacles)
    run["obstacles"].push_back(
        {o.kind, o.box.center.x, o.box.center.y, o.box.size.x, o.box.size.y, o.box.size.z, o.box.yaw});
  return run;
}

void LiveView::Observe(sim::RunBus& bus) {
  step_ended_ =
      bus.On<sim::StepEnded>(sim::RunStage::kObserve, [this](const sim::StepEnded& e) { AfterStep(e.world); });
  energy_.push_back(bus.On<sim::EnergySampled>(sim::RunStage::kObserve, [this](const sim::EnergySampled& e) {
    for (const sim::EnergyLevel& l : e.levels) {
      while (charge_.size() <= l.node) charge_.push_back(nullptr);
      charge_[l.node] = Rounded(l.battery.fraction);
    }
  }));
  energy_.push_back(bus.On<sim::Died>(sim::RunStage::kObserve, [this](const sim::Died& e) { SetDead(e.node, true); }));
  energy_.push_back(
      bus.On<sim::Revived>(sim::RunStage::kObserve, [this](const sim::Revived& e) { SetDead(e.node, false); }));
}

void LiveView::SetDead(NodeId node, bool dead) {
  if (dead_.size() <= node) dead_.resize(node + 1, false);
  dead_[node] = dead;
}

// A run with batteries: "energy", each node's charge (null: none), and "dead", the dead nodes.
void LiveView::AddEnergy(nlohmann::json& frame) const {
  if (charge_.empty() && dead_.empty()) return;
  frame["energy"] = charge_;
  frame["dead"] = nlohmann::json::array();
  for (NodeId id = 0; id < dead_.size(); ++id)
    if (dead_[id]) frame["dead"].push_back(id);
}

void LiveView::AfterStep(const sim::WorldSnapshot& snapshot) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::duration<double>(settings_.period)) return;
  last_ = now;
  nlohmann::json frame = {
      {"t", snapshot.time()}, {"poses", nlohmann::json::array()}, {"links", nlohmann::json::array()}};
  const auto& bodies = snapshot.bodies();
  for (const sim::BodyState& b : bodies)
    frame["poses"].push_back({Rounded(b.pose.x), Rounded(b.pose.y), Rounded(b.pose.theta)});
  frame["states"] = snapshot.controller_states();
  const auto& neighbours = snapshot.radio_neighbours();
  for (NodeId a = 0; a < neighbours.size(); ++a)
    for (NodeId b : neighbours[a])
      if (a < b) frame["links"].push_back({a, b});
  AddEnergy(frame);
  std::string text = JsonText(frame);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    frame_.swap(text);
    ++sequence_;
  }
  changed_.notify_all();
}

void LiveView::Finish() {
  finished_ = true;
  changed_.notify_all();
}

// Waits (up to a second) for a frame newer than `after`; false once the run is over and no newer
// frame is left.
bool LiveView::WaitForFrame(std::uint64_t after, std::string* frame) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, std::chrono::seconds(1), [&] { return sequence_ > after || finished_; });
  if (sequence_ > after) *frame = frame_;
  return !finished_;
}

}  // namespace sanet::view
