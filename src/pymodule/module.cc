// The extension module behind the Python package `sanet` (python/sanet): the controller interface
// (python/controller_api.h) and Simulation (pymodule/simulation.h).
#include <pybind11/pybind11.h>

#include "pymodule/simulation.h"
#include "pymodule/study_binding.h"
#include "python/controller_api.h"

PYBIND11_MODULE(_sanet, module) {
  sanet::python::BindControllerApi(module);
  sanet::pymodule::BindSimulation(module);
  sanet::pymodule::BindStudyReader(module);
}
