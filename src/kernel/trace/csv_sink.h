// A CSV output written whole (temporary file, then rename) and hashed as it is written, so the
// run's fingerprint covers exactly the bytes on disk. Without a path it only hashes.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/atomic_file.h"
#include "core/fingerprint.h"

namespace sanet::trace {

class CsvSink {
 public:
  // Rows are buffered up to `buffer_bytes` before they go to the file.
  CsvSink(std::optional<std::string> path, std::string_view header, std::size_t buffer_bytes = 1 << 20);
  void Row(std::string_view line);  // without the newline
  void Commit();                    // flush and move into place
  std::uint64_t hash() const { return fingerprint_.Value(); }
  std::size_t rows() const { return rows_; }

 private:
  void Flush();
  std::unique_ptr<AtomicFile> file_;
  std::string buffer_;
  Fingerprint fingerprint_;
  std::size_t rows_ = 0;
  std::size_t buffer_bytes_;
};

// Quotes a CSV field when it holds a comma, quote or newline.
std::string CsvField(std::string_view text);
// A time (s) as the results files write it: six decimals.
std::string CsvTime(double seconds);

}  // namespace sanet::trace
