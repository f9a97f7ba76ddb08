// The wireless network of a run: radio, propagation, routing and what to trace. All of it is
// built from ns-3's own models (see wireless_network.cc); defaults are the scenario defaults.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "net/duty_cycle.h"
#include "net/link_calibration.h"
#include "net/ns3_attributes.h"

namespace sanet::net {

enum class WifiStandard { k80211b, k80211g, k80211a };
enum class LossModel { kLogDistance, kFriis, kTwoRayGround };
enum class DelayModel { kConstantSpeed, kRandom };
// Which radios a frame is handed to: every other radio (ns-3's YansWifiChannel), or only those
// where it arrives at least at the floor (net/indexed_channel.h).
enum class ChannelModel { kYans, kIndexed };
enum class Routing { kNone, kAodv, kOlsr, kDsdv, kDsr };
// The UDP ports of ns-3's routing protocols.
constexpr std::uint16_t kAodvPort = 654, kOlsrPort = 698, kDsdvPort = 269;
constexpr std::uint8_t kUdpProtocol = 17;  // IP protocol number

// The seed ns-3 is given for a run's seed: seed mod (2^32 - 1) + 1, folded under ns-3's largest
// (its RngStream refuses seeds of 4294944443 and more).
std::uint32_t Ns3Seed(std::uint64_t seed);

const char* RoutingName(Routing routing);
const char* ChannelName(ChannelModel model);
const char* StandardName(WifiStandard standard);
// The data rates (Mbps) a standard offers.
std::vector<double> DataRates(WifiStandard standard);
// A frame's PHY preamble and header: 192 us for 802.11b's long DSSS preamble, 20 us for OFDM.
inline double PreambleSeconds(WifiStandard standard) { return standard == WifiStandard::k80211b ? 192e-6 : 20e-6; }
// The carrier frequency (Hz) of the channel sanet uses: 2.412 GHz (channel 1) for 802.11b and
// 802.11g, 5.18 GHz (channel 36) for 802.11a.
inline double FrequencyHz(WifiStandard standard) { return standard == WifiStandard::k80211a ? 5.18e9 : 2.412e9; }

// The radios a node carries: an 802.11 radio (the run's standard), an IEEE 802.15.4 radio, or
// both (docs/network.md#ieee-802154).
struct Radios {
  bool wifi = true;
  bool lr_wpan = false;
  bool operator==(const Radios& o) const { return wifi == o.wifi && lr_wpan == o.lr_wpan; }
  bool both() const { return wifi && lr_wpan; }
};
constexpr const char* kLrWpanName = "802.15.4";

// IEEE 802.15.4 radios (ns-3's lr-wpan: 2.4 GHz O-QPSK at 250 kbit/s, unslotted CSMA-CA,
// acknowledged unicast) carrying IPv6 through 6LoWPAN. The defaults are the CC2420's (a TelosB or
// MICAz mote's transceiver) and the standard's MAC constants.
struct LrWpanSpec {
  double tx_power = 0;        // dBm: the CC2420's highest
  double rx_threshold = -95;  // dBm: the CC2420's sensitivity; weaker frames never reach the radio
  int min_be = 3;             // macMinBE: the first backoff exponent
  int max_be = 5;             // macMaxBE
  int max_csma_backoffs = 4;  // macMaxCSMABackoffs: busy channels before a frame is given up
  int max_frame_retries = 3;  // macMaxFrameRetries: retransmissions of an unacknowledged unicast
};
constexpr int kLrWpanChannel = 11;              // the first 2.4 GHz channel
constexpr double kLrWpanFrequencyHz = 2.405e9;  // its centre
constexpr double kLrWpanRateMbps = 0.25;

// Log-normal shadowing, spatially correlated (net/shadowing.h); sigma 0 is none.
struct Shadowing {
  double sigma_db = 0;        // deviation of the shadowing (dB)
  double correlation_m = 10;  // decorrelation distance: the correlation is exp(-moved / this)
  double clip_sigmas = 3;     // values are clipped at +- this many sigmas
  bool symmetric = true;      // the same both ways of a link, or drawn apart
};

// Fast fading per frame (net/fading.h).
enum class FadingModel { kNone, kNakagami, kRayleigh };
struct Fading {
  FadingModel model = FadingModel::kNone;
  double m = 1;  // Nakagami's shape (rayleigh: 1)
};

// Hardware variance (Zuniga and Krishnamachari's second cause of asymmetric links): each node's
// transmit power and noise figure are off by a Gaussian amount drawn from the seed.
struct HardwareSpread {
  double tx_power_db = 0;      // deviation of each node's transmit power
  double noise_figure_db = 0;  // deviation of each node's receiver noise figure
  static constexpr double kClipSigmas = 3;
};

// How 802.11 radios are simulated: ns-3's whole 802.11 model, or a calibrated abstraction of it
// (net/abstract_channel.h) for swarms.
enum class RadioModel { kFull, kAbstract };

struct NetworkSpec {
  Radios radios;
  RadioModel radio_model = RadioModel::kFull;
  // With the abstract model: what the full model delivers against a link's mean power.
  std::optional<LinkCalibration> calibration;
  std::string calibration_file;                   // the scenario's `network.calibration` file, where it named one
  std::string calibration_source;                 // "measured", "cached" or "file", for the summary
  bool broadcast_at_data_rate = false;            // not a scenario's: the calibration measures unicasts' PRR so
  WifiStandard standard = WifiStandard::k80211b;  // of every 802.11 radio: they share one channel
  double data_rate = 1;                           // Mbps, one of the standard's rates; broadcasts go at the lowest
  double tx_power = 16;                           // dBm, every node unless it overrides it
  double rx_threshold = -82;                      // dBm: frames received weaker than this are not detected

  LossModel loss = LossModel::kLogDistance;
  double exponent = 3.0;            // log-distance path-loss exponent
  double reference_loss = 46.6777;  // dB at reference_distance (log-distance)
  double reference_distance = 1.0;  // m
  double antenna_height = 1.0;      // m above each node, for two-ray ground
  double max_range = 0;             // m; beyond it nothing is received (0: no cut-off)
  Shadowing shadowing;
  Fading fading;
  HardwareSpread spread;
  DelayModel delay = DelayModel::kConstantSpeed;
  double random_delay_max = 1e-6;  // s: `random` delays are uniform in [0, this]

  ChannelModel channel = ChannelModel::kIndexed;
  std::optional<double> channel_floor;               // dBm; unset: kFloorBelowThreshold under rx_threshold
  static constexpr double kFloorBelowThreshold = 9;  // dB: docs/network.md#the-indexed-channel
  // With fading, frames from far radios land under the floor and over the noise often enough to
  // matter: the floor goes down to ns-3's default sensitivity at the default threshold (exact).
  static constexpr double kFloorBelowThresholdFaded = 19;
  double ChannelFloor() const {
    const double below = fading.model == FadingModel::kNone ? kFloorBelowThreshold : kFloorBelowThresholdFaded;
    return channel_floor.value_or(rx_threshold - below);
  }

  Routing routing = Routing::kAodv;
  bool aodv_hello = true;       // AODV hello messages (neighbour sensing)
  int flood_ttl = 16;           // hops a flooded message may travel
  double broadcast_jitter = 0;  // s: a broadcast waits uniformly up to this before it is sent

  std::uint16_t port = 9000;  // UDP port of controller messages
  bool pcap = false;          // a pcap file per node (802.11 frames)
  bool flow_monitor = false;  // ns-3 FlowMonitor statistics (XML)
  bool packet_log = true;     // a CSV of packet events per node
  LrWpanSpec lr_wpan;         // the 802.15.4 radios', if any node has one
  // Which kinds of radio the nodes (and spawn classes) carry: set by the loader.
  bool wifi_in_use = true, lr_wpan_in_use = false;

  Ns3Attributes ns3;  // ns-3 attribute defaults (network.ns3), checked when read

  // The run's seed (RunSpec::seed, set when the run is assembled): shadowing, fading and the
  // hardware spread draw from it.
  std::uint64_t seed = 0;
};

// The network's own radio (`network.radio`: what a node that names none carries, and what a link
// curve measures): its transmit power, threshold and carrier frequency. `SetDefaultTxPower` sets
// that radio's power.
inline double DefaultTxPower(const NetworkSpec& n) { return n.radios.wifi ? n.tx_power : n.lr_wpan.tx_power; }
inline double DefaultThreshold(const NetworkSpec& n) { return n.radios.wifi ? n.rx_threshold : n.lr_wpan.rx_threshold; }
inline double DefaultFrequencyHz(const NetworkSpec& n) {
  return n.radios.wifi ? FrequencyHz(n.standard) : kLrWpanFrequencyHz;
}
inline void SetDefaultTxPower(NetworkSpec& n, double dbm) { (n.radios.wifi ? n.tx_power : n.lr_wpan.tx_power) = dbm; }

// Radio settings a node may override.
struct NodeRadio {
  std::optional<Radios> radios;            // unset: the network's
  std::optional<double> tx_power;          // dBm, its 802.11 radio
  std::optional<double> lr_wpan_tx_power;  // dBm, its 802.15.4 radio
  double antenna_height = 0;               // m above the node's position, for the walls between antennas only
  std::optional<DutyCycle> duty_cycle;     // none: awake unless its controller puts it to sleep (every radio it has)
  WifiStandard wifi_standard = WifiStandard::k80211b;  // the run's, to print `standard` with
  Radios RadiosIn(const NetworkSpec& network) const { return radios.value_or(network.radios); }
};

}  // namespace sanet::net
