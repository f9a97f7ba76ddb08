#include "sim/radio_contact_outputs.h"

#include <cstdio>
#include <set>
#include <utility>

#include "core/statistics.h"
#include "trace/csv_sink.h"

namespace sanet::sim {
namespace {

constexpr const char* kHeader = "a,b,start_s,end_s,frames,frames_a_to_b,frames_b_to_a,open";

std::string Numbers(const trace::RadioContact& c) {
  char row[160];
  std::snprintf(row, sizeof row, ",%.6f,%.6f,%llu,%llu,%llu,%d", c.start, c.end, (unsigned long long)c.frames(),
                (unsigned long long)c.a_to_b, (unsigned long long)c.b_to_a, c.open ? 1 : 0);
  return row;
}

// Durations of the closed contacts only: an open one's is cut short by the run's end.
nlohmann::ordered_json Summary(const std::vector<trace::RadioContact>& contacts, double silence) {
  std::vector<double> durations;
  std::set<std::pair<NodeId, NodeId>> pairs;
  for (const trace::RadioContact& c : contacts) {
    pairs.insert({c.a, c.b});
    if (!c.open) durations.push_back(c.duration());
  }
  return {{"silence_s", silence},
          {"contacts", contacts.size()},
          {"open", contacts.size() - durations.size()},
          {"pairs", pairs.size()},
          {"duration_s", Quartiles(durations)},
          {"inter_contact_s", Quartiles(trace::InterContactTimes(contacts))}};
}

}  // namespace

RadioContactOutputs::RadioContactOutputs(const RunSpec& spec, const RunNodes& nodes, RunBus& bus,
                                         trace::ResultsFolder& folder)
    : nodes_(nodes), folder_(folder), contacts_(spec.contact_silence) {
  if (!spec.radio_contacts || !spec.network || !folder.writes()) return;
  recording_ = true;
  subscription_ = bus.On<net::FrameEvent>(RunStage::kRecord, [this](const net::FrameEvent& f) {
    if (!f.sent && f.peer) contacts_.Heard(f.t, *f.peer, f.node);
  });
}

std::optional<nlohmann::ordered_json> RadioContactOutputs::Write(double run_end) {
  if (!recording_) return std::nullopt;
  Stop();
  const std::vector<trace::RadioContact> contacts = contacts_.Contacts(run_end);
  trace::CsvSink& csv = folder_.Csv("radio_contacts.csv", kHeader);
  for (const trace::RadioContact& c : contacts)
    csv.Row(trace::CsvField(nodes_.NameOf(c.a)) + "," + trace::CsvField(nodes_.NameOf(c.b)) + Numbers(c));
  return Summary(contacts, contacts_.silence());
}

}  // namespace sanet::sim
