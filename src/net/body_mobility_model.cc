#include "net/body_mobility_model.h"

namespace sanet::net {

NS_OBJECT_ENSURE_REGISTERED(BodyMobilityModel);

ns3::TypeId BodyMobilityModel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::BodyMobilityModel")
                               .SetParent<ns3::MobilityModel>()
                               .SetGroupName("sanet")
                               .AddConstructor<BodyMobilityModel>();
  return tid;
}

void BodyMobilityModel::Bind(std::function<ns3::Vector()> position, std::function<ns3::Vector()> velocity) {
  position_ = std::move(position);
  velocity_ = std::move(velocity);
}

ns3::Vector BodyMobilityModel::DoGetPosition() const { return position_ ? position_() : ns3::Vector(); }

void BodyMobilityModel::DoSetPosition(const ns3::Vector&) {}

ns3::Vector BodyMobilityModel::DoGetVelocity() const { return velocity_ ? velocity_() : ns3::Vector(); }

}  // namespace sanet::net
