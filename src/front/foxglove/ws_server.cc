#include "foxglove/ws_server.h"

#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <deque>
#include <map>
#include <stdexcept>
#include <thread>

namespace sanet::foxglove {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace asio = boost::asio;
using tcp = asio::ip::tcp;

namespace {

// Whether a Sec-WebSocket-Protocol list ("a, b") offers `wanted`.
bool Offers(beast::string_view list, const std::string& wanted) {
  std::string all(list);
  std::size_t at = 0;
  while (at <= all.size()) {
    std::size_t end = all.find(',', at);
    if (end == std::string::npos) end = all.size();
    std::string item = all.substr(at, end - at);
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    if (item == wanted) return true;
    at = end + 1;
  }
  return false;
}

}  // namespace

class WsServer::Impl {
 public:
  class Session;
  Impl(const std::string& bind, int port, std::string subprotocol, WsLimits limits, WsHandlers handlers);
  void Accept();
  void Opened(ClientId id, const std::shared_ptr<Session>& session);
  void Closed(ClientId id, const std::string& why);
  std::shared_ptr<Session> Find(ClientId id) {
    const auto s = sessions_.find(id);
    return s == sessions_.end() ? nullptr : s->second;
  }

  asio::io_context io_;
  tcp::acceptor acceptor_{io_};
  const std::string subprotocol_;
  const WsLimits limits_;
  const WsHandlers handlers_;
  std::map<ClientId, std::shared_ptr<Session>> sessions_;  // the server's thread only
  std::atomic<std::size_t> count_{0};
  std::atomic<std::uint64_t> dropped_{0}, sessions_count_{0}, refused_{0};
  ClientId next_ = 1;
  std::thread thread_;
};

class WsServer::Impl::Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket socket, Impl& server, ClientId id) : ws_(std::move(socket)), server_(server), id_(id) {}
  void Start();
  void Send(bool binary, std::string bytes);
  // Policy violation, or (`going_away`) the server stopping.
  void Close(const std::string& why, bool going_away = false);

 private:
  void Upgrade();
  void Refuse(http::status status, const std::string& why);
  void Read();
  void WriteNext();
  void Fail(const std::string& why);

  websocket::stream<beast::tcp_stream> ws_;
  Impl& server_;
  const ClientId id_;
  beast::flat_buffer buffer_;
  http::request<http::string_body> request_;
  std::deque<std::pair<bool, std::string>> queue_;
  std::size_t queued_ = 0;
  bool writing_ = false, open_ = false, gone_ = false;
};

void WsServer::Impl::Session::Start() {
  beast::get_lowest_layer(ws_).expires_after(std::chrono::seconds(30));
  http::async_read(ws_.next_layer(), buffer_, request_, [self = shared_from_this()](beast::error_code e, std::size_t) {
    if (e) return self->Fail("no WebSocket handshake: " + e.message());
    self->Upgrade();
  });
}

void WsServer::Impl::Session::Refuse(http::status status, const std::string& why) {
  ++server_.refused_;
  auto response = std::make_shared<http::response<http::string_body>>(status, request_.version());
  response->set(http::field::content_type, "text/plain");
  response->body() = why + "\n";
  response->prepare_payload();
  http::async_write(ws_.next_layer(), *response,
                    [self = shared_from_this(), response, why](beast::error_code, std::size_t) {
                      beast::error_code ignored;
                      beast::get_lowest_layer(self->ws_).socket().shutdown(tcp::socket::shutdown_both, ignored);
                      self->Fail(why);
                    });
}

void WsServer::Impl::Session::Upgrade() {
  if (!websocket::is_upgrade(request_)) return Refuse(http::status::bad_request, "a WebSocket server (Foxglove)");
  if (!Offers(request_[http::field::sec_websocket_protocol], server_.subprotocol_))
    return Refuse(http::status::bad_request, "offer the subprotocol " + server_.subprotocol_);
  if (server_.count_ >= server_.limits_.max_clients)
    return Refuse(http::status::service_unavailable,
                  "too many clients (at most " + std::to_string(server_.limits_.max_clients) + ")");
  beast::get_lowest_layer(ws_).expires_never();
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  ws_.read_message_max(server_.limits_.max_message_bytes);
  ws_.set_option(websocket::stream_base::decorator([protocol = server_.subprotocol_](websocket::response_type& r) {
    r.set(http::field::sec_websocket_protocol, protocol);
    r.set(http::field::server, "sanet");
  }));
  ws_.async_accept(request_, [self = shared_from_this()](beast::error_code e) {
    if (e) return self->Fail("handshake: " + e.message());
    self->open_ = true;
    self->server_.Opened(self->id_, self);
    self->Read();
  });
}

void WsServer::Impl::Session::Read() {
  ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code e, std::size_t) {
    if (e) return self->Fail(e == websocket::error::closed ? "closed by the client" : e.message());
    const auto data = self->buffer_.data();
    const auto* bytes = static_cast<const std::uint8_t*>(data.data());
    if (self->ws_.got_text()) {
      if (self->server_.handlers_.text)
        self->server_.handlers_.text(self->id_, std::string(bytes, bytes + data.size()));
    } else if (self->server_.handlers_.binary) {
      self->server_.handlers_.binary(self->id_, std::vector<std::uint8_t>(bytes, bytes + data.size()));
    }
    self->buffer_.consume(self->buffer_.size());
    if (!self->gone_) self->Read();
  });
}

// On the server's thread. A client that lets its queue pass the bound has stopped reading.
void WsServer::Impl::Session::Send(bool binary, std::string bytes) {
  if (gone_ || !open_) return;
  if (queued_ + bytes.size() > server_.limits_.max_queued_bytes) {
    ++server_.dropped_;
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
    return Fail("dropped: it stopped reading (" + std::to_string(queued_) + " bytes waiting)");
  }
  queued_ += bytes.size();
  queue_.emplace_back(binary, std::move(bytes));
  if (!writing_) WriteNext();
}

void WsServer::Impl::Session::WriteNext() {
  if (queue_.empty() || gone_) {
    writing_ = false;
    return;
  }
  writing_ = true;
  ws_.binary(queue_.front().first);
  ws_.async_write(asio::buffer(queue_.front().second), [self = shared_from_this()](beast::error_code e, std::size_t) {
    if (e) return self->Fail(e.message());
    self->queued_ -= self->queue_.front().second.size();
    self->queue_.pop_front();
    self->WriteNext();
  });
}

void WsServer::Impl::Session::Close(const std::string& why, bool going_away) {
  if (gone_ || !open_) return;
  const auto code = going_away ? websocket::close_code::going_away : websocket::close_code::policy_error;
  ws_.async_close(websocket::close_reason(code, why),
                  [self = shared_from_this(), why](beast::error_code) { self->Fail(why); });
}

void WsServer::Impl::Session::Fail(const std::string& why) {
  if (gone_) return;
  gone_ = true;
  if (open_) server_.Closed(id_, why);
}

WsServer::Impl::Impl(const std::string& bind, int port, std::string subprotocol, WsLimits limits, WsHandlers handlers)
    : subprotocol_(std::move(subprotocol)), limits_(limits), handlers_(std::move(handlers)) {
  beast::error_code e;
  const tcp::endpoint at(asio::ip::make_address(bind, e), static_cast<unsigned short>(port));
  if (e) throw std::runtime_error("'" + bind + "' is not an IP address");
  acceptor_.open(at.protocol(), e);
  if (!e) acceptor_.set_option(asio::socket_base::reuse_address(true), e);
  if (!e) acceptor_.bind(at, e);
  if (!e) acceptor_.listen(asio::socket_base::max_listen_connections, e);
  if (e) throw std::runtime_error("cannot listen on " + bind + ":" + std::to_string(port) + ": " + e.message());
}

void WsServer::Impl::Accept() {
  acceptor_.async_accept(io_, [this](beast::error_code e, tcp::socket socket) {
    if (e) return;  // the acceptor closed: the server is stopping
    std::make_shared<Session>(std::move(socket), *this, next_++)->Start();
    Accept();
  });
}

void WsServer::Impl::Opened(ClientId id, const std::shared_ptr<Session>& session) {
  sessions_[id] = session;
  ++count_;
  ++sessions_count_;
  if (handlers_.opened) handlers_.opened(id);
}

void WsServer::Impl::Closed(ClientId id, const std::string& why) {
  if (sessions_.erase(id) == 0) return;
  --count_;
  if (handlers_.closed) handlers_.closed(id, why);
}

WsServer::WsServer(const std::string& bind, int port, std::string subprotocol, WsLimits limits, WsHandlers handlers)
    : impl_(std::make_unique<Impl>(bind, port, std::move(subprotocol), limits, std::move(handlers))) {
  impl_->Accept();
  impl_->thread_ = std::thread([this] { impl_->io_.run(); });
}

WsServer::~WsServer() {
  asio::post(impl_->io_, [this] {
    beast::error_code ignored;
    impl_->acceptor_.close(ignored);
    for (auto& [id, session] : impl_->sessions_) session->Close("the run is over", /*going_away=*/true);
  });
  // Let the closing frames go, then stop whatever still waits.
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  impl_->io_.stop();
  impl_->thread_.join();
}

int WsServer::port() const { return impl_->acceptor_.local_endpoint().port(); }

void WsServer::SendText(ClientId client, std::string text) {
  asio::post(impl_->io_, [this, client, text = std::move(text)]() mutable {
    if (auto s = impl_->Find(client)) s->Send(false, std::move(text));
  });
}

void WsServer::SendBinary(ClientId client, std::vector<std::uint8_t> bytes) {
  asio::post(impl_->io_, [this, client, bytes = std::string(bytes.begin(), bytes.end())]() mutable {
    if (auto s = impl_->Find(client)) s->Send(true, std::move(bytes));
  });
}

void WsServer::Close(ClientId client, const std::string& why) {
  asio::post(impl_->io_, [this, client, why] {
    if (auto s = impl_->Find(client)) s->Close(why);
  });
}

std::size_t WsServer::clients() const { return impl_->count_; }
std::uint64_t WsServer::dropped() const { return impl_->dropped_; }
std::uint64_t WsServer::sessions() const { return impl_->sessions_count_; }
std::uint64_t WsServer::refused() const { return impl_->refused_; }

}  // namespace sanet::foxglove
