// The one message of a robot that keeps a sensor network alive: a mote's battery report,
//   report  mote -> robot  its charge (fraction of the capacity), whether it is charging, and
//                          where it is (x, y), when it was measured
// sent over the multi-hop network (a lost report is a mote the robot does not know is low).
#pragma once

#include <cstdint>
#include <optional>

#include "sanet/codec.h"
#include "sanet/geometry.h"

namespace sanet::controllers::charging {

constexpr std::uint8_t kReport = 1;

struct Report {
  double fraction = 0;
  bool charging = false;
  Vec2 position;
  double time = 0;  // s, simulated, when the mote measured it
};

inline Bytes ReportMessage(const Report& r) {
  return Writer()
      .U8(kReport)
      .F64(r.fraction)
      .U8(r.charging ? 1 : 0)
      .F64(r.position.x)
      .F64(r.position.y)
      .F64(r.time)
      .bytes();
}

inline std::optional<Report> ReadReport(const Bytes& payload) {
  Reader in(payload);
  if (in.U8() != kReport) return std::nullopt;
  Report r;
  r.fraction = in.F64();
  r.charging = in.U8() != 0;
  r.position = {in.F64(), in.F64()};
  r.time = in.F64();
  if (!in.ok()) return std::nullopt;
  return r;
}

}  // namespace sanet::controllers::charging
