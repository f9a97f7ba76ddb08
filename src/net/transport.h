// How messages between controllers travel. The simulated network (ns-3 UDP over radios) and the
// local stand-in implement it; the simulated node talks only to this interface.
#pragma once

#include <functional>

#include "sanet/message.h"
#include "sanet/node.h"

namespace sanet::net {

class Transport {
 public:
  // Called when `message` reaches node `to`.
  using Receiver = std::function<void(NodeId to, const Message& message)>;
  virtual ~Transport() = default;
  virtual void SetReceiver(Receiver receiver) = 0;
  virtual void Send(NodeId from, NodeId to, const Bytes& payload) = 0;
  virtual void Broadcast(NodeId from, const Bytes& payload) = 0;
  virtual NetworkView& View(NodeId node) = 0;
};

}  // namespace sanet::net
