// What the subcommands share: the Command record, and options that mean the same on each.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hosting/controller_registry.h"

namespace sanet::cli {

constexpr int kExitScenarioError = 2;
constexpr int kExitRunFailed = 1;
// The run ended without a robot it needed a client for (serve, launch): status failed.
constexpr int kExitRobotsMissing = 3;
constexpr int kExitInterrupted = 130;

// One subcommand: its options live as long as the program, its action runs when it was chosen.
struct Command {
  CLI::App* app;
  std::function<int(hosting::Registry&)> action;
};

// The ranges a scenario's duration and seed have in a file hold on the command line too.
extern const CLI::Validator kDurationRange;
extern const CLI::Validator kSeedText;

// "1 run", "3 runs".
std::string Count(std::size_t n, const std::string& thing);

// The command line as given (main records it), for provenance.json and the study database.
void RememberCommandLine(int argc, char** argv);
const std::vector<std::string>& CommandLine();

CLI::Option* AddScenario(CLI::App* cmd, std::string& file);
void AddSet(CLI::App* cmd, std::vector<std::string>& sets);
void AddDuration(CLI::App* cmd, std::optional<double>& duration);
// Read as text so that every wrong value gets the same message ("two not in {1,2}").
void AddThreads(CLI::App* cmd, std::optional<std::string>& threads);
void AddForce(CLI::App* cmd, bool& force);
// --python-path DIR (repeatable): where Python controllers' modules are looked for after the
// scenario's folder; every command that loads a scenario takes it, into one process-wide list.
void AddPythonPath(CLI::App* cmd);
const std::vector<std::string>& PythonPathArgs();

}  // namespace sanet::cli
