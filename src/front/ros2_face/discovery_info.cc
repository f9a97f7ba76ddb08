#include "ros2_face/discovery_info.h"

namespace sanet::ros2_face {
namespace {

// A Gid: the GUID, then zeros up to the distro's size (rmw_cyclonedds's convert_guid_to_gid
// zeroes the rmw_gid_t before copying the 16 bytes in).
void PutGid(ros2msg::CdrWriter& out, const DdsDomain::Guid& guid, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) out.Put(static_cast<std::uint8_t>(i < guid.size() ? guid[i] : 0));
}

void PutGids(ros2msg::CdrWriter& out, const std::vector<DdsDomain::Guid>& guids, std::size_t size) {
  out.PutCount(guids.size());
  for (const DdsDomain::Guid& g : guids) PutGid(out, g, size);
}

}  // namespace

std::size_t GidSize(sections::Ros2Distro distro) { return distro == sections::Ros2Distro::kHumble ? 24 : 16; }

ros2msg::Bytes EncodeParticipantEntitiesInfo(sections::Ros2Distro distro, const DdsDomain::Guid& participant,
                                             const std::vector<NodeEntities>& nodes) {
  const std::size_t size = GidSize(distro);
  ros2msg::CdrWriter out;
  PutGid(out, participant, size);
  out.PutCount(nodes.size());
  for (const NodeEntities& node : nodes) {
    out.PutString(node.node_namespace);
    out.PutString(node.node_name);
    PutGids(out, node.readers, size);
    PutGids(out, node.writers, size);
  }
  return out.Take();
}

DiscoveryInfo::DiscoveryInfo(DdsDomain& dds, sections::Ros2Distro distro)
    : dds_(dds), distro_(distro), writer_(dds.BareWriter(kDiscoveryTopic, kDiscoveryType, Qos::kDiscovery)) {}

void DiscoveryInfo::Update() {
  if (sent_ && dds_.EndpointCount() == endpoints_) return;
  const NodeEntities node{kNodeNamespace, kNodeName, dds_.ReaderGuids(), dds_.WriterGuids()};
  dds_.Write(writer_, EncodeParticipantEntitiesInfo(distro_, dds_.ParticipantGuid(), {node}));
  sent_ = true;
  endpoints_ = dds_.EndpointCount();
}

}  // namespace sanet::ros2_face
