#include "robot_server/attendance.h"

#include <algorithm>
#include <cstdio>

#include "core/seconds_text.h"

namespace sanet::robot_server {
void Attendance::Joined(NodeId robot, double now) {
  if (Expected(robot)) stints_[robot].push_back({now, -1, ""});
}

void Attendance::Left(NodeId robot, double now, const std::string& why) {
  if (!Expected(robot) || stints_[robot].empty() || stints_[robot].back().to >= 0) return;
  stints_[robot].back().to = now;
  stints_[robot].back().why = why;
}

void Attendance::Excuse(const std::vector<std::string>& names) {
  for (std::string& name : expected_)
    if (std::find(names.begin(), names.end(), name) != names.end()) name.clear();
}

std::vector<std::string> Attendance::NeverDriven() const {
  std::vector<std::string> names;
  for (NodeId id = 0; id < expected_.size(); ++id)
    if (Expected(id) && stints_[id].empty()) names.push_back(expected_[id]);
  return names;
}

std::vector<std::string> Attendance::Warnings(double end) const {
  std::vector<std::string> warnings;
  for (NodeId id = 0; id < expected_.size(); ++id) {
    if (!Expected(id) || stints_[id].empty()) continue;
    const std::string& name = expected_[id];
    const std::vector<Stint>& stints = stints_[id];
    if (stints.front().from > kLateAfter)
      warnings.push_back("robot " + name + " joined late: first driven at " + SecondsText(stints.front().from) +
                         " (its controller did not run before)");
    for (std::size_t i = 0; i < stints.size(); ++i) {
      const Stint& s = stints[i];
      if (s.to < 0 || s.to >= end) continue;
      const bool back = i + 1 < stints.size();
      warnings.push_back("robot " + name + " dropped out at " + SecondsText(s.to) + " (its client: " + s.why + ")" +
                         (back ? ", driven again from " + SecondsText(stints[i + 1].from) : ", not driven again"));
    }
  }
  return warnings;
}

nlohmann::ordered_json Attendance::Summary() const {
  nlohmann::ordered_json robots = nlohmann::ordered_json::object();
  for (NodeId id = 0; id < expected_.size(); ++id) {
    if (!Expected(id)) continue;
    nlohmann::ordered_json driven = nlohmann::ordered_json::array();
    for (const Stint& s : stints_[id]) {
      nlohmann::ordered_json stint = {{"from_s", s.from}, {"to_s", nullptr}};
      if (s.to >= 0) stint["to_s"] = s.to, stint["left_because"] = s.why;
      driven.push_back(stint);
    }
    robots[expected_[id]] = {{"driven", driven}};
  }
  return robots;
}

}  // namespace sanet::robot_server
