// Scenario values given on the command line (`--set path=value`), applied to the file's YAML
// before it is read, so that they are checked exactly like the file. A path is the keys from
// the top separated by dots; in a list, an item is addressed by its name (`nodes.robot`), a
// grid by its grid name (`nodes.r`: the value applies to every node of the grid) or by its
// index (`world.obstacles.0`). The value is YAML: `25`, `true`, `[1, 2]`, `{floor: -85}`.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "scenario/yaml_reader.h"

namespace sanet::scenario {

struct Override {
  std::string text;   // as given: "network.tx_power=25"
  std::string path;   // "network.tx_power"
  std::string value;  // "25"
  std::string field;  // where it landed, as errors name fields: "nodes[1].controller.params.speed"
};

// Splits "path=value"; a text without '=' or with an empty path is a ScenarioError naming it.
Override ParseOverride(const std::string& text);

// Sets each value in `root` (a mapping), creating the mappings on the way; fills `field`.
// A path that leads nowhere (no such item in a list, a value where a mapping should be) is a
// ScenarioError naming the option.
void ApplyOverrides(YAML::Node root, std::vector<Override>& overrides);

// The same error, told as the option's when its field is where an override landed (or below).
ScenarioError Attributed(const ScenarioError& error, const std::vector<Override>& overrides);

}  // namespace sanet::scenario
