#include "net/link_calibration.h"

#include <algorithm>
#include <sstream>

namespace sanet::net {
namespace {

constexpr const char* kColumns[] = {"mean_dbm", "prr", "access_delay_s", "unicast_prr"};

// Linear interpolation of `field` at `dbm` between the rows around it, the end rows' beyond them.
template <typename Field>
double Interpolate(const std::vector<LinkCalibration::Row>& rows, double dbm, Field field) {
  if (rows.empty()) return 0;
  if (dbm <= rows.front().mean_dbm) return field(rows.front());
  if (dbm >= rows.back().mean_dbm) return field(rows.back());
  const auto above = std::upper_bound(rows.begin(), rows.end(), dbm,
                                      [](double v, const LinkCalibration::Row& r) { return v < r.mean_dbm; });
  const auto below = above - 1;
  const double share = (dbm - below->mean_dbm) / (above->mean_dbm - below->mean_dbm);
  return field(*below) + share * (field(*above) - field(*below));
}

std::string Trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\xEF\xBB\xBF");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// Every cell, a trailing empty one included ("1,2," has three).
std::vector<std::string> Cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
    cells.push_back(Trim(line.substr(start, comma - start)));
  cells.push_back(Trim(line.substr(start)));
  return cells;
}

double Number(const std::string& cell, int line, const char* column) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(cell, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != cell.size()) throw CalibrationCsvError(line, column, "'" + cell + "' is not a number");
  return value;
}

}  // namespace

double LinkCalibration::Prr(double dbm) const {
  if (dbm < LowestHeardDbm()) return 0;
  return std::clamp(Interpolate(rows, dbm, [](const Row& r) { return r.prr; }), 0.0, 1.0);
}

double LinkCalibration::UnicastPrr(double dbm) const {
  if (dbm < LowestHeardDbm()) return 0;
  return std::clamp(Interpolate(rows, dbm, [](const Row& r) { return r.unicast_prr; }), 0.0, 1.0);
}

double LinkCalibration::AccessDelay(double dbm) const {
  return std::max(0.0, Interpolate(rows, dbm, [](const Row& r) { return r.access_delay_s; }));
}

double LinkCalibration::LowestHeardDbm() const {
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].prr > 0 || rows[i].unicast_prr > 0) return i == 0 ? rows[0].mean_dbm : rows[i - 1].mean_dbm;
  return rows.empty() ? 0 : rows.back().mean_dbm + 1;  // never heard
}

LinkCalibration ParseLinkCalibrationCsv(const std::string& text) {
  std::stringstream in(text);
  std::vector<int> lines;  // the text's line of each row
  LinkCalibration c;
  std::size_t columns = 0;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (Trim(line).empty() || Trim(line)[0] == '#') continue;
    const std::vector<std::string> cells = Cells(line);
    if (columns == 0) {
      columns = cells.size();
      if ((columns != 3 && columns != 4) || !std::equal(cells.begin(), cells.end(), std::begin(kColumns)))
        throw CalibrationCsvError(number, "header", "expected the columns mean_dbm,prr,access_delay_s[,unicast_prr]");
      continue;
    }
    if (cells.size() != columns)
      throw CalibrationCsvError(
          number, "row", "expected " + std::to_string(columns) + " values, found " + std::to_string(cells.size()));
    LinkCalibration::Row r{Number(cells[0], number, kColumns[0]), Number(cells[1], number, kColumns[1]),
                           Number(cells[2], number, kColumns[2]), 0};
    r.unicast_prr = columns == 4 ? Number(cells[3], number, kColumns[3]) : r.prr;
    c.rows.push_back(r);
    lines.push_back(number);
  }
  if (columns == 0) throw CalibrationCsvError(number, "header", "no header line (mean_dbm,prr,access_delay_s)");
  CheckCalibration(c, [&](std::size_t i, int column, const std::string& message) {
    throw CalibrationCsvError(lines.empty() ? number : lines[std::min(i, lines.size() - 1)], kColumns[column], message);
  });
  return c;
}

std::string LinkCalibrationCsv(const LinkCalibration& c, const std::string& comment) {
  std::ostringstream out;
  out.precision(17);
  out << "# " << comment << "\nmean_dbm,prr,access_delay_s,unicast_prr\n";
  for (const auto& r : c.rows)
    out << r.mean_dbm << ',' << r.prr << ',' << r.access_delay_s << ',' << r.unicast_prr << '\n';
  return out.str();
}

}  // namespace sanet::net
