// The `sanet` command: parses the command line and calls the kernel; nothing else.
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "agents/controller_registry.h"
#include "builtin.h"
#include "core/atomic_file.h"
#include "hil/agent.h"
#include "hil/namespaces.h"
#include "hil/remote_node.h"
#include "hil/sim_server.h"
#include "robots/node_model.h"
#include "scenario/scenario_loader.h"
#include "sim/sweep.h"
#include "sim/world.h"

namespace {

using namespace sanet;

constexpr int kExitScenarioError = 2;
constexpr int kExitRunFailed = 1;

struct RunArgs {
  std::string file;
  std::optional<std::uint64_t> seed;
  std::optional<double> duration;
  std::string output;
  bool quiet = false;
  bool no_progress = false;
};

scenario::Scenario LoadChecked(const std::string& file, agents::Registry& registry) {
  scenario::Scenario sc = scenario::LoadScenario(file);
  scenario::CheckControllers(sc, registry);
  return sc;
}

int Run(const RunArgs& args, agents::Registry& registry) {
  scenario::Scenario sc = LoadChecked(args.file, registry);
  if (args.seed) sc.run.seed = *args.seed;
  if (args.duration) sc.run.duration = *args.duration;
  sim::RunOptions options;
  options.output_dir = args.output.empty() ? sc.output_folder : args.output;
  options.scenario_file = args.file;
  options.progress = !args.quiet && !args.no_progress && isatty(STDERR_FILENO);
  if (!args.quiet)
    std::printf("sanet: running %s (%zu nodes, %.1f s simulated, seed %llu)\n", sc.run.name.c_str(),
                sc.run.nodes.size(), sc.run.duration, static_cast<unsigned long long>(sc.run.seed));
  sim::World world(sc.run, registry);
  const sim::RunResult r = world.Run(options);
  if (!args.quiet) {
    std::printf("  simulated %.1f s in %.2f s wall (%.1fx real time), %llu events\n", r.simulated, r.wall,
                r.real_time_factor, static_cast<unsigned long long>(r.events));
    std::printf("  fingerprint %s\n  results in %s/\n", r.fingerprint.c_str(), options.output_dir.c_str());
  }
  return 0;
}

// "1-10" or "1,4,7" or a mix ("1-3,8").
std::vector<std::uint64_t> ParseSeeds(const std::string& text) {
  std::vector<std::uint64_t> seeds;
  std::stringstream parts(text);
  for (std::string part; std::getline(parts, part, ',');) {
    const auto dash = part.find('-');
    try {
      std::size_t used = 0;
      const std::uint64_t first = std::stoull(part.substr(0, dash), &used);
      if (used != (dash == std::string::npos ? part.size() : dash)) throw std::invalid_argument(part);
      const std::uint64_t last = dash == std::string::npos ? first : std::stoull(part.substr(dash + 1), &used);
      if (dash != std::string::npos && used != part.size() - dash - 1) throw std::invalid_argument(part);
      if (last < first || last - first > 100000) throw std::invalid_argument(part);
      for (std::uint64_t s = first; s <= last; ++s) seeds.push_back(s);
    } catch (const std::exception&) {
      throw CLI::ValidationError("--seeds", "'" + part + "' is not a seed or a range like 1-10");
    }
  }
  return seeds;
}

int Sweep(const std::string& file, const std::string& seeds_text, const std::string& output, bool quiet,
          agents::Registry& registry) {
  const scenario::Scenario sc = LoadChecked(file, registry);
  const std::vector<std::uint64_t> seeds = ParseSeeds(seeds_text);
  const std::string dir = output.empty() ? sc.output_folder + "-sweep" : output;
  const sim::SweepResult r = sim::RunSweep(sc.run, seeds, dir, file, registry, [&](const sim::SweepRun& run) {
    if (!quiet)
      std::printf("  seed %llu: %s, ended by %s at %.1f s (%.1f s wall)\n", (unsigned long long)run.seed,
                  run.status.c_str(), run.ended_by.c_str(), run.ended_at, run.wall);
    std::fflush(stdout);
  });
  if (!quiet)
    std::printf(
        "%d of %zu runs met the end condition; end time %.1f s +/- %.1f s (95 %% confidence)\n"
        "results in %s/ (sweep.csv, sweep.json, seed-*/)\n",
        r.ended_by_condition, r.runs.size(), r.mean, r.ci95, dir.c_str());
  for (const auto& run : r.runs)
    if (run.status != "completed") return kExitRunFailed;
  return 0;
}

int Serve(const std::string& file, const std::string& bind, int port, const std::string& port_file,
          const std::string& output, bool quiet, std::optional<double> duration, agents::Registry& registry) {
  scenario::Scenario sc = LoadChecked(file, registry);
  if (duration) sc.run.duration = *duration;
  sc.run.robots_remote = true;
  sim::UseRealTimeClock();  // the same schedule, run against the wall clock
  sim::World world(sc.run, registry);
  hil::ServerSettings settings;
  settings.bind = bind;
  settings.port = static_cast<std::uint16_t>(port);
  hil::SimServer server(world, settings);
  server.Start();
  std::signal(SIGINT, [](int) { hil::RequestStop(); });
  std::signal(SIGTERM, [](int) { hil::RequestStop(); });
  std::printf("sanet: serving %s on %s:%u for %.1f s\n", sc.run.name.c_str(), bind.c_str(), server.port(),
              sc.run.duration);
  std::fflush(stdout);
  if (!port_file.empty()) WriteFileAtomically(port_file, std::to_string(server.port()) + "\n");
  sim::RunOptions options;
  options.output_dir = output.empty() ? sc.output_folder : output;
  options.scenario_file = file;
  options.add_to_summary = [&](nlohmann::ordered_json& j) { j["real_time_lag"] = server.LagSummary(); };
  const sim::RunResult r = world.Run(options);
  if (!quiet) {
    const auto lag = server.LagSummary();
    std::printf(
        "  served %.1f s; lag behind the wall clock p50 %.4f s, p99 %.4f s, max %.4f s, %lld missed deadlines\n"
        "  results in %s/\n",
        r.simulated, lag["p50_s"].get<double>(), lag["p99_s"].get<double>(), lag["max_s"].get<double>(),
        static_cast<long long>(lag["missed_deadlines"].get<std::int64_t>()), options.output_dir.c_str());
  }
  return 0;
}

int Agent(const std::string& file, const std::string& robot, const std::string& server, std::optional<int> udp_base,
          const std::string& udp_subnet, bool shared_clock, agents::Registry& registry) {
  const scenario::Scenario sc = LoadChecked(file, registry);
  const auto colon = server.rfind(':');
  if (colon == std::string::npos) throw CLI::ValidationError("--server", "expected HOST:PORT, not '" + server + "'");
  hil::AgentSettings settings;
  settings.server_host = server.substr(0, colon);
  settings.server_port = static_cast<std::uint16_t>(std::stoi(server.substr(colon + 1)));
  settings.udp_base_port = static_cast<std::uint16_t>(udp_base.value_or(sc.run.loop.udp_port));
  settings.udp_subnet = udp_subnet;
  settings.shared_clock = shared_clock;
  std::optional<NodeId> id;
  for (NodeId i = 0; i < sc.run.nodes.size(); ++i)
    if (sc.run.nodes[i].name == robot) id = i;
  if (!id || !sc.run.nodes[*id].controller)
    throw CLI::ValidationError("--robot", "'" + robot + "' is not a robot with a controller in " + file);
  return hil::RunAgent(sc.run, *id, settings, registry);
}

volatile std::sig_atomic_t g_interrupted = 0;

[[noreturn]] void Exec(const std::string& program, const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execvp(program.c_str(), argv.data());  // searches PATH for a bare name
  std::_Exit(127);
}

// The port a starting server wrote to `path`, or nothing if the server ended (or took more
// than 30 s) before it did.
std::optional<int> WaitForPort(const std::string& path, pid_t server) {
  for (int waited = 0; waited < 30000; waited += 10) {
    std::ifstream in(path);
    int port = 0;
    if (in >> port && port > 0) return port;
    if (::waitpid(server, nullptr, WNOHANG) != 0) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return std::nullopt;
}

// Starts the server and one agent per robot with a controller, as processes of this program;
// ends them all when the server's run ends or on Ctrl-C.
int Launch(const std::string& file, const std::string& output, std::optional<int> udp_base_option,
           std::optional<double> duration, agents::Registry& registry) {
  const scenario::Scenario sc = LoadChecked(file, registry);
  const int udp_base = udp_base_option.value_or(sc.run.loop.udp_port);
  std::vector<std::uint32_t> robots;
  for (std::uint32_t i = 0; i < sc.run.nodes.size(); ++i)
    if (sc.run.nodes[i].model.kind != robots::ModelKind::kMote && sc.run.nodes[i].controller) robots.push_back(i);
  // Real links between namespaces where the machine allows it; loopback otherwise.
  std::unique_ptr<hil::NetworkNamespaces> namespaces;
  if (sc.run.loop.namespaces) {
    std::string why;
    if (hil::NetworkNamespaces::Permitted(&why)) {
      const auto& s = sc.run.loop.shaping;
      const bool wants_shaping = s.delay > 0 || s.jitter > 0 || s.loss > 0 || s.rate > 0;
      std::string no_shaping;
      const bool shape = wants_shaping && hil::NetworkNamespaces::ShapingPermitted(&no_shaping);
      namespaces = std::make_unique<hil::NetworkNamespaces>(robots, s, shape);
      std::printf("sanet: each agent in its own network namespace, linked by veth pairs and a bridge\n");
      if (wants_shaping && !shape)
        std::printf(
            "sanet: netem is not available (%s): the links are not shaped; messages.loss and "
            "messages.delay in the scenario impair messages in the agents instead\n",
            no_shaping.c_str());
    } else {
      std::printf(
          "sanet: network namespaces are not available (%s): falling back to loopback, without "
          "netem shaping\n",
          why.c_str());
    }
  }
  const std::string bind = namespaces ? hil::NetworkNamespaces::ServerAddress() : "127.0.0.1";
  const std::string self = std::filesystem::read_symlink("/proc/self/exe");
  const std::string out = output.empty() ? sc.output_folder : output;
  // The server tells its port through a file, not through text meant for people.
  char port_dir[] = "/tmp/sanet-launch-XXXXXX";
  if (!::mkdtemp(port_dir)) throw std::runtime_error("cannot create a temporary folder for the server's port");
  const std::string port_file = std::string(port_dir) + "/port";
  const pid_t server = ::fork();
  if (server == 0) {
    std::vector<std::string> args = {"sanet", "serve", file, "--port", "0",           "--bind",
                                     bind,    "-o",    out,  "-q",     "--port-file", port_file};
    if (duration) args.insert(args.end(), {"--duration", std::to_string(*duration)});
    Exec(self, args);
  }
  std::signal(SIGINT, [](int) { g_interrupted = 1; });
  std::signal(SIGTERM, [](int) { g_interrupted = 1; });
  const std::optional<int> port = WaitForPort(port_file, server);
  std::filesystem::remove_all(port_dir);
  if (!port) {
    ::waitpid(server, nullptr, 0);
    throw std::runtime_error("the server did not start");
  }
  const std::string address = bind + ":" + std::to_string(*port);
  std::vector<pid_t> agents;
  for (std::uint32_t id : robots) {
    const std::string& name = sc.run.nodes[id].name;
    const pid_t agent = ::fork();
    if (agent == 0) {
      std::vector<std::string> args = {"sanet",         "agent",
                                       "--server",      address,
                                       "--scenario",    file,
                                       "--robot",       name,
                                       "--udp-base",    std::to_string(udp_base),
                                       "--shared-clock"};
      if (namespaces) {
        args.insert(args.end(), {"--udp-subnet", hil::NetworkNamespaces::Subnet()});
        args[0] = self;  // ip runs the program itself: its path, not a name, comes first
        args.insert(args.begin(), {"ip", "netns", "exec", namespaces->Namespace(id)});
        Exec("ip", args);
      }
      Exec(self, args);
    }
    std::printf("  agent %s: process %d%s\n", name.c_str(), agent,
                namespaces ? (" in namespace " + namespaces->Namespace(id)).c_str() : "");
    agents.push_back(agent);
  }
  std::fflush(stdout);
  int status = 0;
  bool forwarded = false;
  while (::waitpid(server, &status, WNOHANG) == 0) {
    if (g_interrupted && !forwarded) {
      ::kill(server, SIGINT);  // the server ends its run and writes its results
      forwarded = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  for (pid_t a : agents) ::kill(a, SIGTERM);
  for (pid_t a : agents) ::waitpid(a, nullptr, 0);
  std::printf("  results in %s/\n", out.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : kExitRunFailed;
}

int Validate(const std::string& file, agents::Registry& registry) {
  const scenario::Scenario sc = LoadChecked(file, registry);
  std::size_t robots = 0, controlled = 0;
  for (const auto& n : sc.run.nodes) {
    robots += n.model.kind != robots::ModelKind::kMote;
    controlled += n.controller.has_value();
  }
  std::printf("%s: valid: %zu nodes (%zu robots, %zu with controllers), %zu obstacles, %.1f s, seed %llu\n",
              file.c_str(), sc.run.nodes.size(), robots, controlled, sc.run.obstacles.size(), sc.run.duration,
              static_cast<unsigned long long>(sc.run.seed));
  return 0;
}

int List(agents::Registry& registry) {
  std::printf("models:\n");
  std::printf("  mote       a 10 cm cube of 50 g that rests until pushed; no drive\n");
  std::printf("  omni3      Robertino-like omnidirectional robot: three omni wheels, six IR sensors\n");
  std::printf("  diffdrive  Pioneer-P2DX-like differential drive: two wheels and a caster, 180-degree laser\n");
  std::printf("sensors:\n");
  std::printf("  ir, laser, odometry, ground_truth, bearing (see docs/scenario.md)\n");
  std::printf("controllers:\n");
  for (const ControllerInfo* c : registry.List()) std::printf("  %-18s %s\n", c->name.c_str(), c->description.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "sanet: integrated simulator for sensor/actuator networks and networked robots.\n"
      "Physics (ODE) and network (ns-3) advance on one clock; controllers see one portable interface."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "sanet 0.1.0");

  RunArgs run;
  CLI::App* run_cmd = app.add_subcommand("run",
                                         "Run a scenario and write its results folder "
                                         "(trajectories.csv, log.csv, messages.csv, summary.json)");
  run_cmd->add_option("scenario", run.file, "Scenario file (YAML)")->required();
  run_cmd->add_option("--seed", run.seed, "Override the scenario's seed");
  run_cmd->add_option("--duration", run.duration, "Override the simulated duration (s)")->check(CLI::PositiveNumber);
  run_cmd->add_option("-o,--output", run.output,
                      "Results folder (default: the scenario's outputs.folder, "
                      "or results/<name>)");
  run_cmd->add_flag("-q,--quiet", run.quiet, "Print nothing but errors");
  run_cmd->add_flag("--no-progress", run.no_progress, "Do not show progress (shown only on a terminal)");

  std::string validate_file;
  CLI::App* validate_cmd = app.add_subcommand("validate",
                                              "Check a scenario without running it: structure, "
                                              "types, ranges, models, controllers and their parameters");
  validate_cmd->add_option("scenario", validate_file, "Scenario file (YAML)")->required();

  std::string sweep_file, sweep_seeds = "1-10", sweep_output;
  bool sweep_quiet = false;
  CLI::App* sweep_cmd = app.add_subcommand("sweep",
                                           "Run a scenario once per seed (replications) and summarise "
                                           "when the runs met their end condition (mean, 95% confidence)");
  sweep_cmd->add_option("scenario", sweep_file, "Scenario file (YAML)")->required();
  sweep_cmd->add_option("--seeds", sweep_seeds, "Seeds: a list and/or ranges, e.g. 1-10 or 1,5,9")
      ->capture_default_str();
  sweep_cmd->add_option("-o,--output", sweep_output,
                        "Folder for the runs and sweep.csv/sweep.json "
                        "(default: results/<name>-sweep)");
  sweep_cmd->add_flag("-q,--quiet", sweep_quiet, "Print nothing but errors");

  std::string serve_file, serve_bind = "127.0.0.1", serve_output, serve_port_file;
  int serve_port = 3000;
  bool serve_quiet = false;
  CLI::App* serve_cmd = app.add_subcommand("serve",
                                           "Serve a scenario's world in real time over the robot protocol "
                                           "(USARSim-compatible; docs/protocol.md): clients drive its robots");
  serve_cmd->add_option("scenario", serve_file, "Scenario file (YAML)")->required();
  serve_cmd->add_option("--bind", serve_bind, "Address to listen on (loopback by default)")->capture_default_str();
  serve_cmd->add_option("--port", serve_port, "TCP port (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  serve_cmd->add_option("--port-file", serve_port_file,
                        "Once listening, write the port number to this file "
                        "(for programs that start the server with --port 0)");
  serve_cmd->add_option("-o,--output", serve_output, "Results folder (default: the scenario's)");
  serve_cmd->add_flag("-q,--quiet", serve_quiet, "Print only the listening line and errors");
  std::optional<double> serve_duration, launch_duration;
  serve_cmd->add_option("--duration", serve_duration, "Override the scenario's duration (s)")
      ->check(CLI::PositiveNumber);

  std::string agent_file, agent_robot, agent_server = "127.0.0.1:3000", agent_subnet;
  std::optional<int> udp_base;
  bool agent_shared_clock = false;
  CLI::App* agent_cmd = app.add_subcommand("agent",
                                           "Run one robot's controller as its own process: sensors and "
                                           "motors through a `sanet serve` server, messages over real UDP");
  agent_cmd->add_option("--scenario", agent_file, "Scenario file: the robot's controller and parameters, the peers")
      ->required();
  agent_cmd->add_option("--robot", agent_robot, "The robot to drive (its name in the scenario)")->required();
  agent_cmd->add_option("--server", agent_server, "The server, HOST:PORT")->capture_default_str();
  agent_cmd
      ->add_option("--udp-base", udp_base,
                   "UDP port of node 0; node i uses base + i (default: the "
                   "scenario's loop.udp_port, 47000)")
      ->check(CLI::Range(1024, 60000));
  agent_cmd->add_option("--udp-subnet", agent_subnet,
                        "Instead: node i listens on SUBNET.(i+1) at the base port "
                        "(agents in network namespaces)");
  agent_cmd->add_flag("--shared-clock", agent_shared_clock, "The server runs on this machine: share its clock exactly");

  std::string launch_file, launch_output;
  CLI::App* launch_cmd = app.add_subcommand("launch",
                                            "Start a server and one agent process per robot on this "
                                            "machine, run the scenario in real time, stop them all (also on Ctrl-C)");
  launch_cmd->add_option("scenario", launch_file, "Scenario file (YAML)")->required();
  launch_cmd->add_option("-o,--output", launch_output, "Results folder (default: the scenario's)");
  launch_cmd->add_option("--duration", launch_duration, "Override the scenario's duration (s)")
      ->check(CLI::PositiveNumber);
  launch_cmd->add_option("--udp-base", udp_base, "UDP port of node 0 (default: the scenario's loop.udp_port, 47000)")
      ->check(CLI::Range(1024, 60000));

  std::vector<std::string> libraries;
  CLI::App* list_cmd = app.add_subcommand("list", "List the models, sensors and controllers sanet knows");
  list_cmd->add_option("--library", libraries, "Also load this controller library (repeatable)");

  CLI11_PARSE(app, argc, argv);

  agents::Registry registry;
  controllers::RegisterBuiltinControllers(registry);
  try {
    if (*run_cmd) return Run(run, registry);
    if (*validate_cmd) return Validate(validate_file, registry);
    if (*sweep_cmd) return Sweep(sweep_file, sweep_seeds, sweep_output, sweep_quiet, registry);
    if (*serve_cmd)
      return Serve(serve_file, serve_bind, serve_port, serve_port_file, serve_output, serve_quiet, serve_duration,
                   registry);
    if (*agent_cmd)
      return Agent(agent_file, agent_robot, agent_server, udp_base, agent_subnet, agent_shared_clock, registry);
    if (*launch_cmd) return Launch(launch_file, launch_output, udp_base, launch_duration, registry);
    for (const auto& lib : libraries) registry.LoadLibrary(lib);
    return List(registry);
  } catch (const CLI::ValidationError& e) {
    std::fprintf(stderr, "sanet: error: %s\n", e.what());
    return kExitScenarioError;
  } catch (const scenario::ScenarioError& e) {
    std::fprintf(stderr, "sanet: error: %s\n", e.what());
    return kExitScenarioError;
  } catch (const agents::RegistryError& e) {
    std::fprintf(stderr, "sanet: error: %s\n", e.what());
    return kExitScenarioError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sanet: run failed: %s\n", e.what());
    return kExitRunFailed;
  }
}
