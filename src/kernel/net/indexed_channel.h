// A wireless channel that hands each frame only to the radios near enough for it to matter.
//
// ns-3's YansWifiChannel schedules a reception at every other radio on the channel for every
// frame, and the receiving PHY then drops the frames weaker than its sensitivity: with n radios
// a frame costs n events, wherever the radios are. IndexedWifiChannel keeps ns-3's propagation
// models, PHY and MAC, and changes only who is asked: a spatial grid over the radios' positions
// (net/spatial_grid.h) gives the candidates within the range at which a frame still arrives at
// `floor` dBm, and a candidate whose received power (the channel's own loss model, as Yans
// computes it) is under the floor is skipped. With the floor at the receivers' sensitivity the
// receptions are exactly Yans's; above it, frames too weak to be detected are skipped and with
// them their share of the interference at that receiver (docs/scenario.md#channel measures it).
//
// In ns-3 3.37, YansWifiChannel::Send is not virtual, so the glue is a PHY whose StartTx sends
// through this channel (IndexedWifiPhy), made by IndexedWifiPhyHelper; the channel derives from
// YansWifiChannel so that ns-3's helpers and the rest of sanet treat it as one.
#pragma once

#include <ns3/mobility-model.h>
#include <ns3/propagation-delay-model.h>
#include <ns3/propagation-loss-model.h>
#include <ns3/yans-wifi-channel.h>
#include <ns3/yans-wifi-helper.h>
#include <ns3/yans-wifi-phy.h>

#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <vector>

#include "net/spatial_grid.h"

namespace sanet::net {

class IndexedWifiChannel : public ns3::YansWifiChannel {
 public:
  static ns3::TypeId GetTypeId();

  struct Counters {
    std::uint64_t candidates = 0;  // radios the grid offered, over all frames
    std::uint64_t handed = 0;      // receptions scheduled (received power at or over the floor)
  };

  // Frames that would arrive weaker than `dbm` (after the receiver's antenna gain) are not
  // handed to that receiver. Set before the first frame.
  void SetFloor(double dbm) { floor_ = dbm; }
  // The loss model ranges are computed with, if not the channel's own: the path loss without the
  // walls, which only add loss, so that the candidates stay a superset of the radios reached
  // (probing through walls from wherever the probe stood would shrink the range wrongly).
  void SetRangeLossModel(ns3::Ptr<ns3::PropagationLossModel> loss) { range_loss_ = std::move(loss); }
  // The most the loss models beyond the range model can add to a frame (dB: shadowing's clip and
  // fading's cap): ranges reach that much farther, so that no frame lifted by them is missed.
  void SetRangeMargin(double db) { margin_db_ = db; }
  double floor() const { return floor_; }
  // The radio at `index` (the order radios joined the channel: a node's id in sanet) has moved:
  // its grid cell is brought up to date. Call it after every change of position, before the
  // next frame: the grid is exact only if it is told.
  void Moved(std::uint32_t index);
  // Replaces YansWifiChannel::Send: schedules the reception of `ppdu` at every radio near enough.
  void SendNear(ns3::Ptr<ns3::YansWifiPhy> sender, ns3::Ptr<const ns3::WifiPpdu> ppdu, double tx_power_dbm);
  const Counters& counters() const { return counters_; }
  // Range (m) at which a frame sent at `tx_power_dbm` still arrives at the floor.
  double Range(double tx_power_dbm);

 private:
  struct Radio {
    ns3::Ptr<ns3::YansWifiPhy> phy;
    ns3::Ptr<ns3::MobilityModel> mobility;
    std::uint32_t context = 0;  // the node's ns-3 id, the context of its events
  };
  void JoinNewRadios();
  void Index(std::uint32_t index);
  double LossAt(double tx_power_dbm, double distance) const;
  static void Receive(ns3::Ptr<ns3::YansWifiPhy> phy, ns3::Ptr<const ns3::WifiPpdu> ppdu, double rx_power_dbm);

  double floor_ = -101;
  double margin_db_ = 0;
  double top_ = 0;  // highest antenna (m) seen: ranges are computed with both ends there
  double max_rx_gain_ = std::numeric_limits<double>::lowest();  // dB, the largest receiver gain: ranges
                                                                // must reach its radio too
  ns3::Ptr<ns3::PropagationLossModel> loss_, range_loss_;
  ns3::Ptr<ns3::PropagationDelayModel> delay_;
  ns3::Ptr<ns3::MobilityModel> probe_from_, probe_to_;  // positions for computing ranges
  std::vector<Radio> radios_;
  std::unique_ptr<SpatialGrid> grid_;
  std::map<double, double> ranges_;  // by transmit power (dBm)
  std::vector<std::uint32_t> near_;  // scratch for queries
  Counters counters_;
};

// A YansWifiPhy that transmits through an IndexedWifiChannel; everything else is ns-3's.
class IndexedWifiPhy : public ns3::YansWifiPhy {
 public:
  static ns3::TypeId GetTypeId();
  void StartTx(ns3::Ptr<const ns3::WifiPpdu> ppdu, const ns3::WifiTxVector& tx_vector) override;
};

// ns-3's Yans PHY helper, making IndexedWifiPhy radios once UseIndexedPhy is called.
class RadioPhyHelper : public ns3::YansWifiPhyHelper {
 public:
  void UseIndexedPhy();
};

}  // namespace sanet::net
