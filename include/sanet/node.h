// The abstract node a controller sees: identity, time, sensors, actuators, messages and a view
// of its network layer. The simulated node (physics + network simulation) and the remote node
// (sensors over the simulation protocol, messages over real UDP) both implement it, so a
// controller written against this header runs unchanged in every mode.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sanet/geometry.h"
#include "sanet/message.h"
#include "sanet/readings.h"

namespace sanet {

// One entry of the node's routing table.
struct RouteEntry {
  NodeId destination = 0;
  NodeId next_hop = 0;
  int hops = 0;
  bool valid = false;
  double expires_in = 0;  // s until the routing protocol drops the entry
};

// Read-mostly view of the node's own network layer.
class NetworkView {
 public:
  virtual ~NetworkView() = default;
  virtual std::string Protocol() const = 0;  // "none" when there is no routing layer
  virtual std::vector<RouteEntry> RoutingTable() const = 0;
  virtual std::vector<NodeId> Neighbours() const = 0;
  // Marks the route to `destination` invalid so the protocol rediscovers it. False where the
  // protocol offers no such operation.
  virtual bool InvalidateRoute(NodeId destination) = 0;
  // Starts a route discovery towards `destination` (by sending towards it).
  virtual void RequestRoute(NodeId destination) = 0;
};

class Node {
 public:
  virtual ~Node() = default;

  // Identity and time.
  virtual double Now() const = 0;  // s since the start of the run
  virtual NodeId Id() const = 0;
  virtual const std::string& Name() const = 0;
  virtual std::optional<NodeId> Lookup(const std::string& name) const = 0;
  virtual std::string NameOf(NodeId id) const = 0;  // "" for an unknown id
  virtual std::size_t NodeCount() const = 0;

  // Sensors. Sensor(name) reads the sensor the scenario names `name` (a kind's own name, such as
  // "laser", for its default instance; or an instance's name, such as "laser_rear"): empty when
  // the node has no sensor of that name. Which reading type a kind gives is listed by
  // `sanet list --sensors`; SensorAs<T> reads one and keeps it only if it is a T.
  virtual std::optional<SensorReading> Sensor(const std::string& name) = 0;
  template <typename T>
  std::optional<T> SensorAs(const std::string& name) {
    std::optional<SensorReading> reading = Sensor(name);
    if (!reading) return std::nullopt;
    if (T* value = std::get_if<T>(&*reading)) return std::move(*value);
    return std::nullopt;
  }
  // The default instances of the first kinds, as before Sensor(name).
  std::optional<RangeScan> Ir() { return SensorAs<RangeScan>("ir"); }
  std::optional<RangeScan> Laser() { return SensorAs<RangeScan>("laser"); }
  std::optional<Pose2D> Odometry() { return SensorAs<Pose2D>("odometry"); }         // from wheel rotation
  std::optional<Pose2D> GroundTruth() { return SensorAs<Pose2D>("ground_truth"); }  // the true pose
  // One node's bearing, read on its own (Sensor("bearing") reads every node in range): empty
  // without a bearing sensor or when `target` is out of its range.
  virtual std::optional<BearingReading> Bearing(NodeId target) = 0;

  // Actuators. Drive takes a body velocity in the robot frame (vx forward, vy left, omega
  // counter-clockwise); a differential drive ignores vy. Both return false on a node that
  // cannot move, and refuse a command that holds a NaN or an infinity (false, the node's log
  // says why, the motors keep the last command they took). The check is made here, once, for
  // every kind of node; what passes it goes to ApplyDrive / ApplyWheelSpeeds.
  bool Drive(const Twist2D& velocity) {
    if (!std::isfinite(velocity.vx) || !std::isfinite(velocity.vy) || !std::isfinite(velocity.omega)) {
      Log("drive refused: a velocity that is not a finite number (the motors keep their last command)");
      return false;
    }
    return ApplyDrive(velocity);
  }
  bool SetWheelSpeeds(const std::vector<double>& rad_per_s) {
    for (double w : rad_per_s)
      if (!std::isfinite(w)) {
        Log("wheel speeds refused: a speed that is not a finite number (the motors keep their last command)");
        return false;
      }
    return ApplyWheelSpeeds(rad_per_s);
  }
  // True for a holonomic drive (omni3), which honours vy.
  virtual bool Holonomic() const = 0;

  // Messages: unicast (routed where the network routes), one-hop broadcast, and flooding
  // through the whole network (every node relays it once).
  virtual void Send(NodeId to, const Bytes& payload) = 0;
  virtual void Broadcast(const Bytes& payload) = 0;
  virtual void Flood(const Bytes& payload) = 0;
  virtual NetworkView& Network() = 0;
  // Puts the node's radio to sleep (true) or wakes it (false), as the MAC's power save does:
  // asleep, it neither receives nor transmits, and what the node sends meanwhile is queued or
  // dropped as its MAC does (docs/controllers.md says which, per mode). False where the node's
  // radio cannot sleep (the node's log says why).
  virtual bool SetRadioSleep(bool asleep) = 0;

  // A uniform random number in [0, 1) from this node's own seeded stream: the same run
  // draws the same numbers.
  virtual double Random() = 0;

  // A line in the run's log, log.csv (time and node are added). Free text for people: nothing
  // reads it back.
  virtual void Log(const std::string& text) = 0;

  // Typed events, which results and viewers read:
  // a state machine's step (transitions.csv, and the node's state in the world's snapshots),
  virtual void Transition(const std::string& from, const std::string& to, const std::string& why) = 0;
  // a measurement (metrics.csv; quartiles per node and name in summary.json).
  virtual void Metric(const std::string& name, double value) = 0;

 protected:
  // A kind of node's own part of Drive and SetWheelSpeeds, for commands of finite numbers only.
  virtual bool ApplyDrive(const Twist2D& velocity) = 0;
  virtual bool ApplyWheelSpeeds(const std::vector<double>& rad_per_s) = 0;
};

}  // namespace sanet
