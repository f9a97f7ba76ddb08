#include "python_controllers/python_controller.h"

#include <pybind11/pybind11.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "python_controllers/controller_api.h"
#include "python_controllers/python_runtime.h"

namespace py = pybind11;

namespace sanet::python_controllers {
namespace {

// A Python object's method, or None when it has none (start, on_message and finish are optional).
py::object MethodOrNone(const py::object& instance, const char* name) {
  if (!py::hasattr(instance, name)) return py::none();
  return instance.attr(name);
}

class PythonController : public Controller {
 public:
  PythonController(py::object instance, std::string name)
      : name_(std::move(name)),
        instance_(std::move(instance)),
        start_(MethodOrNone(instance_, "start")),
        control_step_(instance_.attr("control_step")),
        on_message_(MethodOrNone(instance_, "on_message")),
        finish_(MethodOrNone(instance_, "finish")) {}
  ~PythonController() override {
    // Python objects go while the interpreter holds them; nothing may throw from here.
    node_ = py::object();
  }

  void Start(Node& node) override {
    if (!start_.is_none()) Call("start", [&] { start_(Wrapped(node)); });
  }
  void ControlStep(Node& node) override {
    Call("control_step", [&] { control_step_(Wrapped(node)); });
  }
  void OnMessage(Node& node, const Message& message) override {
    if (!on_message_.is_none()) Call("on_message", [&] { on_message_(Wrapped(node), ToPython(message)); });
  }
  void Finish(Node& node) override {
    if (!finish_.is_none()) Call("finish", [&] { finish_(Wrapped(node)); });
  }

 private:
  // One Python wrapper of the node for the controller's life (the node outlives it).
  const py::object& Wrapped(Node& node) {
    if (!node_) node_ = py::cast(&node, py::return_value_policy::reference);
    return node_;
  }
  template <typename Body>
  void Call(const char* method, Body body) {
    try {
      body();
    } catch (py::error_already_set& e) {
      throw std::runtime_error("Python controller " + name_ + ", in " + method + ":\n" + TracebackText(e));
    }
  }

  std::string name_;
  py::object instance_, start_, control_step_, on_message_, finish_, node_;
};

struct ModuleClass {
  std::string module, cls;
};

ModuleClass Split(const std::string& text) {
  const auto colon = text.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size() ||
      text.find(':', colon + 1) != std::string::npos)
    throw hosting::RegistryError("python: '" + text + "' must be MODULE:CLASS, e.g. waypoint:Waypoint");
  return {text.substr(0, colon), text.substr(colon + 1)};
}

std::string Folders(const std::vector<std::string>& path) {
  std::string text;
  for (const std::string& f : path) text += (text.empty() ? "" : ", ") + f;
  return text.empty() ? "none" : text;
}

py::module_ Import(const ModuleClass& name, const hosting::ControllerSpec& spec) {
  try {
    return py::module_::import(name.module.c_str());
  } catch (py::error_already_set& e) {
    if (e.matches(PyExc_ModuleNotFoundError) && e.value().attr("name").cast<std::string>() == name.module)
      throw hosting::RegistryError(
          "no Python module '" + name.module + "' in " + Folders(spec.python_path) +
          " (the scenario's folder, or the current one, and --python-path's) or on PYTHONPATH" +
          (name.module.size() > 3 && name.module.substr(name.module.size() - 3) == ".py"
               ? ": a module is named without .py (" + name.module.substr(0, name.module.size() - 3) + ":" + name.cls +
                     ")"
               : ""));
    throw hosting::RegistryError("Python module '" + name.module + "' does not import:\n" + TracebackText(e));
  }
}

py::object ClassOf(const py::module_& module, const ModuleClass& name, const std::vector<std::string>& path) {
  const std::string file = py::hasattr(module, "__file__") ? py::str(module.attr("__file__")).cast<std::string>() : "";
  const std::string stdlib = py::module_::import("sysconfig").attr("get_paths")()["stdlib"].cast<std::string>();
  const bool own = file.empty() || file.rfind(stdlib + "/", 0) == 0;  // built in, or the standard library's
  for (const std::string& folder : path)  // a file of the user's that Python's own module hides
    if (const std::string mine = folder + "/" + name.module + ".py"; own && std::filesystem::exists(mine))
      throw hosting::RegistryError("'" + name.module + "' is a module of Python's own (" +
                                   (file.empty() ? std::string("built in") : file) + "), which " + mine +
                                   " cannot replace: name your module otherwise");
  if (!py::hasattr(module, name.cls.c_str())) {
    std::vector<std::string> names;
    for (const auto& [key, value] : module.attr("__dict__").cast<py::dict>())
      if (py::isinstance<py::type>(value) && py::hasattr(value, "control_step"))
        names.push_back(key.cast<std::string>());
    std::sort(names.begin(), names.end());
    std::string classes;
    for (const std::string& n : names) classes += (classes.empty() ? "" : ", ") + n;
    throw hosting::RegistryError("Python module '" + name.module + "' (" + file + ") has no class '" + name.cls +
                                 "' (controller classes there: " + (classes.empty() ? "none" : classes) + ")");
  }
  py::object cls = module.attr(name.cls.c_str());
  if (!py::isinstance<py::type>(cls) || !py::hasattr(cls, "control_step"))
    throw hosting::RegistryError("'" + name.module + ":" + name.cls + "' (" + file +
                                 ") is not a controller class: it needs a control_step(self, node) method");
  return cls;
}

std::string Description(const py::object& cls, const std::string& name) {
  const py::object doc = cls.attr("__doc__");
  if (doc.is_none()) return "a Python controller (" + name + ")";
  std::string text = py::str(doc).cast<std::string>();
  text = text.substr(text.find_first_not_of(" \n"));
  text = text.substr(0, text.find("\n\n"));  // the first paragraph, on one line
  std::string line;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c)) || (!line.empty() && line.back() != ' '))
      line += std::isspace(static_cast<unsigned char>(c)) ? ' ' : c;
  return line;
}

// Builds an instance; the parameters' errors become ParamError (key and line), others say why.
std::unique_ptr<Controller> Create(const py::object& cls, const std::string& name, const Params& params) {
  const py::object wrapped = ToPython(params);
  try {
    py::object instance = cls(wrapped);
    Close(wrapped);
    return std::make_unique<PythonController>(std::move(instance), name);
  } catch (py::error_already_set& e) {
    Close(wrapped);
    if (e.matches(ParamErrorType()))
      throw ParamError(py::str(e.value().attr("key")).cast<std::string>(), e.value().attr("line").cast<int>(),
                       py::str(e.value()).cast<std::string>());
    throw std::runtime_error("Python controller " + name + ", in __init__:\n" + TracebackText(e));
  }
}

}  // namespace

ControllerInfo LoadPythonController(const hosting::ControllerSpec& spec) {
  const ModuleClass name = Split(spec.python);
  EnsureInterpreter();
  py::module_::import("sanet");  // the classes controllers are given (Node, Params, ...)
  AddSearchPath(spec.python_path);
  const py::object cls = ClassOf(Import(name, spec), name, spec.python_path);
  return {spec.python, Description(cls, spec.python),
          [cls, id = spec.python](const Params& params) { return Create(cls, id, params); }};
}

void InstallPython(hosting::Registry& registry) { registry.SetPythonSupport({LoadPythonController, SeedRun}); }

}  // namespace sanet::python_controllers
