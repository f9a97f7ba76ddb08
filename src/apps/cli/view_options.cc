#include "view_options.h"

#include <cstdio>
#include <filesystem>

#include "core/atomic_file.h"

namespace sanet::cli {

void AddViewOptions(CLI::App* cmd, ViewArgs& v) {
  CLI::Option* view =
      cmd->add_flag("--view", v.on,
                    "Stream a live view of the run to a web page and to Foxglove, on loopback (docs/viewer.md, "
                    "docs/foxglove.md)");
  cmd->add_option("--view-port", v.port, "The live view's HTTP port (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  cmd->add_option("--view-port-file", v.port_file, "Once the live view listens, write its port to this file");
  AddFoxgloveOptions(cmd, v.foxglove, /*replay=*/false);
  if (cmd->get_name() == "run")  // sanet serve streams to Foxglove with or without the page
    for (const char* name :
         {"--foxglove-port", "--foxglove-port-file", "--foxglove-max-clients", "--foxglove-queue-mb"})
      cmd->get_option(name)->needs(view);
}

void AddFoxgloveOptions(CLI::App* cmd, FoxgloveArgs& f, bool replay) {
  f.port_option =
      cmd->add_option("--foxglove-port", f.port,
                      "The Foxglove WebSocket port (foxglove.websocket.v1; 0: any free port; the default, if "
                      "taken, gives way to a free one); Foxglove and Lichtblick connect to ws://127.0.0.1:PORT")
          ->check(CLI::Range(0, 65535))
          ->capture_default_str();
  cmd->add_option("--foxglove-port-file", f.port_file, "Once the Foxglove stream listens, write its port to this file");
  cmd->add_option("--foxglove-max-clients", f.max_clients, "Foxglove clients connected at once; the next is refused")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--foxglove-queue-mb", f.queue_mb,
                  "MB waiting to be sent to one Foxglove client; a client that lets more pile up (it stopped "
                  "reading) is dropped, and the run never waits for it")
      ->check(CLI::Range(0.01, 4096.0))
      ->capture_default_str();
  if (replay)
    cmd->add_option("--speed", f.speed, "The Foxglove replay's pace, in simulated seconds per second")
        ->check(CLI::Range(0.001, 10000.0))
        ->capture_default_str();
}

void WritePortFile(const std::string& path, std::uint16_t port, const char* option) {
  try {
    if (!path.empty()) WriteFileAtomically(path, std::to_string(port) + "\n");
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError(option, e.what());  // names the file and the system's reason
  }
}

namespace {

// On the port asked for or the default one; the default being taken, on a free one, and `notice`
// says so.
template <typename T>
std::unique_ptr<T> Listening(const FoxgloveArgs& f, std::string& notice) {
  foxglove::HubSettings settings;
  settings.port = f.port;
  settings.limits.max_clients = static_cast<std::size_t>(f.max_clients);
  settings.limits.max_queued_bytes = static_cast<std::size_t>(f.queue_mb * 1e6);
  try {
    return std::make_unique<T>(settings);
  } catch (const std::runtime_error& e) {
    if (f.port_option && f.port_option->count() > 0) throw CLI::ValidationError("--foxglove-port", e.what());
  }
  settings.port = 0;  // the default port is taken (another run's stream): any free one
  notice =
      "sanet: the Foxglove port " + std::to_string(f.port) + " is taken (another run streams?); a free one instead:";
  try {
    return std::make_unique<T>(settings);
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError("--foxglove-port", e.what());
  }
}

}  // namespace

std::unique_ptr<foxglove::FoxgloveHub> StartHub(const FoxgloveArgs& f) {
  std::string notice;
  std::unique_ptr<foxglove::FoxgloveHub> hub = Listening<foxglove::FoxgloveHub>(f, notice);
  if (!notice.empty()) std::printf("%s\n", notice.c_str());
  return hub;
}

void LiveViews::Announce() const {
  if (page) std::printf("sanet: live view at http://127.0.0.1:%d/\n", page->port());
  if (!foxglove_notice.empty()) std::printf("%s\n", foxglove_notice.c_str());
  if (foxglove) std::printf("sanet: Foxglove stream at ws://127.0.0.1:%d\n", foxglove->hub().port());
  std::fflush(stdout);
}

static std::unique_ptr<foxglove::FoxgloveLive> StartFoxglove(sim::World& world,
                                                             ros2_presentation::RunPresentation& presentation,
                                                             const FoxgloveArgs& f, std::string& notice) {
  std::unique_ptr<foxglove::FoxgloveLive> live = Listening<foxglove::FoxgloveLive>(f, notice);
  WritePortFile(f.port_file, static_cast<std::uint16_t>(live->hub().port()), "--foxglove-port-file");
  live->Observe(world.bus(), presentation);
  return live;
}

LiveViews StartLiveViews(sim::World& world, ros2_presentation::RunPresentation& presentation, const ViewArgs& v,
                         bool foxglove_anyway) {
  LiveViews views;
  if (!v.on) {
    if (foxglove_anyway) views.foxglove = StartFoxglove(world, presentation, v.foxglove, views.foxglove_notice);
    return views;
  }
  // First: a port refused stops nothing started.
  views.foxglove = StartFoxglove(world, presentation, v.foxglove, views.foxglove_notice);
  view::LiveSettings settings;
  settings.port = v.port;
  try {
    views.page = std::make_unique<view::LiveView>(world.spec(), settings);
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError("--view", e.what());
  }
  WritePortFile(v.port_file, static_cast<std::uint16_t>(views.page->port()), "--view-port-file");
  views.page->Observe(world.bus());
  return views;
}

std::unique_ptr<foxglove::McapReplay> StartReplay(const std::string& results, foxglove::FoxgloveHub& hub,
                                                  const FoxgloveArgs& f) {
  const std::string path = results + "/trace.mcap";
  if (!std::filesystem::exists(path)) return nullptr;
  try {
    return std::make_unique<foxglove::McapReplay>(path, hub, f.speed);
  } catch (const std::runtime_error& e) {  // the page can still replay trace.sqlite
    std::fprintf(stderr, "sanet: warning: no Foxglove replay: %s\n", e.what());
    return nullptr;
  }
}

}  // namespace sanet::cli
