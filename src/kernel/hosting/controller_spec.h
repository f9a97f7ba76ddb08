// Which controller drives a node, at what rate, with which parameters (from the scenario).
#pragma once

#include <string>
#include <vector>

#include "sanet/params.h"

namespace sanet::hosting {

struct ControllerSpec {
  std::string name;     // registered name
  std::string library;  // shared library to load first ("" for built-in controllers)
  // A Python controller: "module:Class" (then `name` is the same text), the module found on
  // `python_path` (the scenario's folder, then --python-path's).
  std::string python;
  std::vector<std::string> python_path;
  double rate = 10;  // Hz, control steps per second
  Params params;
};

}  // namespace sanet::hosting
