// The Foxglove WebSocket protocol's server side (`foxglove.websocket.v1`, foxglove/ws-protocol
// docs/spec.md) over a WsServer: serverInfo with the `time` capability (the run's simulated
// time), advertise of every channel (a ROS 2 topic: CDR messages with a ros2msg schema, the same
// as the run's MCAP log), subscribe and unsubscribe, message data and time as binary frames.
// Anything else a client sends is answered with a status message. A latched channel's last
// message (/tf_static, /world) reaches a client as soon as it subscribes. Thread-safe: the run
// (or a replay) advertises and publishes from its thread and never waits.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "foxglove/ws_server.h"

namespace sanet::foxglove {

struct HubSettings {
  std::string bind = "127.0.0.1";
  int port = 8765;  // Foxglove's usual port; 0: any free port
  std::string name = "sanet";
  WsLimits limits;
};

struct Channel {
  std::uint32_t id = 0;
  std::string topic, schema_name, schema;  // schema: the ros2msg definition
  bool latched = false;
};

class FoxgloveHub {
 public:
  // Listens (throws std::runtime_error if it cannot).
  explicit FoxgloveHub(HubSettings settings);
  ~FoxgloveHub();
  int port() const;

  void Advertise(const Channel& channel);
  void Publish(std::uint32_t channel, std::uint64_t time_ns, const std::vector<std::uint8_t>& cdr);
  void Time(std::uint64_t time_ns);
  // Latched messages are forgotten (a replay about to start again sends them itself).
  void ForgetLatched();
  std::size_t clients() const;
  std::uint64_t dropped() const;
  // For summary.json: the port, clients served, dropped for not reading, refused.
  nlohmann::ordered_json Summary() const;

 private:
  void Opened(ClientId client);
  void Text(ClientId client, const std::string& text);
  void Subscribe(ClientId client, const nlohmann::json& message);
  void Unsubscribe(ClientId client, const nlohmann::json& message);
  void Status(ClientId client, int level, const std::string& message);
  std::string SubscribeOne(ClientId client, const nlohmann::json& s);  // "" or why it was refused
  static nlohmann::json ChannelJson(const Channel& c);
  static std::vector<std::uint8_t> MessageData(std::uint32_t subscription, std::uint64_t time_ns,
                                               const std::vector<std::uint8_t>& cdr);

  HubSettings settings_;
  const std::string session_;  // one per hub: a client that reconnects knows it is the same server
  mutable std::mutex mutex_;
  std::vector<Channel> channels_;                                                         // by id - 1
  std::map<std::uint32_t, std::pair<std::uint64_t, std::vector<std::uint8_t>>> latched_;  // by channel
  // client -> channel -> the client's subscription id
  std::map<ClientId, std::map<std::uint32_t, std::uint32_t>> subscriptions_;
  std::set<ClientId> clients_;
  std::unique_ptr<WsServer> server_;  // last: it calls back into the above from its thread
};

}  // namespace sanet::foxglove
