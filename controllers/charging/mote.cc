// A mote that reports its battery to the robot that charges it: every `interval` s (every
// `charging_interval` s while a charger gives it something, so that the robot beside it knows
// when it is full), its charge, whether it is charging and where it is, sent to the node `robot`
// over the network (routed: several hops along a line of motes). Metric `reports` (1 per report
// sent).
#include <memory>
#include <stdexcept>

#include "charging/messages.h"
#include "controllers.h"

namespace sanet::controllers {
namespace {

class ChargedMote : public Controller {
 public:
  explicit ChargedMote(const Params& p)
      : robot_name_(p.Text("robot", "charger")),
        interval_(p.Number("interval", 30, 0.1)),
        charging_interval_(p.Number("charging_interval", 5, 0.1)) {}

  void Start(Node& node) override {
    robot_ = node.Lookup(robot_name_);
    if (!robot_) throw std::runtime_error("charged_mote: no node named '" + robot_name_ + "' (parameter 'robot')");
    next_ = interval_ * node.Random();  // motes out of step
  }

  void ControlStep(Node& node) override {
    if (node.Now() < next_) return;
    const std::optional<BatteryReading> battery = node.SensorAs<BatteryReading>("battery");
    const std::optional<Pose2D> pose = node.GroundTruth();
    if (!battery || !pose)
      throw std::runtime_error("charged_mote: the mote needs `energy` and its battery sensor (not `battery: false`)");
    node.Send(*robot_, charging::ReportMessage({battery->fraction, battery->charging, pose->position(), node.Now()}));
    node.Metric("reports", 1);
    next_ = node.Now() + (battery->charging ? charging_interval_ : interval_);
  }

 private:
  std::string robot_name_;
  double interval_, charging_interval_;
  std::optional<NodeId> robot_;
  double next_ = 0;
};

}  // namespace

ControllerInfo ChargedMoteInfo() {
  return {"charged_mote",
          "a mote that reports its battery (charge, charging, position) to the node `robot` every `interval` s, "
          "every `charging_interval` s while charging; metric reports",
          [](const Params& p) { return std::make_unique<ChargedMote>(p); }};
}

}  // namespace sanet::controllers
