#include "net/link_calibration.h"

#include <algorithm>

namespace sanet::net {
namespace {

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

}  // namespace

double LinkCalibration::Prr(double dbm) const {
  if (dbm < LowestHeardDbm()) return 0;
  return std::clamp(Interpolate(rows, dbm, [](const Row& r) { return r.prr; }), 0.0, 1.0);
}

double LinkCalibration::AccessDelay(double dbm) const {
  return std::max(0.0, Interpolate(rows, dbm, [](const Row& r) { return r.access_delay_s; }));
}

double LinkCalibration::LowestHeardDbm() const {
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].prr > 0) return i == 0 ? rows[0].mean_dbm : rows[i - 1].mean_dbm;
  return rows.empty() ? 0 : rows.back().mean_dbm + 1;  // never heard
}

}  // namespace sanet::net
