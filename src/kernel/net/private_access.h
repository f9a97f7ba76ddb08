// Reaching state that ns-3 keeps private and offers no accessor for (AODV's and DSDV's routing
// tables; a LiIonEnergySource's drained capacity; a WifiRadioEnergyModel's pending switch to OFF). Standard C++ allows
// naming a private member in an explicit template instantiation; that instantiation hands the member pointer to a
// friend function we can call. Use only where ns-3 gives no public way, and say so where it is used.
#pragma once

namespace sanet::net {

template <typename Tag, typename Tag::type Member>
struct PrivateMember {
  friend typename Tag::type Get(Tag) { return Member; }
};

}  // namespace sanet::net

// Declares tag `Name` for member `Member` of type `Type` in class `Class`; use it inside
// namespace sanet::net, then read the member with `object.*Get(Name())`.
#define SANET_PRIVATE_MEMBER(Name, Class, Type, Member) \
  struct Name {                                         \
    using type = Type Class::*;                         \
    friend type Get(Name);                              \
  };                                                    \
  template struct PrivateMember<Name, &Class::Member>
