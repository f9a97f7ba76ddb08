// The event bus: handlers hear the kinds they subscribed to, in stage order and then in
// subscription order, for as long as their subscription lives, whichever of the two goes first.
#include "core/event_bus.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace sanet {
namespace {

enum class Stage { kFirst, kSecond, kLast };
struct Ping {
  int n;
};
struct Word {
  const std::string& text;
};
using Bus = EventBus<Stage, Ping, Word>;

TEST(EventBus, HandlersHearTheirKindInStageThenSubscriptionOrder) {
  Bus bus;
  std::vector<std::string> heard;
  Subscription a = bus.On<Ping>(Stage::kLast, [&](const Ping& p) { heard.push_back("last" + std::to_string(p.n)); });
  Subscription b = bus.On<Ping>(Stage::kFirst, [&](const Ping& p) { heard.push_back("first" + std::to_string(p.n)); });
  Subscription c =
      bus.On<Ping>(Stage::kSecond, [&](const Ping& p) { heard.push_back("second" + std::to_string(p.n)); });
  Subscription d = bus.On<Ping>(Stage::kFirst, [&](const Ping& p) { heard.push_back("first'" + std::to_string(p.n)); });
  Subscription w = bus.On<Word>(Stage::kFirst, [&](const Word& e) { heard.push_back(e.text); });
  bus.Publish(Ping{7});
  EXPECT_EQ(heard, (std::vector<std::string>{"first7", "first'7", "second7", "last7"}));
  heard.clear();
  const std::string text = "hello";
  bus.Publish(Word{text});
  EXPECT_EQ(heard, std::vector<std::string>{"hello"});
}

TEST(EventBus, ASubscriptionEndsWithItsObjectAndHeardSaysWhetherAnyoneListens) {
  Bus bus;
  EXPECT_FALSE(bus.Heard<Ping>());
  int count = 0;
  {
    Subscription s = bus.On<Ping>(Stage::kFirst, [&](const Ping&) { ++count; });
    EXPECT_TRUE(bus.Heard<Ping>());
    EXPECT_FALSE(bus.Heard<Word>());
    bus.Publish(Ping{1});
    Subscription moved = std::move(s);
    bus.Publish(Ping{2});
  }
  EXPECT_FALSE(bus.Heard<Ping>());
  bus.Publish(Ping{3});
  EXPECT_EQ(count, 2);
  Subscription r = bus.On<Ping>(Stage::kFirst, [&](const Ping&) { ++count; });
  r.reset();
  bus.Publish(Ping{4});
  EXPECT_EQ(count, 2);
}

TEST(EventBus, ASubscriptionMayOutliveItsBus) {
  Subscription s;
  {
    auto bus = std::make_unique<Bus>();
    s = bus->On<Ping>(Stage::kFirst, [](const Ping&) {});
  }
  s.reset();  // no bus to leave: nothing happens
  SUCCEED();
}

// Handlers that end subscriptions (their own or another's) or subscribe while an event is being
// published: an ended one is not called again, a new one hears the next event, none is skipped.
TEST(EventBus, HandlersMayChangeTheSubscriptionsWhileAnEventIsPublished) {
  Bus bus;
  std::vector<std::string> heard;
  Subscription self, later, added;
  self = bus.On<Ping>(Stage::kFirst, [&](const Ping& p) {
    heard.push_back("self" + std::to_string(p.n));
    self.reset();   // ends itself while it runs
    later.reset();  // and another, not yet called
    added = bus.On<Ping>(Stage::kFirst, [&](const Ping& q) { heard.push_back("added" + std::to_string(q.n)); });
  });
  later = bus.On<Ping>(Stage::kSecond, [&](const Ping& p) { heard.push_back("later" + std::to_string(p.n)); });
  Subscription last = bus.On<Ping>(Stage::kLast, [&](const Ping& p) {
    heard.push_back("last" + std::to_string(p.n));
    if (p.n == 1) bus.Publish(Ping{2});  // a nested publish of the same kind
  });
  bus.Publish(Ping{1});
  EXPECT_EQ(heard, (std::vector<std::string>{"self1", "last1", "last2"}));
  heard.clear();
  bus.Publish(Ping{3});
  EXPECT_EQ(heard, (std::vector<std::string>{"added3", "last3"}));
}

}  // namespace
}  // namespace sanet
