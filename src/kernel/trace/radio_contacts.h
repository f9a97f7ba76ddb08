// Radio contacts between pairs of nodes, from the frames their radios heard: what data-mule and
// delay-tolerant-network studies measure (contact and inter-contact times, as defined by
// Chaintreau et al., "Impact of human mobility on opportunistic forwarding algorithms", IEEE TMC
// 2007). A contact of the unordered pair {a, b} is a maximal run of frames one of them received
// from the other (either direction) in which no two consecutive frames are more than `silence`
// apart: a gap of exactly `silence` keeps the contact. It starts at its first frame and ends at
// its last (a contact of one frame lasts 0 s). A contact is open when the run ended before more
// than `silence` had passed since its last frame: it might have gone on. The inter-contact time
// of a pair is the gap from one of its contacts' end to its next contact's start.
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "sanet/message.h"

namespace sanet::trace {

struct RadioContact {
  NodeId a = 0, b = 0;  // a < b (node ids)
  double start = 0, end = 0;
  std::uint64_t a_to_b = 0, b_to_a = 0;  // frames b heard from a, and a from b
  bool open = false;
  std::uint64_t frames() const { return a_to_b + b_to_a; }
  double duration() const { return end - start; }
};

class RadioContacts {
 public:
  explicit RadioContacts(double silence) : silence_(silence) {}
  double silence() const { return silence_; }

  // `receiver` heard a frame `transmitter` sent, at `t` (s); frames come in time order.
  void Heard(double t, NodeId transmitter, NodeId receiver);

  // Every contact, by start time (then a, then b), those still open at `run_end` (s) marked.
  std::vector<RadioContact> Contacts(double run_end) const;

 private:
  double silence_;
  std::map<std::pair<NodeId, NodeId>, RadioContact> current_;  // each pair's latest contact
  std::vector<RadioContact> closed_;
};

// Every pair's gaps from one contact's end to its next one's start (s), in the order of the
// later contacts' starts; `contacts` as Contacts gives them.
std::vector<double> InterContactTimes(const std::vector<RadioContact>& contacts);

}  // namespace sanet::trace
