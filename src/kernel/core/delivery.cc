#include "core/delivery.h"

namespace sanet {

const char* DeliveryName(Delivery delivery) {
  switch (delivery) {
    case Delivery::kUnicast:
      return "unicast";
    case Delivery::kBroadcast:
      return "broadcast";
    case Delivery::kFlood:
      return "flood";
  }
  return "unicast";
}

std::optional<Delivery> ParseDelivery(const std::string& name) {
  for (Delivery d : {Delivery::kUnicast, Delivery::kBroadcast, Delivery::kFlood})
    if (name == DeliveryName(d)) return d;
  return std::nullopt;
}

}  // namespace sanet
