// Every sensor kind, registered once, in the order a scenario's effective copy lists them.
// KIND(name, Name): the folder sensors/<name>/ defines each layer's part of the kind under a
// name made from `Name` (sensors::NameKind(), scenario::NameSensorFields(), ...), and the
// layers' registries are made from this list, so that a part left out is a link error.
#pragma once

#define SANET_SENSOR_KINDS(KIND)  \
  KIND(ir, Ir)                    \
  KIND(laser, Laser)              \
  KIND(odometry, Odometry)        \
  KIND(ground_truth, GroundTruth) \
  KIND(bearing, Bearing)          \
  KIND(sonar, Sonar)              \
  KIND(battery, Battery)          \
  KIND(encoders, Encoders)        \
  KIND(imu, Imu)                  \
  KIND(gnss, Gnss)                \
  KIND(camera, Camera)
