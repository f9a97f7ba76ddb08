// The abstract radio, a cheaper stand-in for 802.11 in large swarms: ns-3's SimpleNetDevices on a channel of
// sanet's that delivers a frame to each receiver with the probability the full 802.11 model's
// link curve gives at that link's mean received power, after the access delay it measured. IP,
// ARP, the routing protocols and sockets above the devices are ns-3's, unchanged; the PHY and the
// MAC below are replaced by the calibration.
//
// - A link's mean power is the scenario's mean loss chain (path loss, walls, shadowing: fading is
//   in the calibration, which was measured with it). PRR and delay are interpolated linearly in
//   the calibration's table, a broadcast's PRR at the lowest rate, a unicast's at the data rate;
//   nothing is delivered under its lowest power with a non-zero PRR.
// - Each frame's fate at each receiver is a counter-based draw keyed by (seed, sender, receiver,
//   the sender's frame number), so that it depends on nothing else that happens.
// - A unicast frame is considered only at its addressee (an 802.11 MAC's filtering would drop it
//   everywhere else); broadcasts at every radio the spatial grid places within range.
// - A unicast frame is retried, as the 802.11 MAC does, until an attempt and its acknowledgement
//   both arrive (each with the link's PRR, drawn apart) or the attempts run out; each failed
//   attempt costs the frame's airtime, the ACK timeout, a DIFS and a backoff drawn in a contention
//   window that doubles. The addressee has the frame from the first attempt that reached it.
// - The sender's device serializes its frames (IP packets) at the radio's data rate, and the
//   channel adds the rest of the frame's airtime (preamble, MAC bytes; broadcasts at the lowest
//   rate) and the calibration's access delay. Frames do not collide and do not wait for each
//   other's retries: contention and hidden terminals are not modelled (docs/swarms.md measures
//   what that changes).
#pragma once

#include <ns3/mac48-address.h>
#include <ns3/mobility-model.h>
#include <ns3/propagation-loss-model.h>
#include <ns3/simple-channel.h>
#include <ns3/simple-net-device.h>

#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "net/link_calibration.h"
#include "net/network_traces.h"
#include "net/spatial_grid.h"

namespace sanet::net {

class AbstractChannel : public ns3::SimpleChannel {
 public:
  static ns3::TypeId GetTypeId();
  struct Settings {
    LinkCalibration calibration;
    ns3::Ptr<ns3::PropagationLossModel> mean_loss;  // the links' mean power
    std::function<double(std::uint32_t node)> tx_power_dbm;
    std::uint64_t seed = 0;
    double range_m = 0;  // no receiver farther than this is asked (where the loss puts LowestHeardDbm)
    // What a frame's time on the air adds to the sending device's serialization (its IP packet at
    // the data rate): the PHY preamble, the MAC's bytes, and for a broadcast the difference of
    // the lowest rate (802.11 sends broadcasts at a basic rate) to the data rate.
    double preamble_s = 0;
    double data_rate_bps = 1e6, broadcast_rate_bps = 1e6;
    // A unicast frame is retried as the 802.11 MAC retries it (docs/swarms.md#the-abstract-radio).
    struct Retries {
      int attempts = 1;                          // ns-3's MaxSsrc, 7
      double slot_s = 0, sifs_s = 0, ack_s = 0;  // the PHY's slot and SIFS; an ACK's PHY header
      int cw_min = 0, cw_max = 0;                // contention window, in slots
    } unicast;
  };
  AbstractChannel() : grid_(50) {}
  void Configure(Settings settings);

  // Devices join in node order: a device's index is its node's id.
  void Add(ns3::Ptr<ns3::SimpleNetDevice> device) override;
  void Send(ns3::Ptr<ns3::Packet> p, uint16_t protocol, ns3::Mac48Address to, ns3::Mac48Address from,
            ns3::Ptr<ns3::SimpleNetDevice> sender) override;
  std::size_t GetNDevices() const override { return devices_.size(); }
  ns3::Ptr<ns3::NetDevice> GetDevice(std::size_t i) const override { return devices_.at(i); }
  // A radio switched off neither sends nor receives (SimpleNetDevice has no off state).
  void SetOff(std::uint32_t index, bool off) { off_.at(index) = off; }
  bool IsOff(std::uint32_t index) const { return off_.at(index); }
  // Node `index` moved: its grid cell follows (before its next frame).
  void Moved(std::uint32_t index);

  // Frames as the run's trace sees them: sent when the channel takes one, received when it arrives.
  void ObserveFrames(FrameObserver observer) { observer_ = std::move(observer); }
  // Each frame's time on the air at its sender (when the channel takes it) and at each radio it
  // reaches (when it arrives): what the abstract radio draws energy for.
  using OnAirObserver = std::function<void(std::uint32_t node, bool sent, double seconds)>;
  void ObserveAirtime(OnAirObserver observer) { on_air_ = std::move(observer); }
  // A unicast frame none of whose attempts was acknowledged (the MAC gives up on it), at its sender.
  using GaveUpObserver = std::function<void(std::uint32_t node, ns3::Ptr<const ns3::Packet> p)>;
  void ObserveGivingUp(GaveUpObserver observer) { gave_up_ = std::move(observer); }
  // The bytes an 802.11 frame adds to the IP packet: MAC header, LLC/SNAP and FCS.
  static constexpr std::uint32_t kMacOverhead = 24 + 8 + 4;

  struct Counters {
    std::uint64_t frames = 0, asked = 0, delivered = 0;
  };
  const Counters& counters() const { return counters_; }

 private:
  double AirtimeBeyondSerialization(std::uint32_t bytes, bool broadcast) const;
  // Sets attempts_ to the attempts the frame took, acknowledged_ to whether one was acknowledged.
  std::optional<double> UnicastRetries(std::uint32_t from, std::uint32_t to, std::uint64_t frame, double prr,
                                       double airtime);
  void Observe(std::uint32_t node, bool sent, std::optional<std::uint32_t> peer, ns3::Ptr<const ns3::Packet> p,
               uint16_t protocol, bool broadcast) const;
  void Arrive(std::uint32_t from, std::uint32_t to, ns3::Ptr<ns3::Packet> p, uint16_t protocol, ns3::Mac48Address dst,
              ns3::Mac48Address src);
  double Airtime(std::uint32_t bytes, bool broadcast) const;
  void Offer(std::uint32_t from, std::uint32_t to, std::uint64_t frame, ns3::Ptr<ns3::Packet> p, uint16_t protocol,
             ns3::Mac48Address dst, ns3::Mac48Address src);

  Settings settings_;
  double lowest_dbm_ = 0;
  SpatialGrid grid_;
  std::vector<ns3::Ptr<ns3::SimpleNetDevice>> devices_;  // by node id
  std::vector<ns3::Ptr<ns3::MobilityModel>> mobility_;   // by node id: asked for every link of every frame
  std::map<ns3::Mac48Address, std::uint32_t> by_address_;
  std::vector<std::uint64_t> sent_;  // frames each node sent
  std::vector<bool> off_;            // by node id
  std::vector<std::uint32_t> near_;  // scratch
  int attempts_ = 1;                 // the last unicast offered: attempts it took (all, where none was acknowledged)
  bool acknowledged_ = false;        // the last unicast offered
  Counters counters_;
  FrameObserver observer_;
  OnAirObserver on_air_;
  GaveUpObserver gave_up_;
};

}  // namespace sanet::net
