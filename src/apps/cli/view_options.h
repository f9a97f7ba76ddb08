// The live views of a run (`--view` on `sanet run` and `sanet serve`): sanet's own page
// (view::LiveView, docs/viewer.md) and, beside it on a port of its own, the Foxglove WebSocket
// stream of the run's ROS 2 messages (docs/foxglove.md). And `sanet view`'s Foxglove replay of a
// finished run's trace.mcap.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "foxglove/foxglove_live.h"
#include "foxglove/mcap_replay.h"
#include "sim/world.h"
#include "view/live_view.h"

namespace sanet::cli {

struct FoxgloveArgs {
  int port = 8765;  // Foxglove's usual port; when it is taken and was not asked for, any free one
  std::string port_file;
  double speed = 1;  // replay only
  int max_clients = 16;
  double queue_mb = 16;  // per client
  CLI::Option* port_option = nullptr;
};

// A hub on the port asked for, or on the default one, or (the default being taken) on any.
std::unique_ptr<foxglove::FoxgloveHub> StartHub(const FoxgloveArgs& f);

struct ViewArgs {
  bool on = false;
  int port = 8000;
  std::string port_file;
  FoxgloveArgs foxglove;
};

void AddViewOptions(CLI::App* cmd, ViewArgs& v);
// `replay`: sanet view's options (and --speed).
void AddFoxgloveOptions(CLI::App* cmd, FoxgloveArgs& f, bool replay);

struct LiveViews {
  std::unique_ptr<view::LiveView> page;
  std::unique_ptr<foxglove::FoxgloveLive> foxglove;
  std::string foxglove_notice;  // why the stream is not on the default port, if it is not
  void Finish() {
    if (page) page->Finish();
  }
  // Says where the page and Foxglove are, after what the command prints first (which scripts read).
  void Announce() const;
};
// Both views, watching `world`; none without --view, or only the Foxglove stream if `foxglove_anyway`
// (`sanet serve`, whose world runs in real time). Prints nothing: LiveViews::Announce does.
LiveViews StartLiveViews(sim::World& world, ros2_presentation::RunPresentation& presentation, const ViewArgs& v,
                         bool foxglove_anyway = false);

// The Foxglove replay of `results`/trace.mcap, on `hub`; null if the folder has no trace.mcap.
std::unique_ptr<foxglove::McapReplay> StartReplay(const std::string& results, foxglove::FoxgloveHub& hub,
                                                  const FoxgloveArgs& f);

void WritePortFile(const std::string& path, std::uint16_t port, const char* option);

}  // namespace sanet::cli
