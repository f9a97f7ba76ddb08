// A read-only view of the world after a step, for any number of observers (the real-time
// server, tests, later a viewer). Each part is built the first time an observer asks for it
// during that step, so a run whose observers ask for nothing pays nothing for it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sanet/geometry.h"
#include "sanet/message.h"

namespace sanet::sim {

struct BodyState {
  Pose2D pose;
  Twist2D velocity;                      // world frame
  std::array<double, 3> wheel_angles{};  // rad, each wheel's turn so far (a diffdrive's: left, right)
};

// An application message sent and not yet delivered (see MessageLedger for when it stops being
// in flight).
struct MessageInFlight {
  NodeId from = 0;
  std::optional<NodeId> to;  // empty for a broadcast or flood
  Delivery delivery = Delivery::kUnicast;
  double time_sent = 0;
  std::size_t bytes = 0;
};

// Where a snapshot reads the world from (the run's assembly).
class SnapshotSource {
 public:
  virtual ~SnapshotSource() = default;
  virtual std::size_t NodeCount() const = 0;
  virtual BodyState Body(NodeId node) const = 0;
  virtual std::vector<NodeId> RadioNeighbours(NodeId node) const = 0;
  virtual std::vector<MessageInFlight> MessagesInFlight() const = 0;
  virtual std::string ControllerState(NodeId node) const = 0;  // "" before its first transition
};

class WorldSnapshot {
 public:
  WorldSnapshot(const SnapshotSource& source, double time, std::uint64_t step)
      : source_(source), time_(time), step_(step) {}
  WorldSnapshot(const WorldSnapshot&) = delete;
  WorldSnapshot& operator=(const WorldSnapshot&) = delete;

  double time() const { return time_; }         // s, simulated
  std::uint64_t step() const { return step_; }  // physics steps so far
  std::size_t node_count() const { return source_.NodeCount(); }
  const std::vector<BodyState>& bodies() const;                      // per node
  const std::vector<std::vector<NodeId>>& radio_neighbours() const;  // per node, as its routing layer knows them
  const std::vector<MessageInFlight>& messages_in_flight() const;
  const std::vector<std::string>& controller_states() const;  // per node: the state of its last transition

 private:
  const SnapshotSource& source_;
  double time_;
  std::uint64_t step_;
  mutable std::optional<std::vector<BodyState>> bodies_;
  mutable std::optional<std::vector<std::vector<NodeId>>> neighbours_;
  mutable std::optional<std::vector<MessageInFlight>> in_flight_;
  mutable std::optional<std::vector<std::string>> states_;
};

}  // namespace sanet::sim
