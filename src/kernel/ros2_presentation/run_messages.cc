#include "ros2_presentation/run_messages.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/delivery.h"
#include "ros2_presentation/sensor_messages.h"
#include "ros2_presentation/urdf_frames.h"
#include "ros2msg/codec.h"

namespace sanet::ros2_presentation {
namespace {

// Frames delivered within this many seconds of simulated time are drawn together, for as long.
constexpr double kRadioWindow = 0.25;

// A node's name as a ROS name token (letters, digits, underscores, not starting with a digit),
// so that every topic is one ROS 2 accepts: "P2DX-1" is published as "/P2DX_1/odom".
std::string RosToken(const std::string& name) {
  std::string token;
  for (const char c : name) token += std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '_';
  if (token.empty() || std::isdigit(static_cast<unsigned char>(token[0]))) token = "_" + token;
  return token;
}

// The time of a message in the log, as its header's stamp says it (StampOf).
std::uint64_t Nanoseconds(double t) {
  if (t <= 0) return 0;
  const msg::builtin_interfaces::Time stamp = StampOf(t);
  return static_cast<std::uint64_t>(stamp.sec) * 1000000000u + stamp.nanosec;
}

msg::rcl_interfaces::Log RosoutLine(double t, const std::string& node, const std::string& text) {
  msg::rcl_interfaces::Log line;
  line.stamp = StampOf(t);
  line.level = msg::rcl_interfaces::Log::INFO;
  line.name = node;
  line.msg = text;
  return line;
}

}  // namespace

RunMessages::RunMessages(const sim::RunSpec& spec, const sim::RunNodes& nodes) : spec_(spec), nodes_(nodes) {
  Statics(0);
}

void RunMessages::AddSink(MessageSink& sink) {
  sinks_.push_back(&sink);
  std::vector<const Topic*> in_order(topics_.size());
  for (const auto& [name, topic] : topics_) in_order[topic.id - 1] = &topic;
  for (const Topic* topic : in_order) {
    sink.Advertise(*topic);
    if (const auto last = latched_.find(topic->id); last != latched_.end())
      sink.Publish(*topic, last->second.first, last->second.second);
  }
}

const Topic& RunMessages::TopicOf(const std::string& name, const std::string& type, const std::string& definition) {
  if (const auto known = topics_.find(name); known != topics_.end()) return known->second;
  Topic& topic = topics_[name];
  topic.id = static_cast<std::uint32_t>(topics_.size());
  topic.name = name;
  topic.type = type;
  topic.definition = definition;
  const std::string description = "/robot_description";
  topic.latched = name == "/tf_static" || name == "/world" ||
                  (name.size() > description.size() &&
                   name.compare(name.size() - description.size(), description.size(), description) == 0);
  for (MessageSink* sink : sinks_) sink->Advertise(topic);
  return topic;
}

template <typename M>
const Topic& RunMessages::TopicOf(const std::string& name) {
  return TopicOf(name, ros2msg::TypeOf<M>::kName, ros2msg::TypeOf<M>::Definition());
}

bool RunMessages::Listened(const Topic& topic) const {
  return topic.latched || std::any_of(sinks_.begin(), sinks_.end(), [](MessageSink* s) { return s->Active(); });
}

void RunMessages::Publish(const Topic& topic, double t, const std::vector<std::uint8_t>& cdr) {
  if (topic.latched) latched_[topic.id] = {Nanoseconds(t), cdr};
  for (MessageSink* sink : sinks_) sink->Publish(topic, Nanoseconds(t), cdr);
}

template <typename M>
void RunMessages::Publish(const Topic& topic, double t, const M& message) {
  if (Listened(topic)) Publish(topic, t, ros2msg::Encode(message));
}

template <typename M>
void RunMessages::Publish(const std::string& name, double t, const M& message) {
  Publish(TopicOf<M>(name), t, message);
}

const RobotFrames& RunMessages::FramesOf(NodeId node) {
  while (frames_.size() <= node) {
    const sim::NodeSpec& n = nodes_[frames_.size()];
    frames_.push_back(ros2_presentation::FramesOf(n.name));
    if (!robots::HasDrive(n.model)) frames_.back().base = n.name;  // its frame in /tf_static
  }
  return frames_[node];
}

// Whether this is the node's first read of sensor `instance` at time `t` (a controller may read
// twice).
bool RunMessages::FirstAt(double t, NodeId node, const std::string& instance) {
  if (last_read_.size() <= node) last_read_.resize(node + 1);
  auto [at, added] = last_read_[node].try_emplace(instance, t);
  if (!added && at->second == t) return false;
  at->second = t;
  return true;
}

void RunMessages::Statics(double t) {
  // Motes' frames go in /tf instead (Pose): something may push a mote.
  msg::tf2_msgs::TFMessage statics = StaticTransforms(
      nodes_.size(), [this](NodeId id) -> const sim::NodeSpec& { return nodes_[id]; }, {}, t);
  auto& transforms = statics.transforms;
  transforms.erase(std::remove_if(transforms.begin(), transforms.end(),
                                  [this](const msg::geometry_msgs::TransformStamped& tf) {
                                    const auto node = nodes_.Find(tf.child_frame_id);
                                    return node && !robots::HasDrive(nodes_[*node].model);
                                  }),
                   transforms.end());
  Publish("/tf_static", t, statics);
  Publish("/world", t, WorldMarkers(spec_, nodes_, t));
  if (where_.empty()) AdvertiseShared();
  for (NodeId id = where_.size(); id < nodes_.size(); ++id) {
    where_.push_back({nodes_[id].pose.x, nodes_[id].pose.y});
    AdvertiseNode(id);
    DescribeRobot(id, t);
  }
}

// A robot brought as a URDF: its text on /<robot>/robot_description, latched, as ROS 2's
// robot_state_publisher gives it, for RViz's and Foxglove's robot-model panels.
void RunMessages::DescribeRobot(NodeId node, double t) {
  const auto& urdf = nodes_[node].model.urdf;
  if (!urdf) return;
  msg::std_msgs::String description;
  description.data = urdf->text;
  Publish("/" + RosToken(nodes_[node].name) + "/robot_description", t, description);
}

// Every topic is known before its first message, so that a live client can subscribe in time
// for it (a first log line, a first transition).
void RunMessages::AdvertiseShared() {
  TopicOf<msg::tf2_msgs::TFMessage>("/tf");
  TopicOf<msg::sanet_msgs::NetworkMessage>("/messages");
  TopicOf<msg::sanet_msgs::Transition>("/transitions");
  TopicOf<msg::sanet_msgs::Metric>("/metrics");
  TopicOf<msg::rcl_interfaces::Log>("/rosout");
  TopicOf<msg::sanet_msgs::NodeEvent>("/events");
  if (!spec_.network) return;
  TopicOf<msg::sanet_msgs::RadioFrame>("/radio/frames");
  TopicOf<msg::visualization_msgs::MarkerArray>("/radio/links");
  TopicOf<msg::sanet_msgs::RouteChange>("/routes");
}

// Each sensor instance's topics under /<node>/ (ros2_presentation/sensor_messages.h), in topic order.
void RunMessages::AdvertiseNode(NodeId node) {
  if (sensor_topics_.size() <= node) sensor_topics_.resize(node + 1);
  const std::string ns = "/" + RosToken(nodes_[node].name) + "/";
  for (const auto& [instance, config] : sensors::PresentationOrder(nodes_[node].model)) {
    const SensorMessages* kind = MessagesOf(config->kind);
    if (!kind) continue;
    std::vector<const Topic*>& topics = sensor_topics_[node][instance];
    for (const SensorTopic& t : kind->Topics(instance, config->settings))  // null: the face's alone
      topics.push_back(t.recorded ? &TopicOf(ns + t.name, t.type, t.definition) : nullptr);
  }
}

void RunMessages::Spawned(double t) { Statics(t); }

MessageContext RunMessages::ContextOf(double t, NodeId node, const Pose2D& pose, const Twist2D& velocity) {
  return {t, &FramesOf(node), nodes_[node].pose, pose, velocity, /*recording=*/true};
}

// The true pose on the node's ground truth topic, its body in /tf, and a URDF robot's wheels.
void RunMessages::Pose(double t, NodeId node, const Pose2D& pose, const Twist2D& velocity,
                       const std::array<double, 3>& wheel_angles) {
  FlushRadio(t);  // as time passes, not only at the next frame: the log stays in time order
  const RobotFrames& frames = FramesOf(node);
  PublishReading(node, "ground_truth", pose, ContextOf(t, node, pose, velocity));
  msg::tf2_msgs::TFMessage tf;
  if (!robots::HasDrive(nodes_[node].model))
    tf.transforms.push_back(Transform("world", frames.base, t, pose.x, pose.y, 0, pose.theta));
  else
    tf.transforms.push_back(OdomToBase(t, pose, nodes_[node].pose, frames));
  if (const auto& urdf = nodes_[node].model.urdf) {
    const auto wheels = UrdfWheelTransforms(*urdf, frames, t, wheel_angles).transforms;
    tf.transforms.insert(tf.transforms.end(), wheels.begin(), wheels.end());
  }
  Publish("/tf", t, tf);
  if (node < where_.size()) where_[node] = {pose.x, pose.y};
}

// The kind's own ground truth is the trajectory's (Pose), not the reads'; a battery's are the
// energy samples (Battery).
void RunMessages::Read(double t, NodeId node, const std::string& instance, const std::string& kind,
                       const SensorReading& reading, const sim::BodyState& body) {
  if ((instance == "ground_truth" && kind == "ground_truth") || kind == "battery") return;
  if (!FirstAt(t, node, instance)) return;
  PublishReading(node, instance, reading, ContextOf(t, node, body.pose, body.velocity));
}

void RunMessages::Battery(double t, NodeId node, const BatteryReading& battery) {
  PublishReading(node, "battery", battery, ContextOf(t, node, Pose2D{}, Twist2D{}));
}

void RunMessages::PublishReading(NodeId node, const std::string& instance, const SensorReading& reading,
                                 const MessageContext& context) {
  if (node >= sensor_topics_.size()) return;
  const auto topics = sensor_topics_[node].find(instance);
  const auto config = nodes_[node].model.sensors.find(instance);
  if (topics == sensor_topics_[node].end() || config == nodes_[node].model.sensors.end()) return;
  const SensorMessages* kind = MessagesOf(config->second.kind);
  const auto listened = [this](const Topic* t) { return t && Listened(*t); };
  if (!kind || std::none_of(topics->second.begin(), topics->second.end(), listened)) return;
  for (const SensorMessage& m : kind->Messages(instance, config->second.settings, reading, context))
    if (const Topic* topic = topics->second.at(m.topic)) Publish(*topic, context.time, m.cdr);
}

void RunMessages::Frame(const net::FrameEvent& f) {
  msg::sanet_msgs::RadioFrame frame;
  frame.stamp = StampOf(f.t);
  frame.node = nodes_.NameOf(f.node);
  frame.sent = f.sent;
  frame.peer = f.peer ? nodes_.NameOf(*f.peer) : "";
  frame.kind = f.kind;
  frame.bytes = f.bytes;
  Publish("/radio/frames", f.t, frame);
  FlushRadio(f.t);
  last_frame_ = f.t;
  if (!f.sent && f.peer && *f.peer < where_.size() && f.node < where_.size()) {
    const std::string kind = f.kind;
    // Where both stood when the frame crossed (the first frame of the pair in the window).
    auto [line, added] = radio_.try_emplace({*f.peer, f.node}, RadioLine{where_[*f.peer], where_[f.node], false});
    line->second.data |= kind == "data" || kind == "broadcast";
  }
}

// Draws the frames of the window that ended before `now`, stamped `now` so that the log stays
// in time order; they last one window.
void RunMessages::FlushRadio(double now) {
  if (now < radio_window_ + kRadioWindow) return;
  if (!radio_.empty()) {
    std::vector<RadioLine> lines;
    for (const auto& [pair, line] : radio_) lines.push_back(line);
    Publish("/radio/links", now, RadioMarkers(now, kRadioWindow, lines));
  }
  radio_.clear();
  radio_window_ = std::floor(now / kRadioWindow) * kRadioWindow;
}

void RunMessages::Message(double t, const sanet::Message& m, NodeId to, bool delivered) {
  msg::sanet_msgs::NetworkMessage out;
  out.stamp = StampOf(t);
  out.sender = nodes_.NameOf(m.from);
  out.receiver = nodes_.NameOf(to);
  out.delivery = DeliveryName(m.delivery);
  out.bytes = static_cast<std::uint32_t>(m.payload.size());
  out.sent = m.time_sent;
  out.received = delivered ? m.time_received : std::nan("");
  out.delay = delivered ? m.time_received - m.time_sent : std::nan("");
  out.hops = delivered && m.hops ? *m.hops : -1;
  Publish("/messages", t, out);
}

void RunMessages::Route(const sim::RouteChange& r) {
  msg::sanet_msgs::RouteChange out;
  out.stamp = StampOf(r.time);
  out.node = nodes_.NameOf(r.node);
  out.destination = nodes_.NameOf(r.destination);
  out.next_hop = r.next_hop ? nodes_.NameOf(*r.next_hop) : "";
  out.hops = r.next_hop ? r.hops : 0;
  Publish("/routes", r.time, out);
}

void RunMessages::Transition(double t, NodeId node, const std::string& from, const std::string& to,
                             const std::string& why) {
  msg::sanet_msgs::Transition out;
  out.stamp = StampOf(t);
  out.node = nodes_.NameOf(node);
  out.from_state = from;
  out.to_state = to;
  out.why = why;
  Publish("/transitions", t, out);
}

void RunMessages::Metric(double t, NodeId node, const std::string& name, double value) {
  msg::sanet_msgs::Metric out;
  out.stamp = StampOf(t);
  out.node = nodes_.NameOf(node);
  out.name = name;
  out.value = value;
  Publish("/metrics", t, out);
}

void RunMessages::Event(double t, NodeId node, const std::string& kind, const std::string& detail) {
  if (kind == "log") return Publish("/rosout", t, RosoutLine(t, nodes_.NameOf(node), detail));
  msg::sanet_msgs::NodeEvent out;
  out.stamp = StampOf(t);
  out.node = nodes_.NameOf(node);
  out.kind = kind;
  out.detail = detail;
  Publish("/events", t, out);
}

void RunMessages::Flush() { FlushRadio(last_frame_ + kRadioWindow); }

}  // namespace sanet::ros2_presentation
