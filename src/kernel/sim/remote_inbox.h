// How messages reach a node that someone outside the run drives, and how strongly one node's
// radio hears another: what the assembly offers its front ends (sim/driver.h).
#pragma once

#include <functional>

#include "sanet/message.h"

namespace sanet::sim {

// Someone outside the run who drives a node (the server's protocol client): messages that reach
// the node are handed to it. It says whether the message was delivered, lost (nobody drives the
// node now) or is none of its business (it reaches the driver another way), and is not recorded.
enum class InboxResult { kDelivered, kLost, kIgnored };
using RemoteInbox = std::function<InboxResult(NodeId to, const Message& message)>;

// How strongly one node hears another now (dBm), and the radio's detection threshold.
struct Signal {
  double received_dbm, threshold_dbm;
};

}  // namespace sanet::sim
