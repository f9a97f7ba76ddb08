// The controller interface (include/sanet/) as Python sees it, in the module `sanet`: the node a
// controller drives (the C++ Node's calls in snake_case: now, id, name, lookup, name_of,
// node_count, sensor, ir, laser, odometry, ground_truth, bearing, drive, set_wheel_speeds,
// holonomic, send, broadcast, flood, set_radio_sleep, network, random, log, transition, metric),
// its readings (Pose, RangeScan with numpy arrays, Bearing, and python/sensor_readings.cc's), its network view
// (NetworkView, Route), messages (Message), the parameters a controller is built with (Params: a read-only mapping that
// notes what the controller reads) and ParamError. docs/python.md documents each.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>

#include "sanet/message.h"
#include "sanet/params.h"
#include "sanet/readings.h"

namespace sanet::python_controllers {

// A range scan as the Python classes give it (numpy arrays), None for none.
pybind11::object ScanOrNone(const std::optional<RangeScan>& scan);
// Node.sensor's answer: the reading as its Python class (python/sensor_readings.cc), None for none.
pybind11::object SensorToPython(const std::optional<SensorReading>& reading);
// Adds the reading classes of sanet/readings.h beyond RangeScan, Pose and Bearing.
void BindSensorReadings(pybind11::module_& module);

// Adds the classes above to `module` (the embedded `sanet` module; the extension module too).
void BindControllerApi(pybind11::module_& module);

// A message as Python receives it.
pybind11::object ToPython(const Message& message);

// The parameters as Python's Params, which refers to `params` until Close (then reading them
// raises an error naming the rule: parameters are read while the controller is built).
pybind11::object ToPython(const Params& params);
void Close(const pybind11::object& params);

// A payload from bytes, bytearray or memoryview (a TypeError for text, which has no one encoding).
Bytes BytesOf(const pybind11::object& payload);

// The Python class ParamError (key, line, message) that controllers raise for bad parameters.
pybind11::object ParamErrorType();

}  // namespace sanet::python_controllers
