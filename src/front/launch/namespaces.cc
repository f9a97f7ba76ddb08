#include "launch/namespaces.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "launch/shell.h"

namespace sanet::launch {
namespace {

std::string Millis(double seconds) { return std::to_string(seconds * 1000) + "ms"; }

}  // namespace

bool NetworkNamespaces::Permitted(std::string* why) {
  const std::string probe = "sanetprobe" + std::to_string(::getpid());
  if (RunQuietly("ip netns add " + probe) != 0) {
    *why = RunQuietly("command -v ip") != 0 ? "the ip command (iproute2) is missing"
                                            : "'ip netns add' is not permitted here";
    return false;
  }
  RunQuietly("ip netns del " + probe);
  return true;
}

bool NetworkNamespaces::ShapingPermitted(std::string* why) {
  const std::string probe = "sanetprobe" + std::to_string(::getpid());
  if (RunQuietly("ip netns add " + probe) != 0) {
    *why = "no network namespaces";
    return false;
  }
  const bool ok = RunQuietly("ip netns exec " + probe + " ip link add sanetdummy type dummy") == 0 &&
                  RunQuietly("ip netns exec " + probe + " tc qdisc add dev sanetdummy root netem delay 1ms") == 0;
  RunQuietly("ip netns del " + probe);
  if (!ok)
    *why = RunQuietly("command -v tc") != 0 ? "the tc command (iproute2) is missing"
                                            : "this kernel has no netem queueing discipline (sch_netem)";
  return ok;
}

NetworkNamespaces::NetworkNamespaces(const RunSlot& slot, const std::vector<std::uint32_t>& nodes,
                                     const sections::LinkShaping& shaping, bool shape)
    : tag_(slot.NamePrefix()), subnet_(slot.Subnet()), nodes_(nodes), shape_(shape) {
  try {
    Run("ip link add " + tag_ + "br type bridge");
    bridge_ = true;
    Run("ip addr add " + ServerAddress() + "/24 dev " + tag_ + "br");
    Run("ip link set " + tag_ + "br up");
    for (std::uint32_t node : nodes) {
      if (node >= 253) throw std::runtime_error("network namespaces support node ids below 253");
      const std::string ns = Namespace(node), host = tag_ + "h" + std::to_string(node),
                        inside = tag_ + "n" + std::to_string(node);
      Run("ip netns add " + ns);
      made_.push_back(ns);
      Run("ip link add " + host + " type veth peer name " + inside);
      Run("ip link set " + inside + " netns " + ns);
      Run("ip -n " + ns + " link set dev " + inside + " name " + kSimulatorInterface);
      Run("ip link set " + host + " master " + tag_ + "br up");
      Run("ip -n " + ns + " addr add " + Subnet() + "." + std::to_string(node + 1) + "/24 dev " + kSimulatorInterface);
      Run("ip -n " + ns + " link set " + kSimulatorInterface + " up");
      Run("ip netns exec " + ns + " ip link set lo up");
      if (shape_ && (shaping.delay > 0 || shaping.jitter > 0 || shaping.loss > 0 || shaping.rate > 0)) {
        std::string netem =
            "ip netns exec " + ns + " tc qdisc add dev " + std::string(kSimulatorInterface) + " root netem";
        if (shaping.delay > 0 || shaping.jitter > 0)
          netem += " delay " + Millis(shaping.delay) + " " + Millis(shaping.jitter);
        if (shaping.loss > 0) netem += " loss " + std::to_string(shaping.loss * 100) + "%";
        if (shaping.rate > 0) netem += " rate " + std::to_string(static_cast<long long>(shaping.rate)) + "bit";
        Run(netem);
      }
    }
  } catch (...) {
    Remove();
    throw;
  }
}

NetworkNamespaces::~NetworkNamespaces() { Remove(); }

// The veth pairs first, by their host ends: deleting a namespace takes its pair along, but only
// when the kernel gets round to freeing the namespace, so that a launch on the same slot just
// after this one could find the name still taken.
void NetworkNamespaces::Remove() {
  for (std::uint32_t node : nodes_) RunQuietly("ip link del " + tag_ + "h" + std::to_string(node));
  for (const std::string& ns : made_) RunQuietly("ip netns del " + ns);
  made_.clear();
  if (bridge_) RunQuietly("ip link del " + tag_ + "br");
  bridge_ = false;
}

std::string NetworkNamespaces::Namespace(std::uint32_t node) const { return tag_ + "-" + std::to_string(node); }

void NetworkNamespaces::Run(const std::string& command) {
  if (RunQuietly(command) != 0)
    throw std::runtime_error("could not set up the agents' network: '" + command + "' failed");
}

}  // namespace sanet::launch
