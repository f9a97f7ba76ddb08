#include "scenario/lr_wpan_fields.h"

#include <algorithm>

namespace sanet::scenario {

using net::LrWpanSpec;
using net::NetworkSpec;

const Fields<LrWpanSpec>& LrWpanFields() {
  static const Fields<LrWpanSpec> fields = [] {
    Fields<LrWpanSpec> f;
    f.Number("tx_power", Member(&LrWpanSpec::tx_power), "dBm", -50, 60,
             "every 802.15.4 radio's transmit power unless a node sets its own (`0`: the CC2420's highest)");
    f.Number("rx_threshold", Member(&LrWpanSpec::rx_threshold), "dBm", -150, 0,
             "receiver sensitivity: frames arriving weaker never reach the radio, not even as interference "
             "(`-95`: the CC2420's)");
    f.Whole<int>("min_be", Member(&LrWpanSpec::min_be), "", 0, 8, "macMinBE: CSMA-CA's first backoff exponent");
    f.Whole<int>("max_be", Member(&LrWpanSpec::max_be), "", 3, 8, "macMaxBE: its largest backoff exponent");
    f.Whole<int>("max_csma_backoffs", Member(&LrWpanSpec::max_csma_backoffs), "", 0, 5,
                 "macMaxCSMABackoffs: channels found busy before a frame is given up");
    f.Whole<int>("max_frame_retries", Member(&LrWpanSpec::max_frame_retries), "", 0, 7,
                 "macMaxFrameRetries: retransmissions of a unicast frame that is not acknowledged");
    return f;
  }();
  return fields;
}

FieldInfo LrWpanEntry() {
  return {"lr_wpan",
          "mapping",
          "",
          "the CC2420's, see below",
          "see [lr_wpan](#lr_wpan)",
          "the 802.15.4 radios: transmit power, sensitivity, CSMA-CA"};
}

void ReadLrWpan(const Field& f, NetworkSpec& n) {
  LrWpanFields().Read(f, n.lr_wpan);
  if (n.lr_wpan.min_be > n.lr_wpan.max_be)
    f.Require(f.Get("min_be") ? "min_be" : "max_be")
        .Fail("macMinBE (" + std::to_string(n.lr_wpan.min_be) + ") may not exceed macMaxBE (" +
              std::to_string(n.lr_wpan.max_be) + ")");
}

YAML::Node PrintLrWpan(const NetworkSpec& n) { return LrWpanFields().Print(n.lr_wpan); }

namespace {

constexpr net::WifiStandard kWifiStandards[] = {net::WifiStandard::k80211b, net::WifiStandard::k80211g,
                                                net::WifiStandard::k80211a};

std::optional<net::WifiStandard> WifiStandardNamed(const std::string& text) {
  for (auto s : kWifiStandards)
    if (text == net::StandardName(s)) return s;
  return std::nullopt;
}

// One standard's name: an 802.11 one, or 802.15.4 (`lr-wpan` and `lrwpan` too).
bool IsLrWpanName(const std::string& text) { return text == net::kLrWpanName || text == "lr-wpan" || text == "lrwpan"; }

[[noreturn]] void UnknownStandard(const Field& f, const std::string& text) {
  f.Fail("unknown value '" + text + "' (expected one of: 802.11b, 802.11g, 802.11a, 802.15.4)");
}

}  // namespace

FieldInfo NetworkRadioEntry() {
  return {"radio",
          "text",
          "",
          "`802.11b`",
          "`802.11b`, `802.11g`, `802.11a`, `802.15.4`",
          "every node's radio unless it names its own (`radio.standard`): an 802.11 standard, or IEEE 802.15.4 "
          "(see [802.15.4](network.md#ieee-802154))"};
}

void ReadNetworkRadio(const Field& f, NetworkSpec& n) {
  const std::string text = f.Text();
  if (IsLrWpanName(text)) return void(n.radios = {false, true});
  const auto standard = WifiStandardNamed(text);
  if (!standard) UnknownStandard(f, text);
  n.standard = *standard;
  n.radios = {true, false};
}

YAML::Node PrintNetworkRadio(const NetworkSpec& n) {
  return YAML::Node(std::string(n.radios.wifi ? net::StandardName(n.standard) : net::kLrWpanName));
}

FieldInfo NodeStandardEntry() {
  return {"standard",
          "text, or a list of two",
          "",
          "`network.radio`",
          "`802.11b`, `802.11g`, `802.11a`, `802.15.4`; two: an 802.11 standard and `802.15.4`",
          "the node's radio, or its two radios (see [two radios](network.md#two-radios)); its 802.11 radio uses the "
          "run's one 802.11 standard"};
}

void ReadNodeStandard(const Field& f, net::NodeRadio& r) {
  std::vector<Field> names = f.IsSequence() ? f.Items() : std::vector<Field>{f};
  if (names.empty() || names.size() > 2) f.Fail("names one radio or two (an 802.11 standard and 802.15.4)");
  net::Radios radios{false, false};
  for (const Field& name : names) {
    const std::string text = name.Text();
    bool& slot = IsLrWpanName(text) ? radios.lr_wpan : radios.wifi;
    if (!IsLrWpanName(text) && !WifiStandardNamed(text)) UnknownStandard(name, text);
    if (slot) name.Fail("a node has at most one radio of each kind: one 802.11 and one 802.15.4");
    slot = true;
  }
  r.radios = radios;
}

YAML::Node PrintNodeStandard(const net::NodeRadio& r) {
  // The 802.11 name is the run's: the node's own printer does not know it, so the effective
  // scenario gets it from ResolveNodeRadio's record of the standard.
  if (!r.radios) return YAML::Node();
  const std::string wifi = net::StandardName(r.wifi_standard);
  if (r.radios->both()) {
    YAML::Node both(YAML::NodeType::Sequence);
    both.push_back(wifi);
    both.push_back(std::string(net::kLrWpanName));
    both.SetStyle(YAML::EmitterStyle::Flow);
    return both;
  }
  return YAML::Node(r.radios->wifi ? wifi : std::string(net::kLrWpanName));
}

FieldInfo NodeTxPowerEntry() {
  return {"tx_power",
          "number, or mapping standard: number",
          "dBm",
          "`network.tx_power` (802.11), `network.lr_wpan.tx_power` (802.15.4)",
          "[−50, 60]",
          "this node's transmit power; on a node with two radios, one per standard "
          "(`{802.11b: 16, 802.15.4: 0}`)"};
}

void ReadNodeTxPower(const Field& f, net::NodeRadio& r) {
  if (!f.IsMap()) return void(r.tx_power = f.Number(-50, 60));
  for (const auto& entry : f.node()) {
    const std::string key = entry.first.Scalar();
    const Field power = f.Require(key);
    if (IsLrWpanName(key))
      r.lr_wpan_tx_power = power.Number(-50, 60);
    else if (WifiStandardNamed(key))
      r.tx_power = power.Number(-50, 60);
    else
      power.Fail("is not a radio standard (expected 802.11b, 802.11g, 802.11a or 802.15.4)");
  }
}

// A node with two radios gets a mapping (a plain number is refused there), even of one power.
YAML::Node PrintNodeTxPower(const net::NodeRadio& r) {
  if ((r.tx_power && r.lr_wpan_tx_power) || (r.radios && r.radios->both() && (r.tx_power || r.lr_wpan_tx_power))) {
    YAML::Node out(YAML::NodeType::Map);
    if (r.tx_power) out[std::string(net::StandardName(r.wifi_standard))] = NumberNode(*r.tx_power);
    if (r.lr_wpan_tx_power) out[std::string(net::kLrWpanName)] = NumberNode(*r.lr_wpan_tx_power);
    out.SetStyle(YAML::EmitterStyle::Flow);
    return out;
  }
  if (r.tx_power) return NumberNode(*r.tx_power);
  return r.lr_wpan_tx_power ? NumberNode(*r.lr_wpan_tx_power) : YAML::Node();
}

namespace {

// The 802.11 standard a node's `standard` names, if it names one.
std::optional<std::pair<Field, net::WifiStandard>> NamedWifi(const Field& radio) {
  const auto standard = radio.Get("standard");
  if (!standard) return std::nullopt;
  for (const Field& name : standard->IsSequence() ? standard->Items() : std::vector<Field>{*standard})
    if (auto s = WifiStandardNamed(name.Text())) return std::pair{name, *s};
  return std::nullopt;
}

// A per-standard tx_power must name the node's own radios, and the run's 802.11 standard.
void CheckTxPowerKeys(const Field& power, const net::Radios radios, net::WifiStandard run_standard) {
  for (const auto& entry : power.node()) {
    const std::string key = entry.first.Scalar();
    const bool lr_wpan = IsLrWpanName(key);
    if (lr_wpan ? !radios.lr_wpan : !radios.wifi)
      power.Require(key).Fail("the node has no " + std::string(lr_wpan ? "802.15.4" : "802.11") + " radio");
    if (!lr_wpan && WifiStandardNamed(key) != run_standard)
      power.Require(key).Fail(std::string("the run's 802.11 radios are ") + net::StandardName(run_standard));
  }
}

}  // namespace

void ResolveNodeRadio(const Field& f, NetworkSpec& network, bool& wifi_standard_named, net::NodeRadio& r) {
  if (const auto named = NamedWifi(f)) {
    const auto& [name, standard] = *named;
    if ((network.radios.wifi || wifi_standard_named) && standard != network.standard)
      name.Fail(std::string("the 802.11 radios of a run share one channel, and this run's are ") +
                net::StandardName(network.standard));
    network.standard = standard;
    wifi_standard_named = true;
  }
  r.wifi_standard = network.standard;
  const net::Radios radios = r.RadiosIn(network);
  const auto power = f.Get("tx_power");
  if (!power) return;
  if (power->IsMap()) return CheckTxPowerKeys(*power, radios, network.standard);
  if (radios.both())
    power->Fail("the node has two radios: give one power per standard, e.g. {" +
                std::string(net::StandardName(network.standard)) + ": 16, 802.15.4: 0}");
  if (!radios.wifi) r.lr_wpan_tx_power = r.tx_power, r.tx_power.reset();
}

namespace {

// The lowest rate when the scenario gives none; else one of the standard's.
void CheckDataRate(const Field& network, net::NetworkSpec& n) {
  const std::vector<double> rates = net::DataRates(n.standard);
  const auto given = network.Get("data_rate");
  if (!given) return void(n.data_rate = rates.front());
  if (std::find(rates.begin(), rates.end(), n.data_rate) == rates.end())
    given->Fail(std::string("the run's 802.11 radios are ") + net::StandardName(n.standard) + ", which offer " +
                ShortNumber(rates.front()) + " to " + ShortNumber(rates.back()) + " Mbps");
}

}  // namespace

void CheckRadiosInUse(const Field& network, const std::vector<net::Radios>& used, bool wifi_standard_named,
                      net::NetworkSpec& n) {
  const bool wifi = std::any_of(used.begin(), used.end(), [](net::Radios r) { return r.wifi; });
  const bool lr_wpan = std::any_of(used.begin(), used.end(), [](net::Radios r) { return r.lr_wpan; });
  n.wifi_in_use = wifi;
  n.lr_wpan_in_use = lr_wpan;
  if (wifi_standard_named) CheckDataRate(network, n);
  if (!lr_wpan)
    if (const auto section = network.Get("lr_wpan")) section->Fail("no node has an 802.15.4 radio");
  if (wifi) return;
  for (const char* key : {"tx_power", "rx_threshold", "data_rate", "channel"})
    if (const auto k = network.Get(key))
      k->Fail(std::string("is the 802.11 radios', and no node has one") +
              (std::string(key) == "tx_power" || std::string(key) == "rx_threshold"
                   ? ": the 802.15.4 radios' is lr_wpan." + std::string(key)
                   : ""));
  const auto routing = network.Get("routing");
  if (!routing) return void(n.routing = net::Routing::kNone);
  if (n.routing != net::Routing::kNone)
    routing->Fail(std::string(net::RoutingName(n.routing)) +
                  " routes IPv4 over 802.11 radios, and no node has one: ns-3 3.37 carries IPv6 (6LoWPAN) over "
                  "802.15.4, and its only IPv6 routing protocol, RIPng, is made for wired networks. Use none (one "
                  "hop; a flood is relayed hop by hop all the same)");
}

}  // namespace sanet::scenario
