// The extension module behind the Python package `sanet` (python/sanet): the controller interface
// (python_controllers/controller_api.h), Simulation (python_module/simulation.h), the studies' reader, and the
// errors a script may catch by kind, worded for Python (set=, output=, force=).
#include <pybind11/pybind11.h>

#include "python_controllers/controller_api.h"
#include "python_module/simulation.h"
#include "python_module/study_binding.h"
#include "scenario/yaml_reader.h"
#include "trace/earlier_run.h"

namespace {

std::string Replaced(std::string text, const std::string& what, const std::string& with) {
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + with.size()))
    text.replace(at, what.size(), with);
  return text;
}

// A scenario's mistake (ValueError) and a results folder that is not free (FileExistsError).
void TranslateErrors(pybind11::module_& module) {
  static pybind11::exception<sanet::scenario::ScenarioError> scenario_error(module, "ScenarioError", PyExc_ValueError);
  static pybind11::exception<sanet::trace::FolderRefused> folder_refused(module, "FolderRefused",
                                                                         PyExc_FileExistsError);
  pybind11::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const sanet::scenario::ScenarioError& e) {
      scenario_error(Replaced(e.what(), "--set ", "set ").c_str());
    } catch (const sanet::trace::FolderRefused& e) {
      folder_refused(
          Replaced(Replaced(e.what(), "another folder with -o", "another output="), "--force", "force=True").c_str());
    }
  });
}

}  // namespace

PYBIND11_MODULE(_sanet, module) {
  sanet::python_controllers::BindControllerApi(module);
  sanet::python_module::BindSimulation(module);
  sanet::python_module::BindStudyReader(module);
  TranslateErrors(module);
}
