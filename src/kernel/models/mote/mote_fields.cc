// The mote's `body` keys.
#include "scenario/declarations.h"

namespace sanet::scenario {

const Fields<robots::ModelSpec>& MoteBodyFields() {
  using robots::ModelSpec;
  static const Fields<ModelSpec> fields = [] {
    Fields<ModelSpec> f;
    f.Number(
        "size", [](ModelSpec& m) -> double& { return m.mote.size; }, "m", 0.005, 10, "side of the cube");
    f.Number(
        "mass", [](ModelSpec& m) -> double& { return m.mote.mass; }, "kg", 0.001, 1000, "");
    BodyColor(f);
    return f;
  }();
  return fields;
}

}  // namespace sanet::scenario
