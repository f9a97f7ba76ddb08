// Before a run writes into a results folder, the files of an earlier sanet run there go, so
// that old and new results never mix; a folder that holds anything else is refused (unless
// forced), so that a mistyped -o never deletes someone's files.
#pragma once

#include <stdexcept>
#include <string>

namespace sanet::trace {

class FolderRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Makes `dir` ready for a new run: removes what an earlier run wrote there, if it exists (the
// files its summary.json lists, its provenance.json and scenario.yaml, and the temporary files
// and folders of temporary files of a run that was stopped). Anything else in it is refused with FolderRefused naming a
// few of them; with `force` it is left where it is.
void ClearEarlierRun(const std::string& dir, bool force);

// Refuses (FolderRefused) a folder that holds the results of another kind of sanet run than
// `mode` (summary.json's "mode": none for a simulation's run, "ros2" for an agent's on a ROS 2
// robot, "ros2 team" for sanet merge's), so that one command never clears another's results.
void ExpectEarlierKind(const std::string& dir, const std::string& mode);

}  // namespace sanet::trace
