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
  CsvSink(std::optional<std::string> path, std::string_view header);
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
};

// Quotes a CSV field when it holds a comma, quote or newline.
std::string CsvField(std::string_view text);

}  // namespace sanet::trace
