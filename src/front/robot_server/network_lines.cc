// The server's side of the routing view in the loop (docs/protocol.md, "The routing view"): a
// client asks what its robot's node knows of the network and gets it as the node holds it at the
// poll that answers, between two steps of the world. Answers are rate-limited per client (one in
// `net_period` of simulated time; asks in between are answered together by the next one), so a
// client that asks in a loop costs the run one table per period, not one per line.
#include "robot_server/sim_server.h"
#include "wire/protocol.h"

namespace sanet::robot_server {
namespace {

const char* Truth(bool value) { return value ? "True" : "False"; }

}  // namespace

// GETNET: answered at this poll or, within the rate limit, at a later one.
void SimServer::AskNetwork(Client& c) { c.net_asked = true; }

void SimServer::AnswerNetworkQueries(double now) {
  for (auto& [id, c] : clients_) {
    if (!c.open || !c.robot || !c.net_asked || now + 1e-9 < c.next_net) continue;
    c.net_asked = false;
    c.next_net = now + settings_.net_period;
    Send(c, NetworkLine(*c.robot, now));
  }
}

// NET {Time t} {Source Simulated} {Protocol p} {Route D Next N Hops h Valid v Expires e}...
// {Neighbour n}...: the robot's ns-3 node's view, when a tap joins its programs to the simulated
// radio. Without one, its traffic to other robots goes over real networks: NET {Time t}
// {Source Kernel}, and the agent reads its own host's tables.
wire::ProtocolMessage SimServer::NetworkLine(NodeId robot, double now) const {
  wire::ProtocolMessage line{"NET"};
  line.Add("Time", wire::FormatNumber(now));
  if (!driver_.HasTap(robot)) return line.Add("Source", "Kernel");
  const NetworkView& view = driver_.NetworkOf(robot);
  line.Add("Source", "Simulated").Add("Protocol", view.Protocol());
  for (const RouteEntry& r : view.RoutingTable())
    line.Add("Route", driver_.NameOf(r.destination) + " Next " + driver_.NameOf(r.next_hop) + " Hops " +
                          std::to_string(r.hops) + " Valid " + Truth(r.valid) + " Expires " +
                          wire::FormatNumber(r.expires_in));
  for (NodeId n : view.Neighbours()) line.Add("Neighbour", driver_.NameOf(n));
  return line;
}

// INVALIDATEROUTE {To n}: answered at once with INVALIDATED {To n} {Done True|False} (False where
// the protocol offers no invalidation). REQUESTROUTE {To n}: a route discovery from the robot's
// node; no answer.
void SimServer::ChangeRoute(Client& c, const wire::ProtocolMessage& m) {
  const std::string* to = m.Get("To");
  const auto target = to ? driver_.Lookup(*to) : std::nullopt;
  if (!target)
    return Error(c, m.type + " needs {To node}, a node of this world" + (to ? ": there is no '" + *to + "'" : ""));
  if (*target == *c.robot) return Error(c, m.type + " {To " + *to + "}: that is this robot");
  NetworkView& view = NodeOf(c).Network();
  if (m.type == "REQUESTROUTE") return view.RequestRoute(*target);
  wire::ProtocolMessage reply{"INVALIDATED"};
  Send(c, reply.Add("To", *to).Add("Done", Truth(view.InvalidateRoute(*target))));
}

}  // namespace sanet::robot_server
