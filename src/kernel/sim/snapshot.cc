#include "sim/snapshot.h"

namespace sanet::sim {
namespace {

template <typename T, typename Make>
const T& Lazily(std::optional<T>& cache, Make make) {
  if (!cache) cache = make();
  return *cache;
}

template <typename T, typename Read>
std::vector<T> PerNode(std::size_t count, Read read) {
  std::vector<T> out;
  out.reserve(count);
  for (NodeId id = 0; id < count; ++id) out.push_back(read(id));
  return out;
}

}  // namespace

const std::vector<BodyState>& WorldSnapshot::bodies() const {
  return Lazily(bodies_, [&] { return PerNode<BodyState>(node_count(), [&](NodeId id) { return source_.Body(id); }); });
}

const std::vector<std::vector<NodeId>>& WorldSnapshot::radio_neighbours() const {
  return Lazily(neighbours_, [&] {
    return PerNode<std::vector<NodeId>>(node_count(), [&](NodeId id) { return source_.RadioNeighbours(id); });
  });
}

const std::vector<MessageInFlight>& WorldSnapshot::messages_in_flight() const {
  return Lazily(in_flight_, [&] { return source_.MessagesInFlight(); });
}

const std::vector<std::string>& WorldSnapshot::controller_states() const {
  return Lazily(states_, [&] {
    return PerNode<std::string>(node_count(), [&](NodeId id) { return source_.ControllerState(id); });
  });
}

}  // namespace sanet::sim
