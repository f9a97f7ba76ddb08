#include "ros2_face/dds_domain.h"

#include <arpa/inet.h>
#include <dds/dds.h>
#include <ifaddrs.h>
#include <netinet/in.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "ros2_face/raw_cdr_type.h"

namespace sanet::ros2_face {
namespace {

std::string Why(dds_return_t code) { return dds_strretcode(code); }

// The QoS of a ROS 2 profile; the caller deletes it.
dds_qos_t* QosOf(Qos profile) {
  dds_qos_t* q = dds_create_qos();
  const bool latched = profile == Qos::kTfStatic || profile == Qos::kDiscovery;
  const bool reliable = profile == Qos::kDefault || profile == Qos::kTf || latched;
  dds_qset_reliability(q, reliable ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT, DDS_MSECS(100));
  dds_qset_durability(q, latched ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  const int depth = profile == Qos::kDefault ? 10 : profile == Qos::kSensorData ? 5 : profile == Qos::kTf ? 100 : 1;
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, depth);
  if (profile == Qos::kDiscovery) {
    // As rmw_cyclonedds's create_readwrite_qos: no autodispose, and the durability service keeps
    // what the history keeps.
    dds_qset_writer_data_lifecycle(q, false);
    dds_qset_durability_service(q, 0, DDS_HISTORY_KEEP_LAST, depth, DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED,
                                DDS_LENGTH_UNLIMITED);
  }
  return q;
}

// The participant's QoS: its user data names its security enclave, as rmw_cyclonedds says it
// ("enclave=/;", rmw_node.cpp, rmw_context_impl_t::init), for ROS 2's graph of enclaves.
dds_qos_t* ParticipantQos() {
  dds_qos_t* q = dds_create_qos();
  const std::string user_data = "enclave=/;";
  dds_qset_userdata(q, user_data.data(), user_data.size());
  return q;
}

// A participant in `domain`; the QoS is deleted.
dds_entity_t MakeParticipant(std::uint32_t domain) {
  dds_qos_t* q = ParticipantQos();
  const dds_entity_t made = dds_create_participant(domain, q, nullptr);
  dds_delete_qos(q);
  return made;
}

DdsDomain::Guid GuidOf(dds_entity_t entity) {
  dds_guid_t guid{};
  dds_get_guid(entity, &guid);
  DdsDomain::Guid out;
  static_assert(sizeof guid.v == std::tuple_size_v<DdsDomain::Guid>);
  std::memcpy(out.data(), guid.v, out.size());
  return out;
}

// Cyclone's configuration for `domain` on `interface`, after the user's own (CYCLONEDDS_URI, whose
// other settings still apply): a name or an address of letters, digits and . : _ - only, since it
// goes into XML.
std::string InterfaceConfig(const std::string& interface) {
  const bool plain = std::all_of(interface.begin(), interface.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::strchr(".:_-", c);
  });
  if (!plain) throw std::runtime_error("'" + interface + "' is not a network interface's name or address");
  in_addr address{};
  const char* attribute = ::inet_pton(AF_INET, interface.c_str(), &address) == 1 ? "address" : "name";
  const std::string own = std::string("<CycloneDDS><Domain Id=\"any\"><General><Interfaces><NetworkInterface ") +
                          attribute + "=\"" + interface + "\"/></Interfaces></General></Domain></CycloneDDS>";
  const char* user = std::getenv("CYCLONEDDS_URI");
  return user && *user ? std::string(user) + "," + own : own;
}

// "lo (127.0.0.1), eth0 (10.0.2.15)": this machine's interfaces with IPv4 addresses, for errors.
std::string InterfacesHere() {
  ifaddrs* all = nullptr;
  if (::getifaddrs(&all) != 0) return "none listed";
  std::string list;
  for (const ifaddrs* a = all; a; a = a->ifa_next) {
    if (!a->ifa_addr || a->ifa_addr->sa_family != AF_INET) continue;
    char text[INET_ADDRSTRLEN] = "";
    ::inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in*>(a->ifa_addr)->sin_addr, text, sizeof text);
    list += (list.empty() ? "" : ", ") + std::string(a->ifa_name) + " (" + text + ")";
  }
  ::freeifaddrs(all);
  return list.empty() ? "none with an IPv4 address" : list;
}

// A domain of this process's own, configured for `interface`; 0 when none is asked.
dds_entity_t MakeDomain(std::uint32_t domain, const std::string& interface) {
  if (interface.empty()) return 0;
  const dds_entity_t made = dds_create_domain(domain, InterfaceConfig(interface).c_str());
  if (made < 0)
    throw std::runtime_error("cannot join DDS domain " + std::to_string(domain) + " on interface " + interface +
                             (made == DDS_RETCODE_ERROR ? "" : ": " + Why(made)) +
                             "; the interfaces here: " + InterfacesHere());
  return made;
}

}  // namespace

DdsDomain::DdsDomain(std::uint32_t domain, const std::string& interface)
    : domain_(domain), domain_entity_(MakeDomain(domain, interface)), participant_(MakeParticipant(domain)) {
  if (participant_ < 0) {
    if (domain_entity_ > 0) dds_delete(domain_entity_);
    throw std::runtime_error("cannot join DDS domain " + std::to_string(domain) + " (ROS_DOMAIN_ID): " +
                             Why(participant_) + " (CYCLONEDDS_URI may name an interface this machine lacks)");
  }
}

DdsDomain::~DdsDomain() {
  dds_delete(participant_);
  if (domain_entity_ > 0) dds_delete(domain_entity_);
}

DdsDomain::Entity DdsDomain::Topic(const std::string& dds_topic, const std::string& dds_type) {
  ddsi_sertype* type = MakeRawCdrType(dds_type);
  const dds_entity_t topic =
      dds_create_topic_sertype(participant_, dds_topic.c_str(), &type, nullptr, nullptr, nullptr);
  if (topic < 0) throw std::runtime_error("cannot create DDS topic " + dds_topic + ": " + Why(topic));
  return topic;
}

DdsDomain::Entity DdsDomain::Writer(const std::string& ros_topic, const std::string& dds_type, Qos qos) {
  return writers_.emplace_back(Endpoint(dds_create_writer, "publish", "rt" + ros_topic, dds_type, qos));
}

DdsDomain::Entity DdsDomain::Reader(const std::string& ros_topic, const std::string& dds_type, Qos qos) {
  return readers_.emplace_back(Endpoint(dds_create_reader, "subscribe to", "rt" + ros_topic, dds_type, qos));
}

DdsDomain::Entity DdsDomain::BareWriter(const std::string& dds_topic, const std::string& dds_type, Qos qos) {
  return Endpoint(dds_create_writer, "publish", dds_topic, dds_type, qos);
}

DdsDomain::Entity DdsDomain::Endpoint(Entity (*create)(Entity, Entity, const dds_qos_t*, const dds_listener_t*),
                                      const char* what, const std::string& dds_topic, const std::string& dds_type,
                                      Qos qos) {
  dds_qos_t* q = QosOf(qos);
  const dds_entity_t e = create(participant_, Topic(dds_topic, dds_type), q, nullptr);
  dds_delete_qos(q);
  if (e < 0) throw std::runtime_error(std::string("cannot ") + what + " DDS topic " + dds_topic + ": " + Why(e));
  return e;
}

void DdsDomain::Write(Entity writer, const ros2msg::Bytes& sample) { dds_write(writer, &sample); }

std::vector<DdsDomain::Sample> DdsDomain::Take(Entity reader, std::size_t most) {
  std::vector<Sample> taken;
  ros2msg::Bytes bytes;
  void* buffer = &bytes;
  dds_sample_info_t info;
  while (taken.size() < most && dds_take(reader, &buffer, &info, 1, 1) > 0)
    if (info.valid_data) taken.push_back({std::move(bytes), info.publication_handle});
  return taken;
}

}  // namespace sanet::ros2_face

namespace sanet::ros2_face {

std::uint32_t DdsDomain::NewIncompatibleWriters(Entity reader) {
  dds_requested_incompatible_qos_status_t status{};
  if (dds_get_requested_incompatible_qos_status(reader, &status) != DDS_RETCODE_OK) return 0;
  return status.total_count_change;
}

std::uint32_t DdsDomain::MatchedReaders(Entity writer) {
  dds_publication_matched_status_t status{};
  if (dds_get_publication_matched_status(writer, &status) != DDS_RETCODE_OK) return 0;
  return status.current_count;
}

std::uint32_t DdsDomain::IncompatibleWriters(Entity reader) {
  dds_requested_incompatible_qos_status_t status{};
  if (dds_get_requested_incompatible_qos_status(reader, &status) != DDS_RETCODE_OK) return 0;
  return status.total_count;
}

DdsDomain::Guid DdsDomain::ParticipantGuid() const { return GuidOf(participant_); }

std::vector<DdsDomain::Guid> DdsDomain::WriterGuids() const {
  std::vector<Guid> guids;
  for (const Entity w : writers_) guids.push_back(GuidOf(w));
  return guids;
}

std::vector<DdsDomain::Guid> DdsDomain::ReaderGuids() const {
  std::vector<Guid> guids;
  for (const Entity r : readers_) guids.push_back(GuidOf(r));
  return guids;
}

}  // namespace sanet::ros2_face
