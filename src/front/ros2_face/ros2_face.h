// The ROS 2 face of a served world: every robot that no other front end drives is a ROS 2 robot
// under its name as namespace. It publishes /<robot>/odom, /<robot>/ground_truth, /<robot>/scan
// (a laser), /<robot>/ir_<i> (each IR sensor; a ROS name token may not start with a digit),
// /<robot>/robot_description (a robot from a URDF, with its links in tf), /tf, /tf_static and /clock,
// and takes
// /<robot>/cmd_vel (geometry_msgs/Twist, or TwistStamped) to the robot's Node, as a controller
// would drive it. Over plain DDS as ROS 2 nodes speak it (docs/ros2.md): no ROS install needed.
//
// One owner per robot: the face claims a robot only for the moment it reads its sensors or
// takes a command, so a USARSim client or an agent may claim it at any time; while one does,
// the face publishes what that owner read, and refuses (counts, and says once) cmd_vel to it.
// Bad samples, commands that are not finite numbers, publishers taking turns on one cmd_vel and
// publishers whose QoS cannot match are counted and said once per robot; a robot the face drives
// stops when cmd_vel stays quiet for cmd_vel_timeout; the simulation never waits for DDS.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ros2_face/dds_domain.h"
#include "ros2_face/discovery_info.h"
#include "ros2_presentation/robot_messages.h"
#include "sections/ros2_section.h"
#include "sim/driver.h"
#include "sim/fresh_samples.h"

namespace sanet::ros2_face {

namespace msg = ros2msg;
using ros2_presentation::FramesOf, ros2_presentation::OdomToBase, ros2_presentation::RobotFrames,
    ros2_presentation::StampOf, ros2_presentation::StaticTransforms;

struct Ros2Settings {
  std::uint32_t domain = 0;                 // ROS_DOMAIN_ID
  std::string interface;                    // network interface (name or address); empty: Cyclone's choice
  double sensor_period = 0.1;               // s between a robot's sensor messages (odom, scan, ranges, tf)
  double command_period = 0.01;             // s between takes of cmd_vel
  bool twist_stamped = false;               // cmd_vel as geometry_msgs/TwistStamped (ROS 2 Jazzy's controllers)
  double cmd_vel_timeout = 0.5;             // s without cmd_vel before a robot the face drives stops; 0: never
  std::vector<sections::Ros2Robot> robots;  // robots with a namespace or a rate of their own
  sections::Ros2Distro distro = sections::Ros2Distro::kJazzy;  // whose ros_discovery_info (discovery_info.h)
};

class Ros2Face {
 public:
  // Joins the DDS domain and creates every robot's topics. Throws std::runtime_error.
  Ros2Face(sim::Driver& driver, Ros2Settings settings);
  ~Ros2Face();
  void Start();                                        // schedules the face on the simulation clock
  void AfterStep(const sim::WorldSnapshot& snapshot);  // /clock; heard on the run's bus

  // What the face did, by robot: messages published, commands taken and refused (summary.json).
  nlohmann::ordered_json Summary() const;
  // The robots that took at least one cmd_vel.
  std::vector<std::string> Driven() const;

 private:
  Subscription step_ended_;  // AfterStep, on the run's bus
  struct Robot;
  void AddRobots();
  void Describe(Robot& robot, const sim::NodeSpec& node, const std::string& ns);
  void PublishWheels(const sim::WorldSnapshot& snapshot);
  void Publish(Robot& robot);
  void TakeCommands(Robot& robot);
  void StopIfQuiet(Robot& robot);
  void Apply(Robot& robot, const DdsDomain::Sample& sample);
  void SayOnce(Robot& robot, const std::string& what, const std::string& text);
  void Poll();

  sim::Driver& driver_;
  Ros2Settings settings_;
  DdsDomain dds_;
  DiscoveryInfo discovery_;  // node /sanet in `ros2 node list`: every reader and writer above
  DdsDomain::Entity clock_, tf_, tf_static_;
  std::vector<std::unique_ptr<Robot>> robots_;
  std::size_t nodes_seen_ = 0;
  double next_clock_ = 0;
  bool any_urdf_ = false;  // a robot from a URDF: wheels in /tf
  double next_wheels_ = 0;
  std::uint64_t clock_messages_ = 0;
};

}  // namespace sanet::ros2_face
