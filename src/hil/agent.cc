#include "hil/agent.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <thread>

#include "agents/controller_host.h"

namespace sanet::hil {
namespace {

// The agent's estimate of the simulation clock (the remote node's), with the delayed actions the
// host asks for, run as the agent's loop polls.
class AgentClock : public agents::HostClock {
 public:
  explicit AgentClock(const RemoteNode& node) : node_(node) {}
  double Now() const override { return node_.Now(); }
  void After(double delay, std::function<void()> action) override { due_.emplace(Now() + delay, std::move(action)); }
  void RunDue() {
    while (!due_.empty() && due_.begin()->first <= Now()) {
      auto action = std::move(due_.begin()->second);
      due_.erase(due_.begin());
      action();
    }
  }

 private:
  const RemoteNode& node_;
  std::multimap<double, std::function<void()>> due_;  // in time order, then in order asked
};

}  // namespace

int RunAgent(const sim::RunSpec& spec, NodeId robot, const AgentSettings& settings, agents::Registry& registry) {
  const sim::ControllerSpec& controller = *spec.nodes.at(robot).controller;
  RemoteNode node(spec, robot, settings);
  AgentClock clock(node);
  std::string failure;
  agents::ControllerHost::Hooks hooks;
  hooks.failed = [&](const std::string& why) { failure = why; };
  agents::ControllerHost host(node, agents::MakeController(controller, registry), controller.rate,
                              {spec.message_loss, spec.message_delay}, spec.seed, clock, hooks);
  const auto deliver = [&](const Message& m) { host.Receive(m); };
  // The first sensor lines tell where the robot is and what time it is.
  while (!node.HasPose()) {
    if (!node.Poll(deliver)) return 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  host.Start();
  double next = node.Now();
  while (host.running() && node.Poll(deliver)) {
    clock.RunDue();
    if (node.Now() >= next) {
      host.Step();
      next = std::max(next + host.period(), node.Now() - host.period());  // no burst of steps after a stall
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (failure.empty()) return 0;  // the server ended the run
  std::fprintf(stderr, "sanet agent: %s\n", failure.c_str());
  node.Log(failure);
  return 1;
}

}  // namespace sanet::hil
