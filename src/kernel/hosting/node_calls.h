// Every Node and NetworkView call that a controller in another process makes, listed once and
// expanded into the call numbers, the child's proxy node and the parent's dispatcher
// (hosting/isolated_controller.cc). A call added to include/sanet/node.h is added here, and only
// here. Identity (Id, Name, NodeCount, Holonomic) travels with the first call instead.
//
// CALL(name, the proxy's override, result, (parameters), (arguments), const or nothing)
#pragma once

#define SANET_NODE_CALLS(CALL)                                                                                 \
  CALL(Now, Now, double, (), (), const)                                                                        \
  CALL(Lookup, Lookup, std::optional<NodeId>, (const std::string& name), (name), const)                        \
  CALL(NameOf, NameOf, std::string, (NodeId id), (id), const)                                                  \
  CALL(Sensor, Sensor, std::optional<SensorReading>, (const std::string& name), (name), )                      \
  CALL(Bearing, Bearing, std::optional<BearingReading>, (NodeId target), (target), )                           \
  CALL(Drive, ApplyDrive, bool, (const Twist2D& velocity), (velocity), )                                       \
  CALL(SetWheelSpeeds, ApplyWheelSpeeds, bool, (const std::vector<double>& rad_per_s), (rad_per_s), )          \
  CALL(Send, Send, void, (NodeId to, const Bytes& payload), (to, payload), )                                   \
  CALL(Broadcast, Broadcast, void, (const Bytes& payload), (payload), )                                        \
  CALL(Flood, Flood, void, (const Bytes& payload), (payload), )                                                \
  CALL(SetRadioSleep, SetRadioSleep, bool, (bool asleep), (asleep), )                                          \
  CALL(Random, Random, double, (), (), )                                                                       \
  CALL(Log, Log, void, (const std::string& text), (text), )                                                    \
  CALL(Transition, Transition, void, (const std::string& from, const std::string& to, const std::string& why), \
       (from, to, why), )                                                                                      \
  CALL(Metric, Metric, void, (const std::string& name, double value), (name, value), )

#define SANET_NETWORK_CALLS(CALL)                                                     \
  CALL(Protocol, Protocol, std::string, (), (), const)                                \
  CALL(RoutingTable, RoutingTable, std::vector<RouteEntry>, (), (), const)            \
  CALL(Neighbours, Neighbours, std::vector<NodeId>, (), (), const)                    \
  CALL(InvalidateRoute, InvalidateRoute, bool, (NodeId destination), (destination), ) \
  CALL(RequestRoute, RequestRoute, void, (NodeId destination), (destination), )
