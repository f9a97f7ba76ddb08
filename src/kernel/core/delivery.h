// The names of the ways a message travels, as results files and the protocol write them.
#pragma once

#include <optional>
#include <string>

#include "sanet/message.h"

namespace sanet {

const char* DeliveryName(Delivery delivery);                     // "unicast", "broadcast", "flood"
std::optional<Delivery> ParseDelivery(const std::string& name);  // nullopt for any other name

}  // namespace sanet
