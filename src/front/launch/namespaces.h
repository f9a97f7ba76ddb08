// Real links between the agents of a launch: every agent in its own Linux network namespace,
// joined to the others and to the server by a veth pair and a bridge, with netem shaping what
// the agent sends (delay, jitter, loss, rate). All of it on this machine; removed at the end.
#pragma once

#include <string>
#include <vector>

#include "launch/run_slot.h"
#include "sections/loop_section.h"

namespace sanet::launch {

class NetworkNamespaces {
 public:
  // Whether this process may create namespaces here; if not, `why` says what failed.
  static bool Permitted(std::string* why);
  // Whether netem can shape links here (the kernel may lack it).
  static bool ShapingPermitted(std::string* why);

  // One namespace per node id in `nodes` (ids < 253), named after `slot` and on its subnet; throws
  // std::runtime_error naming the command that failed (everything made so far is removed).
  NetworkNamespaces(const RunSlot& slot, const std::vector<std::uint32_t>& nodes, const sections::LinkShaping& shaping,
                    bool shape);
  ~NetworkNamespaces();

  std::string Namespace(std::uint32_t node) const;
  // Every namespace's link to the bridge has this one name, so that configurations (Cyclone DDS's
  // interface for the ROS 2 face's domain) name it alike in every namespace and every launch.
  static constexpr const char* kSimulatorInterface = "sim0";
  const std::string& Subnet() const { return subnet_; }  // node i is Subnet().(i+1)
  std::string ServerAddress() const { return subnet_ + ".254"; }

 private:
  void Run(const std::string& command);
  void Remove();
  std::string tag_;     // the slot's name prefix
  std::string subnet_;  // the slot's
  std::vector<std::uint32_t> nodes_;
  bool shape_;
  bool bridge_ = false;
  std::vector<std::string> made_;  // namespaces created
};

}  // namespace sanet::launch
