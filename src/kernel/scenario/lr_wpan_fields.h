// IEEE 802.15.4 in a scenario (docs/network.md#ieee-802154): `network.radio: 802.15.4`, the
// `network.lr_wpan` section (transmit power, threshold, CSMA-CA), a node's `radio.standard` (one
// radio or two) and its `tx_power` per radio. The section prints only when some node has an
// 802.15.4 radio, so an 802.11 scenario prints (and fingerprints) as before it existed.
#pragma once

#include "net/network_spec.h"
#include "scenario/fields.h"

namespace sanet::scenario {

const Fields<net::LrWpanSpec>& LrWpanFields();
FieldInfo LrWpanEntry();
void ReadLrWpan(const Field& f, net::NetworkSpec& n);
YAML::Node PrintLrWpan(const net::NetworkSpec& n);

// `network.radio`: an 802.11 standard, or 802.15.4 for every node.
FieldInfo NetworkRadioEntry();
void ReadNetworkRadio(const Field& f, net::NetworkSpec& n);
YAML::Node PrintNetworkRadio(const net::NetworkSpec& n);

// A node's `radio.standard` and `radio.tx_power` (a number, or one per standard on two radios).
FieldInfo NodeStandardEntry();
void ReadNodeStandard(const Field& f, net::NodeRadio& r);
YAML::Node PrintNodeStandard(const net::NodeRadio& r);
FieldInfo NodeTxPowerEntry();
void ReadNodeTxPower(const Field& f, net::NodeRadio& r);
YAML::Node PrintNodeTxPower(const net::NodeRadio& r);

// After a node's radio is read, with the network known: a plain `tx_power` goes to the one radio
// it has. In a network whose radio is 802.15.4 the first node to name an 802.11 standard sets the
// run's (`wifi_standard_named`); the others must name the same. `f` is the node's `radio`.
void ResolveNodeRadio(const Field& f, net::NetworkSpec& network, bool& wifi_standard_named, net::NodeRadio& r);

// Once every node and spawn class is read (`used`: their radios): the 802.11 keys need an 802.11
// radio, `lr_wpan` an 802.15.4 one, routing protocols an 802.11 radio (ns-3 3.37 routes no IPv6
// ad hoc network); a data rate is checked against the standard a node named.
void CheckRadiosInUse(const Field& network, const std::vector<net::Radios>& used, bool wifi_standard_named,
                      net::NetworkSpec& n);

}  // namespace sanet::scenario
