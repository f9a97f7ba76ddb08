// Descriptions of the built-in controllers, one function per controller file.
#pragma once

#include "sanet/controller.h"

namespace sanet::controllers {

ControllerInfo ConstantVelocityInfo();
ControllerInfo WaypointInfo();
ControllerInfo PingerInfo();

}  // namespace sanet::controllers
