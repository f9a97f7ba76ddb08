#include "trace/csv_sink.h"

#include <cstdio>

namespace sanet::trace {

CsvSink::CsvSink(std::optional<std::string> path, std::string_view header, std::size_t buffer_bytes)
    : buffer_bytes_(buffer_bytes) {
  if (path) file_ = std::make_unique<AtomicFile>(*path);
  buffer_.append(header);
  buffer_.push_back('\n');
}

void CsvSink::Row(std::string_view line) {
  buffer_.append(line);
  buffer_.push_back('\n');
  ++rows_;
  if (buffer_.size() > buffer_bytes_) Flush();
}

void CsvSink::Flush() {
  fingerprint_.Add(buffer_);
  if (file_) file_->Write(buffer_);
  buffer_.clear();
}

void CsvSink::Commit() {
  Flush();
  if (file_) file_->Commit();
}

std::string CsvField(std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out.push_back('"');
    out.push_back(c);
  }
  out.push_back('"');
  return out;
}

std::string CsvTime(double seconds) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6f", seconds);
  return text;
}

}  // namespace sanet::trace
