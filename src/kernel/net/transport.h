// How messages between controllers travel. The simulated wireless network (ns-3 UDP over
// radios) and the local stand-in implement it; the simulated node talks only to this interface.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "net/network_traces.h"
#include "sanet/message.h"
#include "sanet/node.h"
#include "trace/results_folder.h"

namespace sanet::net {

// The largest payload a message carries: one UDP datagram over IPv4 (65,507 bytes), less sanet's
// 27-byte header (net/message_header.h). Over 802.11 it goes as IP fragments, and a lost
// fragment loses the message.
inline constexpr std::size_t kMostMessageBytes = 65480;

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
  // A node switched off comes back (its battery was recharged): its radio sends and receives again.
  virtual void SwitchOn(NodeId node) = 0;
  // Puts the node's radio to sleep or wakes it (802.11 power save: asleep, it neither receives
  // nor transmits; frames sent meanwhile wait in the MAC's queue, which drops those that wait too
  // long). False where there is no radio to sleep.
  virtual bool SetSleep(NodeId node, bool asleep) {
    (void)node;
    (void)asleep;
    return false;
  }

  // Before the run: open the traces written as the run goes (packet logs, pcap) in `folder`.
  virtual void Open(trace::ResultsFolder& folder) { (void)folder; }
  // After the run: close them (they are committed with the folder).
  virtual void Close() {}
  // Every radio frame from now on goes to `observer` (the run's trace); transports without
  // radios have none.
  virtual void ObserveFrames(FrameObserver observer) { (void)observer; }
  // The bodies of `nodes` moved (in the physics step just taken): radios that index positions
  // bring them up to date before the next frame.
  virtual void Moved(const std::vector<NodeId>& nodes) { (void)nodes; }
  // What the network did, for the results; empty for a transport without radios.
  virtual std::optional<NetworkTraces> Traces() const { return std::nullopt; }
};

}  // namespace sanet::net
