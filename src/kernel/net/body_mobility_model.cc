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

}  // namespace sanet::net
