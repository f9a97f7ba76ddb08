// sanet.Simulation: one run of a scenario, stepped from a Python script or notebook. It loads and
// checks the scenario as `sanet run` does (with `set` values, a seed, a duration), then the
// script advances it (step, run), looks at it between steps (poses, velocities, readings,
// routing tables, neighbours, the messages and frames since the last step) and acts on it
// (drives a robot that no controller drives, sends a message from such a node, switches a node
// off); finish() writes the results as `sanet run` does: a script that does not act gets its
// files and fingerprint. ns-3's simulator is one per process, so one Simulation is live at a
// time; a second is refused.
#pragma once

#include <pybind11/pybind11.h>

namespace sanet::python_module {

void BindSimulation(pybind11::module_& module);

}  // namespace sanet::python_module
