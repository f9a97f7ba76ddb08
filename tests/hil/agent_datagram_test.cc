#include "wire/agent_datagram.h"

#include <gtest/gtest.h>

namespace sanet::wire {
namespace {

AgentDatagram Pose(std::uint64_t sequence) {
  AgentDatagram d;
  d.from = 0;
  d.to = 1;
  d.sequence = sequence;
  d.time_sent = 12.5;
  d.payload = {1, 2, 3, 0x7b};
  return d;
}

std::optional<AgentDatagram> Open(const Bytes& b, const DatagramKey& key, std::string* why) {
  return OpenDatagram(b.data(), b.size(), key, why);
}

TEST(AgentDatagram, ASealedDatagramOpensWithItsKeyOnly) {
  const DatagramKey key = DatagramKey::Random();
  const Bytes sealed = SealDatagram(Pose(7), key);
  std::string why;
  const auto opened = Open(sealed, key, &why);
  ASSERT_TRUE(opened) << why;
  EXPECT_EQ(opened->from, 0u);
  EXPECT_EQ(opened->to, 1u);
  EXPECT_EQ(opened->sequence, 7u);
  EXPECT_EQ(opened->time_sent, 12.5);
  EXPECT_EQ(opened->payload, Pose(7).payload);
  EXPECT_FALSE(Open(sealed, DatagramKey::Random(), &why)) << "another run's key";
  EXPECT_NE(why.find("MAC"), std::string::npos) << why;
}

// Any byte changed, whether header, payload or MAC, and the datagram is refused.
TEST(AgentDatagram, EveryAlteredByteIsRefused) {
  const DatagramKey key = DatagramKey::Random();
  const Bytes sealed = SealDatagram(Pose(7), key);
  std::string why;
  for (std::size_t i = 0; i < sealed.size(); ++i) {
    Bytes altered = sealed;
    altered[i] ^= 0x01;
    EXPECT_FALSE(Open(altered, key, &why)) << "byte " << i;
  }
  EXPECT_FALSE(Open(Bytes(sealed.begin(), sealed.end() - 1), key, &why)) << "cut short";
  EXPECT_FALSE(Open(Bytes(10, 0x53), key, &why));
  EXPECT_EQ(why, "not a sanet datagram");
}

// The old attack: a pose claiming the leader with the highest sequence number, without the key.
TEST(AgentDatagram, AForgedDatagramWithoutTheKeyIsRefused) {
  const DatagramKey key = DatagramKey::Random();
  AgentDatagram forged = Pose(0xFFFFFFFFFFFFFFFF);
  Bytes bytes = SealDatagram(forged, DatagramKey::Random());
  std::string why;
  EXPECT_FALSE(Open(bytes, key, &why));
  bytes.resize(bytes.size() - kDatagramMac);
  bytes.insert(bytes.end(), kDatagramMac, 0);
  EXPECT_FALSE(Open(bytes, key, &why));
}

TEST(AgentDatagram, KeysRoundTripThroughHexAndAreNewEachTime) {
  const DatagramKey key = DatagramKey::Random();
  EXPECT_EQ(key.Hex().size(), 64u);
  EXPECT_EQ(DatagramKey::FromHex(key.Hex())->bytes(), key.bytes());
  EXPECT_NE(DatagramKey::Random().bytes(), key.bytes());
  EXPECT_FALSE(DatagramKey::FromHex("00"));
  EXPECT_FALSE(DatagramKey::FromHex(std::string(64, 'g')));
}

TEST(ReplayWindow, EachSequenceNumberCountsOnceAndOldOnesNever) {
  ReplayWindow w;
  EXPECT_FALSE(w.Take(0));
  EXPECT_TRUE(w.Take(1));
  EXPECT_FALSE(w.Take(1)) << "replayed";
  EXPECT_TRUE(w.Take(5));
  EXPECT_TRUE(w.Take(3)) << "reordered by the network: still counts, once";
  EXPECT_FALSE(w.Take(3));
  EXPECT_TRUE(w.Take(100));
  EXPECT_FALSE(w.Take(36)) << "older than the window of 64";
  EXPECT_TRUE(w.Take(37));
  EXPECT_TRUE(w.Take(1000000));
  EXPECT_FALSE(w.Take(100));
}

}  // namespace
}  // namespace sanet::wire
