// The tour of mobility.cc, for controllers that tour and do something else on the way (a data
// mule collecting readings).
#pragma once

#include <memory>

#include "sanet/controller.h"

namespace sanet::controllers {

// `tour`'s controller from its parameters (points, order, loop, speed, tolerance, ...).
std::unique_ptr<Controller> MakeTour(const Params& p);

}  // namespace sanet::controllers
