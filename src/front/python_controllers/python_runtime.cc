#include "python_controllers/python_runtime.h"

#include <pybind11/embed.h>

#include <optional>
#include <stdexcept>

namespace py = pybind11;

namespace sanet::python_controllers {
namespace {

std::optional<std::uint64_t> g_pending_seed;  // a run's seed given before the interpreter started

void Seed(std::uint64_t seed) {
  py::module_::import("random").attr("seed")(seed);
  // numpy's legacy global generator takes 32 bits.
  py::module_::import("numpy.random").attr("seed")(static_cast<std::uint32_t>(seed & 0xFFFFFFFFu));
}

void Start() {
  PyConfig config;
  PyConfig_InitIsolatedConfig(&config);
  config.isolated = 0;
  config.use_environment = 1;          // PYTHONPATH and the like, as a Python user expects
  config.install_signal_handlers = 0;  // sanet's handlers stop a run with its results
  config.use_hash_seed = 1;            // hash randomisation off: sets and dicts iterate alike
  config.hash_seed = 0;
  py::initialize_interpreter(&config, 0, nullptr, false);
}

}  // namespace

void EnsureInterpreter() {
  if (Py_IsInitialized()) return;
  Start();
  py::module_::import("random");  // before any controller's folder is on the path
  py::module_::import("numpy.random");
  if (g_pending_seed) Seed(*g_pending_seed);
  g_pending_seed.reset();
}

// Folders go after Python's standard library and before the installed packages: a controller's
// module may not replace a module of Python's own (a random.py beside the scenario would break
// every run's seeding), and is found before a package of the same name.
void AddSearchPath(const std::vector<std::string>& folders) {
  EnsureInterpreter();
  py::list path = py::module_::import("sys").attr("path");
  std::size_t at = 0;
  while (at < path.size()) {
    const std::string entry = py::str(path[at]);
    if (entry.find("-packages") != std::string::npos) break;
    ++at;
  }
  for (const std::string& folder : folders)
    if (!path.contains(py::str(folder))) path.insert(at++, py::str(folder));
}

bool OnSearchPath(const std::string& file, const std::vector<std::string>& folders) {
  for (const std::string& folder : folders)
    if (file.rfind(folder + "/", 0) == 0) return true;
  return false;
}

void SeedRun(std::uint64_t seed) {
  if (!Py_IsInitialized()) {
    g_pending_seed = seed;
    return;
  }
  Seed(seed);
}

std::string TracebackText(py::error_already_set& error) {
  try {
    const auto or_none = [](const py::object& o) { return o ? o : py::object(py::none()); };
    const py::object lines =
        py::module_::import("traceback")
            .attr("format_exception")(or_none(error.type()), or_none(error.value()), or_none(error.trace()));
    return py::str("").attr("join")(lines).cast<std::string>();
  } catch (const py::error_already_set&) {
    return error.what();  // traceback itself failed (out of memory): pybind11's own summary
  }
}

}  // namespace sanet::python_controllers
