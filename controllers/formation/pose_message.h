// The leader's pose, as broadcast at 10 Hz and relayed by followers (case study 2).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sanet/codec.h"
#include "sanet/geometry.h"
#include "sanet/node.h"

namespace sanet::controllers::formation {

struct PoseMessage {
  std::uint32_t sequence = 0;
  double time = 0;  // s, when the leader measured it
  Pose2D pose;

  Bytes Encode() const {
    return Writer().U8(kMagic).U32(sequence).F64(time).F64(pose.x).F64(pose.y).F64(pose.theta).bytes();
  }
  static std::optional<PoseMessage> Decode(const Bytes& bytes) {
    Reader r(bytes);
    if (r.U8() != kMagic) return std::nullopt;
    PoseMessage m;
    m.sequence = r.U32();
    m.time = r.F64();
    m.pose = {r.F64(), r.F64(), r.F64()};
    if (!r.ok() || !r.at_end()) return std::nullopt;
    return m;
  }

 private:
  static constexpr std::uint8_t kMagic = 0x50;  // 'P'
};

// Node ids of `names`; throws naming the controller when one does not exist.
inline std::vector<NodeId> Resolve(Node& node, const std::vector<std::string>& names, const char* who) {
  std::vector<NodeId> ids;
  for (const std::string& name : names) {
    const auto id = node.Lookup(name);
    if (!id) throw std::runtime_error(std::string(who) + ": no node named '" + name + "'");
    ids.push_back(*id);
  }
  return ids;
}

}  // namespace sanet::controllers::formation
