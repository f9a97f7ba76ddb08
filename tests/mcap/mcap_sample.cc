// Writes an MCAP file with trace::McapWriter for tests/mcap/mcap_test.py: two schemas (ROS 2
// message definitions, as the trace will carry them), three channels, one of them without
// messages, and COUNT messages a channel, with times that sometimes go back, in chunks of
// CHUNK bytes, so that the file has many chunks and indexes; with `zstd`, compressed.
//
//   mcap_sample FILE COUNT CHUNK [zstd]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "trace/mcap_writer.h"

int main(int argc, char** argv) {
  using sanet::trace::McapWriter;
  if (argc != 4 && argc != 5) {
    std::fprintf(stderr, "usage: mcap_sample FILE COUNT CHUNK [zstd]\n");
    return 2;
  }
  const long count = std::atol(argv[2]);
  const auto compression = argc == 5 ? McapWriter::Compression::kZstd : McapWriter::Compression::kNone;
  McapWriter mcap(argv[1], "ros2", "sanet tests", compression, static_cast<std::size_t>(std::atol(argv[3])));
  const auto point = mcap.AddSchema("geometry_msgs/msg/Point", "ros2msg", "float64 x\nfloat64 y\nfloat64 z\n");
  const auto text = mcap.AddSchema("std_msgs/msg/String", "ros2msg", "string data\n");
  const auto a = mcap.AddChannel(point, "/r1/point", "cdr", {{"offered_qos_profiles", ""}});
  const auto b = mcap.AddChannel(text, "/log", "cdr");
  mcap.AddChannel(text, "/silent", "cdr");
  for (long i = 0; i < count; ++i) {
    const std::uint64_t t = static_cast<std::uint64_t>(i) * 100000000 + (i % 7 == 3 ? 0 : 50000000);
    // CDR, little endian: encapsulation header, then the fields (doubles aligned to 8 from after it).
    sanet::trace::McapWriter::Bytes p(4);  // encapsulation: CDR, little endian
    p[1] = 0x01;
    p.reserve(28);  // (GCC 12 warns of a copy into the first 4 bytes' storage otherwise)
    for (double v : {static_cast<double>(i), -static_cast<double>(i), 0.5}) {
      const auto* bytes = reinterpret_cast<const std::uint8_t*>(&v);
      p.insert(p.end(), bytes, bytes + 8);
    }
    mcap.Write(a, t, t, p);
    const std::string s = "message " + std::to_string(i);
    sanet::trace::McapWriter::Bytes m(4);
    m[1] = 0x01;
    m.reserve(64);
    const auto n = static_cast<std::uint32_t>(s.size() + 1);
    for (int k = 0; k < 4; ++k) m.push_back(static_cast<std::uint8_t>(n >> (8 * k)));
    m.insert(m.end(), s.begin(), s.end());
    m.push_back(0);
    mcap.Write(b, t + 1, t, m);
  }
  mcap.Close();
  std::printf("%llu\n", static_cast<unsigned long long>(mcap.messages()));
  return 0;
}
