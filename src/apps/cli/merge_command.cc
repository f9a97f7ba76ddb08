#include "merge_command.h"

#include <cstdio>
#include <memory>

#include "ros2_agent/team_timeline.h"
#include "trace/earlier_run.h"

namespace sanet::cli {
namespace {

struct MergeArgs {
  std::vector<std::string> folders;
  std::string output;
  bool force = false;
  bool quiet = false;
};

void PrintLinks(const nlohmann::ordered_json& summary) {
  const auto& clocks = summary["clocks"];
  std::printf("clocks: %s\n", clocks["trusted_as"].get<std::string>().c_str());
  for (const auto& [robot, moved] : clocks["moved_by_s"].items())
    std::printf("  %-12s moved by %+.3f s\n", robot.c_str(), moved.get<double>());
  for (const auto& p : clocks["from_messages"])
    if (p.contains("to_clock_ahead_by_s")) {
      if (p["from"] < p["to"])  // each pair once
        std::printf("  messages say %s's clock is ahead of %s's by %+.4f s\n", p["to"].get<std::string>().c_str(),
                    p["from"].get<std::string>().c_str(), p["to_clock_ahead_by_s"].get<double>());
    } else if (p["smallest_delay_s"].get<double>() < 0)
      std::printf(
          "  %s -> %s: a message arrived %.4f s before it was sent: %s\n", p["from"].get<std::string>().c_str(),
          p["to"].get<std::string>().c_str(), -p["smallest_delay_s"].get<double>(),
          p.contains("note") ? "the agents read neighbouring /clock samples" : "the clocks disagree by at least that");
}

int Merge(const MergeArgs& a) {
  nlohmann::ordered_json summary;
  try {
    summary = ros2_agent::MergeTeam(a.folders, a.output, a.force);
  } catch (const ros2_agent::TeamFolderError& e) {
    throw CLI::ValidationError(e.what());
  } catch (const trace::FolderRefused& e) {
    throw CLI::ValidationError("-o", e.what());
  }
  if (a.quiet) return 0;
  if (a.folders.size() == 1)
    std::fprintf(stderr, "sanet merge: warning: one folder only: a team's time line needs each robot's folder\n");
  std::printf("sanet merge: %zu agents of %s, %zu messages received; the team's time line in %s/\n",
              summary["agents"].size(), summary["scenario"].get<std::string>().c_str(),
              summary["messages"]["received"].get<std::size_t>(), a.output.c_str());
  PrintLinks(summary);
  return 0;
}

}  // namespace

Command AddMerge(CLI::App& app) {
  auto a = std::make_shared<MergeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "merge",
      "Put the results folders of a team's agents on ROS 2 robots (sanet agent --ros2 -o) on one time line: "
      "log, transitions, metrics, messages with both ends' clocks, each link's delivery and delay, and what the "
      "messages say of the clocks (docs/ros2-robots.md)");
  cmd->add_option("folders", a->folders, "The agents' results folders, one per robot")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", a->output, "The team's folder")->required();
  AddForce(cmd, a->force);
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing but errors");
  return {cmd, [a](hosting::Registry&) { return Merge(*a); }};
}

}  // namespace sanet::cli
