// help_request_robot: the robot's state machine of the help-request case study.
//   idle -> select_destination            a help request was heard
//   select_destination -> request_assignment   a waiting mote chosen at random
//   request_assignment -> find_next_hop    the mote put the robot in charge (ma)
//   request_assignment -> select/idle      refused, or no answer to `attempts` requests (gives up)
//   find_next_hop -> go_to_next_hop / go_to_destination   a neighbour n chosen with probability
//        P(n) = r(n,d) / sum r(i,d), r = H if n = d, else 1/hops of n's route to d
//   find_next_hop -> request_next_hop      no route to d: send to d, which starts a discovery
//   request_next_hop -> find_next_hop      the mote answered (a route exists now)
//   go_to_next_hop -> find_next_hop        within `hop_reached_distance` of the hop; at
//        `refresh_distance` the route to d is invalidated and d messaged to rediscover it
//   go_to_destination -> arrived           within `arrival_distance`: tell d (a)
// Any wait longer than its limit, or a hop longer than `hop_time`, makes the robot give up
// (ra = false to d) and pick another waiting mote, if any.
#include <algorithm>
#include <cmath>
#include <memory>

#include "controllers.h"
#include "help_request/messages.h"
#include "navigation.h"

namespace sanet::controllers {
namespace {

using help::HelpMessage;
using help::Kind;

class HelpRequestRobot : public Controller {
 public:
  explicit HelpRequestRobot(const Params& p)
      : pilot_(PilotSettings::FromParams(p)),
        h_(p.Number("H", 1000, 1)),
        reply_timeout_(p.Number("reply_timeout", 30, 0.1)),
        attempts_allowed_(p.Integer("attempts", 3, 1, 1000)),
        hop_time_(p.Number("hop_time", 300, 1)),
        refresh_distance_(p.Number("refresh_distance", 10, 0)),
        hop_reached_(p.Number("hop_reached_distance", 1.5, 0.1)),
        arrival_(p.Number("arrival_distance", 1.5, 0.1)),
        keepalive_(p.Number("keepalive_interval", 60, 1)) {}

  void OnMessage(Node& node, const Message& message) override {
    const auto m = HelpMessage::Decode(message.payload);
    if (!m) return;
    const NodeId from = message.from;
    if (m->kind == Kind::kRequest) {
      if (std::find(waiting_.begin(), waiting_.end(), from) == waiting_.end() && !(has_dest_ && from == dest_)) {
        waiting_.push_back(from);
        node.Log("help request from " + node.NameOf(from));
      }
      if (state_ == State::kIdle) Go(node, State::kSelect, "help request from " + node.NameOf(from));
      return;
    }
    if (m->kind != Kind::kMote || !has_dest_ || from != dest_) return;
    if (!m->ma) {
      if (state_ != State::kArrived) GiveUp(node, node.NameOf(from) + " refused");
      return;
    }
    if (state_ == State::kRequestAssignment)
      Go(node, State::kFindNextHop, node.NameOf(from) + " put the robot in charge");
    else if (state_ == State::kRequestNextHop)
      Go(node, State::kFindNextHop, node.NameOf(from) + " answered");
  }

  void ControlStep(Node& node) override {
    const double now = node.Now();
    const double dt = last_step_ ? now - *last_step_ : 0;
    last_step_ = now;
    switch (state_) {
      case State::kIdle:
      case State::kArrived:
        node.Drive({});
        break;
      case State::kSelect:
        SelectDestination(node);
        break;
      case State::kRequestAssignment:
      case State::kRequestNextHop:
        node.Drive({});
        if (state_ == State::kRequestNextHop && HasRoute(node)) {
          Go(node, State::kFindNextHop, "a route to " + node.NameOf(dest_) + " appeared");
        } else if (now >= deadline_) {
          if (attempts_ < attempts_allowed_)
            SendToDestination(node, true);
          else
            GiveUp(node, "no answer from " + node.NameOf(dest_) + " after " + std::to_string(attempts_) + " messages");
        }
        break;
      case State::kFindNextHop:
        FindNextHop(node);
        break;
      case State::kGoToNextHop:
      case State::kGoToDestination:
        Travel(node, dt);
        break;
    }
  }

 private:
  enum class State {
    kIdle,
    kSelect,
    kRequestAssignment,
    kFindNextHop,
    kRequestNextHop,
    kGoToNextHop,
    kGoToDestination,
    kArrived
  };
  static const char* StateName(State s) {
    static const char* names[] = {"idle",
                                  "select_destination",
                                  "request_assignment",
                                  "find_next_hop",
                                  "request_next_hop",
                                  "go_to_next_hop",
                                  "go_to_destination",
                                  "arrived"};
    return names[static_cast<int>(s)];
  }

  void Go(Node& node, State to, const std::string& why) {
    node.Transition(StateName(state_), StateName(to), why);
    state_ = to;
    attempts_ = 0;
    deadline_ = 0;
  }

  void SelectDestination(Node& node) {
    if (waiting_.empty()) {
      Go(node, State::kIdle, "no mote waiting");
      return;
    }
    const std::size_t pick = std::min(waiting_.size() - 1, static_cast<std::size_t>(node.Random() * waiting_.size()));
    dest_ = waiting_[pick];
    has_dest_ = true;
    waiting_.erase(waiting_.begin() + pick);
    started_ = node.Now();
    avoiding_ = 0;
    Go(node, State::kRequestAssignment,
       "chose " + node.NameOf(dest_) + " among " + std::to_string(waiting_.size() + 1));
    SendToDestination(node, true);
  }

  // ra = true: take the request, ask for a route, keep alive.
  void SendToDestination(Node& node, bool ra) {
    HelpMessage m{Kind::kRobot};
    m.ra = ra;
    m.hop_time = hop_time_;
    node.Send(dest_, m.Encode());
    last_sent_ = node.Now();
    ++attempts_;
    deadline_ = node.Now() + reply_timeout_;
  }

  bool HasRoute(Node& node) const {
    for (const RouteEntry& e : node.Network().RoutingTable())
      if (e.destination == dest_ && e.valid) return true;
    return false;
  }

  void FindNextHop(Node& node) {
    // Candidates: the destination itself if it is a neighbour (weight H), and the next hop of
    // every valid route to it (weight 1 / hops); the mote just reached is not a way forward.
    std::vector<std::pair<NodeId, double>> candidates;
    for (const RouteEntry& e : node.Network().RoutingTable()) {
      if (!e.valid || e.destination != dest_) continue;
      if (e.next_hop == dest_)
        candidates.push_back({dest_, h_});
      else if (!(has_hop_ && e.next_hop == hop_))
        candidates.push_back({e.next_hop, 1.0 / e.hops});
    }
    if (candidates.empty()) {
      Go(node, State::kRequestNextHop, "no route to " + node.NameOf(dest_));
      node.Network().InvalidateRoute(dest_);
      SendToDestination(node, true);
      return;
    }
    double total = 0;
    for (const auto& c : candidates) total += c.second;
    double draw = node.Random() * total;
    NodeId chosen = candidates.back().first;
    for (const auto& c : candidates)
      if ((draw -= c.second) < 0) {
        chosen = c.first;
        break;
      }
    hop_ = chosen;
    has_hop_ = true;
    hop_started_ = node.Now();
    refreshed_ = false;
    Go(node, chosen == dest_ ? State::kGoToDestination : State::kGoToNextHop,
       "next hop " + node.NameOf(chosen) + " of " + std::to_string(candidates.size()) + " towards " +
           node.NameOf(dest_));
  }

  void Travel(Node& node, double dt) {
    const double now = node.Now();
    const bool final_leg = state_ == State::kGoToDestination;
    const auto bearing = node.Bearing(hop_);
    const auto pose = node.GroundTruth();
    if (!bearing || !pose) {
      node.Drive({});
      Go(node, State::kFindNextHop, node.NameOf(hop_) + " is out of sight");
      return;
    }
    if (bearing->distance <= (final_leg ? arrival_ : hop_reached_)) {
      node.Drive({});
      node.Metric("hop_time", now - hop_started_);
      if (final_leg) {
        HelpMessage m{Kind::kRobot};
        m.a = true;
        node.Send(dest_, m.Encode());
        node.Metric("travel_time", now - started_);
        node.Metric("time_avoiding_obstacles", avoiding_);
        Go(node, State::kArrived, "reached " + node.NameOf(dest_));
        node.Log("arrived");
      } else {
        Go(node, State::kFindNextHop, "reached " + node.NameOf(hop_));
      }
      return;
    }
    if (now - hop_started_ > hop_time_) {
      GiveUp(node, "the hop to " + node.NameOf(hop_) + " took more than " + std::to_string(hop_time_) + " s");
      return;
    }
    if (!final_leg && !refreshed_ && bearing->distance <= refresh_distance_) {
      // Still in range of this hop: have the routing protocol find the way on from here.
      refreshed_ = true;
      node.Network().InvalidateRoute(dest_);
      SendToDestination(node, true);
      node.Log("route refresh at " + std::to_string(bearing->distance) + " m from " + node.NameOf(hop_));
    } else if (now - last_sent_ >= keepalive_) {
      SendToDestination(node, true);
    }
    const Vec2 goal = ToWorld(*pose, Rotate({bearing->distance, 0}, bearing->bearing));
    const std::optional<RangeScan> ir = node.Ir();
    node.Drive(pilot_.Steer(now, *pose, goal, ir ? &*ir : nullptr, node.Holonomic()));
    if (pilot_.following()) avoiding_ += dt;
  }

  void GiveUp(Node& node, const std::string& why) {
    node.Drive({});
    HelpMessage m{Kind::kRobot};  // ra = false
    node.Send(dest_, m.Encode());
    node.Metric("gave_up", 1);
    has_dest_ = false;
    has_hop_ = false;
    Go(node, waiting_.empty() ? State::kIdle : State::kSelect, "gave up: " + why);
  }

  Pilot pilot_;
  double h_, reply_timeout_;
  int attempts_allowed_;
  double hop_time_, refresh_distance_, hop_reached_, arrival_, keepalive_;

  State state_ = State::kIdle;
  std::vector<NodeId> waiting_;  // motes whose requests were heard, in the order heard
  NodeId dest_ = 0, hop_ = 0;
  bool has_dest_ = false, has_hop_ = false, refreshed_ = false;
  int attempts_ = 0;
  double deadline_ = 0, last_sent_ = 0, hop_started_ = 0, started_ = 0, avoiding_ = 0;
  std::optional<double> last_step_;
};

}  // namespace

ControllerInfo HelpRequestRobotInfo() {
  return {"help_request_robot",
          "case study 1, robot: takes a waiting mote's request and travels to it from neighbour to "
          "neighbour along its routing table (P(n) = r(n,d) / sum r), refreshing the route `refresh_distance` "
          "before each hop; needs a bearing sensor and IR",
          [](const Params& p) { return std::make_unique<HelpRequestRobot>(p); }};
}

}  // namespace sanet::controllers
