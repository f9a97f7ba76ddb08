// A ROS 2 robot seen through its topics (robot_topics.h): the readings a controller's Node
// gives (odometry, laser, IR ranges, ground truth where a pose topic exists, the robot's clock
// with use_sim_time) and cmd_vel for its motion. Samples are taken when Poll is called, the
// newest of each kind kept; a sample that does not decode is counted and said once per topic.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "robots/node_model.h"
#include "ros2_agent/robot_topics.h"
#include "ros2_face/dds_domain.h"
#include "sanet/node.h"

namespace sanet::ros2_agent {

struct Ros2RobotSettings {
  std::uint32_t domain = 0;  // ROS_DOMAIN_ID
  std::string interface;     // the network interface of its DDS traffic; "" for Cyclone's choice
  RobotTopics topics;
  robots::ModelSpec model;  // for the IR sensors' angles and whether it is holonomic
  Pose2D start;             // where odometry starts (the scenario's pose of the robot)
};

class Ros2Robot {
 public:
  // Joins the domain and subscribes and advertises the robot's topics. Throws std::runtime_error.
  explicit Ros2Robot(Ros2RobotSettings settings);

  // Takes what arrived; `now` is this computer's monotonic clock (s), for the ages below.
  void Poll(double now);
  std::optional<Pose2D> Odometry() const { return odometry_; }  // in the world, from the start pose
  std::optional<Pose2D> GroundTruth() const { return ground_truth_; }
  std::optional<RangeScan> Laser() const { return laser_; }
  std::optional<RangeScan> Ir() const;                         // once every IR topic has said something
  std::optional<double> SimTime() const { return sim_time_; }  // the last /clock
  // When the last odometry came (the monotonic clock of Poll), if any did.
  std::optional<double> OdometryAt() const { return odometry_at_; }
  // Publishes cmd_vel (stamped at `stamp` s of the robot's clock, for TwistStamped).
  void Drive(const Twist2D& velocity, double stamp);

  struct Counts {
    std::uint64_t odometry = 0, scans = 0, ranges = 0, ground_truth = 0, clock = 0, undecodable = 0, cmd_vel = 0;
  };
  const Counts& counts() const { return counts_; }
  // What may be wrong with the robot's topics so far, one sentence each: readers that never got
  // a sample (with the writers whose QoS or type could not match them), cmd_vel that no reader
  // takes. Empty when every topic works.
  std::vector<std::string> TopicTrouble();
  const RobotTopics& topics() const { return settings_.topics; }

 private:
  template <typename Message, typename Use>
  void TakeAll(ros2_face::DdsDomain::Entity reader, const std::string& topic, Use use);
  ros2_face::DdsDomain::Entity Subscribe(const Topic& topic, const char* dds_type);
  void TakeGroundTruth();

  Ros2RobotSettings settings_;
  ros2_face::DdsDomain dds_;
  ros2_face::DdsDomain::Entity odom_ = 0, scan_ = 0, truth_ = 0, clock_ = 0, cmd_vel_ = 0;
  std::vector<ros2_face::DdsDomain::Entity> ir_;
  std::optional<Pose2D> odometry_, ground_truth_;
  std::optional<RangeScan> laser_;
  std::vector<std::optional<double>> ranges_;
  std::optional<double> sim_time_, odometry_at_;
  std::map<std::string, bool> said_undecodable_;
  Counts counts_;
};

}  // namespace sanet::ros2_agent
