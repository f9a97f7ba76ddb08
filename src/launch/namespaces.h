// Real links between the agents of a launch: every agent in its own Linux network namespace,
// joined to the others and to the server by a veth pair and a bridge, with netem shaping what
// the agent sends (delay, jitter, loss, rate). All of it on this machine; removed at the end.
#pragma once

#include <string>
#include <vector>

#include "sections/loop_section.h"

namespace sanet::hil {

class NetworkNamespaces {
 public:
  // Whether this process may create namespaces here; if not, `why` says what failed.
  static bool Permitted(std::string* why);
  // Whether netem can shape links here (the kernel may lack it).
  static bool ShapingPermitted(std::string* why);

  // One namespace per node id in `nodes` (ids < 253); throws std::runtime_error naming the
  // command that failed (everything made so far is removed).
  NetworkNamespaces(const std::vector<std::uint32_t>& nodes, const sections::LinkShaping& shaping, bool shape);
  ~NetworkNamespaces();

  std::string Namespace(std::uint32_t node) const;
  // Every namespace's link to the bridge has this one name, so that configurations (Cyclone DDS's
  // interface for the ROS 2 face's domain) name it alike in every namespace and every launch.
  static constexpr const char* kSimulatorInterface = "sim0";
  static std::string Subnet() { return "10.77.0"; }  // node i is Subnet().(i+1)
  static std::string ServerAddress() { return "10.77.0.254"; }

 private:
  void Run(const std::string& command);
  void Remove();
  std::string tag_;
  std::vector<std::uint32_t> nodes_;
  bool shape_;
  bool bridge_ = false;
  std::vector<std::string> made_;  // namespaces created
};

}  // namespace sanet::hil
