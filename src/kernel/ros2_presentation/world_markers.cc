#include "ros2_presentation/world_markers.h"

#include <cmath>

#include "ros2_presentation/robot_messages.h"

namespace sanet::ros2_presentation {
namespace {

using msg::visualization_msgs::Marker;
using msg::visualization_msgs::MarkerArray;

msg::std_msgs::ColorRGBA Colour(float r, float g, float b, float a = 1) {
  msg::std_msgs::ColorRGBA c;
  c.r = r, c.g = g, c.b = b, c.a = a;
  return c;
}

Marker Shape(const std::string& frame, double t, const char* ns, int id, int type) {
  Marker m;
  m.header.stamp = StampOf(t);
  m.header.frame_id = frame;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = Marker::ADD;
  m.pose.orientation.w = 1;
  return m;
}

void Place(Marker& m, double x, double y, double z, double yaw) {
  m.pose.position.x = x, m.pose.position.y = y, m.pose.position.z = z;
  m.pose.orientation = YawQuaternion(yaw);
}

Marker ObstacleMarker(const sim::Obstacle& o, int id, double t) {
  Marker m = Shape("world", t, "obstacles", id, Marker::CUBE);
  Place(m, o.box.center.x, o.box.center.y, o.box.center.z, o.box.yaw);
  m.scale.x = o.box.size.x, m.scale.y = o.box.size.y, m.scale.z = o.box.size.z;
  m.color = o.kind == "wall" || o.kind == "map" ? Colour(0.55f, 0.55f, 0.6f) : Colour(0.7f, 0.5f, 0.3f);
  return m;
}

Marker MoteMarker(const sim::NodeSpec& node, int id, double t) {
  const double side = node.model.mote.size;
  Marker m = Shape(node.name, t, "motes", id, Marker::CUBE);  // the mote's frame, which /tf moves
  m.frame_locked = true;
  Place(m, 0, 0, side / 2, 0);
  m.scale.x = m.scale.y = m.scale.z = side;
  m.color = Colour(1.0f, 0.6f, 0.1f);
  return m;
}

// In the robot's own frame, which /tf moves: the body needs no update while the robot drives.
Marker BodyMarker(const sim::NodeSpec& node, int id, double t) {
  const RobotFrames frames = FramesOf(node.name);
  Marker m = Shape(frames.base, t, "bodies", id, Marker::CYLINDER);
  m.frame_locked = true;
  m.color = Colour(0.2f, 0.45f, 0.9f);
  const robots::BodyShape shape = node.model.model().Shape(node.model);
  Place(m, 0, 0, shape.base + shape.height / 2, 0);
  m.scale.z = shape.height;
  if (shape.box) {
    m.type = Marker::CUBE;
    m.scale.x = shape.length, m.scale.y = shape.width;
  } else {
    m.scale.x = m.scale.y = 2 * shape.radius;
  }
  return m;
}

Marker NameMarker(const sim::NodeSpec& node, const std::string& frame, int id, double t) {
  Marker m = Shape(frame, t, "names", id, Marker::TEXT_VIEW_FACING);
  m.frame_locked = true;
  m.pose.position.z = 0.5;
  m.scale.z = 0.25;  // the text's height, m
  m.color = Colour(1, 1, 1);
  m.text = node.name;
  return m;
}

msg::geometry_msgs::Point At(Vec2 p, double z) {
  msg::geometry_msgs::Point point;
  point.x = p.x, point.y = p.y, point.z = z;
  return point;
}

}  // namespace

MarkerArray WorldMarkers(const sim::RunSpec& spec, const sim::RunNodes& nodes, double t) {
  MarkerArray out;
  int id = 0;
  for (const sim::Obstacle& o : spec.obstacles) out.markers.push_back(ObstacleMarker(o, id++, t));
  for (NodeId n = 0; n < nodes.size(); ++n) {
    const sim::NodeSpec& node = nodes[n];
    const int marker = static_cast<int>(n);
    if (!robots::HasDrive(node.model)) {
      out.markers.push_back(MoteMarker(node, marker, t));
      out.markers.push_back(NameMarker(node, node.name, marker, t));
    } else {
      out.markers.push_back(BodyMarker(node, marker, t));
      out.markers.push_back(NameMarker(node, FramesOf(node.name).base, marker, t));
    }
  }
  return out;
}

MarkerArray RadioMarkers(double t, double lifetime, const std::vector<RadioLine>& lines) {
  MarkerArray out;
  for (const bool data : {true, false}) {
    Marker m = Shape("world", t, data ? "radio_data" : "radio_other", 0, Marker::LINE_LIST);
    m.scale.x = data ? 0.04 : 0.02;  // the lines' width, m
    m.color = data ? Colour(0.2f, 0.9f, 0.3f, 0.9f) : Colour(0.3f, 0.6f, 1.0f, 0.6f);
    m.lifetime.sec = static_cast<std::int32_t>(std::floor(lifetime));
    m.lifetime.nanosec = static_cast<std::uint32_t>(std::llround((lifetime - std::floor(lifetime)) * 1e9));
    for (const RadioLine& line : lines)
      if (line.data == data) {
        m.points.push_back(At(line.from, 0.3));
        m.points.push_back(At(line.to, 0.3));
      }
    if (!m.points.empty()) out.markers.push_back(std::move(m));
  }
  return out;
}

}  // namespace sanet::ros2_presentation
