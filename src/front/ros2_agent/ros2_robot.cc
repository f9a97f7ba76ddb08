#include "ros2_agent/ros2_robot.h"

#include <cstdio>

#include "ros2_agent/readings.h"
#include "ros2msg/codec.h"
#include "sensors/range_fan.h"

namespace sanet::ros2_agent {
namespace {

template <typename Message>
const char* DdsName() {
  return ros2msg::TypeOf<Message>::kDdsName;
}

}  // namespace

Ros2Robot::Ros2Robot(Ros2RobotSettings settings)
    : settings_(std::move(settings)), dds_(settings_.domain, settings_.interface) {
  const RobotTopics& t = settings_.topics;
  odom_ = Subscribe(t.odom, DdsName<msg::nav_msgs::Odometry>());
  if (sensors::DefaultFan(settings_.model, "laser")) scan_ = Subscribe(t.scan, DdsName<msg::sensor_msgs::LaserScan>());
  for (const Topic& ir : t.ir) ir_.push_back(Subscribe(ir, DdsName<msg::sensor_msgs::Range>()));
  ranges_.resize(ir_.size());
  if (t.ground_truth_type == GroundTruthType::kOdometry)
    truth_ = Subscribe(t.ground_truth, DdsName<msg::nav_msgs::Odometry>());
  if (t.ground_truth_type == GroundTruthType::kPoseStamped)
    truth_ = Subscribe(t.ground_truth, DdsName<msg::geometry_msgs::PoseStamped>());
  if (t.use_sim_time) clock_ = Subscribe(t.clock, DdsName<msg::rosgraph_msgs::Clock>());
  cmd_vel_ = dds_.Writer(FullName(t, t.cmd_vel),
                         t.cmd_vel_type == CmdVelType::kTwistStamped ? DdsName<msg::geometry_msgs::TwistStamped>()
                                                                     : DdsName<msg::geometry_msgs::Twist>(),
                         t.cmd_vel.qos);
}

ros2_face::DdsDomain::Entity Ros2Robot::Subscribe(const Topic& topic, const char* dds_type) {
  return dds_.Reader(FullName(settings_.topics, topic), dds_type, topic.qos);
}

// Every sample of `reader` decoded as Message and handed to `use`; one that does not decode is
// counted, and said once per topic.
template <typename Message, typename Use>
void Ros2Robot::TakeAll(ros2_face::DdsDomain::Entity reader, const std::string& topic, Use use) {
  if (!reader) return;
  for (const ros2_face::DdsDomain::Sample& s : dds_.Take(reader)) {
    std::string error;
    if (const auto m = ros2msg::Decode<Message>(s.bytes, &error)) {
      use(*m);
      continue;
    }
    ++counts_.undecodable;
    if (!said_undecodable_[topic])
      std::fprintf(stderr, "sanet agent: %s: a sample that is no %s (%s); further ones are only counted\n",
                   topic.c_str(), ros2msg::TypeOf<Message>::kName, error.c_str());
    said_undecodable_[topic] = true;
  }
}

void Ros2Robot::Poll(double now) {
  const RobotTopics& t = settings_.topics;
  TakeAll<msg::nav_msgs::Odometry>(odom_, FullName(t, t.odom), [&](const msg::nav_msgs::Odometry& m) {
    odometry_ = InWorld(settings_.start, PoseOf(m.pose.pose));
    odometry_at_ = now;
    ++counts_.odometry;
  });
  TakeAll<msg::sensor_msgs::LaserScan>(scan_, FullName(t, t.scan), [&](const msg::sensor_msgs::LaserScan& m) {
    laser_ = ScanOf(m);  // in the laser's frame, which a turned laser turns with it
    if (const auto* laser = sensors::DefaultFan(settings_.model, "laser"))
      for (double& angle : laser_->angles) angle += laser->direction;
    ++counts_.scans;
  });
  for (std::size_t i = 0; i < ir_.size(); ++i)
    TakeAll<msg::sensor_msgs::Range>(ir_[i], FullName(t, t.ir[i]), [&](const msg::sensor_msgs::Range& m) {
      ranges_[i] = RangeOf(m);
      ++counts_.ranges;
    });
  TakeGroundTruth();
  TakeAll<msg::rosgraph_msgs::Clock>(clock_, FullName(t, t.clock), [&](const msg::rosgraph_msgs::Clock& m) {
    sim_time_ = Seconds(m.clock);
    ++counts_.clock;
  });
}

// As an odometry message (the face's, a localisation's) or a pose (a motion-capture system's).
void Ros2Robot::TakeGroundTruth() {
  const std::string topic = FullName(settings_.topics, settings_.topics.ground_truth);
  if (settings_.topics.ground_truth_type == GroundTruthType::kPoseStamped)
    TakeAll<msg::geometry_msgs::PoseStamped>(truth_, topic, [&](const msg::geometry_msgs::PoseStamped& m) {
      ground_truth_ = PoseOf(m.pose);
      ++counts_.ground_truth;
    });
  else
    TakeAll<msg::nav_msgs::Odometry>(truth_, topic, [&](const msg::nav_msgs::Odometry& m) {
      ground_truth_ = PoseOf(m.pose.pose);
      ++counts_.ground_truth;
    });
}

std::optional<RangeScan> Ros2Robot::Ir() const {
  const auto& ir = sensors::DefaultFan(settings_.model, "ir");
  if (!ir || ranges_.empty()) return std::nullopt;
  RangeScan scan;
  scan.angles = ir->angles;
  scan.max_range = ir->max_range;
  for (const std::optional<double>& r : ranges_) {
    if (!r) return std::nullopt;
    scan.ranges.push_back(*r);
  }
  return scan;
}

void Ros2Robot::Drive(const Twist2D& velocity, double stamp) {
  if (settings_.topics.cmd_vel_type == CmdVelType::kTwistStamped) {
    msg::geometry_msgs::TwistStamped m;
    m.header.stamp = StampAt(stamp);
    m.header.frame_id = settings_.topics.ns.empty() ? "base_link" : settings_.topics.ns.substr(1) + "/base_link";
    m.twist = TwistOf(velocity);
    dds_.Write(cmd_vel_, ros2msg::Encode(m));
  } else {
    dds_.Write(cmd_vel_, ros2msg::Encode(TwistOf(velocity)));
  }
  ++counts_.cmd_vel;
}

namespace {

std::string Silent(const std::string& topic, const char* what, std::uint32_t incompatible) {
  std::string text = "nothing on " + topic + " (" + what + ")";
  if (incompatible)
    text += ": " + std::to_string(incompatible) +
            " publisher(s) there offer a QoS this reader cannot take (see qos: in the robot's file)";
  else
    text += ": is the topic's name right (--ros2-remap, the robot's file)?";
  return text;
}

}  // namespace

std::vector<std::string> Ros2Robot::TopicTrouble() {
  const RobotTopics& t = settings_.topics;
  std::vector<std::string> trouble;
  if (scan_ && counts_.scans == 0)
    trouble.push_back(Silent(FullName(t, t.scan), "the laser", dds_.IncompatibleWriters(scan_)));
  for (std::size_t i = 0; i < ir_.size(); ++i)
    if (!ranges_[i]) trouble.push_back(Silent(FullName(t, t.ir[i]), "an IR sensor", dds_.IncompatibleWriters(ir_[i])));
  if (truth_ && counts_.ground_truth == 0)
    trouble.push_back(
        Silent(FullName(t, t.ground_truth), "GroundTruth(), empty until it comes", dds_.IncompatibleWriters(truth_)));
  if (dds_.MatchedReaders(cmd_vel_) == 0)
    trouble.push_back("no one subscribes to " + FullName(t, t.cmd_vel) + " as " +
                      (t.cmd_vel_type == CmdVelType::kTwistStamped ? "TwistStamped" : "Twist") +
                      ": the robot does not move (a driver on the other type? --ros2-cmd-vel-stamped, "
                      "cmd_vel: {type: ...} in the robot's file)");
  return trouble;
}

}  // namespace sanet::ros2_agent
