// A controller drives one node. It is created from its scenario parameters, started once, and
// then called at its control rate and on every message that reaches its node.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "sanet/message.h"
#include "sanet/node.h"
#include "sanet/params.h"

namespace sanet {

class Controller {
 public:
  virtual ~Controller() = default;
  virtual void Start(Node& node) { (void)node; }
  virtual void ControlStep(Node& node) = 0;
  virtual void OnMessage(Node& node, const Message& message) {
    (void)node;
    (void)message;
  }
  // Called once when the run ends, in every mode, while the node can still log and record
  // metrics (its results are written after): a place for end-of-run statistics.
  virtual void Finish(Node& node) { (void)node; }
};

struct ControllerInfo {
  std::string name;
  std::string description;
  // Reads its parameters from `params` (throwing ParamError for bad ones) and builds the
  // controller.
  std::function<std::unique_ptr<Controller>(const Params& params)> create;
};

// Where controllers are registered by name. Abstract so that a plugin library needs only the
// headers.
class ControllerRegistry {
 public:
  virtual ~ControllerRegistry() = default;
  virtual void Add(ControllerInfo info) = 0;
};

}  // namespace sanet
