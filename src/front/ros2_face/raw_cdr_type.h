// A Cyclone DDS type whose samples are already serialized: the CDR bytes of ros2msg's encoders,
// written and taken as they are, so that sanet has one encoder for ROS 2 messages (DDS, and the
// logs and streams that reuse ros2msg). Cyclone's extension interface for this is a "sertype"
// with its "serdata" (dds/ddsi/ddsi_sertype.h, ddsi_serdata.h, as ROS 2's rmw_cyclonedds uses
// it): samples are ros2msg::Bytes (the encapsulation header and the payload); the types have no
// key and no XTypes type information, so DDS matches them by type name, as with ROS 2 nodes.
#pragma once

#include <string>

struct ddsi_sertype;

namespace sanet::ros2_face {

// A new type named `dds_type_name` (e.g. "nav_msgs::msg::dds_::Odometry_"), for
// dds_create_topic_sertype, which takes it over.
ddsi_sertype* MakeRawCdrType(const std::string& dds_type_name);

}  // namespace sanet::ros2_face
