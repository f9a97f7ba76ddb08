// ns-3 attributes set from a scenario (`network.ns3`): the defaults of ns-3's own TypeId
// attributes, in effect while a run's network is built and runs, checked against ns-3's
// attribute lists before any run. Names are ns-3's: "ns3::aodv::RoutingProtocol::ActiveRouteTimeout".
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sanet::net {

using Ns3Attributes = std::vector<std::pair<std::string, std::string>>;  // name -> value, in order

// "" when ns-3 knows the attribute and takes the value; otherwise why not, with the closest
// valid names where a name is wrong, and the scenario key to use where sanet sets it itself.
std::string CheckNs3Attribute(const std::string& name, const std::string& value);

// A number attribute of ns-3's WifiPhy as its default now stands (network.ns3 may have set it):
// "RxSensitivity", "RxGain", "RxNoiseFigure".
double WifiPhyDefault(const char* attribute);

// Makes `attributes` the defaults of their types; puts the earlier ones back when it ends, so that
// the next run in the process starts from ns-3's own. The values must have passed
// CheckNs3Attribute (the scenario loader checks them): the one ns-3 aborts on is not tried here.
class Ns3Defaults {
 public:
  explicit Ns3Defaults(const Ns3Attributes& attributes);
  ~Ns3Defaults();
  Ns3Defaults(const Ns3Defaults&) = delete;
  Ns3Defaults& operator=(const Ns3Defaults&) = delete;

 private:
  void Apply(const Ns3Attributes& attributes);
  void Restore();
  Ns3Attributes earlier_;  // the values they had, to restore in reverse order
};

}  // namespace sanet::net
