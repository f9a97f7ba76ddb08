// Answers every message addressed to it alone with the same bytes, back to its sender: a node
// to talk to when trying a network or a client (round trips, reachability). Broadcasts and
// floods are not answered, so that two echoes never talk forever.
#include <memory>

#include "controllers.h"

namespace sanet::controllers {
namespace {

class Echo : public Controller {
 public:
  void ControlStep(Node&) override {}
  void OnMessage(Node& node, const Message& message) override {
    if (message.delivery == Delivery::kUnicast) node.Send(message.from, message.payload);
  }
};

}  // namespace

ControllerInfo EchoInfo() {
  return {"echo", "sends every unicast message it receives back to its sender, unchanged",
          [](const Params&) { return std::make_unique<Echo>(); }};
}

}  // namespace sanet::controllers
