#include "wire/agent_datagram.h"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <openssl/rand.h>

#include <algorithm>
#include <stdexcept>

#include "sanet/codec.h"
#include "wire/message_lines.h"

namespace sanet::wire {
namespace {

constexpr std::uint8_t kMagic = 0x53;  // 'S'
constexpr std::uint8_t kVersion = 2;   // 1 had neither sequence number nor MAC

std::array<std::uint8_t, kDatagramMac> Mac(const DatagramKey& key, const std::uint8_t* data, std::size_t size) {
  std::array<std::uint8_t, kDatagramMac> mac{};
  unsigned int length = 0;
  HMAC(EVP_sha256(), key.bytes().data(), static_cast<int>(key.bytes().size()), data, size, mac.data(), &length);
  return mac;
}

}  // namespace

DatagramKey DatagramKey::Random() {
  DatagramKey key;
  if (RAND_bytes(key.bytes_.data(), static_cast<int>(key.bytes_.size())) != 1)
    throw std::runtime_error("the operating system gave no random bytes for the run's datagram key");
  return key;
}

std::string DatagramKey::Hex() const { return ToHex(Bytes(bytes_.begin(), bytes_.end())); }

std::optional<DatagramKey> DatagramKey::FromHex(const std::string& hex) {
  const std::optional<Bytes> bytes = wire::FromHex(hex);
  DatagramKey key;
  if (!bytes || bytes->size() != key.bytes_.size()) return std::nullopt;
  std::copy(bytes->begin(), bytes->end(), key.bytes_.begin());
  return key;
}

Bytes SealDatagram(const AgentDatagram& d, const DatagramKey& key) {
  Bytes bytes =
      Writer().U8(kMagic).U8(kVersion).U32(d.from).U32(d.to).U8(d.kind).U64(d.sequence).F64(d.time_sent).bytes();
  bytes.insert(bytes.end(), d.payload.begin(), d.payload.end());
  return WithMac(std::move(bytes), key);
}

Bytes WithMac(Bytes bytes, const DatagramKey& key) {
  const auto mac = Mac(key, bytes.data(), bytes.size());
  bytes.insert(bytes.end(), mac.begin(), mac.end());
  return bytes;
}

std::optional<AgentDatagram> OpenDatagram(const std::uint8_t* data, std::size_t size, const DatagramKey& key,
                                          std::string* why) {
  if (size < kDatagramHeader + kDatagramMac || data[0] != kMagic) {
    *why = "not a sanet datagram";
    return std::nullopt;
  }
  if (data[1] != kVersion) {
    *why = "datagram version " + std::to_string(data[1]) + ", this agent speaks " + std::to_string(kVersion);
    return std::nullopt;
  }
  const std::size_t signed_size = size - kDatagramMac;
  const auto mac = Mac(key, data, signed_size);
  if (CRYPTO_memcmp(mac.data(), data + signed_size, kDatagramMac) != 0) {
    *why =
        "its MAC does not hold (forged, altered, from another run, or sent with another key: a team's "
        "agents share one, --key-file or SANET_TEAM_KEY)";
    return std::nullopt;
  }
  Reader r(Bytes(data + 2, data + kDatagramHeader));
  AgentDatagram d;
  d.from = r.U32();
  d.to = r.U32();
  const std::uint8_t kind = r.U8();
  d.sequence = r.U64();
  d.time_sent = r.F64();
  if (kind != AgentDatagram::kUnicast && kind != AgentDatagram::kBroadcast) {
    *why = "unknown kind " + std::to_string(kind);
    return std::nullopt;
  }
  d.kind = static_cast<AgentDatagram::Kind>(kind);
  d.payload.assign(data + kDatagramHeader, data + signed_size);
  return d;
}

bool ReplayWindow::Take(std::uint64_t sequence) {
  if (sequence == 0) return false;
  if (sequence > highest_) {
    const std::uint64_t shift = sequence - highest_;
    seen_ = shift >= 64 ? 0 : seen_ << shift;
    seen_ |= 1;
    highest_ = sequence;
    return true;
  }
  const std::uint64_t age = highest_ - sequence;
  if (age >= 64 || (seen_ >> age & 1)) return false;
  seen_ |= std::uint64_t{1} << age;
  return true;
}

}  // namespace sanet::wire
