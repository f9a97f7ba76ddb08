// The face as a node in ROS 2's graph, so that `ros2 node list` shows it. ROS 2's DDS middlewares
// tell each other which nodes a participant holds, and which readers and writers each node has,
// on a DDS topic of their own; what `ros2 node list` lists comes from there (rmw_dds_common,
// graph_cache.cpp: update_participant_entities, get_node_names). What rmw_cyclonedds does,
// release by release (ros2/rmw_cyclonedds, rmw_node.cpp, branches humble and jazzy):
// - the topic is `ros_discovery_info`, without ROS 2's `rt/` prefix (its QoS sets
//   avoid_ros_namespace_conventions), of type rmw_dds_common/msg/ParticipantEntitiesInfo, whose
//   DDS name is rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_;
// - its writer is reliable, transient local, keep last 1 (and no autodispose), so that a
//   participant that joins later still reads the last sample;
// - a gid is the entity's Cyclone GUID (dds_get_guid, 16 bytes) copied into a zeroed rmw_gid_t,
//   whose data is RMW_GID_STORAGE_SIZE bytes (ros2/rmw, rmw/types.h): 24 in Humble, so the GUID
//   and 8 zero bytes, and 16 from Iron on;
// - the message is published again, whole, whenever the participant's nodes or their readers and
//   writers change; the ros_discovery_info writer itself belongs to no node.
// The messages (ros2/rmw_dds_common, rmw_dds_common/msg/*.msg, branches humble, iron, jazzy):
//   Gid: char[24] data (Humble), char[16] data (Iron, Jazzy); a .msg char is an IDL uint8
//     (ros2/rosidl, rosidl_adapter: MSG_TYPE_TO_IDL), so a fixed array of bytes in CDR;
//   NodeEntitiesInfo: string<=256 node_namespace, string<=256 node_name, Gid[] reader_gid_seq,
//     Gid[] writer_gid_seq;
//   ParticipantEntitiesInfo: Gid gid, NodeEntitiesInfo[] node_entities_info_seq.
// A Humble sample and a Jazzy one share the type name, so DDS matches them, and neither release
// reads the other's: the distro must be chosen (ros2.distro).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ros2_face/dds_domain.h"
#include "ros2msg/cdr.h"
#include "sections/ros2_section.h"

namespace sanet::ros2_face {

inline constexpr const char* kDiscoveryTopic = "ros_discovery_info";
inline constexpr const char* kDiscoveryType = "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_";
// The face's node: `ros2 node list` shows /sanet (a node in the root namespace "/", as rcl
// names one started without a namespace).
inline constexpr const char* kNodeNamespace = "/";
inline constexpr const char* kNodeName = "sanet";

// rmw_dds_common/msg/NodeEntitiesInfo, its gids as DDS GUIDs.
struct NodeEntities {
  std::string node_namespace, node_name;
  std::vector<DdsDomain::Guid> readers, writers;
};

// The Gid's size in `distro`: 24 bytes in Humble, 16 in Jazzy.
std::size_t GidSize(sections::Ros2Distro distro);
// rmw_dds_common/msg/ParticipantEntitiesInfo of `distro` in CDR, as its rmw writes it.
ros2msg::Bytes EncodeParticipantEntitiesInfo(sections::Ros2Distro distro, const DdsDomain::Guid& participant,
                                             const std::vector<NodeEntities>& nodes);

// Publishes the participant's one node, with every reader and writer the domain has made, on
// ros_discovery_info; again whenever they change.
class DiscoveryInfo {
 public:
  // Creates the writer; throws std::runtime_error as DdsDomain does.
  DiscoveryInfo(DdsDomain& dds, sections::Ros2Distro distro);
  // Publishes when the domain has made readers or writers since it last did (and at the first
  // call); cheap otherwise.
  void Update();

 private:
  DdsDomain& dds_;
  sections::Ros2Distro distro_;
  DdsDomain::Entity writer_;
  bool sent_ = false;
  std::size_t endpoints_ = 0;  // the domain's endpoints when last published
};

}  // namespace sanet::ros2_face
