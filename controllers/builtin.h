// Registers the controllers that ship with sanet.
#pragma once

#include "sanet/controller.h"

namespace sanet::controllers {

void RegisterBuiltinControllers(ControllerRegistry& registry);

}  // namespace sanet::controllers
