#include "python_controllers/controller_api.h"

#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/delivery.h"
#include "sanet/node.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace sanet::python_controllers {
namespace {

// A range scan as Python holds it: numpy copies, valid after the call that read them.
struct Scan {
  py::array_t<double> angles, ranges;
  double max_range = 0;
};

struct PyMessage {
  NodeId sender = 0;
  std::optional<NodeId> to;  // None for a broadcast or a flood
  std::string delivery;
  py::bytes payload;
  double time_sent = 0, time_received = 0;
  std::optional<int> hops;
};

}  // namespace

py::object ScanOrNone(const std::optional<RangeScan>& scan) {
  if (!scan) return py::none();
  return py::cast(Scan{py::array_t<double>(scan->angles.size(), scan->angles.data()),
                       py::array_t<double>(scan->ranges.size(), scan->ranges.data()), scan->max_range});
}

namespace {

// ---- Params: a read-only mapping that notes every read, so that unknown keys are found and
// `sanet list` can show what a Python controller reads, as for C++ controllers.

struct PyParams {
  const Params* params;  // null once the controller is built: a Params is read in __init__
  const Params& Open() const {
    if (!params) throw std::runtime_error("a controller's Params are read while it is built (in __init__), not later");
    return *params;
  }
};

[[noreturn]] void RaiseParamError(const std::string& key, const std::string& message, int line) {
  PyErr_SetObject(ParamErrorType().ptr(), py::make_tuple(key, message, line).ptr());
  throw py::error_already_set();
}

[[noreturn]] void Refuse(const std::string& key, const ParamValue& v, const std::string& why) {
  RaiseParamError(key, "parameter '" + key + "' " + why, v.line);
}

std::optional<double> AsNumber(const std::string& text) {
  char* end = nullptr;
  const double d = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(d)) return std::nullopt;
  return d;
}

std::optional<bool> AsFlag(const std::string& text) {
  if (text == "true" || text == "True" || text == "yes") return true;
  if (text == "false" || text == "False" || text == "no") return false;
  return std::nullopt;
}

// A scalar as YAML would read it: a whole number, a number, a boolean, else text.
py::object Guess(const std::string& text) {
  if (const auto d = AsNumber(text)) {
    if (*d == std::floor(*d) && text.find_first_of(".eE") == std::string::npos && std::fabs(*d) < 9e15)
      return py::int_(static_cast<long long>(*d));
    return py::float_(*d);
  }
  if (const auto b = AsFlag(text)) return py::bool_(*b);
  return py::str(text);
}

py::object GuessValue(const ParamValue& v) {
  if (v.shape == ParamValue::Shape::kScalar) return Guess(v.rows.at(0).at(0));
  py::list rows;
  for (const auto& row : v.rows) {
    py::list items;
    for (const std::string& s : row) items.append(Guess(s));
    rows.append(items);
  }
  return v.shape == ParamValue::Shape::kList ? rows[0] : py::object(rows);
}

const std::string& Scalar(const std::string& key, const ParamValue& v) {
  if (v.shape != ParamValue::Shape::kScalar) Refuse(key, v, "must be a single value, not a list");
  return v.rows.at(0).at(0);
}

// The value converted to the kind of `fallback` (a bool, int, float, str, list or None).
py::object Converted(const std::string& key, const ParamValue& v, const py::object& fallback) {
  if (py::isinstance<py::bool_>(fallback)) {
    const auto b = AsFlag(Scalar(key, v));
    if (!b) Refuse(key, v, "must be true or false, not '" + Scalar(key, v) + "'");
    return py::bool_(*b);
  }
  if (py::isinstance<py::int_>(fallback) || py::isinstance<py::float_>(fallback)) {
    const auto d = AsNumber(Scalar(key, v));
    if (!d) Refuse(key, v, "must be a number, not '" + Scalar(key, v) + "'");
    if (py::isinstance<py::float_>(fallback)) return py::float_(*d);
    if (*d != std::floor(*d))
      Refuse(key, v,
             "must be a whole number, as its default (" + py::str(fallback).cast<std::string>() +
                 ") is: a controller that takes any number writes its default as " +
                 py::str(fallback).cast<std::string>() + ".0");
    return py::int_(static_cast<long long>(*d));
  }
  if (py::isinstance<py::str>(fallback)) return py::str(Scalar(key, v));
  if ((py::isinstance<py::list>(fallback) || py::isinstance<py::tuple>(fallback)) &&
      v.shape == ParamValue::Shape::kScalar)
    Refuse(key, v, "must be a list");
  return GuessValue(v);
}

std::string KindOf(const py::object& fallback) {
  if (fallback.is_none()) return "any";
  if (py::isinstance<py::bool_>(fallback)) return "boolean";
  if (py::isinstance<py::int_>(fallback)) return "whole number";
  if (py::isinstance<py::float_>(fallback)) return "number";
  if (py::isinstance<py::str>(fallback)) return "text";
  return "list";
}

// A default as `sanet list` shows C++ controllers' ("false", "0.5", "robot").
std::string Shown(const py::object& fallback) {
  if (fallback.is_none()) return "none";
  if (py::isinstance<py::bool_>(fallback)) return fallback.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(fallback)) return fallback.cast<std::string>();
  if (py::isinstance<py::int_>(fallback) || py::isinstance<py::float_>(fallback)) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", fallback.cast<double>());
    return text;
  }
  return py::repr(fallback).cast<std::string>();
}

py::object Get(const PyParams& p, const std::string& key, const py::object& fallback) {
  const ParamValue* v = p.Open().Read(key, KindOf(fallback), Shown(fallback));
  return v ? Converted(key, *v, fallback) : fallback;
}

py::object Required(const PyParams& p, const std::string& key) {
  const ParamValue* v = p.Open().Read(key, "required", "required");
  if (!v) RaiseParamError(key, "parameter '" + key + "' is required", 0);
  return GuessValue(*v);
}

py::list Keys(const PyParams& p) {
  py::list keys;
  for (const auto& [key, value] : p.Open().All()) keys.append(key);
  return keys;
}

void BindParams(py::module_& m) {
  py::exec(R"(
class ParamError(ValueError):
    """A bad parameter: Params raises it; a controller raises it for a value it refuses.
    ParamError(key, message, line=0); sanet reports it with the scenario's file and line."""
    def __init__(self, key, message, line=0):
        super().__init__(message)
        self.key = key
        self.line = line
)",
           m.attr("__dict__"));
  py::class_<PyParams>(m, "Params", "A controller's parameters as the scenario gives them (read-only)")
      .def("get", &Get, "key"_a, "default"_a = py::none(),
           "The value of `key` converted to the type of `default` (bool, int, float, str, list), or `default`")
      .def("__getitem__", &Required, "key"_a, "The value of a required parameter (ParamError when absent)")
      .def("__contains__", [](const PyParams& p, const std::string& key) { return p.Open().Has(key); })
      .def("__len__", [](const PyParams& p) { return p.Open().All().size(); })
      .def("__iter__", [](const PyParams& p) { return py::iter(Keys(p)); })
      .def("keys", &Keys, "The keys the scenario gives (reading none)");
}

// ---- The node and what it reads.

void BindReadings(py::module_& m) {
  py::class_<Pose2D>(m, "Pose", "A pose on the ground: x, y (m), theta (rad, counter-clockwise from +x)")
      .def(py::init([](double x, double y, double theta) {
             return Pose2D{x, y, theta};
           }),
           "x"_a = 0, "y"_a = 0, "theta"_a = 0)
      .def_readonly("x", &Pose2D::x)
      .def_readonly("y", &Pose2D::y)
      .def_readonly("theta", &Pose2D::theta)
      .def("__iter__", [](const Pose2D& p) { return py::iter(py::make_tuple(p.x, p.y, p.theta)); })
      .def(py::pickle([](const Pose2D& p) { return py::make_tuple(p.x, p.y, p.theta); },
                      [](const py::tuple& t) {
                        return Pose2D{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>()};
                      }))
      .def("__repr__", [](const Pose2D& p) { return py::str("Pose(x={}, y={}, theta={})").format(p.x, p.y, p.theta); });
  py::class_<Scan>(m, "RangeScan", "Ranges in the robot frame: numpy arrays angles (rad) and ranges (m), max_range")
      .def_readonly("angles", &Scan::angles)
      .def_readonly("ranges", &Scan::ranges)
      .def_readonly("max_range", &Scan::max_range);
  py::class_<BearingReading>(m, "Bearing", "Where another node lies: distance (m), bearing (rad, robot frame)")
      .def_readonly("distance", &BearingReading::distance)
      .def_readonly("bearing", &BearingReading::bearing)
      .def("__repr__", [](const BearingReading& b) {
        return py::str("Bearing(distance={}, bearing={})").format(b.distance, b.bearing);
      });
  py::class_<RouteEntry>(m, "Route", "A routing table entry")
      .def_readonly("destination", &RouteEntry::destination)
      .def_readonly("next_hop", &RouteEntry::next_hop)
      .def_readonly("hops", &RouteEntry::hops)
      .def_readonly("valid", &RouteEntry::valid)
      .def_readonly("expires_in", &RouteEntry::expires_in)
      .def("__repr__", [](const RouteEntry& r) {
        return py::str("Route(destination={}, next_hop={}, hops={}, valid={}, expires_in={})")
            .format(r.destination, r.next_hop, r.hops, r.valid, r.expires_in);
      });
  py::class_<PyMessage>(m, "Message", "A message that reached this node")
      .def_readonly("sender", &PyMessage::sender)
      .def_readonly("to", &PyMessage::to)
      .def_readonly("delivery", &PyMessage::delivery)
      .def_readonly("payload", &PyMessage::payload)
      .def_readonly("time_sent", &PyMessage::time_sent)
      .def_readonly("time_received", &PyMessage::time_received)
      .def_readonly("hops", &PyMessage::hops);
}

void BindNetworkView(py::module_& m) {
  py::class_<NetworkView, std::unique_ptr<NetworkView, py::nodelete>>(m, "NetworkView",
                                                                      "The node's view of its network layer")
      .def("protocol", &NetworkView::Protocol)
      .def("routing_table", &NetworkView::RoutingTable)
      .def("neighbours", &NetworkView::Neighbours)
      .def("invalidate_route", &NetworkView::InvalidateRoute, "destination"_a)
      .def("request_route", &NetworkView::RequestRoute, "destination"_a);
}

void BindNode(py::module_& m) {
  py::class_<Node, std::unique_ptr<Node, py::nodelete>>(m, "Node", "The node a controller drives")
      .def("now", &Node::Now)
      .def("id", &Node::Id)
      .def("name", &Node::Name)
      .def("lookup", &Node::Lookup, "name"_a)
      .def("name_of", &Node::NameOf, "id"_a)
      .def("node_count", &Node::NodeCount)
      .def("ir", [](Node& n) { return ScanOrNone(n.Ir()); })
      .def("laser", [](Node& n) { return ScanOrNone(n.Laser()); })
      .def("odometry", &Node::Odometry)
      .def("ground_truth", &Node::GroundTruth)
      .def("bearing", &Node::Bearing, "target"_a)
      .def(
          "sensor", [](Node& n, const std::string& name) { return SensorToPython(n.Sensor(name)); }, "name"_a,
          "The sensor the scenario names `name` (a kind's name, or an instance's), None if the node has none")
      .def("set_radio_sleep", &Node::SetRadioSleep, "asleep"_a)
      .def(
          "drive",
          [](Node& n, double vx, double vy, double omega) {
            return n.Drive({vx, vy, omega});
          },
          "vx"_a = 0.0, "vy"_a = 0.0, "omega"_a = 0.0)
      .def("set_wheel_speeds", &Node::SetWheelSpeeds, "rad_per_s"_a)
      .def("holonomic", &Node::Holonomic)
      .def(
          "send", [](Node& n, NodeId to, const py::object& payload) { n.Send(to, BytesOf(payload)); }, "to"_a,
          "payload"_a)
      .def(
          "broadcast", [](Node& n, const py::object& payload) { n.Broadcast(BytesOf(payload)); }, "payload"_a)
      .def(
          "flood", [](Node& n, const py::object& payload) { n.Flood(BytesOf(payload)); }, "payload"_a)
      .def("network", &Node::Network, py::return_value_policy::reference)
      .def("random", &Node::Random)
      .def("log", &Node::Log, "text"_a)
      .def("transition", &Node::Transition, "from_state"_a, "to_state"_a, "why"_a = "")
      .def("metric", &Node::Metric, "name"_a, "value"_a);
}

}  // namespace

void BindControllerApi(py::module_& module) {
  module.doc() = "sanet's controller interface: the node a Python controller drives (docs/python.md)";
  BindParams(module);
  BindReadings(module);
  BindSensorReadings(module);
  BindNetworkView(module);
  BindNode(module);
}

// bytes, bytearray, memoryview and the like (a TypeError for text, which has no one encoding).
Bytes BytesOf(const py::object& payload) {
  if (py::isinstance<py::str>(payload))
    throw py::type_error("a payload is bytes, not text: encode it (\"...\".encode()) or build it with struct.pack");
  const auto bytes = py::reinterpret_steal<py::bytes>(PyBytes_FromObject(payload.ptr()));
  if (!bytes) throw py::error_already_set();
  const std::string text = bytes;
  return Bytes(text.begin(), text.end());
}

py::object ToPython(const Message& m) {
  PyMessage out{m.from,
                m.to == kBroadcast ? std::nullopt : std::optional<NodeId>(m.to),
                DeliveryName(m.delivery),
                py::bytes(reinterpret_cast<const char*>(m.payload.data()), m.payload.size()),
                m.time_sent,
                m.time_received,
                m.hops};
  return py::cast(std::move(out));
}

py::object ToPython(const Params& params) { return py::cast(PyParams{&params}); }

void Close(const py::object& params) { params.cast<PyParams&>().params = nullptr; }

py::object ParamErrorType() { return py::module_::import("sanet").attr("ParamError"); }

}  // namespace sanet::python_controllers
