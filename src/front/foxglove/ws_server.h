// A WebSocket server for the Foxglove protocol on Boost.Beast (Debian's libboost-dev: Beast and
// Asio are header-only there, so the server adds no library to install; websocketpp would need
// the same Asio and is no longer maintained upstream; libwebsockets' C callbacks would need more
// code around them). Its own thread runs Asio. Clients must offer the subprotocol asked for. The
// simulation never waits for a client: every send only queues a frame, each client's queue is
// bounded in bytes, and a client whose queue passes the bound (one that stops reading) is
// dropped; a cap on clients refuses the next one.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sanet::foxglove {

using ClientId = std::uint64_t;

struct WsLimits {
  std::size_t max_clients = 16;
  std::size_t max_queued_bytes = 64 << 20;  // per client
  std::size_t max_message_bytes = 1 << 20;  // a client's message
};

// Called on the server's thread.
struct WsHandlers {
  std::function<void(ClientId)> opened;
  std::function<void(ClientId, const std::string&)> text;
  std::function<void(ClientId, const std::vector<std::uint8_t>&)> binary;
  std::function<void(ClientId, const std::string& why)> closed;
};

class WsServer {
 public:
  // Listens on `bind`:`port` (0: any free port); throws std::runtime_error if it cannot.
  WsServer(const std::string& bind, int port, std::string subprotocol, WsLimits limits, WsHandlers handlers);
  ~WsServer();
  WsServer(const WsServer&) = delete;
  WsServer& operator=(const WsServer&) = delete;
  int port() const;

  // From any thread; a client that is gone is ignored.
  void SendText(ClientId client, std::string text);
  void SendBinary(ClientId client, std::vector<std::uint8_t> bytes);
  void Close(ClientId client, const std::string& why);
  std::size_t clients() const;
  std::uint64_t dropped() const;   // clients dropped for not reading
  std::uint64_t sessions() const;  // clients that ever connected
  std::uint64_t refused() const;   // handshakes refused (no subprotocol, too many clients)

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sanet::foxglove
