#include "python_module/simulation.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "builtin.h"
#include "core/delivery.h"
#include "core/version.h"
#include "python_controllers/controller_api.h"
#include "python_controllers/python_controller.h"
#include "ros2_presentation/presentation.h"
#include "scenario/effective_scenario.h"
#include "scenario/scenario_loader.h"
#include "sim/assembly.h"
#include "sim/world.h"
#include "trace/earlier_run.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace sanet::python_module {
namespace {

constexpr const char* kScript = "the script";  // the owner of the robots a script drives
bool g_live = false;                           // ns-3's simulator is one per process

// What happened since the last step, for the script.
class SinceLastStep {
 public:
  explicit SinceLastStep(bool frames) : frames_(frames) {}
  void Observe(sim::RunBus& bus) {
    delivered_ = bus.On<sim::MessageDelivered>(
        sim::RunStage::kObserve, [this](const sim::MessageDelivered& e) { messages.emplace_back(e.to, e.message); });
    if (frames_)  // frames cost something to trace: only when the script asked for them
      frames_heard_ =
          bus.On<net::FrameEvent>(sim::RunStage::kObserve, [this](const net::FrameEvent& f) { frames.push_back(f); });
  }
  void Clear() {
    messages.clear();
    frames.clear();
  }
  std::vector<std::pair<NodeId, Message>> messages;
  std::vector<net::FrameEvent> frames;

 private:
  bool frames_;
  Subscription delivered_, frames_heard_;
};

// The states of Python's `random` and numpy's global generator: a script's own, or the run's
// (seeded from its seed), swapped so that neither disturbs the other.
struct RandomStates {
  py::object random, numpy;
  static RandomStates Now() {
    return {py::module_::import("random").attr("getstate")(), py::module_::import("numpy.random").attr("get_state")()};
  }
  void Apply() const {
    py::module_::import("random").attr("setstate")(random);
    py::module_::import("numpy.random").attr("set_state")(numpy);
  }
};

// JSON is YAML's flow style: a Python str stays text ("a: b" is no mapping), lists stay lists.
std::string YamlText(const py::handle& value) {
  return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

bool HasPythonControllers(const sim::RunSpec& spec) {
  for (const sim::NodeSpec& n : spec.nodes)
    if (n.controller && !n.controller->python.empty()) return true;
  return false;
}

class Simulation {
 public:
  Simulation(const std::string& path, const py::dict& set, std::optional<std::uint64_t> seed,
             std::optional<std::string> output, std::optional<double> duration, bool force, bool frames,
             const std::vector<std::string>& python_path)
      : since_(frames) {
    if (g_live)
      throw std::runtime_error(
          "a Simulation is already live in this process, and ns-3's simulator is one per process: finish() it "
          "(or use `with sanet.Simulation(...) as sim:`) before starting another");
    controllers::RegisterBuiltinControllers(registry_);
    python_controllers::InstallPython(registry_);
    if (duration && !(*duration > 0 && *duration <= 1e9))
      throw py::value_error("duration must be more than 0 and at most 1e9 s, not " + std::to_string(*duration));
    scenario::SetPythonPath(python_path);
    Load(path, set, seed, duration);
    Build(path, output, force);
  }
  ~Simulation() {
    if (!world_) return;
    try {  // the script dropped it unfinished: its results are written, saying so
      EndEarly("the script dropped the Simulation at " + std::to_string(Now()) + " s without finish()");
    } catch (...) {
    }
  }

  // The time the run was advanced to (it stands just before it: what happens at exactly that
  // time comes with the next step), or where it ended.
  double Now() const {
    if (!world_) return ended_at_;
    return running_ ? target_ : std::min(target_, world_->Now());
  }
  bool running() const { return world_ && running_; }
  bool finished() const { return !world_; }
  bool Step(double seconds) {
    if (!(seconds >= 0)) throw py::value_error("step(seconds): seconds must be 0 or more");
    Live();  // refuses a finished Simulation
    // Summed on the clock's nanoseconds, so that ten steps of 0.1 s end at 1 s.
    return RunTo(std::round((target_ + seconds) * 1e9) / 1e9);
  }
  bool Run(std::optional<double> until) {
    Live();  // refuses a finished Simulation
    return RunTo(until.value_or(scenario_.run.duration));
  }
  py::dict Finish();
  // Finishes before the run's end, `why` in summary.json's ended_by.
  py::dict EndEarly(const std::string& why);

  std::vector<std::string> Nodes() const {
    std::vector<std::string> names;
    for (NodeId id = 0; id < Live().NodeCount(); ++id) names.push_back(Live().NameOf(id));
    return names;
  }
  Pose2D PoseOf(const std::string& node) const { return Live().driver().PoseOf(Id(node)); }
  py::tuple VelocityOf(const std::string& node) {
    const Twist2D v = Live().model(Id(node)).body().velocity();
    return py::make_tuple(v.vx, v.vy, v.omega);
  }
  py::dict Readings(const std::string& node);
  std::vector<RouteEntry> RoutingTable(const std::string& node) const {
    return Live().driver().NetworkOf(Id(node)).RoutingTable();
  }
  std::vector<NodeId> Neighbours(const std::string& node) const {
    return Live().driver().NetworkOf(Id(node)).Neighbours();
  }
  py::list Messages() const;
  py::list Frames() const;

  bool Drive(const std::string& robot, double vx, double vy, double omega) {
    return Driven(robot).Drive({vx, vy, omega});
  }
  void Send(const std::string& from, const std::string& to, const py::object& payload) {
    Driven(from).Send(Id(to), python_controllers::BytesOf(payload));
  }
  void Broadcast(const std::string& from, const py::object& payload) {
    Driven(from).Broadcast(python_controllers::BytesOf(payload));
  }
  void SwitchOff(const std::string& node) { Live().SwitchOff(Id(node)); }

 private:
  void Load(const std::string& path, const py::dict& set, std::optional<std::uint64_t> seed,
            std::optional<double> duration);
  void Build(const std::string& path, std::optional<std::string> output, bool force);
  bool RunTo(double t);
  sim::World& Live() const {
    if (!world_) throw std::runtime_error("this Simulation has finished: its results are in " + options_.output_dir);
    return *world_;
  }
  NodeId Id(const std::string& node) const {
    if (const auto id = Live().Lookup(node)) return *id;
    throw py::key_error("no node named '" + node + "' in " + scenario_.run.name);
  }
  // The node of a robot (or mote) that the script drives: one without a controller.
  Node& Driven(const std::string& node) {
    const NodeId id = Id(node);
    if (const auto refused = Live().driver().Claim(id, kScript)) throw py::value_error(*refused);
    return Live().driver().NodeOf(id, kScript);
  }
  // Runs `body` with the run's random states in place of the script's (Python controllers only).
  template <typename Body>
  auto WithRunsRandom(Body body) {
    if (!python_controllers_) return body();
    const RandomStates script = RandomStates::Now();
    run_random_.Apply();
    struct Restore {
      RandomStates& run;
      const RandomStates& script;
      ~Restore() {
        const py::error_scope pending;  // a KeyboardInterrupt the run stopped on stays raised after this
        run = RandomStates::Now();
        script.Apply();
      }
    } restore{run_random_, script};
    return body();
  }

  hosting::Registry registry_;
  scenario::Scenario scenario_;
  sim::RunOptions options_;
  SinceLastStep since_;
  std::unique_ptr<sim::World> world_;
  std::unique_ptr<ros2_presentation::RunPresentation> ros2_messages_;  // trace.mcap
  bool running_ = true, python_controllers_ = false;
  double target_ = 0;    // s: where the script has advanced the run to
  double ended_at_ = 0;  // s: where it ended, once finished
  RandomStates run_random_;
};

void Simulation::Load(const std::string& path, const py::dict& set, std::optional<std::uint64_t> seed,
                      std::optional<double> duration) {
  std::vector<std::string> overrides;
  for (const auto& [key, value] : set) overrides.push_back(py::str(key).cast<std::string>() + "=" + YamlText(value));
  if (seed) overrides.push_back("seed=" + std::to_string(*seed));  // scattered nodes follow it
  scenario_ = scenario::LoadScenario(path, overrides);
  scenario::CheckControllers(scenario_, registry_);
  if (duration) scenario_.run.duration = *duration;
  python_controllers_ = HasPythonControllers(scenario_.run);
  options_.warnings = scenario_.warnings;
  if (python_controllers_ && py::module_::import("sys").attr("flags").attr("hash_randomization").cast<int>() != 0) {
    const std::string why =
        "Python controllers in a process without PYTHONHASHSEED=0: sets and dicts may iterate otherwise in each "
        "run, so the same seed may not give the same run (start Python with PYTHONHASHSEED=0)";
    py::module_::import("warnings").attr("warn")(why, py::module_::import("builtins").attr("RuntimeWarning"));
    options_.warnings.push_back(why);
  }
}

void Simulation::Build(const std::string& path, std::optional<std::string> output, bool force) {
  options_.output_dir = output.value_or(scenario_.output_folder);
  options_.scenario_file = path;
  options_.force = force;
  const scenario::EffectiveScenario effective = scenario::Effective(scenario_);
  options_.provenance = sim::Provenance{effective.yaml, effective.fingerprint, {"python3", "sanet.Simulation", path}};
  options_.stop_requested = [] {
    return PyErr_CheckSignals() != 0 ? std::string("interrupted by SIGINT (Ctrl-C)") : "";
  };
  trace::ClearEarlierRun(options_.output_dir, force);
  const RandomStates script = python_controllers_ ? RandomStates::Now() : RandomStates{};
  world_ = std::make_unique<sim::World>(scenario_.run, registry_);  // seeds the run's random states
  since_.Observe(world_->bus());
  ros2_messages_ = std::make_unique<ros2_presentation::RunPresentation>(*world_);
  options_.trace_files = {ros2_messages_->McapFile()};
  world_->Start(options_);
  if (python_controllers_) {
    run_random_ = RandomStates::Now();
    script.Apply();
  }
  g_live = true;
}

bool Simulation::RunTo(double t) {
  since_.Clear();
  if (!running_) return false;
  target_ = std::max(target_, std::min(t, scenario_.run.duration));
  // Up to just before the target: the bodies stand where they are at the target (its physics
  // step has not started the next), and what happens at the target happens in the next piece.
  // At the end, the end itself.
  const double cut = target_ >= scenario_.run.duration ? target_ : target_ - 1e-9;
  running_ = WithRunsRandom([&] { return Live().RunUntil(cut); });
  if (PyErr_Occurred()) throw py::error_already_set();  // Ctrl-C: the run ended there, marked
  return running_;
}

py::dict Simulation::EndEarly(const std::string& why) {
  if (running_) {
    Live().Stop(why);
    WithRunsRandom([&] { return Live().RunUntil(target_); });  // takes the stop: summary.json's ended_by
  }
  return Finish();
}

py::dict Simulation::Finish() {
  const sim::RunResult r = WithRunsRandom([&] { return Live().Finish(); });
  std::vector<std::string> warnings = options_.warnings;
  warnings.insert(warnings.end(), r.warnings.begin(), r.warnings.end());
  ended_at_ = world_->ended_by().empty() ? scenario_.run.duration : world_->ended_at();
  py::dict out("fingerprint"_a = r.fingerprint, "simulated"_a = r.simulated, "wall"_a = r.wall,
               "ended_by"_a = world_->ended_by().empty() ? std::string("duration") : world_->ended_by(),
               "interrupted"_a = world_->interrupted(), "output"_a = options_.output_dir, "warnings"_a = warnings);
  ros2_messages_.reset();  // before the world whose bus and nodes it holds
  world_.reset();
  g_live = false;
  return out;
}

py::object ScanOrNone(const RangeScan* scan) {
  if (!scan) return py::none();
  return py::dict("angles"_a = py::array_t<double>(scan->angles.size(), scan->angles.data()),
                  "ranges"_a = py::array_t<double>(scan->ranges.size(), scan->ranges.data()),
                  "max_range"_a = scan->max_range);
}

// The readings of a node as the script sees them (a controller's last reads, or the driver's).
py::dict ReadingsDict(const sim::SensorReadings& r, const std::optional<Pose2D>& ground_truth) {
  return py::dict("time"_a = r.time, "ground_truth"_a = ground_truth, "odometry"_a = r.odometry(),
                  "ir"_a = ScanOrNone(r.ir()), "laser"_a = ScanOrNone(r.laser()));
}

// A controller's last reads, as the driver's readings hold them.
sim::SensorReadings AsReadings(const hosting::SimulatedNode::LastReads& last) {
  sim::SensorReadings r;
  r.time = last.time;
  for (const auto& [name, reading] : last.readings)
    if (reading) r.by_instance.emplace_back(name, *reading);
  return r;
}

py::dict Simulation::Readings(const std::string& node) {
  const NodeId id = Id(node);
  if (Live().driver().Spec(id).controller) {
    const sim::SensorReadings last = AsReadings(Live().parts().node(id).last_reads());
    const Pose2D* truth = last.Get<Pose2D>("ground_truth");
    return ReadingsDict(last, truth ? std::optional<Pose2D>(*truth) : std::nullopt);
  }
  Driven(node);  // the script's node: its sensors now
  const sim::SensorReadings& r = Live().driver().TakeReadings(id, kScript);
  py::list bearings;
  if (const BearingsReading* in_range = r.Get<BearingsReading>("bearing"))
    for (const NodeBearing& b : in_range->in_range)
      bearings.append(py::make_tuple(Live().NameOf(b.node), b.reading.distance, b.reading.bearing));
  py::dict out = ReadingsDict(r, r.ground_truth);
  out["bearings"] = bearings;
  return out;
}

py::list Simulation::Messages() const {
  py::list out;
  for (const auto& [to, m] : since_.messages)
    out.append(py::dict("time_sent"_a = m.time_sent, "from"_a = Live().NameOf(m.from), "to"_a = Live().NameOf(to),
                        "delivery"_a = DeliveryName(m.delivery), "bytes"_a = m.payload.size(),
                        "time_received"_a = m.time_received, "delay"_a = m.time_received - m.time_sent,
                        "hops"_a = m.hops,
                        "payload"_a = py::bytes(reinterpret_cast<const char*>(m.payload.data()), m.payload.size())));
  return out;
}

py::list Simulation::Frames() const {
  py::list out;
  for (const net::FrameEvent& f : since_.frames)
    out.append(py::dict("time"_a = f.t, "node"_a = Live().NameOf(f.node), "sent"_a = f.sent,
                        "peer"_a = f.peer ? py::object(py::str(Live().NameOf(*f.peer))) : py::object(py::none()),
                        "kind"_a = f.kind, "bytes"_a = f.bytes));
  return out;
}

}  // namespace

void BindSimulation(py::module_& m) {
  py::class_<Simulation>(m, "Simulation", R"(One run of a scenario, stepped from Python (docs/python-module.md).

Simulation(path, set={}, seed=None, output=None, duration=None, force=False, frames=False)
  path      the scenario file (YAML), loaded and checked as `sanet run` does
  set       {"PATH": value}: scenario values to change, as `--set PATH=VALUE`
  seed      the run's seed instead of the scenario's
  output    the results folder (default: the scenario's, results/<name>)
  duration  the simulated duration instead of the scenario's (s)
  force     write beside files in `output` that no sanet run wrote
  frames    keep the radio frames of each step for frames()
  python_path  folders where Python controllers' modules are looked for after the scenario's

Only one Simulation is live in a process (ns-3 has one simulator): finish() it first.)")
      .def(py::init<const std::string&, const py::dict&, std::optional<std::uint64_t>, std::optional<std::string>,
                    std::optional<double>, bool, bool, const std::vector<std::string>&>(),
           "path"_a, "set"_a = py::dict(), "seed"_a = py::none(), "output"_a = py::none(), "duration"_a = py::none(),
           "force"_a = false, "frames"_a = false, "python_path"_a = std::vector<std::string>{})
      .def_property_readonly("now", &Simulation::Now, "Simulated time (s)")
      .def_property_readonly("running", &Simulation::running, "False once the run has ended")
      .def("step", &Simulation::Step, "seconds"_a,
           "Advances the run by `seconds` of simulated time; False once it has ended (duration, end condition)")
      .def("run", &Simulation::Run, "until"_a = py::none(), "Advances to `until` (s; default: the end)")
      .def(
          "finish", [](Simulation& s) { return s.EndEarly("finish() at " + std::to_string(s.Now()) + " s"); },
          "Writes the results as `sanet run` does; returns fingerprint, ended_by, output, ...")
      .def("nodes", &Simulation::Nodes, "The nodes' names, in id order")
      .def("pose", &Simulation::PoseOf, "node"_a, "Where the node's body stands (the truth: no noise)")
      .def("velocity", &Simulation::VelocityOf, "node"_a, "(vx, vy, omega): the body's velocity, world frame")
      .def("readings", &Simulation::Readings, "node"_a,
           "What the node's controller read last (or, for a robot the script drives, its sensors now)")
      .def("routing_table", &Simulation::RoutingTable, "node"_a)
      .def("neighbours", &Simulation::Neighbours, "node"_a)
      .def("messages", &Simulation::Messages, "The messages delivered during the last step (messages.csv's columns)")
      .def("frames", &Simulation::Frames, "The radio frames of the last step (with frames=True)")
      .def("drive", &Simulation::Drive, "robot"_a, "vx"_a = 0.0, "vy"_a = 0.0, "omega"_a = 0.0,
           "Drives a robot that no controller drives (robot frame, m/s and rad/s); False as Node.drive")
      .def("send", &Simulation::Send, "sender"_a, "to"_a, "payload"_a,
           "Sends a message from a node that no controller drives")
      .def("broadcast", &Simulation::Broadcast, "sender"_a, "payload"_a)
      .def("switch_off", &Simulation::SwitchOff, "node"_a, "Switches the node off now, as a scenario event does")
      .def("__enter__", [](Simulation& s) -> Simulation& { return s; })
      .def("__exit__", [](Simulation& s, const py::object& type, const py::object& value, const py::object&) {
        if (s.finished()) return;
        const std::string at = " at " + std::to_string(s.Now()) + " s";
        if (type.is_none()) return void(s.EndEarly("the with block ended" + at));
        s.EndEarly("the script raised " + py::str(type.attr("__name__")).cast<std::string>() + " (" +
                   py::str(value).cast<std::string>() + ")" + at);
      });
}

}  // namespace sanet::python_module
