// The IMU's kernel part: samples at its rate from the body's motion between physics steps, with
// white noise and walking biases (sensors/imu/imu.h).
#include "sensors/imu/imu.h"

#include <array>
#include <cmath>

#include "sensors/sampling_sensor.h"
#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class Imu : public SamplingSensor {
 public:
  Imu(ImuSettings settings, Mount mount)
      : SamplingSensor(settings.rate, mount.world), settings_(settings), mount_(mount) {}

 private:
  // A sample's acceleration is the change of the body's velocity since the previous sample over
  // the sample period (an IMU's delta velocity): integrated, the samples give the velocity back
  // exactly.
  SensorReading Sample(double period) override {
    const Twist2D v = mount_.model.body().velocity();
    const bool first = !sampled_;
    const Vec2 a = first ? Vec2{0, 0} : Vec2{(v.vx - velocity_.vx) / period, (v.vy - velocity_.vy) / period};
    const double alpha = first ? 0 : (v.omega - velocity_.omega) / period;
    velocity_ = v, sampled_ = true;
    return Noisy(Truth(a, alpha), period);
  }

  // The specific force and turn rate at the mount, in the robot's frame, from the body's
  // acceleration `a` (world frame) and angular acceleration.
  ImuReading Truth(Vec2 a, double alpha) const {
    const Pose2D pose = mount_.model.body().pose();
    const Twist2D v = mount_.model.body().velocity();
    const double c = std::cos(pose.theta), s = std::sin(pose.theta);
    // The mount's acceleration: the body's, plus the turn's tangential and centripetal parts.
    const double rx = settings_.mount_x, ry = settings_.mount_y;
    const double body_x = c * a.x + s * a.y - alpha * ry - v.omega * v.omega * rx;
    const double body_y = -s * a.x + c * a.y + alpha * rx - v.omega * v.omega * ry;
    ImuReading r;
    r.angular_velocity = {0, 0, v.omega};
    r.linear_acceleration = {body_x, body_y, mount_.world.gravity()};
    if (settings_.orientation)
      r.orientation = Quaternion{0, 0, std::sin(pose.theta / 2), std::cos(pose.theta / 2)};
    else
      r.orientation_covariance[0] = -1;  // sensor_msgs/Imu: no orientation
    return r;
  }

  // White noise and each axis's bias, whose walk moves at every sample.
  ImuReading Noisy(ImuReading r, double period) {
    const double root_rate = std::sqrt(1 / period);
    const auto add = [&](Vector3& value, std::array<double, 3>& bias, double density, double walk) {
      double* axes[3] = {&value.x, &value.y, &value.z};
      for (int i = 0; i < 3; ++i) {
        if (walk > 0) bias[i] += mount_.random.Gaussian(0, walk / root_rate);
        *axes[i] += bias[i] + (density > 0 ? mount_.random.Gaussian(0, density * root_rate) : 0);
      }
    };
    add(r.angular_velocity, gyro_bias_, settings_.gyroscope_noise_density, settings_.gyroscope_random_walk);
    add(r.linear_acceleration, accel_bias_, settings_.accelerometer_noise_density, settings_.accelerometer_random_walk);
    const double gyro = std::pow(settings_.gyroscope_noise_density * root_rate, 2);
    const double accel = std::pow(settings_.accelerometer_noise_density * root_rate, 2);
    for (int i = 0; i < 3; ++i)
      r.angular_velocity_covariance[4 * i] = gyro, r.linear_acceleration_covariance[4 * i] = accel;
    return r;
  }

  ImuSettings settings_;
  Mount mount_;
  Twist2D velocity_;  // at the previous sample
  bool sampled_ = false;
  std::array<double, 3> gyro_bias_{}, accel_bias_{};
};

class InertialUnit : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"imu",
                                 "an inertial measurement unit: turn rate and specific force, with noise and "
                                 "walking biases",
                                 "ImuReading",
                                 "angular velocity in rad/s, linear acceleration in m/s^2 (at rest: +g on z), "
                                 "orientation (optional)",
                                 "sensor_msgs/msg/Imu",
                                 "imu"};
    return info;
  }
  std::any DefaultSettings(const robots::ModelSpec& /*model*/) const override { return ImuSettings{}; }
  bool SamplesOnItsOwn() const override { return true; }
  std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const override {
    return std::make_unique<Imu>(std::any_cast<ImuSettings>(settings), mount);
  }
};

}  // namespace

const SensorKind& ImuKind() {
  static const InertialUnit kind;
  return kind;
}

}  // namespace sanet::sensors
