#include "robots/robot_models.h"

#include <optional>

#include "robots/node_model.h"

namespace sanet::robots {

const RobotModel& ModelOf(ModelKind kind) {
  switch (kind) {
#define SANET_MODEL_CASE(name, Name, kind) \
  case ModelKind::kind:                    \
    return Name##Model();
    SANET_ROBOT_MODELS(SANET_MODEL_CASE)
#undef SANET_MODEL_CASE
  }
  return MoteModel();
}

const std::vector<ModelKind>& AllModels() {
#define SANET_MODEL_ITEM(name, Name, kind) ModelKind::kind,
  static const std::vector<ModelKind> all = {SANET_ROBOT_MODELS(SANET_MODEL_ITEM)};
#undef SANET_MODEL_ITEM
  return all;
}

std::optional<ModelKind> FindModel(const std::string& name) {
  for (ModelKind kind : AllModels())
    if (name == ModelOf(kind).Name()) return kind;
  return std::nullopt;
}

}  // namespace sanet::robots
