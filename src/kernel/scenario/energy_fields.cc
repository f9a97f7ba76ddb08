#include "scenario/energy_fields.h"

#include <string>

namespace sanet::scenario {
namespace {

using energy::EnergySpec;
using energy::RadioCurrents;

// The presets' names, each between `quote`s.
std::string PresetNames(const std::string& quote) {
  std::string names;
  for (const energy::RadioPreset& p : energy::RadioPresets())
    names += (names.empty() ? "" : ", ") + quote + p.name + quote;
  return names;
}

const energy::RadioPreset& PresetNamed(const Field& f) {
  const std::string name = f.Text();
  for (const energy::RadioPreset& p : energy::RadioPresets())
    if (p.name == name) return p;
  f.Fail("unknown radio preset '" + name + "' (expected one of: " + PresetNames("") + ")");
}

void ReadPreset(const Field& f, EnergySpec& spec) {
  const energy::RadioPreset& p = PresetNamed(f);
  spec.radio_preset = p.name;
  spec.radio = p.currents;
}

void ReadLrWpanPreset(const Field& f, EnergySpec& spec) {
  const energy::RadioPreset& p = PresetNamed(f);
  spec.lr_wpan_radio = {p.name, p.currents};
}

// A current in A, printed back always (the preset's when the scenario gives none).
void Current(Fields<EnergySpec>& f, const char* key, double RadioCurrents::*member, const char* meaning) {
  f.Number(
      key, [member](EnergySpec& s) -> double& { return s.radio.*member; }, "A", 0, 1000, meaning);
}

void LrWpanCurrent(Fields<EnergySpec>& f, const char* key, double RadioCurrents::*member, const char* meaning) {
  f.Number(
      key,
      [member](EnergySpec& s) -> double& {
        if (!s.lr_wpan_radio) s.lr_wpan_radio = {"cc2420", energy::RadioPresetNamed("cc2420").currents};
        return s.lr_wpan_radio->currents.*member;
      },
      "A", 0, 1000, meaning);
}

// A key of the drive's costs: read into `drive` (which the loader keeps on robots only), printed
// on robots.
void DriveCost(Fields<EnergySpec>& f, FieldInfo info, double energy::DriveCosts::*member, double max, bool above_zero) {
  f.Custom(
      std::move(info),
      [member, max, above_zero](const Field& v, EnergySpec& s) {
        if (!s.drive) s.drive.emplace();
        (*s.drive).*member = above_zero ? v.NumberAbove(0, max) : v.Number(0, max);
      },
      [member](const EnergySpec& s) { return s.drive ? NumberNode((*s.drive).*member) : YAML::Node(); });
}

void DriveCosts(Fields<EnergySpec>& f) {
  const energy::DriveCosts d;
  DriveCost(f,
            {"motion_efficiency", "number", "", "`" + ShortNumber(d.efficiency) + "`", "(0, 1]",
             "a robot's: of its motors, gears and drivers, the wheels' mechanical power over the electrical power "
             "drawn (docs/energy.md#motion)"},
            &energy::DriveCosts::efficiency, 1, true);
  DriveCost(f,
            {"drive_idle_w", "number", "W", "`" + ShortNumber(d.idle_w) + "`", "[0, 1e6]",
             "a robot's: what its drive draws while the node is on, moving or not (motor drivers, encoders)"},
            &energy::DriveCosts::idle_w, 1e6, false);
  DriveCost(f,
            {"rolling_resistance", "number", "", "`" + ShortNumber(d.rolling_resistance) + "`", "[0, 1]",
             "a robot's: the force it takes to roll its wheels, per newton of the weight they carry"},
            &energy::DriveCosts::rolling_resistance, 1, false);
}

}  // namespace

const Fields<energy::WirelessCharger>& WirelessChargerFields() {
  static const Fields<energy::WirelessCharger> fields = [] {
    Fields<energy::WirelessCharger> f;
    f.Number("power_w", Member(&energy::WirelessCharger::power_w), "W", 0, 1e6,
             "what the charger radiates while the robot is on (drawn from the robot's battery)", true)
        .Required();
    f.Number("range_m", Member(&energy::WirelessCharger::range_m), "m", 0, 1e4,
             "motes farther than this (reference point to reference point, on the ground) receive nothing", true)
        .Required();
    f.Number("alpha", Member(&energy::WirelessCharger::alpha), "m^2", 0, 1e6,
             "the received share is alpha / (d + beta)^2, at most 1 (docs/energy.md#chargers)", true);
    f.Number("beta", Member(&energy::WirelessCharger::beta), "m", 0, 1e3,
             "the model's correction of Friis's equation at short distances", false);
    return f;
  }();
  return fields;
}

const Fields<EnergySpec>& RadioEnergyFields() {
  static const Fields<EnergySpec> fields = [] {
    Fields<EnergySpec> f;
    f.Custom({"preset", "text", "", "`ns3_wifi`", PresetNames("`"),
              "the currents of a known radio (docs/energy.md lists their sources); the keys below change them"},
             ReadPreset, [](const EnergySpec& s) { return YAML::Node(s.radio_preset); });
    Current(f, "tx_a", &RadioCurrents::tx_a, "while transmitting");
    Current(f, "rx_a", &RadioCurrents::rx_a, "while receiving a frame");
    Current(f, "idle_a", &RadioCurrents::idle_a, "while listening to an idle channel");
    f.Custom(
        {"cca_busy_a", "number", "A", "`idle_a`", "[0, 1000]", "while the channel is busy (carrier sensed)"},
        [](const Field& v, EnergySpec& s) { s.radio.cca_busy_a = v.Number(0, 1000); },
        [](const EnergySpec& s) { return NumberNode(s.radio.cca_busy()); });
    Current(f, "sleep_a", &RadioCurrents::sleep_a, "while asleep (Node::SetRadioSleep)");
    return f;
  }();
  return fields;
}

const Fields<EnergySpec>& LrWpanRadioEnergyFields() {
  static const Fields<EnergySpec> fields = [] {
    Fields<EnergySpec> f;
    f.Custom({"preset", "text", "", "`cc2420`", PresetNames("`"),
              "the currents of a known radio (docs/energy.md lists their sources); the keys below change them"},
             ReadLrWpanPreset, [](const EnergySpec& s) { return YAML::Node(s.lr_wpan_radio->preset); });
    LrWpanCurrent(f, "tx_a", &RadioCurrents::tx_a, "while transmitting (the PHY's TX_ON and BUSY_TX)");
    LrWpanCurrent(f, "rx_a", &RadioCurrents::rx_a, "while the receiver is on, listening or receiving");
    LrWpanCurrent(f, "idle_a", &RadioCurrents::idle_a, "transceiver off while the radio is awake (CC2420: idle)");
    LrWpanCurrent(f, "sleep_a", &RadioCurrents::sleep_a,
                  "transceiver off while the radio is asleep (a duty cycle, SetRadioSleep; CC2420: power down)");
    return f;
  }();
  return fields;
}

const Fields<EnergySpec>& EnergyFields() {
  static const Fields<EnergySpec> fields = [] {
    Fields<EnergySpec> f;
    f.Choice<energy::Chemistry>(
        "source", Member(&EnergySpec::source),
        {{"constant_voltage", energy::Chemistry::kConstantVoltage}, {"li_ion", energy::Chemistry::kLiIon}},
        "`constant_voltage`: a battery at `voltage`; `li_ion`: a lithium-ion pack whose voltage follows its "
        "discharge curve (ns-3's LiIonEnergySource, docs/energy.md)");
    f.Number("battery_j", Member(&EnergySpec::battery_j), "J", 0, 1e12, "the battery's capacity", true).Required();
    f.Custom(
        {"voltage", "number", "V", "`3`", "(0, 1000]", "constant, the supply's (not with `li_ion`)"},
        [](const Field& v, EnergySpec& s) { s.voltage = v.NumberAbove(0, 1000); },
        [](const EnergySpec& s) {
          return s.source == energy::Chemistry::kLiIon ? YAML::Node() : NumberNode(s.voltage);
        });
    f.Number("initial_fraction", Member(&EnergySpec::initial_fraction), "", 0, 1,
             "the charge at the start, of the capacity");
    f.Number("electronics_w", Member(&EnergySpec::electronics_w), "W", 0, 1e6,
             "drawn while the node is alive and not switched off (processor, sensors at rest)");
    f.Custom(
        {"cutoff", "number", "", "`0`", "[0, 1)", "the node dies when its charge falls to this fraction"},
        [](const Field& v, EnergySpec& s) {
          s.cutoff = v.Number(0, 1);
          if (s.cutoff >= 1) v.Fail("a cutoff of 1 or more kills the node at once: give a fraction below 1");
        },
        [](const EnergySpec& s) { return NumberNode(s.cutoff); });
    f.Custom(
        {"revive", "number", "", "`cutoff` + 0.05 (at most 1)", "(cutoff, 1]",
         "a dead node comes back once recharged above this fraction"},
        [](const Field& v, EnergySpec& s) { s.revive = v.Number(0, 1); },
        [](const EnergySpec& s) { return NumberNode(s.RevivesAbove()); });
    f.Custom(
        {"radio", "text or mapping", "", "`ns3_wifi`", "a preset's name, or a mapping (the table below)",
         "the radio's current in each of its states (ns-3's WifiRadioEnergyModel)"},
        [](const Field& v, EnergySpec& s) {
          if (v.IsMap()) return RadioEnergyFields().Read(v, s);
          ReadPreset(v, s);
        },
        [](const EnergySpec& s) { return s.wifi_radio ? RadioEnergyFields().Print(s) : YAML::Node(); });
    f.Custom(
        {"lr_wpan_radio", "text or mapping", "", "`cc2420` on a node with an 802.15.4 radio",
         "a preset's name, or a mapping (the table below); only on a node with an 802.15.4 radio",
         "its 802.15.4 radio's current in each state (docs/energy.md#ieee-802154)"},
        [](const Field& v, EnergySpec& s) {
          if (v.IsMap()) return LrWpanRadioEnergyFields().Read(v, s);
          ReadLrWpanPreset(v, s);
        },
        [](const EnergySpec& s) { return s.lr_wpan_radio ? LrWpanRadioEnergyFields().Print(s) : YAML::Node(); });
    DriveCosts(f);
    f.Custom(
        {"wireless_charger", "mapping", "", "none", "{power_w, range_m, alpha, beta} (the table below)",
         "a robot's: a charger that powers the motes near it (docs/energy.md#chargers)"},
        [](const Field& v, EnergySpec& s) { WirelessChargerFields().Read(v, s.wireless_charger.emplace()); },
        [](const EnergySpec& s) {
          return s.wireless_charger ? WirelessChargerFields().Print(*s.wireless_charger) : YAML::Node();
        });
    return f;
  }();
  return fields;
}

energy::EnergySpec ReadEnergy(const Field& f, bool has_drive, net::Radios radios) {
  EnergySpec spec;
  EnergyFields().Read(f, spec);
  if (const auto radio = f.Get("radio"); radio && !radios.wifi)
    radio->Fail("is an 802.11 radio's, and the node's only radio is 802.15.4: give its currents as lr_wpan_radio");
  if (const auto radio = f.Get("lr_wpan_radio"); radio && !radios.lr_wpan)
    radio->Fail("the node has no 802.15.4 radio");
  spec.wifi_radio = radios.wifi || !radios.lr_wpan;
  if (radios.lr_wpan && !spec.lr_wpan_radio)
    spec.lr_wpan_radio = {"cc2420", energy::RadioPresetNamed("cc2420").currents};
  if (!has_drive) {
    for (const char* key : {"motion_efficiency", "drive_idle_w", "rolling_resistance", "wireless_charger"})
      if (const auto v = f.Get(key)) v->Fail("is a robot's: a mote has no drive to carry it");
  } else if (!spec.drive) {
    spec.drive.emplace();
  }
  if (spec.source == energy::Chemistry::kLiIon && f.Get("voltage"))
    f.Require("voltage").Fail("a li_ion pack's voltage follows its discharge curve (4.05 V full): leave it out");
  if (spec.revive && *spec.revive <= spec.cutoff)
    f.Require("revive").Fail("must be above the cutoff (" + ShortNumber(spec.cutoff) +
                             "): a node revived at its cutoff would die again at once");
  if (spec.initial_fraction < spec.cutoff)
    f.Require("initial_fraction")
        .Fail("is below the cutoff (" + ShortNumber(spec.cutoff) + "): the node would be dead from the start");
  return spec;
}

}  // namespace sanet::scenario
