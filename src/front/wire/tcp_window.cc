#include "wire/tcp_window.h"

// linux/tcp.h, not netinet/tcp.h: glibc's copy of struct tcp_info stops before tcpi_snd_wnd.
#include <linux/tcp.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <cstddef>

namespace sanet::wire {

std::optional<std::uint32_t> PeerReceiveWindow(int fd) {
  tcp_info info{};
  socklen_t size = sizeof info;
  if (::getsockopt(fd, IPPROTO_TCP, TCP_INFO, &info, &size) != 0) return std::nullopt;
  if (size < offsetof(tcp_info, tcpi_snd_wnd) + sizeof info.tcpi_snd_wnd) return std::nullopt;
  return info.tcpi_snd_wnd;
}

}  // namespace sanet::wire
