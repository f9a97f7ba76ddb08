// help_request_mote: the mote's state machine of the help-request case study.
//   idle -> request      at `request_at`: flood the help request
//   request -> request   no robot answered within `reply_timeout`: request again
//   request -> gave_up   `request_attempts` requests without an answer
//   request -> wait      a robot takes the request (ra): put it in charge (ma)
//   wait -> request      the robot was silent past its hop time, or gave up: request again
//   wait -> done         the robot arrived (a)
// A robot asking while another is in charge, or after the request is fulfilled, is refused.
#include <cmath>
#include <memory>

#include "controllers.h"
#include "help_request/messages.h"

namespace sanet::controllers {
namespace {

using help::HelpMessage;
using help::Kind;

class HelpRequestMote : public Controller {
 public:
  explicit HelpRequestMote(const Params& p)
      : request_at_(p.Number("request_at", -1)),
        reply_timeout_(p.Number("reply_timeout", 30, 0.1)),
        attempts_allowed_(p.Integer("request_attempts", 3, 1, 1000)),
        flood_(p.Flag("flood", true)) {}

  void ControlStep(Node& node) override {
    const double now = node.Now();
    switch (state_) {
      case State::kIdle:
        if (request_at_ >= 0 && now >= request_at_) Request(node, State::kIdle, "needs help");
        break;
      case State::kRequest:
        if (now < deadline_) break;
        if (attempts_ < attempts_allowed_) {
          SendRequest(node);
          node.Log("request again (attempt " + std::to_string(attempts_) + ")");
        } else {
          Go(node, State::kGaveUp, "no robot answered " + std::to_string(attempts_) + " requests");
        }
        break;
      case State::kWait:
        if (now >= deadline_) {
          node.Metric("robot_timeouts", 1);
          Request(node, State::kWait, "robot " + Name(node, robot_) + " silent past its hop time");
        }
        break;
      case State::kDone:
      case State::kGaveUp:
        break;
    }
  }

  void OnMessage(Node& node, const Message& message) override {
    const auto m = HelpMessage::Decode(message.payload);
    if (!m || m->kind != Kind::kRobot) return;
    const NodeId robot = message.from;
    const bool ours = state_ == State::kWait && robot == robot_;
    if (m->a) {
      if (ours) {
        Reply(node, robot, true);
        Go(node, State::kDone, "robot " + Name(node, robot) + " arrived");
      }
      return;
    }
    if (m->ra) {
      if (state_ == State::kRequest) {
        robot_ = robot;
        deadline_ = node.Now() + m->hop_time;
        Reply(node, robot, true);
        Go(node, State::kWait, "robot " + Name(node, robot) + " takes the request");
      } else if (ours) {
        deadline_ = node.Now() + m->hop_time;  // keep-alive or route refresh
        Reply(node, robot, true);
      } else {
        Reply(node, robot, false);
        node.Log("refuse robot " + Name(node, robot) + ": " +
                 (state_ == State::kWait ? "another robot is in charge" : "no request open"));
      }
      return;
    }
    if (ours) Request(node, State::kWait, "robot " + Name(node, robot) + " gave up");
  }

 private:
  enum class State { kIdle, kRequest, kWait, kDone, kGaveUp };
  static const char* StateName(State s) {
    static const char* names[] = {"idle", "request", "wait", "done", "gave_up"};
    return names[static_cast<int>(s)];
  }
  static std::string Name(Node& node, NodeId id) { return node.NameOf(id); }

  void Go(Node& node, State to, const std::string& why) {
    node.Transition(StateName(state_), StateName(to), why);
    state_ = to;
  }
  void Request(Node& node, State from, const std::string& why) {
    (void)from;
    attempts_ = 0;
    Go(node, State::kRequest, why);
    SendRequest(node);
  }
  void SendRequest(Node& node) {
    const Bytes request = HelpMessage{Kind::kRequest}.Encode();
    if (flood_)
      node.Flood(request);
    else
      node.Broadcast(request);
    ++attempts_;
    deadline_ = node.Now() + reply_timeout_;
  }
  void Reply(Node& node, NodeId robot, bool accept) {
    HelpMessage m{Kind::kMote};
    m.ma = accept;
    node.Send(robot, m.Encode());
  }

  double request_at_, reply_timeout_;
  int attempts_allowed_;
  bool flood_;
  State state_ = State::kIdle;
  int attempts_ = 0;
  double deadline_ = 0;
  NodeId robot_ = 0;
};

}  // namespace

ControllerInfo HelpRequestMoteInfo() {
  return {"help_request_mote",
          "case study 1, mote: floods a help request at `request_at` (s), repeats it every "
          "`reply_timeout` (30 s) up to `request_attempts` (3) times, puts one robot in charge and "
          "drops it when silent past its hop time",
          [](const Params& p) { return std::make_unique<HelpRequestMote>(p); }};
}

}  // namespace sanet::controllers
