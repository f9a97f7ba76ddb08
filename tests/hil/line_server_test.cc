// LineServer's slots: a connection that says nothing within the handshake time is closed, and a
// newcomer to a full server takes the slot of the longest-silent unregistered connection past
// its handshake time, or is refused when there is none. Times here are short (a fraction of a
// second) so that the tests are; the bounds checked are "not before" and a generous "by then".
#include "wire/line_server.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace sanet::wire {
namespace {

double Now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// A blocking client socket; reads time out after 5 s so that a test fails instead of hanging.
class TestClient {
 public:
  explicit TestClient(std::uint16_t port) : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    EXPECT_EQ(::connect(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
    timeval timeout{5, 0};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  }
  ~TestClient() { ::close(fd_); }
  TestClient(const TestClient&) = delete;
  TestClient& operator=(const TestClient&) = delete;

  void Say(const std::string& line) {
    const std::string text = line + "\r\n";
    EXPECT_EQ(::send(fd_, text.data(), text.size(), MSG_NOSIGNAL), static_cast<ssize_t>(text.size()));
  }
  // What the server sent until it closed the connection (or 5 s passed).
  std::string ReadToEnd() {
    std::string text;
    char buffer[4096];
    for (ssize_t n; (n = ::recv(fd_, buffer, sizeof buffer, 0)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
    return text;
  }

 private:
  int fd_;
};

// A LineServer and what its events said, polled as an owner polls it.
class Owner {
 public:
  explicit Owner(LineServerSettings settings) {
    settings.cap_option = "--cap";
    LineServer::Events events;
    events.connected = [this](ConnectionId id) { connected.push_back(id); };
    events.line = [this](ConnectionId id, const std::string& line) {
      heard[id] = line;
      if (line == "INIT") server->Register(id);
    };
    events.gone = [this](ConnectionId id, const std::string& why) { gone[id] = why; };
    server = std::make_unique<LineServer>(settings, std::move(events));
  }
  // Polls until `done` or 10 s; true if `done`.
  bool PollUntil(const std::function<bool()>& done) {
    for (const double until = Now() + 10; Now() < until;) {
      server->Read();
      server->Write();
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
  }
  void PollFor(double seconds) {
    const double until = Now() + seconds;
    PollUntil([&] { return Now() >= until; });
  }
  // What the server sends `client` until it closes the connection, polling meanwhile.
  std::string ReadToEndPolling(TestClient& client) {
    std::atomic<bool> finished{false};
    std::string text;
    std::thread reader([&] {
      text = client.ReadToEnd();
      finished = true;
    });
    PollUntil([&] { return finished.load(); });
    reader.join();
    return text;
  }

  std::unique_ptr<LineServer> server;
  std::vector<ConnectionId> connected;
  std::map<ConnectionId, std::string> heard;  // the last line of each
  std::map<ConnectionId, std::string> gone;   // why
};

LineServerSettings Settings(std::size_t max_clients, double handshake_timeout) {
  LineServerSettings s;
  s.max_clients = max_clients;
  s.handshake_timeout = handshake_timeout;
  return s;
}

TEST(LineServer, ClosesAConnectionSilentForItsHandshakeTimeAndTellsItWhy) {
  Owner owner(Settings(8, 0.3));
  const double start = Now();
  TestClient silent(owner.server->port());
  ASSERT_TRUE(owner.PollUntil([&] { return !owner.gone.empty(); }));
  EXPECT_GE(Now() - start, 0.3) << "not before its handshake time";
  EXPECT_EQ(owner.gone.begin()->second, "silent for 0.3 s after connecting");
  EXPECT_EQ(silent.ReadToEnd(), "connection closed: silent for 0.3 s after connecting\r\n");
  EXPECT_EQ(owner.server->size(), 0u);
}

TEST(LineServer, AConnectionThatSpokeOutlivesItsHandshakeTime) {
  Owner owner(Settings(8, 0.2));
  TestClient slow(owner.server->port());
  slow.Say("hello");
  ASSERT_TRUE(owner.PollUntil([&] { return !owner.heard.empty(); }));
  owner.PollFor(1.0);  // five handshake times with nothing more said
  EXPECT_TRUE(owner.gone.empty());
  EXPECT_EQ(owner.server->size(), 1u);
}

TEST(LineServer, ANewcomerToAFullServerTakesTheSlotOfTheLongestSilentUnregisteredOne) {
  Owner owner(Settings(3, 0.2));
  TestClient registered(owner.server->port()), older(owner.server->port()), newer(owner.server->port());
  ASSERT_TRUE(owner.PollUntil([&] { return owner.connected.size() == 3; }));
  registered.Say("INIT");
  ASSERT_TRUE(owner.PollUntil([&] { return owner.heard.size() == 1; }));
  older.Say("hello");  // speaks, never registers
  ASSERT_TRUE(owner.PollUntil([&] { return owner.heard.size() == 2; }));
  owner.PollFor(0.05);
  newer.Say("hello");  // the same, later
  ASSERT_TRUE(owner.PollUntil([&] { return owner.heard.size() == 3; }));
  owner.PollFor(0.3);  // all past their handshake time; the registered one silent longest of all
  ASSERT_TRUE(owner.gone.empty());

  TestClient newcomer(owner.server->port());
  ASSERT_TRUE(owner.PollUntil([&] { return owner.connected.size() == 4; }));
  const std::string why = "closed to make room: no INIT within 0.2 s of connecting and the server is full";
  EXPECT_EQ(owner.gone, (std::map<ConnectionId, std::string>{{owner.connected[1], why}}));
  EXPECT_EQ(older.ReadToEnd(), why + " (its cap, --cap 3)\r\n");
  EXPECT_EQ(owner.server->size(), 3u);
}

TEST(LineServer, ANewcomerIsRefusedWhenEverySlotHoldsARegisteredClient) {
  Owner owner(Settings(2, 0.2));
  TestClient first(owner.server->port()), second(owner.server->port());
  first.Say("INIT");
  second.Say("INIT");
  ASSERT_TRUE(owner.PollUntil([&] { return owner.heard.size() == 2; }));
  owner.PollFor(0.3);
  TestClient refused(owner.server->port());
  EXPECT_EQ(owner.ReadToEndPolling(refused),
            "connection refused: the server already has 2 connections (its cap, --cap 2)\r\n");
  EXPECT_TRUE(owner.gone.empty()) << "registered clients are never evicted";
  EXPECT_EQ(owner.server->size(), 2u);
}

TEST(LineServer, ANewcomerIsRefusedWhenEverySlotIsInsideItsHandshakeTime) {
  Owner owner(Settings(1, 60));  // a handshake time no test outlasts
  TestClient early(owner.server->port());
  ASSERT_TRUE(owner.PollUntil([&] { return owner.connected.size() == 1; }));
  TestClient refused(owner.server->port());
  EXPECT_EQ(owner.ReadToEndPolling(refused),
            "connection refused: the server already has 1 connections (its cap, --cap 1)\r\n");
  EXPECT_TRUE(owner.gone.empty());
}

}  // namespace
}  // namespace sanet::wire
