// sanet's DDS participant, as a ROS 2 node's is: a ROS 2 topic /a/b is the DDS topic rt/a/b
// (rmw_cyclonedds namespace_prefix.hpp), its type the ROS 2 type's DDS name, its samples the
// CDR bytes of ros2msg's encoders (raw_cdr_type.h), its QoS one of the profiles ROS 2 uses.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "ros2msg/cdr.h"

struct dds_qos;
struct dds_listener;

namespace sanet::ros2_face {

// ROS 2's QoS profiles (rclcpp qos.hpp; tf2_ros qos.hpp).
enum class Qos {
  kDefault,     // reliable, volatile, keep last 10: cmd_vel, odom
  kSensorData,  // best effort, volatile, keep last 5: scan, ranges, ground truth
  kTf,          // reliable, volatile, keep last 100: /tf
  kTfStatic,    // reliable, transient local, keep last 1: /tf_static
  kClock,       // best effort, volatile, keep last 1: /clock
  // reliable, transient local, keep last 1, no autodispose: ros_discovery_info, as rmw_cyclonedds
  // makes that writer (rmw_node.cpp, rmw_context_impl_t::init and create_readwrite_qos)
  kDiscovery,
};

class DdsDomain {
 public:
  // Joins DDS domain `domain` (ROS_DOMAIN_ID), on the network interface `interface` (a name or
  // an IPv4 address) when one is given, else on those CYCLONEDDS_URI or Cyclone's own choice
  // give. Throws std::runtime_error saying why not.
  explicit DdsDomain(std::uint32_t domain, const std::string& interface = "");
  ~DdsDomain();
  DdsDomain(const DdsDomain&) = delete;
  DdsDomain& operator=(const DdsDomain&) = delete;

  using Entity = std::int32_t;
  // `ros_topic`: "/r1/odom"; `dds_type`: "nav_msgs::msg::dds_::Odometry_".
  Entity Writer(const std::string& ros_topic, const std::string& dds_type, Qos qos);
  Entity Reader(const std::string& ros_topic, const std::string& dds_type, Qos qos);
  // A writer on a DDS topic outside ROS 2's names (no rt/ prefix), as rmw's own
  // ros_discovery_info; not one of the node's writers below.
  Entity BareWriter(const std::string& dds_topic, const std::string& dds_type, Qos qos);
  void Write(Entity writer, const ros2msg::Bytes& sample);

  // A sample taken from a reader, and the writer it came from (DDS's publication handle).
  struct Sample {
    ros2msg::Bytes bytes;
    std::uint64_t writer = 0;
  };
  std::vector<Sample> Take(Entity reader, std::size_t most = 64);
  // Writers that asked for this reader but whose QoS cannot match it, since the last call.
  std::uint32_t NewIncompatibleWriters(Entity reader);
  // Readers that match this writer now (same topic, type and compatible QoS).
  std::uint32_t MatchedReaders(Entity writer);
  // Writers that offered this reader a QoS it cannot take (or whose type differs), so far.
  std::uint32_t IncompatibleWriters(Entity reader);
  std::uint32_t domain() const { return domain_; }

  // DDS GUIDs (dds_get_guid: the participant's prefix and the entity's id), which ROS 2 takes as
  // gids: the participant's, and those of every writer and reader made by Writer and Reader.
  using Guid = std::array<std::uint8_t, 16>;
  Guid ParticipantGuid() const;
  std::vector<Guid> WriterGuids() const;
  std::vector<Guid> ReaderGuids() const;
  // How many writers and readers Writer and Reader have made (none is ever deleted).
  std::size_t EndpointCount() const { return writers_.size() + readers_.size(); }

 private:
  Entity Topic(const std::string& dds_topic, const std::string& dds_type);
  // A writer or a reader (`create`), its QoS that of `qos`; throws saying what it could not do.
  Entity Endpoint(Entity (*create)(Entity, Entity, const ::dds_qos*, const ::dds_listener*), const char* what,
                  const std::string& dds_topic, const std::string& dds_type, Qos qos);
  std::uint32_t domain_;
  Entity domain_entity_ = 0;  // the domain this process made, when it chose the interface
  Entity participant_;
  std::vector<Entity> writers_, readers_;  // made by Writer and Reader
};

}  // namespace sanet::ros2_face
