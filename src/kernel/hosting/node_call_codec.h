// The values of Node calls as bytes, for a node whose calls cross a process boundary
// (hosting/isolated_controller.cc): Put writes a value, Get reads one back, for every argument and
// result type that include/sanet/node.h uses, so that a call list names types and nothing more.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "sanet/codec.h"
#include "sanet/node.h"

namespace sanet::hosting::node_calls {

inline void Put(Writer& w, double v) { w.F64(v); }
inline void Put(Writer& w, bool v) { w.Bool(v); }
inline void Put(Writer& w, std::uint32_t v) { w.U32(v); }
inline void Put(Writer& w, std::uint8_t v) { w.U8(v); }
inline void Put(Writer& w, int v) { w.I32(v); }
inline void Put(Writer& w, const std::string& v) { w.Text(v); }
inline void Put(Writer& w, const Twist2D& v) { w.F64(v.vx).F64(v.vy).F64(v.omega); }
inline void Put(Writer& w, const Pose2D& v) { w.F64(v.x).F64(v.y).F64(v.theta); }
inline void Put(Writer& w, const BearingReading& v) { w.F64(v.distance).F64(v.bearing); }
inline void Put(Writer& w, float v) { w.F64(v); }

// The readings of sanet/readings.h, member by member (Put and Get both go through Members).
inline auto Members(NodeBearing& v) { return std::tie(v.node, v.reading); }
inline auto Members(BearingsReading& v) { return std::tie(v.in_range); }
inline auto Members(Vector3& v) { return std::tie(v.x, v.y, v.z); }
inline auto Members(Quaternion& v) { return std::tie(v.x, v.y, v.z, v.w); }
inline auto Members(BatteryReading& v) {
  return std::tie(v.remaining_j, v.fraction, v.voltage, v.charging, v.capacity_j, v.power_w);
}
inline auto Members(ImuReading& v) {
  return std::tie(v.angular_velocity, v.linear_acceleration, v.orientation, v.angular_velocity_covariance,
                  v.linear_acceleration_covariance, v.orientation_covariance);
}
inline auto Members(FixReading& v) {
  return std::tie(v.latitude, v.longitude, v.altitude, v.status, v.position_covariance);
}
inline auto Members(JointStatesReading& v) { return std::tie(v.names, v.angles, v.speeds); }
inline auto Members(ImageReading& v) { return std::tie(v.width, v.height, v.encoding, v.data, v.depth); }
template <typename T>
using HasMembers = decltype(Members(std::declval<T&>()));

template <typename T>
void Put(Writer& w, const std::vector<T>& v);
template <typename T>
void Put(Writer& w, const std::optional<T>& v);
template <typename T, std::size_t N>
void Put(Writer& w, const std::array<T, N>& v);
template <typename... T>
void Put(Writer& w, const std::variant<T...>& v);
template <typename T, typename = HasMembers<T>>
void Put(Writer& w, const T& v);
inline void Put(Writer& w, const RangeScan& v);
inline void Put(Writer& w, const RouteEntry& v);
inline void Put(Writer& w, const Message& v);

template <typename T>
void Put(Writer& w, const std::vector<T>& v) {
  w.U32(static_cast<std::uint32_t>(v.size()));
  for (const T& x : v) Put(w, x);
}
template <typename T>
void Put(Writer& w, const std::optional<T>& v) {
  w.Bool(v.has_value());
  if (v) Put(w, *v);
}
template <typename T, std::size_t N>
void Put(Writer& w, const std::array<T, N>& v) {
  for (const T& x : v) Put(w, x);
}
template <typename... T>
void Put(Writer& w, const std::variant<T...>& v) {
  w.U8(static_cast<std::uint8_t>(v.index()));
  std::visit([&w](const auto& alternative) { Put(w, alternative); }, v);
}
template <typename T, typename>
void Put(Writer& w, const T& v) {
  std::apply([&w](const auto&... member) { (Put(w, member), ...); }, Members(const_cast<T&>(v)));
}
inline void Put(Writer& w, const RangeScan& v) {
  Put(w, v.angles);
  Put(w, v.ranges);
  w.F64(v.max_range);
}
inline void Put(Writer& w, const RouteEntry& v) {
  w.U32(v.destination).U32(v.next_hop).I32(v.hops).Bool(v.valid).F64(v.expires_in);
}
inline void Put(Writer& w, const Message& v) {
  w.U8(static_cast<std::uint8_t>(v.delivery)).U32(v.from).U32(v.to).F64(v.time_sent).F64(v.time_received);
  Put(w, v.hops);
  Put(w, v.payload);
}

// Get<T>(r): reads what Put(w, T) wrote. Without a specialisation, a reading read member by member.
template <typename T>
T Get(Reader& r);
template <typename T>
struct Codec {
  static T Read(Reader& r) {
    T v;
    std::apply([&r](auto&... member) { ((member = Get<std::decay_t<decltype(member)>>(r)), ...); }, Members(v));
    return v;
  }
};
template <typename T>
T Get(Reader& r) {
  return Codec<T>::Read(r);
}

template <>
struct Codec<double> {
  static double Read(Reader& r) { return r.F64(); }
};
template <>
struct Codec<bool> {
  static bool Read(Reader& r) { return r.Bool(); }
};
template <>
struct Codec<std::uint32_t> {
  static std::uint32_t Read(Reader& r) { return r.U32(); }
};
template <>
struct Codec<std::uint8_t> {
  static std::uint8_t Read(Reader& r) { return r.U8(); }
};
template <>
struct Codec<int> {
  static int Read(Reader& r) { return r.I32(); }
};
template <>
struct Codec<std::string> {
  static std::string Read(Reader& r) { return r.Text(); }
};
template <>
struct Codec<Twist2D> {
  static Twist2D Read(Reader& r) {
    Twist2D v;
    v.vx = r.F64(), v.vy = r.F64(), v.omega = r.F64();
    return v;
  }
};
template <>
struct Codec<Pose2D> {
  static Pose2D Read(Reader& r) {
    Pose2D p;
    p.x = r.F64(), p.y = r.F64(), p.theta = r.F64();
    return p;
  }
};
template <>
struct Codec<BearingReading> {
  static BearingReading Read(Reader& r) {
    BearingReading b;
    b.distance = r.F64(), b.bearing = r.F64();
    return b;
  }
};
template <>
struct Codec<float> {
  static float Read(Reader& r) { return static_cast<float>(r.F64()); }
};
template <typename T, std::size_t N>
struct Codec<std::array<T, N>> {
  static std::array<T, N> Read(Reader& r) {
    std::array<T, N> v;
    for (T& x : v) x = Get<T>(r);
    return v;
  }
};
// The alternative the index names; an index out of range reads as a bad packet.
template <typename... T>
struct Codec<std::variant<T...>> {
  static std::variant<T...> Read(Reader& r) {
    const std::size_t index = r.U8();
    std::variant<T...> out;
    std::size_t i = 0;
    const bool found = ((i++ == index ? (out = Get<T>(r), true) : false) || ...);
    if (!found) r.Fail();
    return out;
  }
};
template <typename T>
struct Codec<std::vector<T>> {
  static std::vector<T> Read(Reader& r) {
    std::vector<T> v(r.U32());
    if (!r.ok()) return {};
    for (T& x : v) x = Get<T>(r);
    return v;
  }
};
template <typename T>
struct Codec<std::optional<T>> {
  static std::optional<T> Read(Reader& r) { return r.Bool() ? std::optional<T>(Get<T>(r)) : std::nullopt; }
};
template <>
struct Codec<RangeScan> {
  static RangeScan Read(Reader& r) {
    RangeScan s;
    s.angles = Get<std::vector<double>>(r);
    s.ranges = Get<std::vector<double>>(r);
    s.max_range = r.F64();
    return s;
  }
};
template <>
struct Codec<RouteEntry> {
  static RouteEntry Read(Reader& r) {
    RouteEntry e;
    e.destination = r.U32(), e.next_hop = r.U32(), e.hops = r.I32(), e.valid = r.Bool(), e.expires_in = r.F64();
    return e;
  }
};
template <>
struct Codec<Message> {
  static Message Read(Reader& r) {
    Message m;
    m.delivery = static_cast<Delivery>(r.U8());
    m.from = r.U32(), m.to = r.U32(), m.time_sent = r.F64(), m.time_received = r.F64();
    m.hops = Get<std::optional<int>>(r);
    m.payload = Get<Bytes>(r);
    return m;
  }
};

// The arguments of a call, read in order (a braced list is evaluated left to right).
template <typename... Args>
std::tuple<Args...> GetAll(Reader& r) {
  return std::tuple<Args...>{Get<Args>(r)...};
}

}  // namespace sanet::hosting::node_calls
