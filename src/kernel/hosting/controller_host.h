// What every mode does around one node's controller, written once: it builds the controller from
// its scenario spec, starts it, steps it, hands it the messages that reach its node after the
// scenario's message impairments (loss, added delay), and turns anything it throws into one
// failure that ends the run with its results kept. The in-process run (sim) and the agent
// process (hil) both drive controllers through it; only *when* a step happens is theirs.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/random_stream.h"
#include "hosting/controller_registry.h"
#include "hosting/controller_spec.h"
#include "hosting/host_clock.h"
#include "sanet/controller.h"

namespace sanet::hosting {

// Impairments added on top of the network, as the receiving controller sees them: a message is
// lost with probability `loss`, or reaches the controller `delay` later.
struct MessageImpairments {
  double loss = 0;   // probability
  double delay = 0;  // s
};

// Builds the controller of a node spec: loads its library if any, creates it from its
// parameters and rejects unknown parameters. Throws ParamError or RegistryError.
std::unique_ptr<Controller> MakeController(const ControllerSpec& spec, Registry& registry);

class ControllerHost {
 public:
  struct Hooks {
    // A message passed the impairments and reaches the node now (recorded by the run).
    std::function<void(const Message&)> delivered;
    // A message was dropped by the `loss` impairment.
    std::function<void(const Message&)> dropped;
    // The controller threw: the text says whose controller and where.
    std::function<void(const std::string&)> failed;
  };

  // `controller` may be null (a node without one still receives, for the record). The random
  // stream of the impairments is the node's own: "messages/impairments/<node>".
  ControllerHost(Node& node, std::unique_ptr<Controller> controller, double rate, MessageImpairments impairments,
                 std::uint64_t seed, HostClock& clock, Hooks hooks);

  bool has_controller() const { return controller_ != nullptr; }
  double period() const { return 1.0 / rate_; }  // s between control steps
  // False once the controller failed or the node was switched off: no more steps.
  bool running() const { return controller_ && !failed_ && !off_; }

  void Start();
  void Step();
  // The run ended: the controller's Finish, once (also after a switch-off; not after a failure,
  // nor for a controller that never started).
  // No steps or messages follow.
  void Finish();
  // A message reached the node: impaired, then recorded and given to the controller.
  void Receive(const Message& message);
  // From now on the controller gets no steps and no messages (messages are still recorded).
  void SwitchOff() { off_ = true; }
  // Its controller steps again where it stopped (the node came back), with its state as it was.
  void SwitchOn() { off_ = false; }

 private:
  void Deliver(const Message& message);
  template <typename Call>
  void Guard(const char* where, Call call);

  Node& node_;
  std::unique_ptr<Controller> controller_;
  double rate_;
  MessageImpairments impairments_;
  RandomStream impairment_stream_;
  HostClock& clock_;
  Hooks hooks_;
  bool failed_ = false, off_ = false, started_ = false;
};

}  // namespace sanet::hosting
