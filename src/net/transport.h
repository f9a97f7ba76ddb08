// How messages between controllers travel. The simulated wireless network (ns-3 UDP over
// radios) and the local stand-in implement it; the simulated node talks only to this interface.
#pragma once

#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/fingerprint.h"
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
  virtual void Flood(NodeId from, const Bytes& payload) = 0;
  virtual NetworkView& View(NodeId node) = 0;
  // The node's radio goes silent: it neither sends nor receives from now on.
  virtual void SwitchOff(NodeId node) = 0;

  // IP packets each node received (empty where the transport does not count them).
  virtual std::vector<std::uint64_t> PacketsReceived() const { return {}; }

  // Before the run: where to write traces ("" for nowhere).
  virtual void Open(const std::string& output_dir) { (void)output_dir; }
  // After the run: write the traces whole, add them to the fingerprint, the summary and the list
  // of files written.
  virtual void Finish(Fingerprint& fingerprint, nlohmann::ordered_json& summary,
                      std::vector<std::string>& files) {
    (void)fingerprint;
    (void)summary;
    (void)files;
  }
};

}  // namespace sanet::net
