// The IMU's keys in a scenario.
#include "scenario/sensor_fields.h"
#include "sensors/imu/imu.h"

namespace sanet::scenario {
namespace {

using sensors::ImuSettings;

const Fields<ImuSettings>& ImuFields() {
  static const Fields<ImuSettings> fields = [] {
    Fields<ImuSettings> f;
    f.Number("rate", Member(&ImuSettings::rate), "Hz", 0, 10000, "samples a second, on the simulated clock", true);
    f.Number("mount_x", Member(&ImuSettings::mount_x), "m", -10, 10, "ahead of the reference point");
    f.Number("mount_y", Member(&ImuSettings::mount_y), "m", -10, 10, "to the left of the reference point");
    f.Flag("orientation", Member(&ImuSettings::orientation), "give the orientation (the body's yaw)");
    f.Number("gyroscope_noise_density", Member(&ImuSettings::gyroscope_noise_density), "rad/s/√Hz", 0, 10,
             "white noise of each turn rate");
    f.Number("gyroscope_random_walk", Member(&ImuSettings::gyroscope_random_walk), "rad/s²/√Hz", 0, 10,
             "the walk of each turn rate's bias");
    f.Number("accelerometer_noise_density", Member(&ImuSettings::accelerometer_noise_density), "m/s²/√Hz", 0, 100,
             "white noise of each acceleration");
    f.Number("accelerometer_random_walk", Member(&ImuSettings::accelerometer_random_walk), "m/s³/√Hz", 0, 100,
             "the walk of each acceleration's bias");
    return f;
  }();
  return fields;
}

}  // namespace

const SensorFields& ImuSensorFields() {
  static const DeclaredKeys<ImuSettings> keys(ImuFields());
  return keys;
}

}  // namespace sanet::scenario
