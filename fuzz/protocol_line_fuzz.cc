// Any bytes as a client's stream to the simulation server: split into lines, parsed, and read as
// the messages the server and the agents take apart (numbers, MSG, RECV, every sensor kind's SEN
// line as an agent reads it). None may crash, hang or trip a sanitizer; a line that parses must
// format and parse again to the same message.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "sensors/sensor_registry.h"
#include "wire/message_lines.h"
#include "wire/protocol.h"
#include "wire/sensor_lines.h"

using sanet::wire::ProtocolMessage;

namespace {

// Every kind's SEN line reader, with the kind's settings on a diffdrive.
void ReadAsSensorLines(const ProtocolMessage& m) {
  static const sanet::robots::ModelSpec model = sanet::sensors::DefaultModel(sanet::robots::ModelKind::kDiffDrive);
  sanet::wire::LineContext context;
  context.name_of = [](sanet::NodeId) { return std::string("m1"); };
  context.lookup = [](const std::string&) -> std::optional<sanet::NodeId> { return sanet::NodeId{1}; };
  for (const sanet::sensors::SensorKind* kind : sanet::sensors::AllKinds())
    if (const sanet::wire::SensorLines* lines = sanet::wire::LinesOf(kind->Info().name))
      lines->Read(m, kind->DefaultSettings(model), context);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sanet::wire::LineReader reader(4096);
  // Fed in two pieces, as TCP may split it anywhere.
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::size_t half = size / 2;
  bool too_long = false;
  for (const std::string_view piece : {bytes.substr(0, half), bytes.substr(half)}) {
    reader.Append(piece);
    while (auto line = reader.Next(&too_long)) {
      std::string error;
      const auto m = sanet::wire::ParseLine(*line, &error);
      if (!m) continue;
      for (const auto& [key, value] : m->fields) {
        m->Number(key);
        m->Numbers(key);
      }
      sanet::wire::ParseMsgLine(*m, sanet::NodeId{0}, 1, &error);
      sanet::wire::ParseRecvLine(*m, sanet::NodeId{0}, 1, &error);
      ReadAsSensorLines(*m);
      const std::string again = sanet::wire::FormatLine(*m);
      const auto reparsed = sanet::wire::ParseLine(again.substr(0, again.size() - 2), &error);
      if (!reparsed || reparsed->type != m->type || reparsed->fields != m->fields) std::abort();
    }
    if (too_long) break;
  }
  return 0;
}
