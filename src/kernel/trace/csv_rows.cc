#include "trace/csv_rows.h"

namespace sanet::trace {

CsvRows::CsvRows(const std::string& path) : in_(path) { ok_ = in_ && Next(header_) && !header_.empty(); }

bool CsvRows::Next(std::vector<std::string>& row) {
  row.clear();
  if (in_.peek() == std::char_traits<char>::eof()) return false;
  std::string field;
  bool quoted = false;
  for (char c; in_.get(c);) {
    if (quoted) {
      if (c != '"') {
        field += c;
      } else if (in_.peek() == '"') {
        field += static_cast<char>(in_.get());
      } else {
        quoted = false;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      row.push_back(std::move(field));
      field.clear();
    } else if (c == '\n') {
      break;
    } else if (c != '\r') {
      field += c;
    }
  }
  row.push_back(std::move(field));
  return true;
}

}  // namespace sanet::trace
