// A typed publish-subscribe bus: each event kind is a type of its own, published once and heard
// by every handler subscribed to that type, in the order of their stages and, within a stage, of
// their subscription. Publishing a kind nobody hears costs a check (`Heard`), so that a publisher
// may skip making an event nobody wants. Handlers run on the publisher's thread, at once.
//
// A subscription lasts as long as the Subscription it returns; either side may go first. A
// handler may publish, subscribe and end subscriptions: a subscription ended during a publish is
// not called after that, one made during a publish hears the next event of its kind.
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
  EventBus() : kinds_(std::make_shared<Kinds>()) {}
  EventBus(const EventBus&) = delete;
  EventBus& operator=(const EventBus&) = delete;

  template <typename Event>
  [[nodiscard]] Subscription On(Stage stage, std::function<void(const Event&)> handler) {
    Kind<Event>& kind = std::get<Kind<Event>>(*kinds_);
    const std::uint64_t id = ++last_id_;
    kind.Add(Entry<Event>{id, stage, std::move(handler)});
    std::weak_ptr<Kinds> kinds = kinds_;
    return Subscription([kinds, id] {
      if (const auto alive = kinds.lock()) std::get<Kind<Event>>(*alive).Remove(id);
    });
  }

  template <typename Event>
  void Publish(const Event& event) const {
    std::get<Kind<Event>>(*kinds_).Publish(event);
  }

  template <typename Event>
  bool Heard() const {
    const Kind<Event>& kind = std::get<Kind<Event>>(*kinds_);
    if (kind.entries.empty()) return !kind.waiting.empty();
    return !kind.emptied ||
           std::any_of(kind.entries.begin(), kind.entries.end(), [](const auto& e) { return !e.ended; }) ||
           !kind.waiting.empty();
  }

 private:
  template <typename Event>
  struct Entry {
    std::uint64_t id;
    Stage stage;
    std::function<void(const Event&)> handler;
    bool ended = false;  // during a publish (a handler may end its own subscription while it runs)
  };

  // The handlers of one kind. While a publish goes, the list keeps its places: an ended
  // subscription is marked and removed after it, a new one waits for it.
  template <typename Event>
  struct Kind {
    std::vector<Entry<Event>> entries, waiting;
    int publishing = 0;
    bool emptied = false;

    void Add(Entry<Event> entry) {
      if (publishing > 0) return waiting.push_back(std::move(entry));
      const auto after =
          std::find_if(entries.begin(), entries.end(), [&entry](const auto& e) { return entry.stage < e.stage; });
      entries.insert(after, std::move(entry));
    }
    void Remove(std::uint64_t id) {
      waiting.erase(std::remove_if(waiting.begin(), waiting.end(), [id](const auto& e) { return e.id == id; }),
                    waiting.end());
      for (auto& e : entries)
        if (e.id == id) {
          if (publishing == 0) return void(Erase(id));
          e.ended = true;
          emptied = true;
        }
    }
    void Erase(std::uint64_t id) {
      entries.erase(std::remove_if(entries.begin(), entries.end(), [id](const auto& e) { return e.id == id; }),
                    entries.end());
    }
    void Publish(const Event& event) {
      ++publishing;
      for (std::size_t i = 0; i < entries.size(); ++i)
        if (!entries[i].ended) entries[i].handler(event);
      if (--publishing > 0 || (!emptied && waiting.empty())) return;
      if (std::exchange(emptied, false))
        entries.erase(std::remove_if(entries.begin(), entries.end(), [](const auto& e) { return e.ended; }),
                      entries.end());
      for (auto& entry : std::exchange(waiting, {})) Add(std::move(entry));
    }
  };
  using Kinds = std::tuple<Kind<Events>...>;
  std::shared_ptr<Kinds> kinds_;
  std::uint64_t last_id_ = 0;
};

}  // namespace sanet
