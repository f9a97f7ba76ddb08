// `network.calibration`: where the abstract radio's table (net/link_calibration.h) comes from.
//
// - `measure` (the default): the full 802.11 model's link curve on the scenario's own radio,
//   measured at the first run and cached (sim/radio_calibration.h).
// - a file name (relative to the scenario): a CSV with the columns mean_dbm, prr, access_delay_s
//   and optionally unicast_prr, one row per power, as `sanet link-curve` writes it
//   (calibration.csv) and the cache keeps it; lines starting with `#` are comments.
// - `{file: NAME, rows: [[mean_dbm, prr, access_delay_s, unicast_prr], ...]}` (or three numbers a
//   row): the table itself, as the effective
//   scenario prints a file's content, so that an agent or a rerun needs no file and the scenario's
//   fingerprint covers the table.
#pragma once

#include <string>

#include "net/network_spec.h"
#include "scenario/fields.h"

namespace sanet::scenario {

FieldInfo CalibrationEntry();
void ReadCalibration(const Field& f, net::NetworkSpec& n);
YAML::Node PrintCalibration(const net::NetworkSpec& n);

// A calibration table from CSV text; errors name `file`, the line and the column.
net::LinkCalibration ParseCalibrationCsv(const std::string& text, const std::string& file);

}  // namespace sanet::scenario
