// sanet.Study's reader: a study's database as `sanet report` reads it (study/report.h), so that
// the module's numbers are the command's.
#pragma once

#include <pybind11/pybind11.h>

namespace sanet::python_module {

void BindStudyReader(pybind11::module_& module);

}  // namespace sanet::python_module
