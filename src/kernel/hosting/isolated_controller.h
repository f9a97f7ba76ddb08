// A controller hosted in a child process (`sanet run --isolate-controllers`): the child makes the
// controller from its spec and runs its calls; every call the controller makes on its node comes
// back to this process and is answered by the real node, one call at a time, so the run is the
// same as in process (same steps, same random numbers, same fingerprint). A controller that
// crashes its process (a segmentation fault, abort, exit) ends only the child: the call reports
// it as a failure naming the signal, and the run ends with its results kept, as when a
// controller throws. The price: every node call crosses a socket (microseconds each).
#pragma once

#include <memory>

#include "hosting/controller_registry.h"
#include "hosting/controller_spec.h"
#include "sanet/controller.h"

namespace sanet::hosting {

// Forks the child that makes and hosts the controller of `spec` (its library loaded there);
// throws RegistryError or ParamError as MakeController does, with the child's words.
std::unique_ptr<Controller> MakeIsolatedController(const ControllerSpec& spec, Registry& registry);

}  // namespace sanet::hosting
