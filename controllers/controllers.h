// Descriptions of the built-in controllers, one function per controller file.
#pragma once

#include "sanet/controller.h"

namespace sanet::controllers {

ControllerInfo ConstantVelocityInfo();
ControllerInfo WaypointInfo();
ControllerInfo PingerInfo();
ControllerInfo EchoInfo();
ControllerInfo HelpRequestMoteInfo();
ControllerInfo HelpRequestRobotInfo();
ControllerInfo FormationLeaderInfo();
ControllerInfo FormationFollowerInfo();
ControllerInfo FlockInfo();
ControllerInfo RandomWaypointInfo();
ControllerInfo TourInfo();
ControllerInfo LawnmowerInfo();
ControllerInfo DataMuleSensorInfo();
ControllerInfo DataMuleCollectorInfo();
ControllerInfo DataMuleSinkInfo();
ControllerInfo ChargedMoteInfo();
ControllerInfo ChargerRobotInfo();
ControllerInfo CameraStreamerInfo();
ControllerInfo PictureReceiverInfo();

}  // namespace sanet::controllers
