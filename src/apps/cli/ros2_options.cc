#include "ros2_options.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace sanet::cli {
int Ros2Domain(std::optional<int> given, int section) {
  if (given) return *given;
  if (section >= 0) return section;
  const char* env = std::getenv("ROS_DOMAIN_ID");
  if (!env || !*env) return 0;
  char* end = nullptr;
  const long id = std::strtol(env, &end, 10);
  if (*end || id < 0 || id > 232)
    throw CLI::ValidationError("ROS_DOMAIN_ID", std::string("'") + env + "' is not a DDS domain from 0 to 232");
  return static_cast<int>(id);
}

void AddRos2Options(CLI::App* cmd, Ros2Args& args) {
  cmd->add_flag("--ros2", args.on,
                "Make every robot no client drives a ROS 2 robot over DDS: /ROBOT/odom, scan, ir_I, ground_truth, "
                "cmd_vel, and /tf, /tf_static, /clock (docs/ros2.md); on without it when the scenario has a ros2 "
                "section");
  cmd->add_flag("--no-ros2", args.off, "No ROS 2 face, even if the scenario has a ros2 section");
  cmd->add_option("--ros2-domain", args.domain,
                  "DDS domain of the ROS 2 face (default: the scenario's ros2.domain, else ROS_DOMAIN_ID, else 0)")
      ->check(CLI::Range(0, 232));
  cmd->add_option("--ros2-rate", args.rate,
                  "Hz of each robot's sensor messages on the ROS 2 face (default: the scenario's ros2.rate, 10)")
      ->check(CLI::Range(0.1, 1000.0));
  cmd->add_flag("--ros2-cmd-vel-stamped", args.stamped,
                "Take cmd_vel as geometry_msgs/TwistStamped (as ROS 2 Jazzy's diff_drive_controller subscribes to it), "
                "not Twist");
  cmd->add_option(
      "--ros2-interface", args.interface,
      "The network interface (name or IPv4 address) of the ROS 2 face's DDS traffic; other Cyclone settings "
      "still come from CYCLONEDDS_URI (sanet launch gives its namespaces' bridge)");
  cmd->add_option("--ros2-distro", args.distro,
                  "The ROS 2 release whose `ros2 node list` shows the face as node /sanet: humble, or jazzy (also "
                  "Iron's; default: the scenario's ros2.distro, jazzy)")
      ->check(CLI::IsMember({"humble", "jazzy"}));
}

std::unique_ptr<ros2_face::Ros2Face> StartRos2Face(sim::World& world, const Ros2Args& args,
                                                   const std::optional<sections::Ros2Spec>& section,
                                                   std::vector<std::string>& notices) {
  if (args.off || (!args.on && !section)) return nullptr;
  const sections::Ros2Spec given = section.value_or(sections::Ros2Spec{});
  ros2_face::Ros2Settings settings;
  settings.domain = static_cast<std::uint32_t>(Ros2Domain(args.domain, given.domain));
  if (args.interface && args.interface->empty())
    throw CLI::ValidationError("--ros2-interface", "give an interface's name or IPv4 address (ip -br addr lists them)");
  settings.interface = args.interface.value_or("");
  settings.sensor_period = 1.0 / args.rate.value_or(given.rate);
  settings.twist_stamped = args.stamped || given.cmd_vel == sections::CmdVelType::kTwistStamped;
  settings.distro = !args.distro               ? given.distro
                    : *args.distro == "humble" ? sections::Ros2Distro::kHumble
                                               : sections::Ros2Distro::kJazzy;
  settings.robots = given.robots;
  settings.cmd_vel_timeout = given.cmd_vel_timeout;
  std::unique_ptr<ros2_face::Ros2Face> face;
  try {
    face = std::make_unique<ros2_face::Ros2Face>(world.driver(), settings);
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError("--ros2", e.what());
  }
  face->Start();
  notices.push_back("sanet: ROS 2 face on DDS domain " + std::to_string(settings.domain) +
                    (settings.interface.empty() ? "" : ", interface " + settings.interface) +
                    ": its robots' topics under /ROBOT/, /tf, /tf_static, /clock; node /sanet for ROS 2 " +
                    (settings.distro == sections::Ros2Distro::kHumble ? "Humble" : "Jazzy (and Iron)"));
  return face;
}

}  // namespace sanet::cli
