#include "options.h"

namespace sanet::cli {

void AddForce(CLI::App* cmd, bool& force) {
  cmd->add_flag("--force", force,
                "Write into a results folder that holds files no sanet run wrote (they are left there; an earlier "
                "run's files are always replaced)");
}

namespace {
std::vector<std::string>& PythonPathList() {
  static std::vector<std::string> folders;
  return folders;
}
}  // namespace

void AddPythonPath(CLI::App* cmd) {
  cmd->add_option("--python-path", PythonPathList(),
                  "A folder where Python controllers' modules are looked for after the scenario's own (repeatable; "
                  "docs/python.md)")
      ->check(CLI::ExistingDirectory);
}

const std::vector<std::string>& PythonPathArgs() { return PythonPathList(); }

const CLI::Validator kDurationRange(
    [](std::string& text) {
      const double d = std::strtod(text.c_str(), nullptr);
      return d > 0 && d <= 1e9 ? std::string() : "must be greater than 0 and at most 1e9 s, not " + text;
    },
    "(0, 1e9] s");
const CLI::Validator kSeedText(
    [](std::string& text) {
      const bool digits =
          !text.empty() && text.size() <= 20 && text.find_first_not_of("0123456789") == std::string::npos;
      return digits && (text.size() < 20 || text <= "18446744073709551615")
                 ? std::string()
                 : "must be a whole number from 0 to 18446744073709551615, not " + text;
    },
    "0..2^64-1");

void AddDuration(CLI::App* cmd, std::optional<double>& duration) {
  cmd->add_option("--duration", duration, "Override the scenario's duration (s)")->check(kDurationRange);
}

void AddThreads(CLI::App* cmd, std::optional<std::string>& threads) {
  cmd->add_option("--threads", threads,
                  "1 or 2, overriding the scenario's world.threads: 2 steps the physics on a second thread while "
                  "ns-3 runs the network (same results as 1; faster for swarms, docs/swarms.md)")
      ->check(CLI::IsMember({"1", "2"}));
}

CLI::Option* AddScenario(CLI::App* cmd, std::string& file) {
  return cmd->add_option("scenario", file, "Scenario file (YAML)")->required();
}

void AddSet(CLI::App* cmd, std::vector<std::string>& sets) {
  cmd->add_option("--set", sets,
                  "PATH=VALUE: change one value of the scenario, checked like the file (repeatable), e.g. "
                  "--set network.tx_power=25 --set nodes.robot.controller.params.speed=0.5; a list item by its "
                  "name or index (nodes.robot, nodes[0]), a grid by its grid name (docs/scenario.md)")
      ->allow_extra_args(false);
}

std::string Count(std::size_t n, const std::string& thing) {
  return std::to_string(n) + " " + thing + (n == 1 ? "" : "s");
}

namespace {
std::vector<std::string> g_command;
}  // namespace

void RememberCommandLine(int argc, char** argv) { g_command.assign(argv, argv + argc); }
const std::vector<std::string>& CommandLine() { return g_command; }

}  // namespace sanet::cli
