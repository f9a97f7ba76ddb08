// The nodes of a running world: the scenario's, in its order, then the robots that front ends
// spawned while it runs. The RunSpec stays as it was loaded; this is the run state that the
// assembly, the driver and the outputs read names and models from.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sanet/message.h"
#include "sim/run_spec.h"

namespace sanet::sim {

class RunNodes {
 public:
  explicit RunNodes(const std::vector<NodeSpec>& scenario_nodes)
      : nodes_(scenario_nodes), scenario_count_(nodes_.size()) {}

  std::size_t size() const { return nodes_.size(); }
  const NodeSpec& operator[](NodeId id) const { return nodes_[id]; }
  const NodeSpec& at(NodeId id) const { return nodes_.at(id); }
  std::vector<NodeSpec>::const_iterator begin() const { return nodes_.begin(); }
  std::vector<NodeSpec>::const_iterator end() const { return nodes_.end(); }

  // The id of the node called `name`, if there is one.
  std::optional<NodeId> Find(const std::string& name) const {
    for (NodeId id = 0; id < nodes_.size(); ++id)
      if (nodes_[id].name == name) return id;
    return std::nullopt;
  }
  std::string NameOf(NodeId id) const { return id < nodes_.size() ? nodes_[id].name : ""; }

  // A robot joins (as the class a front end names, e.g. USARBot.P2DX); its id is the next one.
  NodeId Add(const NodeSpec& node, const std::string& spawned_as) {
    nodes_.push_back(node);
    spawned_as_.push_back(spawned_as);
    return static_cast<NodeId>(nodes_.size() - 1);
  }
  std::size_t spawned() const { return spawned_as_.size(); }
  bool IsSpawned(NodeId id) const { return id >= scenario_count_ && id < nodes_.size(); }
  // The class a front end spawned the robot as; "" for the scenario's nodes.
  std::string SpawnedAs(NodeId id) const { return IsSpawned(id) ? spawned_as_[id - scenario_count_] : ""; }

 private:
  std::vector<NodeSpec> nodes_;
  std::size_t scenario_count_;
  std::vector<std::string> spawned_as_;  // of the spawned robots, in id order
};

}  // namespace sanet::sim
