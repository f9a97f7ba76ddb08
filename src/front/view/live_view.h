// The live view of a running world (`sanet run --view`, `sanet serve --view`): an observer that,
// at most every `period` of wall-clock time, turns the world's snapshot into one frame (time,
// poses, controller states, radio neighbours, and the batteries' charge and the dead nodes in a
// run with energy) and keeps only the latest; an HTTP server thread
// (cpp-httplib) streams the frames to browsers as server-sent events and serves the same page
// as `sanet view`. The run only swaps a string under a lock: a slow browser misses frames, the
// run never waits for it.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "sim/run_events.h"
#include "sim/run_spec.h"

namespace httplib {
class Server;
}

namespace sanet::view {

struct LiveSettings {
  std::string bind = "127.0.0.1";
  int port = 8000;      // 0: any free port
  double period = 0.1;  // s of wall-clock time between frames
  std::string javascript = "/usr/share/javascript";
};

class LiveView {
 public:
  // Listens (throws std::runtime_error if it cannot) and serves from its own thread.
  LiveView(const sim::RunSpec& spec, LiveSettings settings);
  ~LiveView();
  int port() const { return port_; }
  std::uint64_t frames() const { return sequence_; }

  // Draws the world on the run's bus from now on: its steps, batteries, deaths and revivals.
  void Observe(sim::RunBus& bus);
  void AfterStep(const sim::WorldSnapshot& snapshot);
  // Ends the stream (the run is over): browsers see the last frame and `end`.
  void Finish();

 private:
  Subscription step_ended_;  // AfterStep, on the run's bus
  std::vector<Subscription> energy_;
  nlohmann::json RunJson(const sim::RunSpec& spec) const;
  void AddEnergy(nlohmann::json& frame) const;
  void SetDead(NodeId node, bool dead);
  bool WaitForFrame(std::uint64_t after, std::string* frame);

  LiveSettings settings_;
  std::string run_json_;
  std::unique_ptr<httplib::Server> server_;
  std::thread thread_;
  int port_ = 0;
  std::chrono::steady_clock::time_point last_ = {};
  // On the simulation thread: each node's charge at the latest sample (null: no battery), and
  // whether it is dead.
  nlohmann::json charge_ = nlohmann::json::array();
  std::vector<bool> dead_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::string frame_;
  std::atomic<std::uint64_t> sequence_{0};
  std::atomic<bool> finished_{false};
};

}  // namespace sanet::view
