#include "builtin.h"

#include "controllers.h"

namespace sanet::controllers {

void RegisterBuiltinControllers(ControllerRegistry& registry) {
  registry.Add(ConstantVelocityInfo());
  registry.Add(WaypointInfo());
  registry.Add(PingerInfo());
  registry.Add(EchoInfo());
  registry.Add(HelpRequestMoteInfo());
  registry.Add(HelpRequestRobotInfo());
  registry.Add(FormationLeaderInfo());
  registry.Add(FormationFollowerInfo());
  registry.Add(FlockInfo());
  registry.Add(RandomWaypointInfo());
  registry.Add(TourInfo());
  registry.Add(LawnmowerInfo());
  registry.Add(DataMuleSensorInfo());
  registry.Add(DataMuleCollectorInfo());
  registry.Add(DataMuleSinkInfo());
  registry.Add(ChargedMoteInfo());
  registry.Add(ChargerRobotInfo());
  registry.Add(CameraStreamerInfo());
  registry.Add(PictureReceiverInfo());
}

}  // namespace sanet::controllers
