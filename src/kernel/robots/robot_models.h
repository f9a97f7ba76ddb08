// Every registered model, once (ROBOT_MODEL(name, Name, kind)): the folder src/models/<name>/
// defines robots::<Name>Model() and its other layers' parts (scenario::<Name>BodyFields()), and
// the registries are made from this list, so that a part left out is a link error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "robots/robot_model.h"

#define SANET_ROBOT_MODELS(MODEL) \
  MODEL(mote, Mote, kMote)        \
  MODEL(omni3, Omni3, kOmni3)     \
  MODEL(diffdrive, DiffDrive, kDiffDrive)

namespace sanet::robots {

enum class ModelKind {
#define SANET_MODEL_ENUM(name, Name, kind) kind,
  SANET_ROBOT_MODELS(SANET_MODEL_ENUM)
#undef SANET_MODEL_ENUM
};

#define SANET_DECLARE_ROBOT_MODEL(name, Name, kind) const RobotModel& Name##Model();
SANET_ROBOT_MODELS(SANET_DECLARE_ROBOT_MODEL)
#undef SANET_DECLARE_ROBOT_MODEL

const RobotModel& ModelOf(ModelKind kind);
const std::vector<ModelKind>& AllModels();
// The model named `name`; empty for none.
std::optional<ModelKind> FindModel(const std::string& name);

}  // namespace sanet::robots
