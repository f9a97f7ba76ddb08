#include "trace/radio_contacts.h"

#include <algorithm>
#include <tuple>

namespace sanet::trace {

void RadioContacts::Heard(double t, NodeId transmitter, NodeId receiver) {
  if (transmitter == receiver) return;
  const NodeId a = std::min(transmitter, receiver), b = std::max(transmitter, receiver);
  auto [it, first] = current_.try_emplace({a, b});
  RadioContact& contact = it->second;
  if (!first && t - contact.end > silence_) {
    closed_.push_back(contact);
    contact = RadioContact{};
  }
  if (contact.frames() == 0) contact.a = a, contact.b = b, contact.start = t;
  contact.end = t;
  ++(transmitter == a ? contact.a_to_b : contact.b_to_a);
}

std::vector<RadioContact> RadioContacts::Contacts(double run_end) const {
  std::vector<RadioContact> all = closed_;
  for (const auto& [pair, contact] : current_) {
    all.push_back(contact);
    all.back().open = run_end - contact.end <= silence_;
  }
  std::sort(all.begin(), all.end(), [](const RadioContact& x, const RadioContact& y) {
    return std::tie(x.start, x.a, x.b) < std::tie(y.start, y.a, y.b);
  });
  return all;
}

std::vector<double> InterContactTimes(const std::vector<RadioContact>& contacts) {
  std::map<std::pair<NodeId, NodeId>, double> last_end;
  std::vector<double> gaps;
  for (const RadioContact& c : contacts) {  // by start time: each pair's contacts in order
    auto [it, first] = last_end.try_emplace({c.a, c.b}, c.end);
    if (!first) gaps.push_back(c.start - it->second);
    it->second = c.end;
  }
  return gaps;
}

}  // namespace sanet::trace
