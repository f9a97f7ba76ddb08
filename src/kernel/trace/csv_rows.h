// Reads a results CSV (RFC 4180: fields with commas, quotes or line breaks are quoted) row by row.
#pragma once

#include <fstream>
#include <string>
#include <vector>

namespace sanet::trace {

class CsvRows {
 public:
  explicit CsvRows(const std::string& path);
  bool ok() const { return ok_; }  // the file exists and has a header
  const std::vector<std::string>& header() const { return header_; }
  bool Next(std::vector<std::string>& row);

 private:
  std::ifstream in_;
  bool ok_ = false;
  std::vector<std::string> header_;
};

}  // namespace sanet::trace
