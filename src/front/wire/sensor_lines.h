// A sensor kind's SEN lines in the robot protocol (USARSim's sensor messages, and sanet's
// extensions where USARSim has none): the robot server writes them from a reading, the agent
// reads them back into one. Each kind's folder holds its part, sensors/<kind>/<kind>_usarsim.cc,
// registered once (sensors/sensor_kinds.h).
//
// Frames: USARSim's is z down (x forward, y right, yaw clockwise), sanet's z up; y and yaw change
// sign at the boundary (UsarsimPose, SanetPose).
#pragma once

#include <any>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sanet/readings.h"
#include "sensors/sensor_kinds.h"
#include "wire/protocol.h"

namespace sanet::wire {

// What lines may refer to besides the reading: the time, the body's height, other nodes' names.
struct LineContext {
  double time = 0;    // s, simulated
  double height = 0;  // m, of the body's centre (USARSim's ground truth is 3D)
  std::function<std::string(NodeId)> name_of;
  std::function<std::optional<NodeId>(const std::string&)> lookup;
};

class SensorLines {
 public:
  virtual ~SensorLines() = default;
  // The SEN lines of one reading of instance `instance` (none where the kind has no line).
  virtual std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                             const LineContext& context) const = 0;
  // Whether a SEN line is instance `instance`'s (of this kind).
  virtual bool IsFrom(const ProtocolMessage& line, const std::string& instance) const = 0;
  // The reading a line carries; `settings` are the instance's from the scenario (what the line
  // leaves out, such as a laser's range). Empty for a line it cannot read.
  virtual std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& settings,
                                            const LineContext& context) const = 0;
  // Whether the lines are sanet's extension, sent only to clients that said SANET.
  virtual bool Extension() const { return false; }
};

#define SANET_DECLARE_SENSOR_LINES(name, Name) const SensorLines& Name##SensorLines();
SANET_SENSOR_KINDS(SANET_DECLARE_SENSOR_LINES)
#undef SANET_DECLARE_SENSOR_LINES

// The part of kind `kind`; null for a kind without one.
const SensorLines* LinesOf(const std::string& kind);

std::vector<double> UsarsimPose(const Pose2D& pose);  // {x, y, yaw} in USARSim's frame
Pose2D SanetPose(double x, double y, double yaw);     // back to sanet's
// The SEN line's head: {Time t} {Type type}.
ProtocolMessage SenLine(double time, const std::string& type);
// "laser_rear" for a named instance, `usarsim_name` ("Scanner1") for the kind's own. Instance
// names start with a lower-case letter (scenario/sensor_fields.cc), USARSim's with a capital.
std::string WireName(const std::string& instance, const std::string& kind, const std::string& usarsim_name);
// Whether `line` is of SEN type `type` and names `instance` ({Name ...}, as WireName gives it).
bool NamesInstance(const ProtocolMessage& line, const std::string& type, const std::string& instance,
                   const std::string& kind, const std::string& usarsim_name);

}  // namespace sanet::wire
