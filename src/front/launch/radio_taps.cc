#include "launch/radio_taps.h"

#include <fcntl.h>
#include <linux/if.h>
#include <linux/if_tun.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "launch/shell.h"

namespace sanet::launch {
namespace {

void Run(const std::string& command) {
  if (RunQuietly(command) != 0)
    throw std::runtime_error("could not set up the simulated radio: '" + command + "' failed");
}

// A tap in this namespace, named `name`; its descriptor, or -1 with errno set.
int OpenTap(const std::string& name) {
  const int fd = ::open("/dev/net/tun", O_RDWR | O_CLOEXEC);
  if (fd < 0) return -1;
  ifreq request{};
  request.ifr_flags = IFF_TAP | IFF_NO_PI;
  std::snprintf(request.ifr_name, IFNAMSIZ, "%s", name.c_str());
  if (::ioctl(fd, TUNSETIFF, &request) < 0) {
    const int error = errno;
    ::close(fd);
    errno = error;
    return -1;
  }
  return fd;
}

}  // namespace

bool RadioTapsPermitted(std::string* why) {
  const std::string how = " (run sanet as root, e.g. with sudo, on Linux with the tun module loaded: modprobe tun)";
  if (::access("/dev/net/tun", F_OK) != 0) return *why = "/dev/net/tun is missing" + how, false;
  const std::string probe = "sanettap" + std::to_string(::getpid() % 100000);
  const int fd = OpenTap(probe);
  if (fd < 0) return *why = std::string("cannot create a tap device: ") + std::strerror(errno) + how, false;
  ::close(fd);
  if (RunQuietly("command -v ip") != 0) return *why = "the ip command (iproute2) is missing", false;
  return true;
}

std::string RadioAddress(NodeId node) { return std::string(kRadioSubnet) + "." + std::to_string(node + 1); }

std::string RadioMac(NodeId node) {
  char mac[32];
  std::snprintf(mac, sizeof mac, "02:5a:00:00:%02x:%02x", ((node + 1) >> 8) & 0xff, (node + 1) & 0xff);
  return mac;
}

void JoinRadioTaps(sim::Driver& world, const std::vector<std::pair<std::string, std::string>>& robot_namespaces) {
  for (const auto& [robot, ns] : robot_namespaces) {
    const auto id = world.Lookup(robot);
    if (!id) throw std::runtime_error("no node named '" + robot + "' in this scenario");
    if (::access(("/var/run/netns/" + ns).c_str(), F_OK) != 0)
      throw std::runtime_error("no network namespace named '" + ns + "' (make one with: ip netns add " + ns + ")");
    if (*id >= 253) throw std::runtime_error("the simulated radio joins robots with node ids below 253");
    const std::string name = "sn" + std::to_string(::getpid() % 100000) + "r" + std::to_string(*id);
    const int fd = OpenTap(name);
    if (fd < 0) throw std::runtime_error("cannot create a tap device for " + robot + ": " + std::strerror(errno));
    world.JoinTap(*id, fd, RadioMac(*id));  // the world's network owns it from here
    Run("ip link set dev " + name + " netns " + ns);
    Run("ip -n " + ns + " link set dev " + name + " name " + kRadioInterface);
    Run("ip -n " + ns + " link set dev " + kRadioInterface + " address " + RadioMac(*id) + " mtu 1500 arp off up");
    Run("ip -n " + ns + " addr add " + RadioAddress(*id) + "/16 dev " + kRadioInterface);
  }
}

}  // namespace sanet::launch
