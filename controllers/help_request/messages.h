// The messages of the help-request case study (spec: case-study-help-request.md): a mote's
// help request, and robot and mote messages carrying the three booleans ra, ma and a.
#pragma once

#include <optional>

#include "sanet/codec.h"

namespace sanet::controllers::help {

enum class Kind : std::uint8_t { kRequest = 1, kRobot = 2, kMote = 3 };

struct HelpMessage {
  Kind kind = Kind::kRequest;
  bool ra = false;      // robot: takes the request / is looking for next hops (false: gives up)
  bool ma = false;      // mote: puts the robot in charge (false: refuses or gives up)
  bool a = false;       // robot: has arrived
  double hop_time = 0;  // robot: the longest it expects to need for one hop (s)

  Bytes Encode() const {
    return Writer().U8(kMagic).U8(static_cast<std::uint8_t>(kind)).Bool(ra).Bool(ma).Bool(a).F64(hop_time).bytes();
  }
  static std::optional<HelpMessage> Decode(const Bytes& bytes) {
    Reader r(bytes);
    if (r.U8() != kMagic) return std::nullopt;
    HelpMessage m;
    const std::uint8_t kind = r.U8();
    if (kind < 1 || kind > 3) return std::nullopt;
    m.kind = static_cast<Kind>(kind);
    m.ra = r.Bool();
    m.ma = r.Bool();
    m.a = r.Bool();
    m.hop_time = r.F64();
    if (!r.ok() || !r.at_end()) return std::nullopt;
    return m;
  }

 private:
  static constexpr std::uint8_t kMagic = 0x48;  // 'H'
};

}  // namespace sanet::controllers::help
