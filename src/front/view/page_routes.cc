#include "view/page_routes.h"

#include <sys/socket.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "view/page_files.h"

namespace sanet::view {
namespace {

const char* ContentType(const std::string& name) {
  if (name.size() > 5 && name.substr(name.size() - 5) == ".html") return "text/html; charset=utf-8";
  if (name.size() > 4 && name.substr(name.size() - 4) == ".css") return "text/css";
  return "application/javascript";
}

// Debian's builds of the libraries the page loads: /lib/NAME -> file under `javascript`.
const std::map<std::string, std::string>& Libraries() {
  static const std::map<std::string, std::string> libraries = {
      {"three.min.js", "three/three.min.js"},
      {"OrbitControls.js", "three/examples/js/controls/OrbitControls.js"},
      {"chart.min.js", "chart.js/chart.min.js"}};
  return libraries;
}

}  // namespace

void CheckLibraries(const std::string& root) {
  for (const auto& [name, path] : Libraries())
    if (!std::filesystem::exists(root + "/" + path))
      throw std::runtime_error(root + "/" + path +
                               " is missing: install libjs-three and libjs-chart.js (./setup does)");
}

void AddPageRoutes(httplib::Server& server, const std::string& javascript) {
  for (const auto& [name, content] : PageFiles()) {
    const std::string path = name == "index.html" ? "/" : "/" + name;
    server.Get(path, [&content = content, type = ContentType(name)](const httplib::Request&, httplib::Response& r) {
      r.set_content(content, type);
    });
  }
  for (const auto& [name, file] : Libraries())
    server.Get("/lib/" + name, [path = javascript + "/" + file](const httplib::Request&, httplib::Response& r) {
      std::ifstream in(path);
      std::stringstream text;
      text << in.rdbuf();
      r.set_content(text.str(), "application/javascript");
    });
}

void ListenAlone(httplib::Server& server) {
  server.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, reinterpret_cast<const void*>(&yes), sizeof yes);
  });
}

}  // namespace sanet::view
