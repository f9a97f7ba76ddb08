// radio_contacts.csv and summary.json's `radio_contacts` (RunSpec::radio_contacts): the contacts
// between pairs of nodes (trace/radio_contacts.h) from the frames the radios received whole from a
// known transmitter (net::FrameEvent, `rx` with a peer: acknowledgements and CTS name none). It
// hears frames on the bus only in a run with a network that writes results. Never part of the
// fingerprint: hearing frames changes nothing in the run (docs/scenario.md#radio_contactscsv).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "sim/run_events.h"
#include "sim/run_nodes.h"
#include "sim/run_spec.h"
#include "trace/radio_contacts.h"
#include "trace/results_folder.h"

namespace sanet::sim {

class RadioContactOutputs {
 public:
  RadioContactOutputs(const RunSpec& spec, const RunNodes& nodes, RunBus& bus, trace::ResultsFolder& folder);
  void Stop() { subscription_ = {}; }
  // Writes radio_contacts.csv, contacts still open at `run_end` (s) marked, and returns
  // summary.json's part; nothing when contacts were not recorded.
  std::optional<nlohmann::ordered_json> Write(double run_end);

 private:
  const RunNodes& nodes_;
  trace::ResultsFolder& folder_;
  trace::RadioContacts contacts_;
  Subscription subscription_;
  bool recording_ = false;
};

}  // namespace sanet::sim
