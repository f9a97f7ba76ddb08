#include "ros2_face/ros2_face.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "ros2_presentation/sensor_messages.h"
#include "ros2_presentation/urdf_frames.h"
#include "ros2msg/codec.h"

namespace sanet::ros2_face {
namespace {

constexpr const char* kOwner = "ROS 2 face";
constexpr double kClockPeriod = 0.005;  // s: /clock at 200 Hz at least, at every step when steps are longer

template <typename Message>
const char* DdsType() {
  return msg::TypeOf<Message>::kDdsName;
}

}  // namespace

struct Ros2Face::Robot {
  NodeId id;
  std::string name;
  RobotFrames frames;
  Pose2D start;
  std::shared_ptr<const robots::UrdfSource> urdf;  // a robot from a URDF: its description and links
  DdsDomain::Entity cmd_vel = 0, description = 0;
  std::map<std::string, std::vector<DdsDomain::Entity>> sensors;  // by instance: a writer per topic
  sim::FreshSamples fresh;  // the samples of sensors on their own clocks already published
  double period = 0.1;      // s between its sensor messages
  double next_sensors = 0;
  std::uint64_t last_writer = 0;
  double last_writer_at = -1e9;  // simulated time of its last sample
  double last_command = -1;      // simulated time of the last cmd_vel taken; -1 once stopped by the timeout
  std::set<std::string> said;    // what this robot's log has been told once
  std::uint64_t published = 0, commands = 0, refused_owned = 0, undecodable = 0, not_finite = 0, writer_switches = 0,
                timeouts = 0, incompatible = 0;
};

Ros2Face::Ros2Face(sim::Driver& driver, Ros2Settings settings)
    : driver_(driver),
      settings_(settings),
      dds_(settings.domain, settings.interface),
      discovery_(dds_, settings.distro) {
  clock_ = dds_.Writer("/clock", DdsType<msg::rosgraph_msgs::Clock>(), Qos::kClock);
  tf_ = dds_.Writer("/tf", DdsType<msg::tf2_msgs::TFMessage>(), Qos::kTf);
  tf_static_ = dds_.Writer("/tf_static", DdsType<msg::tf2_msgs::TFMessage>(), Qos::kTfStatic);
  AddRobots();
}

Ros2Face::~Ros2Face() = default;

// Topics for every robot the face has not seen yet (spawned ones too); /tf_static again, whole.
void Ros2Face::AddRobots() {
  for (NodeId id = static_cast<NodeId>(nodes_seen_); id < driver_.NodeCount(); ++id) {
    const sim::NodeSpec& node = driver_.Spec(id);
    if (!robots::HasDrive(node.model)) continue;
    auto r = std::make_unique<Robot>();
    r->id = id;
    r->name = node.name;
    r->period = settings_.sensor_period;
    std::string name = node.name;  // its namespace and frame prefix
    for (const sections::Ros2Robot& own : settings_.robots)
      if (own.robot == node.name) {
        if (!own.ns.empty()) name = own.ns;
        if (own.rate > 0) r->period = 1 / own.rate;
      }
    if (!sections::IsRosName(name)) {
      const std::string why = "robot '" + node.name +
                              "': its name is no ROS name (letters, digits, _); give it a namespace in the scenario's "
                              "ros2.robots";
      if (nodes_seen_ == 0) throw std::runtime_error(why);  // at start: an error; later (spawned): left out
      std::fprintf(stderr, "sanet: ROS 2: %s (left out)\n", why.c_str());
      continue;
    }
    r->frames = FramesOf(name);
    r->start = node.pose;
    const std::string ns = "/" + name;
    for (const auto& [instance, config] : sensors::PresentationOrder(node.model))
      if (const ros2_presentation::SensorMessages* kind = ros2_presentation::MessagesOf(config->kind))
        for (const ros2_presentation::SensorTopic& t : kind->Topics(instance, config->settings))  // 0: the record's
          r->sensors[instance].push_back(
              t.on_face ? dds_.Writer(ns + "/" + t.name, t.dds_type, t.reliable ? Qos::kDefault : Qos::kSensorData)
                        : 0);
    Describe(*r, node, ns);
    r->cmd_vel = dds_.Reader(
        ns + "/cmd_vel",
        settings_.twist_stamped ? DdsType<msg::geometry_msgs::TwistStamped>() : DdsType<msg::geometry_msgs::Twist>(),
        Qos::kDefault);
    any_urdf_ |= r->urdf != nullptr;
    robots_.push_back(std::move(r));
  }
  nodes_seen_ = driver_.NodeCount();
  std::map<NodeId, RobotFrames> frames;
  for (const auto& r : robots_) frames[r->id] = r->frames;
  dds_.Write(tf_static_,
             ros2msg::Encode(StaticTransforms(
                 driver_.NodeCount(), [this](NodeId id) -> const sim::NodeSpec& { return driver_.Spec(id); }, frames)));
}

// A robot from a URDF: its text on /<robot>/robot_description, latched (reliable, transient local,
// keep last 1, as robot_state_publisher's), its links with the face's /tf_static and /tf.
void Ros2Face::Describe(Robot& r, const sim::NodeSpec& node, const std::string& ns) {
  if (!node.model.urdf) return;
  r.urdf = node.model.urdf;
  r.description = dds_.Writer(ns + "/robot_description", DdsType<msg::std_msgs::String>(), Qos::kTfStatic);
  msg::std_msgs::String description;
  description.data = r.urdf->text;
  dds_.Write(r.description, ros2msg::Encode(description));
}

// The URDF robots' wheel joints at their wheels' angles, once a sensor period.
void Ros2Face::PublishWheels(const sim::WorldSnapshot& snapshot) {
  if (snapshot.time() + 1e-9 < next_wheels_) return;
  next_wheels_ = snapshot.time() + settings_.sensor_period;
  msg::tf2_msgs::TFMessage tf;
  for (const auto& r : robots_) {
    if (!r->urdf || r->id >= snapshot.bodies().size()) continue;
    const auto wheels = ros2_presentation::UrdfWheelTransforms(*r->urdf, r->frames, snapshot.time(),
                                                               snapshot.bodies()[r->id].wheel_angles)
                            .transforms;
    tf.transforms.insert(tf.transforms.end(), wheels.begin(), wheels.end());
  }
  if (!tf.transforms.empty()) dds_.Write(tf_, ros2msg::Encode(tf));
}

void Ros2Face::Start() {
  driver_.Every(settings_.command_period, [this] { Poll(); });
  step_ended_ = driver_.bus().On<sim::StepEnded>(sim::RunStage::kObserve,
                                                 [this](const sim::StepEnded& e) { AfterStep(e.world); });
}

void Ros2Face::AfterStep(const sim::WorldSnapshot& snapshot) {
  if (any_urdf_) PublishWheels(snapshot);
  if (snapshot.time() + 1e-9 < next_clock_) return;
  next_clock_ = snapshot.time() + kClockPeriod;
  msg::rosgraph_msgs::Clock clock;
  clock.clock = StampOf(snapshot.time());
  dds_.Write(clock_, ros2msg::Encode(clock));
  ++clock_messages_;
}

void Ros2Face::Poll() {
  if (driver_.NodeCount() != nodes_seen_) AddRobots();
  discovery_.Update();  // the robots' topics, once made
  const double now = driver_.Now();
  for (auto& r : robots_) {
    TakeCommands(*r);
    if (now + 1e-9 >= r->next_sensors) {
      r->next_sensors = now + r->period;
      Publish(*r);
    }
  }
}

// The robot's readings: the face's own read when nobody drives it, else its owner's last one.
void Ros2Face::Publish(Robot& r) {
  const auto owner = driver_.OwnerOf(r.id);
  const bool mine = !owner && !driver_.Claim(r.id, kOwner);
  const sim::SensorReadings& readings = mine ? driver_.TakeReadings(r.id, kOwner) : driver_.LastReadings(r.id);
  if (mine) driver_.Release(r.id, kOwner);
  if (readings.time < 0) return;  // its owner has read nothing yet
  msg::tf2_msgs::TFMessage tf;
  tf.transforms.push_back(OdomToBase(readings.time, readings.odometry(), r.start, r.frames));
  dds_.Write(tf_, ros2msg::Encode(tf));
  ++r.published;
  ros2_presentation::MessageContext context{readings.time, &r.frames, r.start, readings.ground_truth,
                                            readings.velocity};
  const robots::SensorConfigs& sensors = driver_.Spec(r.id).model.sensors;
  for (const auto& [instance, reading] : readings.by_instance) {
    const auto writers = r.sensors.find(instance);
    const auto config = sensors.find(instance);
    if (writers == r.sensors.end() || config == sensors.end() || !r.fresh.TakeIfNew(instance, readings)) continue;
    context.time = readings.SampledAt(instance).value_or(readings.time);  // as a driver stamps: when taken
    for (const ros2_presentation::SensorMessage& m :
         ros2_presentation::MessagesOf(config->second.kind)
             ->Messages(instance, config->second.settings, reading, context)) {
      const DdsDomain::Entity writer = writers->second.at(m.topic);
      if (!writer) continue;
      dds_.Write(writer, m.cdr);
      ++r.published;
    }
  }
}

void Ros2Face::TakeCommands(Robot& r) {
  for (const DdsDomain::Sample& s : dds_.Take(r.cmd_vel)) Apply(r, s);
  if (const std::uint32_t n = dds_.NewIncompatibleWriters(r.cmd_vel)) {
    r.incompatible += n;
    SayOnce(r, "qos",
            "a cmd_vel publisher whose QoS cannot reach this robot (best effort? the face takes cmd_vel reliable, as "
            "ROS 2's default profile)");
  }
  StopIfQuiet(r);
}

// As ROS 2's diff_drive_controller: no cmd_vel for cmd_vel_timeout, and the robot stops.
void Ros2Face::StopIfQuiet(Robot& r) {
  if (settings_.cmd_vel_timeout <= 0 || r.last_command < 0) return;
  if (driver_.Now() - r.last_command < settings_.cmd_vel_timeout) return;
  r.last_command = -1;
  if (driver_.OwnerOf(r.id) || driver_.Claim(r.id, kOwner)) return;  // another front end drives it now
  driver_.NodeOf(r.id, kOwner).Drive({});
  driver_.Release(r.id, kOwner);
  ++r.timeouts;
}

void Ros2Face::Apply(Robot& r, const DdsDomain::Sample& s) {
  std::string error;
  std::optional<msg::geometry_msgs::Twist> twist;
  if (settings_.twist_stamped) {
    if (const auto stamped = ros2msg::Decode<msg::geometry_msgs::TwistStamped>(s.bytes, &error)) twist = stamped->twist;
  } else {
    twist = ros2msg::Decode<msg::geometry_msgs::Twist>(s.bytes, &error);
  }
  if (!twist) {
    ++r.undecodable;
    return SayOnce(r, "undecodable", "a cmd_vel sample that does not decode: " + error + " (further ones counted)");
  }
  // Publishers taking turns within a second of each other: one after another is no fight.
  const double now = driver_.Now();
  if (r.last_writer && s.writer != r.last_writer && now - r.last_writer_at < 1.0) {
    ++r.writer_switches;
    SayOnce(r, "writers", "cmd_vel from more than one publisher at once: the last one wins (switches counted)");
  }
  r.last_writer = s.writer;
  r.last_writer_at = now;
  if (const auto owner = driver_.OwnerOf(r.id); owner && *owner != kOwner) {
    ++r.refused_owned;
    return SayOnce(r, "owned", "cmd_vel refused: " + *owner + " drives this robot (further ones counted)");
  }
  if (driver_.Claim(r.id, kOwner)) return;
  const Twist2D v{twist->linear.x, twist->linear.y, twist->angular.z};
  r.last_command = driver_.Now();
  if (!driver_.NodeOf(r.id, kOwner).Drive(v))
    ++r.not_finite;  // the node logs why
  else
    ++r.commands;
  driver_.Release(r.id, kOwner);
}

void Ros2Face::SayOnce(Robot& r, const std::string& what, const std::string& text) {
  if (!r.said.insert(what).second) return;
  driver_.Log(r.id, "ROS 2: " + text);
  std::fprintf(stderr, "sanet: ROS 2 %s: %s\n", r.name.c_str(), text.c_str());
}

std::vector<std::string> Ros2Face::Driven() const {
  std::vector<std::string> names;
  for (const auto& r : robots_)
    if (r->commands > 0) names.push_back(r->name);
  return names;
}

nlohmann::ordered_json Ros2Face::Summary() const {
  nlohmann::ordered_json j = {{"domain", dds_.domain()}, {"clock_messages", clock_messages_}};
  for (const auto& r : robots_)
    j["robots"][r->name] = {{"published", r->published},
                            {"cmd_vel_taken", r->commands},
                            {"cmd_vel_refused_owned", r->refused_owned},
                            {"cmd_vel_undecodable", r->undecodable},
                            {"cmd_vel_not_finite", r->not_finite},
                            {"cmd_vel_publisher_switches", r->writer_switches},
                            {"cmd_vel_incompatible_publishers", r->incompatible},
                            {"stopped_by_cmd_vel_timeout", r->timeouts}};
  return j;
}

}  // namespace sanet::ros2_face
