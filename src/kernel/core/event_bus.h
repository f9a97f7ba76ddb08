// A typed publish-subscribe bus: each event kind is a type of its own, published once and heard
// by every handler subscribed to that type, in the order of their stages and, within a stage, of
// their subscription. Publishing a kind nobody hears costs a check (`Heard`), so that a publisher
// may skip making an event nobody wants. Handlers run on the publisher's thread, at once.
//
// A subscription lasts as long as the Subscription it returns; either side may go first.
// Handlers must not subscribe while an event of their own kind is being published.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

namespace sanet {

// Ends a subscription when destroyed (or reset); movable, not copyable.
class Subscription {
 public:
  Subscription() = default;
  explicit Subscription(std::function<void()> cancel) : cancel_(std::move(cancel)) {}
  Subscription(Subscription&& other) noexcept : cancel_(std::exchange(other.cancel_, nullptr)) {}
  Subscription& operator=(Subscription&& other) noexcept {
    if (this != &other) {
      reset();
      cancel_ = std::exchange(other.cancel_, nullptr);
    }
    return *this;
  }
  Subscription(const Subscription&) = delete;
  Subscription& operator=(const Subscription&) = delete;
  ~Subscription() { reset(); }
  void reset() {
    if (cancel_) std::exchange(cancel_, nullptr)();
  }

 private:
  std::function<void()> cancel_;
};

template <typename Stage, typename... Events>
class EventBus {
 public:
  EventBus() : handlers_(std::make_shared<Handlers>()) {}
  EventBus(const EventBus&) = delete;
  EventBus& operator=(const EventBus&) = delete;

  template <typename Event>
  [[nodiscard]] Subscription On(Stage stage, std::function<void(const Event&)> handler) {
    auto& list = std::get<List<Event>>(*handlers_);
    const std::uint64_t id = ++last_id_;
    const auto after = std::find_if(list.begin(), list.end(), [stage](const auto& h) { return stage < h.stage; });
    list.insert(after, Entry<Event>{id, stage, std::move(handler)});
    std::weak_ptr<Handlers> handlers = handlers_;
    return Subscription([handlers, id] {
      if (const auto alive = handlers.lock()) {
        auto& l = std::get<List<Event>>(*alive);
        l.erase(std::remove_if(l.begin(), l.end(), [id](const auto& h) { return h.id == id; }), l.end());
      }
    });
  }

  template <typename Event>
  void Publish(const Event& event) const {
    for (const auto& h : std::get<List<Event>>(*handlers_)) h.handler(event);
  }

  template <typename Event>
  bool Heard() const {
    return !std::get<List<Event>>(*handlers_).empty();
  }

 private:
  template <typename Event>
  struct Entry {
    std::uint64_t id;
    Stage stage;
    std::function<void(const Event&)> handler;
  };
  template <typename Event>
  using List = std::vector<Entry<Event>>;
  using Handlers = std::tuple<List<Events>...>;
  std::shared_ptr<Handlers> handlers_;
  std::uint64_t last_id_ = 0;
};

}  // namespace sanet
