// `sanet view RESULTS_DIR`: an HTTP server (cpp-httplib) on loopback that serves the viewer's page
// (src/front/view/page, compiled in), the JavaScript libraries it uses from Debian's packages (three.js,
// Chart.js) and the run's trace as JSON (/api/...), read by view::TraceReader, with the radios' ranges
// (view::RadioRanges).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "sim/run_spec.h"

namespace sanet::view {

struct ViewerSettings {
  std::string results;  // the results folder
  std::string bind = "127.0.0.1";
  int port = 8000;                                   // 0: any free port
  std::string javascript = "/usr/share/javascript";  // libjs-three, libjs-chart.js
  // The run's scenario (its results' scenario.yaml, loaded by the command, which knows the
  // scenario format), for the radios' ranges; throws saying why it cannot be had.
  std::function<sim::RunSpec()> scenario;
};

// Serves until `stop` (polled) returns true. `listening` gets the port once the server listens.
// Throws std::runtime_error when the results cannot be read or the port not bound.
void ServeViewer(const ViewerSettings& settings, const std::function<void(int port)>& listening,
                 const std::function<bool()>& stop);

}  // namespace sanet::view
