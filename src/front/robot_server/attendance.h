// Which of the scenario's agent robots (those with a controller, which only a client can run here)
// a client drove, from when to when: the run's verdict on them. A robot no client drove makes the
// run fail (its controller never ran: the results are not the experiment's); one that joined late
// or dropped out is a warning naming it and the times.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sanet/message.h"

namespace sanet::robot_server {

class Attendance {
 public:
  // A robot first driven more than this long after the run began joined late (s, simulated). An
  // agent started with the server claims its robot within a second, or a few on a loaded machine.
  static constexpr double kLateAfter = 5.0;

  // `expected`: the agent robots' names by node id (empty for nodes no client has to drive).
  explicit Attendance(std::vector<std::string> expected) : expected_(std::move(expected)), stints_(expected_.size()) {}

  void Joined(NodeId robot, double now);
  void Left(NodeId robot, double now, const std::string& why);
  // Robots left out of the verdict (the ROS 2 face drove them).
  void Excuse(const std::vector<std::string>& names);

  std::vector<std::string> NeverDriven() const;
  // Late joins, drop-outs and returns, one sentence each, for summary.json's warnings.
  std::vector<std::string> Warnings(double end) const;
  // summary.json's "attendance": per expected robot, its stints [from, to] (to: null while driven
  // at the end) and the reasons its clients left.
  nlohmann::ordered_json Summary() const;

 private:
  struct Stint {
    double from;
    double to = -1;  // < 0: still driven
    std::string why;
  };
  bool Expected(NodeId id) const { return id < expected_.size() && !expected_[id].empty(); }
  std::vector<std::string> expected_;
  std::vector<std::vector<Stint>> stints_;
};

}  // namespace sanet::robot_server
