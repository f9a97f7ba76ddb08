// Drives at a fixed body velocity between two times: the simplest test of a drive.
#include <cmath>
#include <memory>

#include "controllers.h"

namespace sanet::controllers {
namespace {

class ConstantVelocity : public Controller {
 public:
  explicit ConstantVelocity(const Params& p)
      : velocity_{p.Number("vx", 0), p.Number("vy", 0), p.Number("omega", 0)},
        start_(p.Number("start", 0, 0)),
        stop_(p.Number("stop", HUGE_VAL, 0)),
        wheels_(p.Numbers("wheel_speeds", {})) {}

  void ControlStep(Node& node) override {
    const double t = node.Now();
    if (t < start_ || t >= stop_) {
      node.Drive({});
    } else if (!wheels_.empty()) {
      if (!node.SetWheelSpeeds(wheels_)) node.Log("wheel_speeds does not match this robot's wheels");
    } else {
      node.Drive(velocity_);
    }
  }

 private:
  Twist2D velocity_;
  double start_, stop_;
  std::vector<double> wheels_;
};

}  // namespace

ControllerInfo ConstantVelocityInfo() {
  return {"constant_velocity",
          "drives at a fixed body velocity (vx, vy m/s, omega rad/s) or fixed wheel_speeds (rad/s) "
          "from `start` to `stop` (s)",
          [](const Params& p) { return std::make_unique<ConstantVelocity>(p); }};
}

}  // namespace sanet::controllers
