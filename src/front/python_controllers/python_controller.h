// Controllers written in Python: a scenario's `controller: {python: "module:Class"}`. The module
// is imported from the spec's python_path (the scenario's folder, then --python-path's), the
// class is built with the parameters (sanet.Params) and lives as a C++ controller does:
// `start(node)` if it has one, `control_step(node)`, `on_message(node, message)` if it has one.
// A Python exception ends the controller's run like a C++ one, its traceback (file:line) in the
// failure; a module that does not import, or has no such class, is a RegistryError saying why.
#pragma once

#include "hosting/controller_registry.h"
#include "hosting/controller_spec.h"

namespace sanet::python_controllers {

// Lets `registry` make Python controllers and seed Python's generators for each run.
void InstallPython(hosting::Registry& registry);

// Imports the spec's module and describes its class (name: "module:Class").
ControllerInfo LoadPythonController(const hosting::ControllerSpec& spec);

}  // namespace sanet::python_controllers
