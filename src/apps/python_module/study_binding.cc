#include "python_module/study_binding.h"

#include <pybind11/stl.h>

#include "study/report.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace sanet::python_module {
namespace {

// sanet report's table: (series, value, runs, mean, ci_low, ci_high, median) per point.
py::list Summary(const study::StudyReader& reader, const std::string& metric, const std::string& by) {
  py::list rows;
  for (const study::Series& series : study::Summarise(reader, metric, by))
    for (const study::Point& p : series.points)
      rows.append(py::make_tuple(series.label, p.x, p.stats.count, p.stats.mean, p.stats.mean - p.stats.half_width,
                                 p.stats.mean + p.stats.half_width, p.median));
  return rows;
}

// (name, runs, nodes) per metric, folded over the nodes unless `per_node`.
py::list Metrics(const study::StudyReader& reader, bool per_node) {
  py::list rows;
  for (const auto& m : reader.Metrics(per_node)) rows.append(py::make_tuple(m.name, m.runs, m.nodes));
  return rows;
}

}  // namespace

void BindStudyReader(py::module_& m) {
  py::register_exception<study::ReportError>(m, "ReportError", PyExc_ValueError);
  py::class_<study::StudyReader>(m, "StudyReader", "A study's database, as `sanet report` reads it (sanet.Study)")
      .def(py::init<const std::string&>(), "where"_a)
      .def("parameters", &study::StudyReader::parameters)
      .def("metrics", &Metrics, "per_node"_a = false)
      .def("define", &study::StudyReader::Define, "name"_a, "expression"_a)
      .def("values", &study::StudyReader::Values, "metric"_a)
      .def("summarise", &Summary, "metric"_a, "by"_a = "");
}

}  // namespace sanet::python_module
