// The headers of the result files that every mode writes alike (docs/scenario.md#results): a
// run's outputs and an agent's own folder on a ROS 2 robot, so that one reader reads both.
#pragma once

namespace sanet::trace {

constexpr const char* kLogHeader = "time,node,text";
constexpr const char* kTransitionsHeader = "time,node,from,to,why";
constexpr const char* kMetricsHeader = "time,node,name,value";
constexpr const char* kMessagesHeader = "time_sent,from,to,delivery,bytes,time_received,delay,hops";

}  // namespace sanet::trace
