#include "usarsim_agent/agent.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <thread>

#include "hosting/controller_host.h"
#include "usarsim_agent/agent_steps.h"
#include "wire/message_lines.h"

namespace sanet::usarsim_agent {
namespace {

// What the agent tells the server about its steps and messages (summary.json's `agents`).
wire::ProtocolMessage Stats(const StepGrid& grid, const RemoteNode& node, std::uint64_t received) {
  wire::ProtocolMessage m("STATS");
  m.Add("Steps", std::to_string(grid.run())).Add("Missed", std::to_string(grid.missed()));
  m.Add("Rate", wire::FormatPrecise(grid.achieved_rate())).Add("Sent", std::to_string(node.messages_sent()));
  const StepGrid::Lateness late = grid.lateness();
  m.Add("Received", std::to_string(received)).Add("LatenessP50", wire::FormatPrecise(late.p50));
  m.Add("LatenessP99", wire::FormatPrecise(late.p99)).Add("LatenessMax", wire::FormatPrecise(late.max));
  const RemoteNode::Datagrams& d = node.datagrams();
  m.Add("DatagramsSent", std::to_string(d.sent)).Add("DatagramsReceived", std::to_string(d.received));
  m.Add("DatagramsRejected", std::to_string(d.rejected));
  m.Add("SendErrors", std::to_string(d.send_errors));
  const ClockFigures clock = node.clock_figures();
  m.Add("ClockOffset", wire::FormatPrecise(clock.offset)).Add("ClockError", wire::FormatPrecise(clock.error_bound));
  m.Add("ClockErrorMax", wire::FormatPrecise(clock.error_bound_max));
  return m;
}

// The clock estimate after a burst of exchanges (clock.csv).
wire::ProtocolMessage ClockLine(const ClockFigures& f) {
  wire::ProtocolMessage m("CLOCK");
  m.Add("Offset", wire::FormatPrecise(f.offset)).Add("Error", wire::FormatPrecise(f.error_bound));
  m.Add("RoundTrip", wire::FormatPrecise(f.round_trip)).Add("Drift", wire::FormatPrecise(f.drift));
  return m;
}

void SayWhereItListens(RemoteNode& node, const AgentSettings& settings) {
  if (settings.quiet) return;
  const ClockFigures clock = node.clock_figures();
  std::printf("sanet agent %s: peers reach it at %s; clock %s, offset %.6f s, error bound %.0f us\n",
              node.Name().c_str(), node.peer_endpoint().c_str(), settings.shared_clock ? "shared" : "estimated",
              clock.offset, clock.error_bound * 1e6);
  std::fflush(stdout);
}

void SayHowItEnded(RemoteNode& node, const StepGrid& grid) {
  const RemoteNode::Datagrams& d = node.datagrams();
  std::printf(
      "sanet agent %s: the run is over (the server closed at %.1f s): %llu steps (%llu missed), %llu datagrams sent, "
      "%llu received, %llu rejected; worst clock error bound %.0f us\n",
      node.Name().c_str(), node.ClockNow(), static_cast<unsigned long long>(grid.run()),
      static_cast<unsigned long long>(grid.missed()), static_cast<unsigned long long>(d.sent),
      static_cast<unsigned long long>(d.received), static_cast<unsigned long long>(d.rejected),
      node.clock_figures().error_bound_max * 1e6);
}

// The controller's steps on the shared clock's grid, with the agent's reports to the server,
// until the server ends the run or the controller fails.
void RunSteps(RemoteNode& node, hosting::ControllerHost& host, AgentClock& clock, StepGrid& grid,
              const std::function<void(const Message&)>& deliver, const std::uint64_t& received) {
  double next_report = 0;
  std::uint64_t bursts_reported = 0;
  while (host.running() && node.Poll(deliver)) {
    clock.RunDue();
    if (const auto t = grid.Due(node.ClockNow())) {
      node.SetStepTime(*t);
      if (grid.run() == 1) host.Start();
      host.Step();
      node.SetStepTime(std::nullopt);
    }
    if (node.ClockNow() >= next_report) {  // five times a second: the server keeps the last
      node.Report(Stats(grid, node, received));
      next_report = node.ClockNow() + 0.2;
    }
    if (const ClockFigures figures = node.clock_figures(); figures.bursts > bursts_reported) {
      node.Report(ClockLine(figures));
      bursts_reported = figures.bursts;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

}  // namespace

int RunAgent(const sim::RunSpec& spec, NodeId robot, const AgentSettings& settings, std::unique_ptr<ServerLink> link,
             hosting::Registry& registry) {
  const sim::ControllerSpec& controller = *spec.nodes.at(robot).controller;
  RemoteNode node(spec, robot, settings, std::move(link));
  AgentClock clock([&node] { return node.Now(); });
  std::string failure;
  hosting::ControllerHost::Hooks hooks;
  hooks.failed = [&](const std::string& why) { failure = why; };
  // The server records what reaches this robot through it; what other agents send over UDP it
  // learns from here, for messages.csv.
  hooks.delivered = [&](const Message& m) {
    if (node.IsAgent(m.from)) node.Report(wire::RecvLine(m, node.NameOf(m.from)));
  };
  registry.StartRun(spec.seed);
  hosting::ControllerHost host(node, hosting::MakeController(controller, registry), controller.rate,
                               {spec.message_loss, spec.message_delay}, spec.seed, clock, hooks);
  std::uint64_t received = 0;
  const std::function<void(const Message&)> deliver = [&](const Message& m) {
    ++received;
    host.Receive(m);
  };
  SayWhereItListens(node, settings);
  // The first sensor lines tell where the robot is and what time it is.
  while (!node.HasPose()) {
    if (!node.Poll(deliver)) return 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  StepGrid grid(controller.rate);
  RunSteps(node, host, clock, grid, deliver, received);
  if (failure.empty() && node.ended()) {  // the server said END: the controller finishes, then says so
    host.Finish();
    if (!failure.empty()) node.Log(failure);  // before FINISHED, while the server still records
    node.Report(wire::ProtocolMessage{"FINISHED"});
    if (!failure.empty()) {
      std::fprintf(stderr, "sanet agent: %s\n", failure.c_str());
      return 1;
    }
  }
  if (failure.empty()) {  // the server ended the run
    if (!settings.quiet) SayHowItEnded(node, grid);
    return 0;
  }
  std::fprintf(stderr, "sanet agent: %s\n", failure.c_str());
  node.Log(failure);
  return 1;
}

}  // namespace sanet::usarsim_agent
