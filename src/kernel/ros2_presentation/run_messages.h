// A run's events as ROS 2 messages, for its sinks: the MCAP log (trace.mcap, which ros2 bag,
// Foxglove, Lichtblick and PlotJuggler open) and live Foxglove streams. Every message is CDR from
// the ROS 2 message layer (ros2msg), built by the functions the ROS 2 face publishes with
// (ros2_presentation/robot_messages.h), at the simulated time of its event. Readings are those the run took (a
// controller's, the server's, the face's), handed over as they were read: the messages never
// read a sensor. docs/mcap.md lists the topics and types.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hosting/simulated_node.h"
#include "net/network_traces.h"
#include "ros2_presentation/message_sink.h"
#include "ros2_presentation/robot_messages.h"
#include "ros2_presentation/sensor_messages.h"
#include "ros2_presentation/world_markers.h"
#include "sim/run_events.h"
#include "sim/run_nodes.h"
#include "sim/run_spec.h"
#include "sim/snapshot.h"

namespace sanet::ros2_presentation {

class RunMessages {
 public:
  // Publishes what stands at time 0 (/tf_static, the world's markers) to the sinks added later.
  RunMessages(const sim::RunSpec& spec, const sim::RunNodes& nodes);
  // From now on `sink` gets every message; it is told of every topic so far and gets the last
  // message of the latched ones.
  void AddSink(MessageSink& sink);

  // A robot joined at `t`: /tf_static and the world's markers again, with it.
  void Spawned(double t);
  // A true pose the trace records (a row of trajectories.csv), and the wheels' angles (rad).
  void Pose(double t, NodeId node, const Pose2D& pose, const Twist2D& velocity,
            const std::array<double, 3>& wheel_angles = {});
  // A reading a node's driver took: published on its instance's topics by its kind's part
  // (ros2_presentation/sensor_messages.h).
  void Read(double t, NodeId node, const std::string& instance, const std::string& kind, const SensorReading& reading,
            const sim::BodyState& body);
  // A battery at an energy sample, on the node's `battery` sensor's topic if it carries one.
  void Battery(double t, NodeId node, const BatteryReading& battery);
  void Frame(const net::FrameEvent& frame);
  // An application message at `t` (when it was delivered, or reached a radio but no controller).
  void Message(double t, const sanet::Message& m, NodeId to, bool delivered);
  void Route(const sim::RouteChange& change);
  void Transition(double t, NodeId node, const std::string& from, const std::string& to, const std::string& why);
  void Metric(double t, NodeId node, const std::string& name, double value);
  // A line of a node's log ("log") or something that happened to it (switch-off, spawn).
  void Event(double t, NodeId node, const std::string& kind, const std::string& detail);
  // Sends what waits to be sent (the radio's last window).
  void Flush();

 private:
  template <typename M>
  void Publish(const std::string& topic, double t, const M& message);
  const Topic& TopicOf(const std::string& name, const std::string& type, const std::string& definition);
  template <typename M>
  const Topic& TopicOf(const std::string& name);
  template <typename M>
  void Publish(const Topic& topic, double t, const M& message);
  void Publish(const Topic& topic, double t, const std::vector<std::uint8_t>& cdr);
  bool Listened(const Topic& topic) const;  // latched, or a sink is active
  const RobotFrames& FramesOf(NodeId node);
  bool FirstAt(double t, NodeId node, const std::string& instance);
  MessageContext ContextOf(double t, NodeId node, const Pose2D& pose, const Twist2D& velocity);
  void PublishReading(NodeId node, const std::string& instance, const SensorReading& reading,
                      const MessageContext& context);
  void FlushRadio(double until);
  void Statics(double t);
  void AdvertiseShared();
  void AdvertiseNode(NodeId node);
  void DescribeRobot(NodeId node, double t);

  const sim::RunSpec& spec_;
  const sim::RunNodes& nodes_;
  std::vector<MessageSink*> sinks_;
  std::map<std::string, Topic> topics_;                                                   // by name
  std::vector<std::map<std::string, std::vector<const Topic*>>> sensor_topics_;           // by node and instance
  std::map<std::uint32_t, std::pair<std::uint64_t, std::vector<std::uint8_t>>> latched_;  // by topic id
  std::vector<RobotFrames> frames_;
  std::vector<std::map<std::string, double>> last_read_;  // per node and instance: when it was read last
  std::vector<Vec2> where_;                               // per node: where it stood last, for the radio's lines
  std::map<std::pair<NodeId, NodeId>, RadioLine> radio_;  // by sender and receiver, in the window
  double last_frame_ = 0;                                 // s, the last frame's time
  double radio_window_ = 0;                               // s, the current window's start
};

}  // namespace sanet::ros2_presentation
