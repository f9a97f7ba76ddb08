#include "net/ns3_attributes.h"

#include <ns3/core-module.h>
#include <ns3/wifi-phy.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "core/closest_names.h"

namespace sanet::net {
namespace {

// Attributes that the scenario's own keys set on the objects (a default would be overwritten).
const std::map<std::string, std::string>& SetBySanet() {
  static const std::map<std::string, std::string> keys = {
      {"ns3::WifiPhy::TxPowerStart", "network.tx_power (or a node's radio.tx_power)"},
      {"ns3::WifiPhy::TxPowerEnd", "network.tx_power (or a node's radio.tx_power)"},
      {"ns3::ConstantRateWifiManager::DataMode", "network.data_rate"},
      {"ns3::ConstantRateWifiManager::ControlMode", "network.data_rate (broadcasts go at the lowest rate)"},
      {"ns3::ConstantRateWifiManager::NonUnicastMode", "network.data_rate (broadcasts go at the lowest rate)"},
      {"ns3::LogDistancePropagationLossModel::Exponent", "network.propagation.exponent"},
      {"ns3::LogDistancePropagationLossModel::ReferenceDistance", "network.propagation.reference_distance"},
      {"ns3::LogDistancePropagationLossModel::ReferenceLoss", "network.propagation.reference_loss"},
      {"ns3::FriisPropagationLossModel::Frequency", "network.radio"},
      {"ns3::TwoRayGroundPropagationLossModel::Frequency", "network.radio"},
      {"ns3::TwoRayGroundPropagationLossModel::HeightAboveZ", "network.propagation.antenna_height"},
      {"ns3::RangePropagationLossModel::MaxRange", "network.propagation.max_range"},
      {"ns3::RandomPropagationDelayModel::Variable", "network.random_delay_max"},
      {"ns3::ThresholdPreambleDetectionModel::MinimumRssi", "network.rx_threshold"},
      {"ns3::aodv::RoutingProtocol::EnableHello", "network.aodv_hello"},
  };
  return keys;
}

// " (did you mean A, B or C?)", or "" when nothing is close.
std::string Closest(const std::string& wanted, const std::vector<std::string>& candidates) {
  const std::vector<std::string> close = ClosestNames(wanted, candidates);
  return close.empty() ? "" : " (did you mean " + OrList(close) + "?)";
}

std::vector<std::string> TypeNames() {
  std::vector<std::string> names;
  for (std::uint16_t i = 0; i < ns3::TypeId::GetRegisteredN(); ++i)
    names.push_back(ns3::TypeId::GetRegistered(i).GetName());
  return names;
}

// The attribute `name` of `tid` itself (not of a parent: ns-3 sets defaults on the type that
// declares the attribute), or -1.
int OwnAttribute(ns3::TypeId tid, const std::string& name) {
  for (std::size_t j = 0; j < tid.GetAttributeN(); ++j)
    if (tid.GetAttribute(j).name == name) return static_cast<int>(j);
  return -1;
}

// The type and index of a named attribute; throws std::invalid_argument saying what is wrong.
std::pair<ns3::TypeId, int> Find(const std::string& full) {
  const auto sep = full.rfind("::");
  if (sep == std::string::npos || sep == 0)
    throw std::invalid_argument("'" + full + "' is not an ns-3 attribute name (TYPE::ATTRIBUTE, e.g. " +
                                "ns3::aodv::RoutingProtocol::ActiveRouteTimeout)");
  const std::string type = full.substr(0, sep), name = full.substr(sep + 2);
  ns3::TypeId tid;
  if (!ns3::TypeId::LookupByNameFailSafe(type, &tid))
    throw std::invalid_argument("ns-3 has no type '" + type + "'" + Closest(type, TypeNames()));
  const int own = OwnAttribute(tid, name);
  if (own >= 0) return {tid, own};
  // The root is its own parent.
  for (ns3::TypeId child = tid, parent = tid.GetParent(); parent != child && parent.GetName() != "ns3::ObjectBase";
       child = parent, parent = parent.GetParent())
    if (OwnAttribute(parent, name) >= 0)
      throw std::invalid_argument("'" + name + "' is an attribute of " + parent.GetName() + ": name it " +
                                  parent.GetName() + "::" + name);
  std::vector<std::string> names;
  for (std::size_t j = 0; j < tid.GetAttributeN(); ++j) names.push_back(tid.GetAttribute(j).name);
  throw std::invalid_argument(type + " has no attribute '" + name + "'" + Closest(name, names));
}

// ns-3 aborts the process on some values it cannot parse (a Time of "ten", an unknown type in
// a random variable): a child process tries first. Returns ns-3's complaint, or "" if it took it.
std::string TryValue(const ns3::AttributeChecker& checker, const std::string& value) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return "";
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    ::dup2(pipe_fds[1], STDERR_FILENO);
    ::dup2(pipe_fds[1], STDOUT_FILENO);
    ::_exit(checker.CreateValidValue(ns3::StringValue(value)) ? 0 : 1);
  }
  ::close(pipe_fds[1]);
  std::string said;
  char buffer[512];
  for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0;) said.append(buffer, n);
  ::close(pipe_fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  const auto msg = said.find("msg=\"");
  if (msg != std::string::npos) return said.substr(msg + 5, said.find('"', msg + 5) - msg - 5);
  return "not taken";
}

// What sanet takes as an ns-3 time: not negative (no timer is), with a unit.
const std::regex& TimeWithUnit() {
  static const std::regex time(R"(\+?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?(y|d|h|min|s|ms|us|ns|ps|fs))");
  return time;
}

std::string ValueType(const ns3::AttributeChecker& checker) {
  if (checker.GetValueTypeName() == "ns3::TimeValue") return "a time such as 10s, 500ms or 2min";
  const std::string underlying = checker.GetUnderlyingTypeInformation();
  return underlying.empty() ? checker.GetValueTypeName() : underlying;
}

std::string DefaultOf(const ns3::TypeId::AttributeInformation& info) {
  if (const auto* time = dynamic_cast<const ns3::TimeValue*>(PeekPointer(info.originalInitialValue))) {
    std::ostringstream s;
    s << time->Get().GetSeconds() << "s";
    return s.str();
  }
  return info.originalInitialValue->SerializeToString(info.checker);
}

}  // namespace

std::string CheckNs3Attribute(const std::string& full, const std::string& value) {
  if (auto key = SetBySanet().find(full); key != SetBySanet().end())
    return "sanet sets this attribute itself: use " + key->second;
  try {
    const auto [tid, index] = Find(full);
    const ns3::TypeId::AttributeInformation info = tid.GetAttribute(index);
    if (!(info.flags & ns3::TypeId::ATTR_CONSTRUCT))
      return full + " cannot be set before an object is made (ns-3 does not take it as a default)";
    if (info.checker->GetValueTypeName() == "ns3::TimeValue" && !std::regex_match(value, TimeWithUnit()))
      return "'" + value + "' is not a time for " + full + ": give a number of 0 or more with its unit, e.g. 10s, " +
             "500ms, 2min (ns-3 would read a bare number as seconds; default " + DefaultOf(info) + ")";
    if (const std::string why = TryValue(*info.checker, value); !why.empty())
      return "'" + value + "' is not a valid value for " + full + " (" +
             (why.find(value) != std::string::npos ? "ns-3: " + why + "; " : "") + "expects " +
             ValueType(*info.checker) + ", default " + DefaultOf(info) + "; " + info.help + ")";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

Ns3Defaults::Ns3Defaults(const Ns3Attributes& attributes) {
  try {
    Apply(attributes);
  } catch (...) {
    Restore();  // those set before the one refused
    throw;
  }
}

void Ns3Defaults::Apply(const Ns3Attributes& attributes) {
  for (const auto& [full, value] : attributes) {
    const auto [tid, index] = Find(full);  // throws for a name ns-3 does not know
    const ns3::TypeId::AttributeInformation info = tid.GetAttribute(index);
    const std::string earlier = info.initialValue->SerializeToString(info.checker);
    if (!ns3::Config::SetDefaultFailSafe(full, ns3::StringValue(value)))
      throw std::invalid_argument("network.ns3: ns-3 does not take '" + value + "' for " + full);
    earlier_.emplace_back(full, earlier);
  }
}

Ns3Defaults::~Ns3Defaults() { Restore(); }

void Ns3Defaults::Restore() {
  for (auto it = earlier_.rbegin(); it != earlier_.rend(); ++it)
    ns3::Config::SetDefaultFailSafe(it->first, ns3::StringValue(it->second));
  earlier_.clear();
}

double WifiPhyDefault(const char* attribute) {
  ns3::TypeId::AttributeInformation info;
  if (!ns3::WifiPhy::GetTypeId().LookupAttributeByName(attribute, &info))
    throw std::logic_error(std::string("WifiPhy has no attribute ") + attribute);
  return ns3::DynamicCast<const ns3::DoubleValue>(info.initialValue)->Get();
}

}  // namespace sanet::net
