// The module `sanet` that Python controllers see inside the sanet command (the embedded
// interpreter's): the controller interface (python/controller_api.h). Outside the command, the
// extension module (python/sanet, docs/python-module.md) gives the same classes.
#include <pybind11/embed.h>

#include "python_controllers/controller_api.h"

PYBIND11_EMBEDDED_MODULE(sanet, module) { sanet::python_controllers::BindControllerApi(module); }
