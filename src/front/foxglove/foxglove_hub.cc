#include "foxglove/foxglove_hub.h"

#include <algorithm>
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

// The protocol's numbers are unsigned 32-bit: larger ones are refused, not wrapped.
bool Id(const nlohmann::json& value) { return value.is_number_unsigned() && value.get<std::uint64_t>() <= 0xFFFFFFFFu; }

}  // namespace

FoxgloveHub::FoxgloveHub(HubSettings settings)
    : settings_(std::move(settings)),
      session_(std::to_string(std::chrono::system_clock::now().time_since_epoch().count())) {
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
  nlohmann::json info = {{"op", "serverInfo"},
                         {"name", settings_.name},
                         {"capabilities", {"time"}},
                         {"supportedEncodings", nlohmann::json::array()},
                         {"metadata", nlohmann::json::object()},
                         {"sessionId", session_}};
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
  // Nothing nested deeper than the protocol's messages is kept: a hostile depth costs nothing.
  const nlohmann::json::parser_callback_t shallow = [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    return depth <= 4;
  };
  const nlohmann::json message = nlohmann::json::parse(text, shallow, /*allow_exceptions=*/false);
  if (message.is_discarded() || !message.is_object())
    return Status(client, kError, "not a JSON object (" + std::to_string(text.size()) + " bytes)");
  const auto op = message.find("op");
  if (op == message.end() || !op->is_string()) return Status(client, kError, "a message without its \"op\"");
  if (*op == "subscribe") return Subscribe(client, message);
  if (*op == "unsubscribe") return Unsubscribe(client, message);
  const std::string name = op->get<std::string>();
  Status(client, kError,
         "unsupported operation \"" + name.substr(0, 40) + "\" (this server streams a run: subscribe and unsubscribe)");
}

std::string FoxgloveHub::SubscribeOne(ClientId client, const nlohmann::json& s) {
  if (!s.is_object() || !s.contains("id") || !s.contains("channelId") || !Id(s["id"]) || !Id(s["channelId"]))
    return "needs \"id\" and \"channelId\", numbers from 0 to 4294967295";
  const auto id = s["id"].get<std::uint32_t>();
  const auto channel = s["channelId"].get<std::uint32_t>();
  if (channel == 0 || channel > channels_.size() || channels_[channel - 1].id == 0)
    return "no channel " + std::to_string(channel);
  auto& mine = subscriptions_[client];
  if (const auto held = mine.find(channel); held != mine.end())
    return "channel " + std::to_string(channel) + " is subscribed already (subscription " +
           std::to_string(held->second) + "): one subscription per channel";
  for (const auto& [c, sub] : mine)
    if (sub == id) return "subscription id " + std::to_string(id) + " is in use";
  mine[channel] = id;
  if (const auto last = latched_.find(channel); last != latched_.end())
    server_->SendBinary(client, MessageData(id, last->second.first, last->second.second));
  return "";
}

void FoxgloveHub::Subscribe(ClientId client, const nlohmann::json& message) {
  const auto list = message.find("subscriptions");
  if (list == message.end() || !list->is_array()) return Status(client, kError, "subscribe without \"subscriptions\"");
  std::vector<std::string> refused;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < list->size(); ++i)
      if (const std::string why = SubscribeOne(client, (*list)[i]); !why.empty())
        refused.push_back("subscriptions[" + std::to_string(i) + "]: " + why);
  }
  for (const std::string& why : refused) Status(client, kWarning, "subscribe: " + why);
}

void FoxgloveHub::Unsubscribe(ClientId client, const nlohmann::json& message) {
  const auto ids = message.find("subscriptionIds");
  if (ids == message.end() || !ids->is_array())
    return Status(client, kError, "unsubscribe without \"subscriptionIds\"");
  std::vector<std::string> unknown;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    auto& mine = subscriptions_[client];
    for (const nlohmann::json& id : *ids) {
      const auto held = std::find_if(mine.begin(), mine.end(),
                                     [&](const auto& s) { return Id(id) && s.second == id.get<std::uint32_t>(); });
      if (held == mine.end())
        unknown.push_back(Id(id) ? std::to_string(id.get<std::uint32_t>()) : std::string("a value that is no id"));
      else
        mine.erase(held);
    }
  }
  for (const std::string& id : unknown) Status(client, kWarning, "unsubscribe: no subscription " + id);
}

void FoxgloveHub::ForgetLatched() {
  const std::lock_guard<std::mutex> lock(mutex_);
  latched_.clear();
}

}  // namespace sanet::foxglove
