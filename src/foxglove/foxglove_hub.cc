#include "foxglove/foxglove_hub.h"

#include <chrono>
#include <cstring>

namespace sanet::foxglove {
namespace {

constexpr std::uint8_t kMessageData = 0x01, kTime = 0x02;
constexpr int kInfo = 0, kWarning = 1, kError = 2;

template <typename T>
void Put(std::vector<std::uint8_t>& out, T value) {  // little endian, as the protocol's binary frames
  for (std::size_t i = 0; i < sizeof(T); ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

}  // namespace

FoxgloveHub::FoxgloveHub(HubSettings settings) : settings_(std::move(settings)) {
  WsHandlers handlers;
  handlers.opened = [this](ClientId c) { Opened(c); };
  handlers.text = [this](ClientId c, const std::string& text) { Text(c, text); };
  handlers.binary = [this](ClientId c, const std::vector<std::uint8_t>&) {
    Status(c, kError, "this server takes no messages from clients (no clientPublish capability)");
  };
  handlers.closed = [this](ClientId c, const std::string&) {
    const std::lock_guard<std::mutex> lock(mutex_);
    clients_.erase(c);
    subscriptions_.erase(c);
  };
  server_ = std::make_unique<WsServer>(settings_.bind, settings_.port, "foxglove.websocket.v1", settings_.limits,
                                       std::move(handlers));
}

FoxgloveHub::~FoxgloveHub() { server_.reset(); }

int FoxgloveHub::port() const { return server_->port(); }
std::size_t FoxgloveHub::clients() const { return server_->clients(); }
std::uint64_t FoxgloveHub::dropped() const { return server_->dropped(); }

nlohmann::ordered_json FoxgloveHub::Summary() const {
  return {{"port", port()},
          {"clients", server_->sessions()},
          {"dropped_for_not_reading", server_->dropped()},
          {"refused", server_->refused()}};
}

nlohmann::json FoxgloveHub::ChannelJson(const Channel& c) {
  return {{"id", c.id},         {"topic", c.topic},           {"encoding", "cdr"}, {"schemaName", c.schema_name},
          {"schema", c.schema}, {"schemaEncoding", "ros2msg"}};
}

void FoxgloveHub::Opened(ClientId client) {
  const auto session = std::chrono::system_clock::now().time_since_epoch().count();
  nlohmann::json info = {{"op", "serverInfo"},
                         {"name", settings_.name},
                         {"capabilities", {"time"}},
                         {"supportedEncodings", nlohmann::json::array()},
                         {"metadata", nlohmann::json::object()},
                         {"sessionId", std::to_string(session)}};
  nlohmann::json advertise = {{"op", "advertise"}, {"channels", nlohmann::json::array()}};
  const std::lock_guard<std::mutex> lock(mutex_);  // no channel advertised between the two
  clients_.insert(client);
  for (const Channel& c : channels_) advertise["channels"].push_back(ChannelJson(c));
  server_->SendText(client, info.dump());
  server_->SendText(client, advertise.dump());
}

void FoxgloveHub::Advertise(const Channel& channel) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (channels_.size() < channel.id) channels_.resize(channel.id);
  channels_[channel.id - 1] = channel;
  const nlohmann::json advertise = {{"op", "advertise"}, {"channels", {ChannelJson(channel)}}};
  const std::string text = advertise.dump();
  for (const ClientId c : clients_) server_->SendText(c, text);
}

std::vector<std::uint8_t> FoxgloveHub::MessageData(std::uint32_t subscription, std::uint64_t time_ns,
                                                   const std::vector<std::uint8_t>& cdr) {
  std::vector<std::uint8_t> frame;
  frame.reserve(13 + cdr.size());
  frame.push_back(kMessageData);
  Put<std::uint32_t>(frame, subscription);
  Put<std::uint64_t>(frame, time_ns);
  frame.insert(frame.end(), cdr.begin(), cdr.end());
  return frame;
}

void FoxgloveHub::Publish(std::uint32_t channel, std::uint64_t time_ns, const std::vector<std::uint8_t>& cdr) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (channel == 0 || channel > channels_.size()) return;
  if (channels_[channel - 1].latched) latched_[channel] = {time_ns, cdr};
  for (const auto& [client, subscribed] : subscriptions_)
    if (const auto s = subscribed.find(channel); s != subscribed.end())
      server_->SendBinary(client, MessageData(s->second, time_ns, cdr));
}

void FoxgloveHub::Time(std::uint64_t time_ns) {
  std::vector<std::uint8_t> frame{kTime};
  Put<std::uint64_t>(frame, time_ns);
  const std::lock_guard<std::mutex> lock(mutex_);
  for (const ClientId c : clients_) server_->SendBinary(c, frame);
}

void FoxgloveHub::Status(ClientId client, int level, const std::string& message) {
  server_->SendText(client, nlohmann::json({{"op", "status"}, {"level", level}, {"message", message}}).dump());
}

void FoxgloveHub::Text(ClientId client, const std::string& text) {
  const nlohmann::json message = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (message.is_discarded() || !message.is_object())
    return Status(client, kError, "not a JSON object: " + text.substr(0, 80));
  const auto op = message.find("op");
  if (op == message.end() || !op->is_string()) return Status(client, kError, "a message without its \"op\"");
  if (*op == "subscribe") return Subscribe(client, message);
  if (*op == "unsubscribe") return Unsubscribe(client, message);
  Status(client, kError,
         "unsupported operation \"" + op->get<std::string>() +
             "\" (this server streams a run: "
             "subscribe and unsubscribe)");
}

void FoxgloveHub::Subscribe(ClientId client, const nlohmann::json& message) {
  const auto list = message.find("subscriptions");
  if (list == message.end() || !list->is_array()) return Status(client, kError, "subscribe without \"subscriptions\"");
  std::vector<std::string> refused;
  const std::lock_guard<std::mutex> lock(mutex_);
  auto& mine = subscriptions_[client];
  for (const nlohmann::json& s : *list) {
    if (!s.is_object() || !s.contains("id") || !s.contains("channelId") || !s["id"].is_number_unsigned() ||
        !s["channelId"].is_number_unsigned()) {
      refused.push_back(s.dump() + ": needs numbers \"id\" and \"channelId\"");
      continue;
    }
    const auto id = s["id"].get<std::uint32_t>();
    const auto channel = s["channelId"].get<std::uint32_t>();
    if (channel == 0 || channel > channels_.size()) {
      refused.push_back("no channel " + std::to_string(channel));
      continue;
    }
    bool reused = false;
    for (const auto& [c, sub] : mine) reused |= sub == id && c != channel;
    if (reused) {
      refused.push_back("subscription id " + std::to_string(id) + " is in use");
      continue;
    }
    mine[channel] = id;
    if (const auto last = latched_.find(channel); last != latched_.end())
      server_->SendBinary(client, MessageData(id, last->second.first, last->second.second));
  }
  for (const std::string& why : refused) Status(client, kWarning, "subscribe: " + why);
}

void FoxgloveHub::Unsubscribe(ClientId client, const nlohmann::json& message) {
  const auto ids = message.find("subscriptionIds");
  if (ids == message.end() || !ids->is_array())
    return Status(client, kError, "unsubscribe without \"subscriptionIds\"");
  const std::lock_guard<std::mutex> lock(mutex_);
  auto& mine = subscriptions_[client];
  for (const nlohmann::json& id : *ids)
    for (auto s = mine.begin(); s != mine.end();)
      s = id.is_number_unsigned() && s->second == id.get<std::uint32_t>() ? mine.erase(s) : std::next(s);
}

}  // namespace sanet::foxglove
