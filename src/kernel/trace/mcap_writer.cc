#include "trace/mcap_writer.h"

#include <zlib.h>
#include <zstd.h>

#include <algorithm>
#include <stdexcept>

#include "trace/mcap_format.h"

namespace sanet::trace {
namespace {

using Bytes = McapWriter::Bytes;

using namespace mcap;  // the format's magic and opcodes

// Little-endian integers, strings and maps as the specification's "Serialization" section says.
template <typename T>
void Int(Bytes& b, T value) {
  for (std::size_t i = 0; i < sizeof(T); ++i) b.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}
void Text(Bytes& b, const std::string& s) {
  Int<std::uint32_t>(b, static_cast<std::uint32_t>(s.size()));
  b.insert(b.end(), s.begin(), s.end());
}
void Append(Bytes& b, const Bytes& more) { b.insert(b.end(), more.begin(), more.end()); }

Bytes Record(Op op, const Bytes& content) {
  Bytes r{op};
  Int<std::uint64_t>(r, content.size());
  Append(r, content);
  return r;
}

std::uint32_t Crc(std::uint32_t crc, const Bytes& b) {
  return static_cast<std::uint32_t>(::crc32(crc, b.data(), static_cast<uInt>(b.size())));
}

template <typename Value>
void Map(Bytes& b, const std::map<std::uint16_t, Value>& map) {
  Int<std::uint32_t>(b, static_cast<std::uint32_t>(map.size() * (2 + sizeof(Value))));
  for (const auto& [key, value] : map) {
    Int<std::uint16_t>(b, key);
    Int<Value>(b, value);
  }
}

const char* CompressionName(McapWriter::Compression c) { return c == McapWriter::Compression::kZstd ? kZstd : ""; }

// A chunk's records as the chunk stores them. Zstandard's fastest level packs a run's repetitive
// messages several times over at a small share of the run's time (bench/trace_bench.py).
Bytes Compressed(McapWriter::Compression c, const Bytes& records) {
  if (c == McapWriter::Compression::kNone) return records;
  Bytes out(ZSTD_compressBound(records.size()));
  const std::size_t n = ZSTD_compress(out.data(), out.size(), records.data(), records.size(), 1);
  if (ZSTD_isError(n))
    throw std::runtime_error(std::string("an MCAP chunk could not be compressed: ") + ZSTD_getErrorName(n));
  out.resize(n);
  return out;
}

}  // namespace

McapWriter::McapWriter(const std::string& path, const std::string& profile, const std::string& library,
                       Compression compression, std::size_t chunk_bytes)
    : out_(path, std::ios::binary | std::ios::trunc), compression_(compression), chunk_bytes_(chunk_bytes) {
  if (!out_) throw std::runtime_error("cannot write " + path);
  Put(Bytes(std::begin(kMagic), std::end(kMagic)));
  Bytes header;
  Text(header, profile);
  Text(header, library);
  Put(Record(kHeader, header));
}

McapWriter::~McapWriter() {
  try {
    Close();
  } catch (...) {
  }
}

void McapWriter::Put(const Bytes& bytes) {
  out_.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  offset_ += bytes.size();
  data_crc_ = Crc(data_crc_, bytes);
}

std::uint16_t McapWriter::AddSchema(const std::string& name, const std::string& encoding, const std::string& data) {
  schemas_.push_back({static_cast<std::uint16_t>(schemas_.size() + 1), name, encoding, data});
  return schemas_.back().id;
}

std::uint16_t McapWriter::AddChannel(std::uint16_t schema, const std::string& topic,
                                     const std::string& message_encoding,
                                     const std::map<std::string, std::string>& metadata) {
  if (channels_.size() >= 65535) throw std::length_error("an MCAP file holds at most 65535 channels");
  channels_.push_back({static_cast<std::uint16_t>(channels_.size() + 1), schema, topic, message_encoding, metadata});
  sequence_.push_back(0);
  per_channel_.push_back(0);
  return channels_.back().id;
}

namespace {

Bytes SchemaRecord(std::uint16_t id, const std::string& name, const std::string& encoding, const std::string& data) {
  Bytes c;
  Int<std::uint16_t>(c, id);
  Text(c, name);
  Text(c, encoding);
  Text(c, data);  // uint32 length-prefixed bytes
  return Record(kSchema, c);
}

Bytes ChannelRecord(std::uint16_t id, std::uint16_t schema, const std::string& topic, const std::string& encoding,
                    const std::map<std::string, std::string>& metadata) {
  Bytes c, entries;
  Int<std::uint16_t>(c, id);
  Int<std::uint16_t>(c, schema);
  Text(c, topic);
  Text(c, encoding);
  for (const auto& [key, value] : metadata) {
    Text(entries, key);
    Text(entries, value);
  }
  Int<std::uint32_t>(c, static_cast<std::uint32_t>(entries.size()));
  Append(c, entries);
  return Record(kChannel, c);
}

}  // namespace

// Schemas and channels added since the last were written go into the chunk being gathered.
void McapWriter::ChunkNewDefinitions() {
  for (; schemas_written_ < schemas_.size(); ++schemas_written_) {
    const Schema& s = schemas_[schemas_written_];
    Append(chunk_, SchemaRecord(s.id, s.name, s.encoding, s.data));
  }
  for (; channels_written_ < channels_.size(); ++channels_written_) {
    const Channel& c = channels_[channels_written_];
    Append(chunk_, ChannelRecord(c.id, c.schema, c.topic, c.encoding, c.metadata));
  }
}

void McapWriter::Write(std::uint16_t channel, std::uint64_t log_time, std::uint64_t publish_time, const Bytes& data) {
  if (closed_) throw std::logic_error("McapWriter::Write after Close");
  if (channel == 0 || channel > channels_.size())
    throw std::out_of_range("McapWriter: no channel " + std::to_string(channel));
  ChunkNewDefinitions();  // before the messages that use them
  const bool first_in_chunk = chunk_index_.empty();
  chunk_start_ = first_in_chunk ? log_time : std::min(chunk_start_, log_time);
  chunk_end_ = first_in_chunk ? log_time : std::max(chunk_end_, log_time);
  first_ = message_count_ == 0 ? log_time : std::min(first_, log_time);
  last_ = message_count_ == 0 ? log_time : std::max(last_, log_time);
  chunk_index_[channel].push_back({log_time, chunk_.size()});
  // The Message record straight into the chunk: opcode, length, channel, sequence, times, data.
  chunk_.push_back(kMessage);
  Int<std::uint64_t>(chunk_, 2 + 4 + 8 + 8 + data.size());
  Int<std::uint16_t>(chunk_, channel);
  Int<std::uint32_t>(chunk_, sequence_[channel - 1]++);
  Int<std::uint64_t>(chunk_, log_time);
  Int<std::uint64_t>(chunk_, publish_time);
  Append(chunk_, data);
  ++message_count_;
  ++per_channel_[channel - 1];
  if (chunk_.size() >= chunk_bytes_) FlushChunk();
}

// The chunk, then a Message Index per channel in it, and its Chunk Index kept for the summary.
void McapWriter::FlushChunk() {
  if (chunk_.empty()) return;
  Bytes c;
  Int<std::uint64_t>(c, chunk_index_.empty() ? 0 : chunk_start_);
  Int<std::uint64_t>(c, chunk_index_.empty() ? 0 : chunk_end_);
  Int<std::uint64_t>(c, chunk_.size());
  Int<std::uint32_t>(c, Crc(0, chunk_));
  const Bytes records = Compressed(compression_, chunk_);
  Text(c, CompressionName(compression_));
  Int<std::uint64_t>(c, records.size());
  Append(c, records);
  const std::uint64_t chunk_offset = offset_;
  const Bytes chunk = Record(kChunk, c);
  Put(chunk);
  std::map<std::uint16_t, std::uint64_t> index_offsets;
  const std::uint64_t indexes_start = offset_;
  for (const auto& [channel, entries] : chunk_index_) {
    Bytes i;
    Int<std::uint16_t>(i, channel);
    Int<std::uint32_t>(i, static_cast<std::uint32_t>(entries.size() * 16));
    for (const auto& [time, at] : entries) {
      Int<std::uint64_t>(i, time);
      Int<std::uint64_t>(i, at);
    }
    index_offsets[channel] = offset_;
    Put(Record(kMessageIndex, i));
  }
  Bytes x;
  Int<std::uint64_t>(x, chunk_index_.empty() ? 0 : chunk_start_);
  Int<std::uint64_t>(x, chunk_index_.empty() ? 0 : chunk_end_);
  Int<std::uint64_t>(x, chunk_offset);
  Int<std::uint64_t>(x, chunk.size());
  Map(x, index_offsets);
  Int<std::uint64_t>(x, offset_ - indexes_start);
  Text(x, CompressionName(compression_));
  Int<std::uint64_t>(x, records.size());
  Int<std::uint64_t>(x, chunk_.size());
  Append(chunk_indexes_, Record(kChunkIndex, x));
  ++chunk_count_;
  chunk_.clear();
  chunk_index_.clear();
}

void McapWriter::Close() {
  if (closed_) return;
  closed_ = true;
  ChunkNewDefinitions();  // channels that had no message
  FlushChunk();
  Bytes end;
  Int<std::uint32_t>(end, data_crc_);
  Put(Record(kDataEnd, end));
  WriteSummary(offset_);
  out_.flush();
  if (!out_) throw std::runtime_error("an MCAP file could not be written whole (disk full?)");
  out_.close();
}

// Schemas, channels, chunk indexes and statistics, each group once, then where each group
// starts (Summary Offset records), the footer with the summary's CRC32, and the magic.
void McapWriter::WriteSummary(std::uint64_t summary_start) {
  std::vector<std::pair<Op, Bytes>> groups;
  Bytes schemas, channels, statistics;
  for (const Schema& s : schemas_) Append(schemas, SchemaRecord(s.id, s.name, s.encoding, s.data));
  for (const Channel& c : channels_) Append(channels, ChannelRecord(c.id, c.schema, c.topic, c.encoding, c.metadata));
  Bytes st;
  Int<std::uint64_t>(st, message_count_);
  Int<std::uint16_t>(st, static_cast<std::uint16_t>(schemas_.size()));
  Int<std::uint32_t>(st, static_cast<std::uint32_t>(channels_.size()));
  Int<std::uint32_t>(st, 0);  // attachments
  Int<std::uint32_t>(st, 0);  // metadata
  Int<std::uint32_t>(st, chunk_count_);
  Int<std::uint64_t>(st, first_);
  Int<std::uint64_t>(st, last_);
  std::map<std::uint16_t, std::uint64_t> per_channel;
  for (std::size_t i = 0; i < per_channel_.size(); ++i)
    if (per_channel_[i] > 0) per_channel[static_cast<std::uint16_t>(i + 1)] = per_channel_[i];
  Map(st, per_channel);
  statistics = Record(kStatistics, st);
  groups = {{kSchema, schemas}, {kChannel, channels}, {kChunkIndex, chunk_indexes_}, {kStatistics, statistics}};
  std::uint32_t crc = 0;  // from the summary's start through the footer's summary_offset_start
  const auto put = [&](const Bytes& b) {
    Put(b);
    crc = Crc(crc, b);
  };
  std::vector<std::pair<Op, std::pair<std::uint64_t, std::uint64_t>>> where;
  for (const auto& [op, bytes] : groups)
    if (!bytes.empty()) {
      where.push_back({op, {offset_, bytes.size()}});
      put(bytes);
    }
  const std::uint64_t offsets_start = offset_;
  for (const auto& [op, at] : where) {
    Bytes o{op};
    Int<std::uint64_t>(o, at.first);
    Int<std::uint64_t>(o, at.second);
    put(Record(kSummaryOffset, o));
  }
  Bytes footer{kFooter};
  Int<std::uint64_t>(footer, 8 + 8 + 4);
  Int<std::uint64_t>(footer, where.empty() ? 0 : summary_start);
  Int<std::uint64_t>(footer, where.empty() ? 0 : offsets_start);
  crc = Crc(crc, footer);
  Int<std::uint32_t>(footer, crc);
  Put(footer);
  Put(Bytes(std::begin(kMagic), std::end(kMagic)));
}

}  // namespace sanet::trace
