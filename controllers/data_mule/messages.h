// The data mule's messages, on one byte of kind each:
//   beacon   robot -> broadcast  "I am here": motes in range send what they hold
//   reading  mote -> robot       one reading: its number and when it was made, padded to `size`
//   ack      robot -> mote       the reading's number: the mote may forget it
// and, where a base station takes the robot's readings (the robot's `sink`):
//   beacon   sink -> broadcast   "I am here": the robot sends what it holds
//   relayed  robot -> sink       one reading with the mote it came from, padded to `size`
//   relayed_ack  sink -> robot   the mote and the reading's number: the robot may forget it
#pragma once

#include <cstdint>

#include "sanet/codec.h"

namespace sanet::controllers::data_mule {

enum Kind : std::uint8_t { kBeacon = 1, kReading = 2, kAck = 3, kRelayed = 4, kRelayedAck = 5 };

struct Reading {
  std::uint32_t number = 0;
  double created = 0;  // s, simulated
};

inline Bytes BeaconMessage(int size) {
  Bytes b = Writer().U8(kBeacon).bytes();
  b.resize(size, 0);
  return b;
}

inline Bytes ReadingMessage(const Reading& r, int size) {
  Bytes b = Writer().U8(kReading).U32(r.number).F64(r.created).bytes();
  if (static_cast<int>(b.size()) < size) b.resize(size, 0);
  return b;
}

inline Bytes AckMessage(std::uint32_t number) { return Writer().U8(kAck).U32(number).bytes(); }

// A reading on its way to the sink: which mote made it.
struct Relayed {
  std::uint32_t mote = 0;
  Reading reading;
};

inline Bytes RelayedMessage(const Relayed& r, int size) {
  Bytes b = Writer().U8(kRelayed).U32(r.mote).U32(r.reading.number).F64(r.reading.created).bytes();
  if (static_cast<int>(b.size()) < size) b.resize(size, 0);
  return b;
}

inline Bytes RelayedAckMessage(std::uint32_t mote, std::uint32_t number) {
  return Writer().U8(kRelayedAck).U32(mote).U32(number).bytes();
}

}  // namespace sanet::controllers::data_mule
