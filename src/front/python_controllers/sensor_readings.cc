// The readings of sanet/readings.h as Python classes (read-only attributes, SI units, the names
// of the C++ fields), and Node.sensor's conversion of SensorReading into them.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python_controllers/controller_api.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace sanet::python_controllers {
namespace {

template <typename T>
py::tuple Tuple3(const T& v) {
  return py::make_tuple(v.x, v.y, v.z);
}

void BindMotionReadings(py::module_& m) {
  py::class_<NodeBearing>(m, "NodeBearing", "One node in a bearing sensor's range: node (id) and reading (Bearing)")
      .def_readonly("node", &NodeBearing::node)
      .def_readonly("reading", &NodeBearing::reading);
  py::class_<ImuReading>(m, "ImuReading",
                         "An IMU's reading: angular_velocity (rad/s) and linear_acceleration (m/s^2) as (x, y, z), "
                         "orientation as (x, y, z, w) or None, and 3x3 row-major covariances")
      .def_property_readonly("angular_velocity", [](const ImuReading& r) { return Tuple3(r.angular_velocity); })
      .def_property_readonly("linear_acceleration", [](const ImuReading& r) { return Tuple3(r.linear_acceleration); })
      .def_property_readonly("orientation",
                             [](const ImuReading& r) -> py::object {
                               if (!r.orientation) return py::none();
                               const Quaternion& q = *r.orientation;
                               return py::make_tuple(q.x, q.y, q.z, q.w);
                             })
      .def_readonly("angular_velocity_covariance", &ImuReading::angular_velocity_covariance)
      .def_readonly("linear_acceleration_covariance", &ImuReading::linear_acceleration_covariance)
      .def_readonly("orientation_covariance", &ImuReading::orientation_covariance)
      .def("__repr__", [](const ImuReading& r) {
        return py::str("ImuReading(angular_velocity={}, linear_acceleration={}, orientation={})")
            .format(Tuple3(r.angular_velocity), Tuple3(r.linear_acceleration),
                    r.orientation ? py::object(py::make_tuple(r.orientation->x, r.orientation->y, r.orientation->z,
                                                              r.orientation->w))
                                  : py::object(py::none()));
      });
  py::class_<JointStatesReading>(m, "JointStatesReading", "Joints: names, angles (rad) and speeds (rad/s)")
      .def_readonly("names", &JointStatesReading::names)
      .def_readonly("angles", &JointStatesReading::angles)
      .def_readonly("speeds", &JointStatesReading::speeds)
      .def("__repr__", [](const JointStatesReading& r) {
        return py::str("JointStatesReading(names={}, angles={}, speeds={})")
            .format(py::cast(r.names), py::cast(r.angles), py::cast(r.speeds));
      });
}

void BindOtherReadings(py::module_& m) {
  py::class_<BatteryReading>(m, "BatteryReading",
                             "A battery: remaining_j (J), fraction (of capacity), voltage (V), charging, capacity_j "
                             "(J), power_w (W drawn now)")
      .def_readonly("remaining_j", &BatteryReading::remaining_j)
      .def_readonly("fraction", &BatteryReading::fraction)
      .def_readonly("voltage", &BatteryReading::voltage)
      .def_readonly("charging", &BatteryReading::charging)
      .def_readonly("capacity_j", &BatteryReading::capacity_j)
      .def_readonly("power_w", &BatteryReading::power_w);
  py::class_<FixReading>(m, "FixReading",
                         "A satellite fix: latitude, longitude (degrees), altitude (m), status (-1 none, 0 fix, "
                         "1 SBAS, 2 GBAS), position_covariance (m^2, east-north-up, 3x3 row-major)")
      .def_readonly("latitude", &FixReading::latitude)
      .def_readonly("longitude", &FixReading::longitude)
      .def_readonly("altitude", &FixReading::altitude)
      .def_readonly("status", &FixReading::status)
      .def_readonly("position_covariance", &FixReading::position_covariance)
      .def("__repr__", [](const FixReading& r) {
        return py::str("FixReading(status={}, latitude={}, longitude={}, altitude={})")
            .format(r.status, r.latitude, r.longitude, r.altitude);
      });
  py::class_<ImageReading>(m, "ImageReading",
                           "A camera image: width, height, encoding, pixels (numpy, height x width x 3, uint8), "
                           "data (the same as bytes, rows top to bottom), depth (numpy, height x width, float32, m "
                           "along the optical axis, inf where nothing is; 0 x 0 without depth)")
      .def_readonly("width", &ImageReading::width)
      .def_readonly("height", &ImageReading::height)
      .def_readonly("encoding", &ImageReading::encoding)
      .def_property_readonly(
          "data",
          [](const ImageReading& r) { return py::bytes(reinterpret_cast<const char*>(r.data.data()), r.data.size()); })
      .def_property_readonly("pixels",
                             [](const ImageReading& r) {
                               return py::array_t<std::uint8_t>({r.height, r.width, 3}, r.data.data());
                             })
      .def_property_readonly("depth",
                             [](const ImageReading& r) {
                               const bool any = !r.depth.empty();
                               return py::array_t<float>({any ? r.height : 0, any ? r.width : 0}, r.depth.data());
                             })
      .def("__repr__", [](const ImageReading& r) {
        return py::str("ImageReading({} x {} {}{})")
            .format(r.width, r.height, r.encoding, r.depth.empty() ? "" : ", depth");
      });
}

}  // namespace

void BindSensorReadings(py::module_& m) {
  BindMotionReadings(m);
  BindOtherReadings(m);
}

py::object SensorToPython(const std::optional<SensorReading>& reading) {
  if (!reading) return py::none();
  return std::visit(
      [](const auto& value) -> py::object {
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, RangeScan>)
          return ScanOrNone(value);
        else if constexpr (std::is_same_v<T, BearingsReading>)
          return py::cast(value.in_range);
        else
          return py::cast(value);
      },
      *reading);
}

}  // namespace sanet::python_controllers
