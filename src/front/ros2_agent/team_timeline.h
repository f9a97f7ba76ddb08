// `sanet merge`: a team's agents on ROS 2 robots each write their own results folder, every time
// on their own clock (sanet agent --ros2 -o). This puts the folders together on one time line:
// the team's log, transitions, metrics, messages (each with its sender's and receiver's clock
// brought onto the team's), what was sent, each link's delivery and delay, and how far the
// clocks can be trusted.
//
// Clocks: agents that read /clock (use_sim_time) share it, so their times are taken as they are.
// Agents on their computers' clocks record the Unix time of their time 0; the team's time 0 is
// the earliest of these, and each agent's times move by the difference (none when all were
// given the same --start-at). What remains is the computers' disagreement, which NTP or PTP
// keeps small and which this cannot remove; the messages show it: a message cannot arrive before
// it was sent, so a link's smallest delay below zero bounds the disagreement from below, and a
// pair that sent both ways gives the classic estimate (half the difference of the smallest delays
// each way), reported per pair (summary.json's `clocks`).
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace sanet::ros2_agent {

// Folders that are not a team's agents' folders, or hold rows that do not read: names the
// folder and file (and the row and field).
class TeamFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes the team's folder `out` (cleared as a run's is; refused when it holds other files
// unless `force`) from the agents' folders; returns its summary.json.
nlohmann::ordered_json MergeTeam(const std::vector<std::string>& agent_folders, const std::string& out, bool force);

}  // namespace sanet::ros2_agent
