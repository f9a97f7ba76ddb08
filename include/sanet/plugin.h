// Entry point of a controller library loaded from a scenario (`controller: {library: ...}`).
//
//   #include <sanet/plugin.h>
//   SANET_CONTROLLER_PLUGIN(registry) {
//     registry.Add({"my_controller", "what it does",
//                   [](const sanet::Params& p) { return std::make_unique<Mine>(p); }});
//   }
//
// sanet loads the library with dlopen, checks that it was built against the same interface
// version, and calls the registration function once.
#pragma once

#include "sanet/controller.h"

// Bump whenever a header under include/sanet changes in a way that breaks binary compatibility.
// 4: Node::Transition and Node::Metric. 5: Node::Drive and SetWheelSpeeds are checked by Node
// itself and call the protected ApplyDrive / ApplyWheelSpeeds (docs/controllers.md, migration).
// 6: Node::Sensor(name) and sanet/readings.h (Ir, Laser, Odometry, GroundTruth read through it),
// Node::SetRadioSleep, Controller::Finish.
#define SANET_CONTROLLER_API_VERSION 6

// The entry points stay visible when a library hides its other symbols (-fvisibility=hidden).
#define SANET_PLUGIN_EXPORT extern "C" __attribute__((visibility("default")))

#define SANET_CONTROLLER_PLUGIN(registry)                                                         \
  SANET_PLUGIN_EXPORT int sanet_controller_api_version() { return SANET_CONTROLLER_API_VERSION; } \
  SANET_PLUGIN_EXPORT void sanet_register_controllers(::sanet::ControllerRegistry& registry)
