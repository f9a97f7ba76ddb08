#include "view/viewer_server.h"

#include <httplib.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/json_text.h"
#include "view/camera_frames.h"
#include "view/page_routes.h"
#include "view/radio_ranges.h"
#include "view/trace_reader.h"

namespace sanet::view {
namespace {

double Number(const httplib::Request& request, const char* key, double fallback) {
  return request.has_param(key) ? std::stod(request.get_param_value(key)) : fallback;
}

void Json(httplib::Response& response, const nlohmann::json& body) {
  response.set_content(JsonText(body), "application/json");
}

void AddRangeRoutes(httplib::Server& server, RadioRanges& ranges) {
  server.Get("/api/radio_ranges", [&](const httplib::Request&, httplib::Response& r) { Json(r, ranges.Ranges()); });
  server.Get("/api/radio_range_shape", [&](const httplib::Request& q, httplib::Response& r) {
    Json(r, ranges.Shape(static_cast<std::size_t>(Number(q, "radio", 0)), Number(q, "x", 0), Number(q, "y", 0)));
  });
}

// The robots' recorded pictures: their times, and the picture at or before a time.
void AddCameraRoutes(httplib::Server& server, CameraFrames& cameras) {
  server.Get("/api/cameras", [&](const httplib::Request&, httplib::Response& r) { Json(r, cameras.Times()); });
  server.Get("/api/camera", [&](const httplib::Request& q, httplib::Response& r) {
    const auto picture = cameras.At(q.get_param_value("node"), Number(q, "t", 0));
    if (!picture) {
      r.status = 404;
      return r.set_content("no picture of that robot at or before that time in trace.mcap", "text/plain");
    }
    r.set_header("Cache-Control", "max-age=3600");  // a picture at a time never changes
    r.set_content(std::string(picture->second.begin(), picture->second.end()), "image/" + picture->first);
  });
}

// The run's scenario for the ranges, or why there is none.
std::unique_ptr<RadioRanges> StartRanges(const ViewerSettings& settings) {
  if (!settings.scenario)
    return std::make_unique<RadioRanges>(std::nullopt, "this viewer was not given the run's scenario");
  try {
    return std::make_unique<RadioRanges>(settings.scenario(), "");
  } catch (const std::exception& e) {
    return std::make_unique<RadioRanges>(std::nullopt, e.what());
  }
}

void AddRoutes(httplib::Server& server, const TraceReader& trace, const std::string& javascript) {
  AddPageRoutes(server, javascript);
  server.Get("/api/run", [&](const httplib::Request&, httplib::Response& r) { Json(r, trace.Run()); });
  server.Get("/api/poses", [&](const httplib::Request&, httplib::Response& r) { Json(r, trace.Poses()); });
  server.Get("/api/messages", [&](const httplib::Request&, httplib::Response& r) { Json(r, trace.Messages()); });
  server.Get("/api/transitions", [&](const httplib::Request&, httplib::Response& r) { Json(r, trace.Transitions()); });
  server.Get("/api/min_distance", [&](const httplib::Request&, httplib::Response& r) { Json(r, trace.MinDistance()); });
  server.Get("/api/energy", [&](const httplib::Request&, httplib::Response& r) { Json(r, trace.Energy()); });
  server.Get("/api/metrics", [&](const httplib::Request&, httplib::Response& r) { Json(r, trace.Metrics()); });
  server.Get("/api/frames", [&](const httplib::Request& q, httplib::Response& r) {
    Json(r, trace.Frames(Number(q, "from", 0), Number(q, "to", 0)));
  });
  server.Get("/api/routes",
             [&](const httplib::Request& q, httplib::Response& r) { Json(r, trace.RoutesAt(Number(q, "t", 0))); });
  server.set_exception_handler([](const httplib::Request&, httplib::Response& r, std::exception_ptr e) {
    try {
      std::rethrow_exception(e);
    } catch (const std::exception& error) {
      r.status = 400;
      r.set_content(error.what(), "text/plain");
    }
  });
}

}  // namespace

void ServeViewer(const ViewerSettings& settings, const std::function<void(int port)>& listening,
                 const std::function<bool()>& stop) {
  CheckLibraries(settings.javascript);
  const TraceReader trace(settings.results);
  const std::unique_ptr<RadioRanges> ranges = StartRanges(settings);
  httplib::Server server;
  AddRoutes(server, trace, settings.javascript);
  AddRangeRoutes(server, *ranges);
  CameraFrames cameras((std::filesystem::path(settings.results) / "trace.mcap").string());
  AddCameraRoutes(server, cameras);
  ListenAlone(server);
  const int port = settings.port == 0 ? server.bind_to_any_port(settings.bind)
                                      : (server.bind_to_port(settings.bind, settings.port) ? settings.port : -1);
  if (port < 0)
    throw std::invalid_argument("cannot listen on " + settings.bind + ":" + std::to_string(settings.port) +
                                " (is the port in use, or the address not this machine's?)");
  listening(port);
  std::thread watcher([&] {
    while (!stop()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    server.stop();
  });
  server.listen_after_bind();
  watcher.join();
}

}  // namespace sanet::view
