// What the full 802.11 model delivers on a link against the link's mean received power, measured
// by its link curve (sim/link_curve.h): the table the abstract radio draws from
// (net/abstract_channel.h).
#pragma once

#include <vector>

namespace sanet::net {

// What the full model delivers against a link's mean received power: rows in ascending power.
struct LinkCalibration {
  struct Row {
    double mean_dbm = 0;
    double prr = 0;             // share of frames received
    double access_delay_s = 0;  // from the frame's end at the sender to its arrival, beyond airtime
  };
  std::vector<Row> rows;
  double Prr(double dbm) const;
  double AccessDelay(double dbm) const;
  // Under this power no frame arrives: the weakest row with a non-zero PRR, or the one below it
  // where the PRR falls to zero between them.
  double LowestHeardDbm() const;
};

}  // namespace sanet::net
