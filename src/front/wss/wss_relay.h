// One relay of the Wireless Simulation Server: a TCP port on the server's host that stands for
// one robot's listening port as seen from another robot. While the radio link between the two is
// up it accepts connections and joins each to the target robot's port, copying bytes both ways;
// when the link goes down it cuts them and stops listening, and listens again (on the same port)
// when the link comes back, as USARSim's WSS does.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sanet::wss {

class WssRelay {
 public:
  // Opens the relay's port on `bind` (any free one); throws std::runtime_error if it cannot.
  WssRelay(const std::string& bind, std::string target_host, std::uint16_t target_port);
  ~WssRelay();
  WssRelay(const WssRelay&) = delete;
  WssRelay& operator=(const WssRelay&) = delete;

  std::uint16_t port() const { return port_; }
  bool up() const { return listener_ >= 0; }
  // Listens while the link is up; cuts every connection and stops listening when it goes down.
  void SetLinkUp(bool up);
  // Accepts, connects and copies what is waiting (non-blocking, bounded buffers).
  void Pump();
  // Whether one of this relay's connections reaches the target from local port `port` (for
  // REVERSEDNS: the target sees the connection come from there).
  bool UsesLocalPort(std::uint16_t port) const;

  std::uint64_t connections() const { return connections_; }
  std::uint64_t cut() const { return cut_; }
  std::uint64_t bytes() const { return bytes_; }

 private:
  struct Pipe {
    int accepted = -1, outgoing = -1;  // the connecting robot's side, the target's side
    std::string to_target, to_source;  // bytes waiting to be written
    std::uint16_t local_port = 0;      // of the outgoing side
    bool closing = false;              // one side ended: flush, then close both
  };
  void Listen();
  void Accept();
  bool Copy(int from, int to, std::string& pending);
  void Close(Pipe& pipe);

  std::string bind_, target_host_;
  std::uint16_t target_port_, port_ = 0;
  int listener_ = -1;
  std::vector<Pipe> pipes_;
  std::uint64_t connections_ = 0, cut_ = 0, bytes_ = 0;
};

}  // namespace sanet::wss
