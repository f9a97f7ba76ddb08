#include "ros2_agent/robot_topics.h"

#include <stdexcept>

#include "scenario/yaml_reader.h"
#include "sections/ros2_section.h"

namespace sanet::ros2_agent {
namespace {

// A ROS name: absolute ("/a/b") or relative ("a/b"), of parts ROS 2 accepts.
bool IsTopicName(const std::string& name) {
  return !name.empty() && sections::IsRosName(name[0] == '/' ? name.substr(1) : name);
}

Qos QosNamed(const scenario::Field& f) {
  const std::string text = f.Text();
  if (text == "reliable") return Qos::kDefault;
  if (text == "best_effort") return Qos::kSensorData;
  f.Fail("expected reliable or best_effort, not '" + text + "'");
}

std::string TopicNamed(const scenario::Field& f) {
  const std::string name = f.Text();
  if (!IsTopicName(name))
    f.Fail("'" + name +
           "' is no ROS topic name (parts of letters, digits and _ that do not start with a digit, "
           "split by /)");
  return name;
}

// `key: TOPIC` or `key: {topic: TOPIC, qos: reliable|best_effort}`, and `type: ...` where the key
// has a choice of types (`typed`): returns the type given, if any (the caller checks it).
std::string ReadTopic(const scenario::Field& f, Topic& topic, bool typed = false) {
  if (f.IsScalar()) {
    topic.name = TopicNamed(f);
    return "";
  }
  if (typed)
    f.ExpectKeys({"topic", "qos", "type"});
  else
    f.ExpectKeys({"topic", "qos"});  // one type only: odom, scan, ranges, clock
  if (const auto name = f.Get("topic")) topic.name = TopicNamed(*name);
  if (const auto qos = f.Get("qos")) topic.qos = QosNamed(*qos);
  const auto type = f.Get("type");
  return type ? type->Text() : "";
}

void ReadGroundTruth(const scenario::Field& f, RobotTopics& topics) {
  if (f.IsScalar() && f.Text() == "none") {
    topics.ground_truth_type = GroundTruthType::kNone;
    return;
  }
  const std::string type = ReadTopic(f, topics.ground_truth, true);
  topics.ground_truth_type = GroundTruthType::kOdometry;
  if (type == "pose_stamped") topics.ground_truth_type = GroundTruthType::kPoseStamped;
  if (!type.empty() && type != "pose_stamped" && type != "odometry")
    f.Require("type").Fail("expected odometry (nav_msgs/msg/Odometry) or pose_stamped (geometry_msgs/msg/PoseStamped)");
}

void ReadCmdVel(const scenario::Field& f, RobotTopics& topics) {
  const std::string type = ReadTopic(f, topics.cmd_vel, true);
  if (type == "twist_stamped") topics.cmd_vel_type = CmdVelType::kTwistStamped;
  if (type == "twist") topics.cmd_vel_type = CmdVelType::kTwist;
  if (!type.empty() && type != "twist" && type != "twist_stamped")
    f.Require("type").Fail(
        "expected twist (geometry_msgs/msg/Twist) or twist_stamped (geometry_msgs/msg/TwistStamped)");
}

void ReadIr(const scenario::Field& f, RobotTopics& topics) {
  const std::vector<scenario::Field> items = f.Items();
  if (items.size() != topics.ir.size())
    f.Fail("the robot's model has " + std::to_string(topics.ir.size()) + " IR sensors: give as many topics, not " +
           std::to_string(items.size()));
  for (std::size_t i = 0; i < items.size(); ++i) ReadTopic(items[i], topics.ir[i]);
}

}  // namespace

RobotTopics DefaultTopics(const std::string& name, std::size_t ir_count) {
  RobotTopics topics;
  topics.ns = "/" + name;
  for (std::size_t i = 0; i < ir_count; ++i) topics.ir.push_back({"ir_" + std::to_string(i), Qos::kSensorData});
  return topics;
}

void ReadRobotFile(const std::string& path, RobotTopics& topics) {
  const scenario::Field root = scenario::ParseYamlFile(path, "a robot's file");
  root.ExpectKeys(
      {"namespace", "odom", "scan", "ir", "ground_truth", "cmd_vel", "clock", "use_sim_time", "odom_timeout"});
  if (const auto ns = root.Get("namespace")) {
    const std::string text = ns->Text();
    if (!text.empty() && !IsTopicName(text)) ns->Fail("'" + text + "' is no ROS namespace");
    topics.ns = text.empty() || text[0] == '/' ? text : "/" + text;
  }
  if (const auto f = root.Get("odom")) ReadTopic(*f, topics.odom);
  if (const auto f = root.Get("scan")) ReadTopic(*f, topics.scan);
  if (const auto f = root.Get("ir")) ReadIr(*f, topics);
  if (const auto f = root.Get("ground_truth")) ReadGroundTruth(*f, topics);
  if (const auto f = root.Get("cmd_vel")) ReadCmdVel(*f, topics);
  if (const auto f = root.Get("clock")) ReadTopic(*f, topics.clock);
  if (const auto f = root.Get("use_sim_time")) topics.use_sim_time = f->Bool();
  if (const auto f = root.Get("odom_timeout")) topics.odom_timeout = f->NumberAbove(0, 60);
}

void Remap(const std::string& assignment, RobotTopics& topics) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos)
    throw std::invalid_argument("expected KEY=TOPIC (e.g. odom=/robot1/odom), not '" + assignment + "'");
  const std::string key = assignment.substr(0, equals), name = assignment.substr(equals + 1);
  if (key == "ground_truth" && name == "none") {
    topics.ground_truth_type = GroundTruthType::kNone;
    return;
  }
  if (!IsTopicName(name))
    throw std::invalid_argument("'" + name +
                                "' is no ROS topic name (parts of letters, digits and _ that do not start with a "
                                "digit, split by /)");
  Topic* topic = key == "odom"           ? &topics.odom
                 : key == "scan"         ? &topics.scan
                 : key == "ground_truth" ? &topics.ground_truth
                 : key == "cmd_vel"      ? &topics.cmd_vel
                 : key == "clock"        ? &topics.clock
                                         : nullptr;
  for (std::size_t i = 0; i < topics.ir.size() && !topic; ++i)
    if (key == "ir_" + std::to_string(i)) topic = &topics.ir[i];
  if (!topic)
    throw std::invalid_argument("'" + key + "' is none of odom, scan, ground_truth, cmd_vel, clock" +
                                (topics.ir.empty() ? "" : ", ir_0 to ir_" + std::to_string(topics.ir.size() - 1)));
  topic->name = name;
  if (key == "ground_truth" && topics.ground_truth_type == GroundTruthType::kNone)
    topics.ground_truth_type = GroundTruthType::kOdometry;
}

std::string FullName(const RobotTopics& topics, const Topic& topic) {
  return topic.name[0] == '/' ? topic.name : topics.ns + "/" + topic.name;
}

}  // namespace sanet::ros2_agent
