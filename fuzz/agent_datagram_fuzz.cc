// Any bytes as a datagram from a peer: the decoder refuses them or opens them, never crashes.
// The first byte chooses: odd, the rest is opened as it came (nearly all fail the MAC); even, the
// rest gets a valid MAC first, so that the decoder's work past the MAC (versions, kinds, sizes
// no sender writes) is fuzzed too, and a datagram that opens must seal back to the same bytes.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "wire/agent_datagram.h"

using sanet::wire::DatagramKey;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const sanet::wire::DatagramKey key = *sanet::wire::DatagramKey::FromHex(std::string(64, '7'));
  if (size == 0) return 0;
  std::string why;
  if (data[0] & 1) {
    sanet::wire::OpenDatagram(data + 1, size - 1, key, &why);
    return 0;
  }
  const sanet::Bytes signed_bytes = sanet::wire::WithMac(sanet::Bytes(data + 1, data + size), key);
  const auto opened = sanet::wire::OpenDatagram(signed_bytes.data(), signed_bytes.size(), key, &why);
  if (opened && sanet::wire::SealDatagram(*opened, key) != signed_bytes) std::abort();
  return 0;
}
