#include "trace/mcap_reader.h"

#include <zstd.h>

#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>

#include "trace/mcap_format.h"

namespace sanet::trace {
namespace {

using namespace mcap;  // the format's magic and opcodes

// Little-endian fields of one record's content, never past its end.
class Fields {
 public:
  Fields(const std::uint8_t* data, std::size_t size, const std::string& where) : p_(data), n_(size), where_(where) {}
  template <typename T>
  T Int() {
    Need(sizeof(T));
    T value = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) value |= static_cast<T>(static_cast<T>(p_[at_ + i]) << (8 * i));
    at_ += sizeof(T);
    return value;
  }
  std::string Text() {
    const auto n = Int<std::uint32_t>();
    Need(n);
    std::string s(reinterpret_cast<const char*>(p_ + at_), n);
    at_ += n;
    return s;
  }
  std::vector<std::uint8_t> Bytes(std::uint64_t n) {
    Need(n);
    std::vector<std::uint8_t> b(p_ + at_, p_ + at_ + n);
    at_ += n;
    return b;
  }
  std::vector<std::uint8_t> Rest() { return Bytes(n_ - at_); }

 private:
  void Need(std::uint64_t n) const {
    if (n > n_ - at_) throw std::runtime_error(where_ + ": a record is cut short");
  }
  const std::uint8_t* p_;
  std::size_t n_, at_ = 0;
  std::string where_;
};

class Reader {
 public:
  Reader(const McapVisitor& visit, const std::string& path) : visit_(visit), path_(path) {}
  // The file, a record at a time; false if the visitor stopped.
  bool File(std::ifstream& in);
  bool stopped() const { return stopped_; }

 private:
  // The records in [data, data + size) (a chunk's).
  void Records(const std::uint8_t* data, std::size_t size, std::uint64_t base);
  void Record(std::uint8_t op, Fields content, std::uint64_t offset);
  void Chunk(Fields content, std::uint64_t offset);
  std::string At(std::uint64_t offset) const { return path_ + " at byte " + std::to_string(offset); }

  const McapVisitor& visit_;
  std::string path_;
  bool stopped_ = false;
  std::map<std::uint16_t, std::vector<std::string>> schemas_;  // id -> name, encoding, data
  std::map<std::uint16_t, bool> channels_;
};

bool Reader::File(std::ifstream& in) {
  std::uint64_t offset = sizeof kMagic;
  std::vector<std::uint8_t> content;
  while (!stopped_) {
    std::uint8_t head[9];
    if (!in.read(reinterpret_cast<char*>(head), sizeof head)) {
      if (in.gcount() == 0) return true;  // the end, without a data end (a run stopped hard)
      throw std::runtime_error(At(offset) + ": the file ends inside a record (cut short?)");
    }
    std::uint64_t length = 0;
    for (int i = 0; i < 8; ++i) length |= static_cast<std::uint64_t>(head[1 + i]) << (8 * i);
    if (head[0] == kDataEnd) return true;
    if (length > (std::uint64_t{1} << 32)) throw std::runtime_error(At(offset) + ": a record of impossible length");
    content.resize(length);
    if (!in.read(reinterpret_cast<char*>(content.data()), static_cast<std::streamsize>(length)))
      throw std::runtime_error(At(offset) + ": the record that starts here (" + std::to_string(length) +
                               " bytes) goes past the file's end (cut short?)");
    Record(head[0], Fields(content.data(), content.size(), At(offset)), offset);
    offset += sizeof head + length;
  }
  return false;
}

void Reader::Records(const std::uint8_t* data, std::size_t size, std::uint64_t base) {
  std::size_t at = 0;
  while (at < size && !stopped_) {
    if (size - at < 9) throw std::runtime_error(At(base) + ": a chunk's record is cut short");
    std::uint64_t length = 0;
    for (int i = 0; i < 8; ++i) length |= static_cast<std::uint64_t>(data[at + 1 + i]) << (8 * i);
    if (length > size - at - 9) throw std::runtime_error(At(base) + ": a chunk's record is cut short");
    Record(data[at], Fields(data + at + 9, length, At(base)), base);
    at += 9 + length;
  }
}

void Reader::Record(std::uint8_t op, Fields f, std::uint64_t offset) {
  if (op == kHeader) {
    const std::string profile = f.Text();
    if (visit_.header) visit_.header(profile);
  } else if (op == kSchema) {
    const auto id = f.Int<std::uint16_t>();
    std::string name = f.Text(), encoding = f.Text(), data = f.Text();
    schemas_[id] = {name, encoding, data};
  } else if (op == kChannel) {
    McapChannel c;
    c.id = f.Int<std::uint16_t>();
    const auto schema = schemas_.find(f.Int<std::uint16_t>());
    c.topic = f.Text();
    c.message_encoding = f.Text();
    if (schema != schemas_.end())
      c.schema_name = schema->second[0], c.schema_encoding = schema->second[1], c.schema = schema->second[2];
    if (!channels_[c.id] && visit_.channel) visit_.channel(c);
    channels_[c.id] = true;
  } else if (op == kMessage) {
    McapMessage m;
    m.channel = f.Int<std::uint16_t>();
    f.Int<std::uint32_t>();  // sequence
    m.log_time = f.Int<std::uint64_t>();
    f.Int<std::uint64_t>();  // publish time
    m.data = f.Rest();
    if (visit_.message && !visit_.message(m)) stopped_ = true;
  } else if (op == kChunk) {
    Chunk(f, offset);
  }
}

void Reader::Chunk(Fields f, std::uint64_t offset) {
  f.Int<std::uint64_t>();  // start and end times
  f.Int<std::uint64_t>();
  const auto size = f.Int<std::uint64_t>();
  f.Int<std::uint32_t>();  // CRC (0: not given); zstd checks its own frames
  const std::string compression = f.Text();
  std::vector<std::uint8_t> records = f.Bytes(f.Int<std::uint64_t>());
  if (compression == kZstd) {
    std::vector<std::uint8_t> plain(size);
    const std::size_t n = ZSTD_decompress(plain.data(), plain.size(), records.data(), records.size());
    if (ZSTD_isError(n) || n != size) throw std::runtime_error(At(offset) + ": a damaged zstd chunk");
    records.swap(plain);
  } else if (!compression.empty()) {
    throw std::runtime_error(At(offset) + ": chunks compressed with '" + compression + "' cannot be read here");
  }
  Records(records.data(), records.size(), offset);
}

}  // namespace

bool ReadMcap(const std::string& path, const McapVisitor& visit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::uint8_t magic[sizeof kMagic];
  if (!in.read(reinterpret_cast<char*>(magic), sizeof magic) || std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    throw std::runtime_error(path + " is not an MCAP file");
  return Reader(visit, path).File(in);
}

}  // namespace sanet::trace
