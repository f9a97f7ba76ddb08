// What a node's sensors give its controller: one struct per kind of reading, and SensorReading,
// the closed set of them that Node::Sensor(name) returns. The set holds every reading sanet's
// sensors produce (some sensors arrive later than the types), so that a new sensor of an existing
// reading type changes no header here and no plugin's binary interface.
//
// Units are SI and frames are the robot's (x forward, y left, z up, angles counter-clockwise), as
// in ROS (REP 103); covariances are 3x3, row-major, as in ROS messages.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "sanet/geometry.h"
#include "sanet/message.h"

namespace sanet {

// Ranges from a ring of IR sensors or a planar laser, in the robot frame.
struct RangeScan {
  std::vector<double> angles;  // rad, counter-clockwise from the robot's forward axis
  std::vector<double> ranges;  // m, max_range where nothing was seen
  double max_range = 0;        // m
};

// Where another node lies, seen from this robot.
struct BearingReading {
  double distance = 0;  // m
  double bearing = 0;   // rad, in the robot frame (0 = straight ahead, positive = left)
};

// Every other node within a bearing sensor's range, at one instant.
struct NodeBearing {
  NodeId node = 0;
  BearingReading reading;
};
struct BearingsReading {
  std::vector<NodeBearing> in_range;
};

struct Vector3 {
  double x = 0, y = 0, z = 0;
};
struct Quaternion {
  double x = 0, y = 0, z = 0, w = 1;
};
using Covariance3 = std::array<double, 9>;  // row-major 3x3

// A node's battery.
struct BatteryReading {
  double remaining_j = 0;  // J left
  double fraction = 0;     // of the capacity, in [0, 1]
  double voltage = 0;      // V
  bool charging = false;
  double capacity_j = 0;  // J when full
  double power_w = 0;     // drawn now (positive while discharging)
};

// An inertial measurement unit, in its own frame (sensor_msgs/Imu's fields).
struct ImuReading {
  Vector3 angular_velocity;               // rad/s
  Vector3 linear_acceleration;            // m/s^2; at rest on flat ground, +g upwards
  std::optional<Quaternion> orientation;  // empty when the IMU gives none
  Covariance3 angular_velocity_covariance{};
  Covariance3 linear_acceleration_covariance{};
  Covariance3 orientation_covariance{};
};

// A satellite position fix (sensor_msgs/NavSatFix's fields).
struct FixReading {
  enum Status : int { kNoFix = -1, kFix = 0, kSbasFix = 1, kGbasFix = 2 };
  double latitude = 0;   // degrees, positive north
  double longitude = 0;  // degrees, positive east
  double altitude = 0;   // m above the WGS 84 ellipsoid
  int status = kNoFix;
  Covariance3 position_covariance{};  // m^2, east-north-up
};

// Joints such as wheels (sensor_msgs/JointState's fields, without efforts).
struct JointStatesReading {
  std::vector<std::string> names;
  std::vector<double> angles;  // rad
  std::vector<double> speeds;  // rad/s
};

// A camera's picture (sensor_msgs/Image's fields), and its depth image when asked for.
struct ImageReading {
  int width = 0, height = 0;
  std::string encoding;            // "rgb8" and the like, as sensor_msgs/image_encodings names them
  std::vector<std::uint8_t> data;  // rows top to bottom
  std::vector<float> depth;        // m per pixel, same layout; empty without depth
};

// A pose reading (odometry, ground truth) is a Pose2D.
using SensorReading = std::variant<RangeScan, Pose2D, BearingsReading, BatteryReading, ImuReading, FixReading,
                                   JointStatesReading, ImageReading>;

}  // namespace sanet
