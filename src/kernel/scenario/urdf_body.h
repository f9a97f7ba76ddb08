// A robot's body from a URDF file (`body.urdf`, robots/urdf_robot.h): on a `diffdrive`, the wheel
// radius, the axle length, the wheels' and the chassis' masses, the chassis box and its ground
// clearance come from the file; keys given beside `urdf` override them. `body.wheels: {left,
// right}` names the wheel joints, `body.base_link` the chassis link (default: the URDF's root).
// The effective scenario prints `urdf: {file, text}` with the values read under their usual keys.
#pragma once

#include <yaml-cpp/yaml.h>

#include "robots/node_model.h"
#include "scenario/yaml_reader.h"

namespace sanet::scenario {

// The keys `body` takes beside the model's own.
inline const std::vector<std::string> kUrdfBodyKeys = {"urdf", "wheels", "base_link"};

// Reads `body.urdf` (with `wheels` and `base_link`) into `m`, if `body` has it. Errors in the
// URDF name its file, element and line; the others the scenario's field.
void ReadUrdfBody(const Field& body, robots::ModelSpec& m);
// `urdf`, `wheels` and `base_link` as the effective scenario prints them.
void PrintUrdfBody(const robots::ModelSpec& m, YAML::Node& body);

}  // namespace sanet::scenario
