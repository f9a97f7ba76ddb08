#include "net/message_header.h"

#include <ostream>

namespace sanet::net {

NS_OBJECT_ENSURE_REGISTERED(MessageHeader);

ns3::TypeId MessageHeader::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::MessageHeader")
                               .SetParent<ns3::Header>()
                               .SetGroupName("sanet")
                               .AddConstructor<MessageHeader>();
  return tid;
}

void MessageHeader::Serialize(ns3::Buffer::Iterator i) const {
  i.WriteHtonU32(kMagic);
  i.WriteU8(kind);
  i.WriteHtonU32(origin);
  i.WriteHtonU32(destination);
  i.WriteHtonU32(sequence);
  i.WriteHtonU64(static_cast<std::uint64_t>(time_sent_ns));
  i.WriteU8(hops);
  i.WriteU8(ttl);
}

std::uint32_t MessageHeader::Deserialize(ns3::Buffer::Iterator i) {
  if (i.GetRemainingSize() < kSize || i.ReadNtohU32() != kMagic) return 0;
  kind = static_cast<Kind>(i.ReadU8());
  origin = i.ReadNtohU32();
  destination = i.ReadNtohU32();
  sequence = i.ReadNtohU32();
  time_sent_ns = static_cast<std::int64_t>(i.ReadNtohU64());
  hops = i.ReadU8();
  ttl = i.ReadU8();
  return kSize;
}

void MessageHeader::Print(std::ostream& os) const {
  os << "sanet kind=" << int(kind) << " origin=" << origin << " destination=" << destination << " seq=" << sequence
     << " hops=" << int(hops) << " ttl=" << int(ttl);
}

}  // namespace sanet::net
