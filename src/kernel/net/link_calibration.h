// What the full 802.11 model delivers on a link against the link's mean received power, measured
// by its link curve (sim/link_curve.h): the table the abstract radio draws from
// (net/abstract_channel.h).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace sanet::net {

// What the full model delivers against a link's mean received power: rows in ascending power.
struct LinkCalibration {
  struct Row {
    double mean_dbm = 0;
    double prr = 0;             // share of broadcast frames received (they go at the lowest rate)
    double access_delay_s = 0;  // from the frame's end at the sender to its arrival, beyond airtime
    double unicast_prr = 0;     // share of frames at the data rate received, per attempt
  };
  std::vector<Row> rows;
  double Prr(double dbm) const;
  double UnicastPrr(double dbm) const;
  double AccessDelay(double dbm) const;
  // Under this power no frame arrives, broadcast or unicast: the weakest row with a non-zero PRR,
  // or the one below it where the PRR falls to zero between them.
  double LowestHeardDbm() const;
};

// The CSV form (`mean_dbm,prr,access_delay_s[,unicast_prr]`, a header line, `#` lines ignored;
// without a unicast_prr column unicasts take the broadcasts' PRR), as the scenario's
// network.calibration and the cache read it. Throws CalibrationCsvError.
LinkCalibration ParseLinkCalibrationCsv(const std::string& text);
std::string LinkCalibrationCsv(const LinkCalibration& table, const std::string& comment);

class CalibrationCsvError : public std::runtime_error {
 public:
  CalibrationCsvError(int line, std::string column, const std::string& message)
      : std::runtime_error(message), line_(line), column_(std::move(column)) {}
  int line() const { return line_; }
  const std::string& column() const { return column_; }

 private:
  int line_;
  std::string column_;
};

// What every table must be, wherever it came from: `fail(row, column, message)` is called for the
// first fault (column 0 mean_dbm, 1 prr, 2 access_delay_s, 3 unicast_prr) and must throw.
template <typename Fail>
void CheckCalibration(const LinkCalibration& c, Fail fail) {
  if (c.rows.size() < 2) fail(c.rows.size(), 0, "a calibration needs at least two rows");
  bool heard = false;
  for (std::size_t i = 0; i < c.rows.size(); ++i) {
    const auto& r = c.rows[i];
    if (!(r.mean_dbm > -1e4 && r.mean_dbm < 1e4)) fail(i, 0, "is not a power in dBm");
    if (!(r.prr >= 0 && r.prr <= 1)) fail(i, 1, "must be within [0, 1]");
    if (!(r.access_delay_s >= 0 && r.access_delay_s <= 60)) fail(i, 2, "must be within [0, 60] s");
    if (!(r.unicast_prr >= 0 && r.unicast_prr <= 1)) fail(i, 3, "must be within [0, 1]");
    if (i > 0 && !(r.mean_dbm > c.rows[i - 1].mean_dbm))
      fail(i, 0,
           "rows must be in strictly ascending mean_dbm (" + std::to_string(r.mean_dbm) + " after " +
               std::to_string(c.rows[i - 1].mean_dbm) + "): sort them, one row for each power");
    heard = heard || r.prr > 0 || r.unicast_prr > 0;
  }
  if (!heard) fail(c.rows.size() - 1, 1, "no row delivers anything (every prr is 0)");
}

}  // namespace sanet::net
