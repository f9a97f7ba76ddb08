#include "net/network_spec.h"

namespace sanet::net {

std::uint32_t Ns3Seed(std::uint64_t seed) {
  constexpr std::uint64_t kLargest = 4294944442;  // ns-3's RngStream: seeds must be under m2 = 4294944443
  const std::uint64_t mapped = seed % 4294967295u + 1;
  return static_cast<std::uint32_t>(mapped <= kLargest ? mapped : mapped - kLargest);
}

std::vector<double> DataRates(WifiStandard standard) {
  switch (standard) {
    case WifiStandard::k80211b:
      return {1, 2, 5.5, 11};
    case WifiStandard::k80211g:
    case WifiStandard::k80211a:
      return {6, 9, 12, 18, 24, 36, 48, 54};
  }
  return {};
}

const char* StandardName(WifiStandard standard) {
  switch (standard) {
    case WifiStandard::k80211b:
      return "802.11b";
    case WifiStandard::k80211g:
      return "802.11g";
    case WifiStandard::k80211a:
      return "802.11a";
  }
  return "?";
}

const char* ChannelName(ChannelModel model) { return model == ChannelModel::kYans ? "yans" : "indexed"; }

const char* RoutingName(Routing routing) {
  switch (routing) {
    case Routing::kNone:
      return "none";
    case Routing::kAodv:
      return "aodv";
    case Routing::kOlsr:
      return "olsr";
    case Routing::kDsdv:
      return "dsdv";
    case Routing::kDsr:
      return "dsr";
  }
  return "?";
}

}  // namespace sanet::net
