// Every kind of mistake in a scenario is reported with file, line and field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scenario/scenario_loader.h"
#include "sensors/range_fan.h"
#include "sim/assembly.h"
#include "sim/world.h"
#include "support/test_world.h"

namespace sanet {
namespace {

struct Case {
  const char* name;
  const char* yaml;
  int line;
  const char* field;    // expected dotted path ("" to skip the check)
  const char* message;  // expected part of the message
};

// gtest prints a parameter with this, instead of its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

constexpr const char* kHeader = "duration: 10\n";  // line 1 of every case below

const Case kCases[] = {
    {"syntax_error", "nodes: [\n  - {name: a, model: mote, pose: [0, 0, 0]\n", 3, "", "YAML syntax error"},
    {"unquoted_colour_in_flow",
     "world:\n  obstacles:\n    - box: {center: [5, 0], size: [1, 1, 1], color: #ff0000}\n"
     "    - box: {center: [9, 0], size: [1, 1, 1]}\nnodes: []\n",
     5, "", "line 4 has a value that starts with '#', which YAML reads as a comment"},
    {"unknown_key", "duraton: 10\nnodes: []\n", 2, "duraton", "unknown key"},
    {"wrong_type", "world:\n  physics_step: fast\nnodes: []\n", 3, "world.physics_step", "must be a number"},
    {"out_of_range", "world:\n  physics_step: 0.5\nnodes: []\n", 3, "world.physics_step",
     "must be between 0.0001 and 0.1"},
    {"unknown_model", "nodes:\n  - name: r\n    model: omni4\n    pose: [0, 0, 0]\n", 4, "nodes[0].model",
     "unknown model 'omni4'"},
    {"missing_pose", "nodes:\n  - name: r\n    model: omni3\n", 3, "nodes[0]", "missing required key 'pose'"},
    {"pose_too_short", "nodes:\n  - name: r\n    model: omni3\n    pose: [1, 2]\n", 5, "nodes[0].pose",
     "list of 3 numbers"},
    {"duplicate_name",
     "nodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\n  - {name: a, model: mote, pose: [1, 0, 0]}\n", 4,
     "nodes[1].name", "already used on line 3"},
    {"unknown_controller",
     "nodes:\n  - name: r\n    model: omni3\n    pose: [0, 0, 0]\n    controller:\n      name: wayponit\n", 7,
     "nodes[0].controller.name", "unknown controller 'wayponit'; did you mean waypoint? (known here: "},
    {"controller_param_out_of_range",
     "nodes:\n  - name: r\n    model: omni3\n    pose: [0, 0, 0]\n    controller:\n      name: waypoint\n"
     "      params:\n        waypoints: [[1, 1]]\n        speed: -1\n",
     10, "nodes[0].controller.params.speed", "parameter 'speed' is -1"},
    {"unknown_controller_param",
     "nodes:\n  - name: r\n    model: omni3\n    pose: [0, 0, 0]\n    controller:\n      name: waypoint\n"
     "      params:\n        waypoints: [[1, 1]]\n        sped: 1\n",
     10, "nodes[0].controller.params.sped", "unknown parameter 'sped'"},
    {"missing_library",
     "nodes:\n  - name: r\n    model: omni3\n    pose: [0, 0, 0]\n    controller:\n      name: mine\n"
     "      library: no/such/lib.so\n",
     8, "nodes[0].controller.library", "no such file"},
    {"degenerate_wall", "world:\n  obstacles:\n    - wall: {from: [1, 1], to: [1, 1]}\nnodes: []\n", 4,
     "world.obstacles[0].wall.to", "must differ"},
    {"unknown_material",
     "world:\n  obstacles:\n    - wall: {from: [0, 0], to: [5, 0]}\n    - wall:\n        from: [0, 1]\n"
     "        to: [5, 1]\n        material: plaster\nnodes: []\n",
     8, "world.obstacles[1].wall.material", "unknown material 'plaster' (expected one of: none, concrete, brick"},
    {"negative_radio_loss",
     "world:\n  obstacles:\n    - box: {center: [5, 2], size: [2, 2, 1], radio_loss_db: -3}\n"
     "nodes: []\n",
     4, "world.obstacles[0].box.radio_loss_db", "must be between 0 and 1000"},
    {"material_and_loss",
     "world:\n  obstacles:\n    - wall: {from: [0, 0], to: [5, 0], material: brick, radio_loss_db: 6}\nnodes: []\n", 4,
     "world.obstacles[0].wall.radio_loss_db", "either 'material' or 'radio_loss_db'"},
    {"wall_loss_without_network",
     "world:\n  obstacles:\n    - wall: {from: [0, 0], to: [5, 0]}\n    - wall: {from: [0, 1], to: [5, 1], material: "
     "brick}\n"
     "nodes:\n  - {name: a, model: mote, pose: [0, 5, 0]}\n",
     5, "world.obstacles[1].wall.material", "needs a 'network' section"},
    {"unknown_default_material", "world:\n  obstacle_material: stone\nnodes: []\n", 3, "world.obstacle_material",
     "unknown material 'stone'"},
    {"negative_antenna_height",
     "network: {}\nnodes:\n  - name: r\n    model: mote\n    pose: [0, 0, 0]\n    radio: {antenna_height: -1}\n", 7,
     "nodes[0].radio.antenna_height", "must be between 0 and 1000"},
    {"duplicate_key", "seed: 1\nseed: 2\nnodes: []\n", 3, "seed", "key given twice"},
    {"robot_inside_a_box",
     "world:\n  obstacles:\n    - box: {center: [5, 2], size: [2, 2, 0.5]}\nnodes:\n  - name: r\n    model: omni3\n"
     "    pose: [5.2, 2, 0]\n",
     8, "nodes[0].pose", "r at (5.20, 2.00) is inside world.obstacles[0], a box (line 4)"},
    {"robot_on_a_mote",
     "nodes:\n  - {name: m, model: mote, pose: [1, 1, 0]}\n  - name: r\n    model: diffdrive\n    pose: [1.1, 1, 0]\n",
     6, "nodes[1].pose", "r at (1.10, 1.00) overlaps m at (1.00, 1.00) (line 3)"},
    {"two_robots_on_one_spot",
     "nodes:\n  - {name: a, model: omni3, pose: [0, 0, 0]}\n  - {name: b, model: omni3, pose: [0.3, 0, 1]}\n", 4,
     "nodes[1].pose", "b at (0.30, 0.00) overlaps a at (0.00, 0.00) (line 3): their bodies reach 0.19 and 0.19 m"},
    {"grid_on_a_robot",
     "nodes:\n  - {name: r, model: omni3, pose: [2, 0, 0]}\n  - grid: {name: m, rows: 1, cols: 5, origin: [0, 0], "
     "spacing: [1, 1]}\n    model: mote\n",
     4, "nodes[1].grid", "m2 at (2.00, 0.00) overlaps r at (2.00, 0.00) (line 3)"},
    {"negative_seed", "seed: -4\nnodes: []\n", 2, "seed", "whole number >= 0"},
    {"unknown_sensor", "nodes:\n  - name: r\n    model: omni3\n    pose: [0, 0, 0]\n    sensors: {radar: {}}\n", 6,
     "nodes[0].sensors.radar", "unknown sensor 'radar'"},
    {"body_param_of_other_model",
     "nodes:\n  - name: r\n    model: omni3\n    pose: [0, 0, 0]\n    body: {axle_length: 0.3}\n", 6,
     "nodes[0].body.axle_length", "unknown key"},
    {"no_nodes", "nodes: []\n", 2, "nodes", "at least one node"},
    {"grid_rows_zero", "nodes:\n  - grid: {name: m, rows: 0, cols: 2}\n    model: mote\n", 3, "nodes[0].grid.rows",
     "must be between 1"},
    {"name_with_a_comma", "nodes:\n  - {name: 'a,b', model: mote, pose: [0, 0, 0]}\n", 3, "nodes[0].name",
     "may hold only letters"},
    {"library_that_is_not_a_plugin",
     "nodes:\n  - name: r\n    model: omni3\n    pose: [0, 0, 0]\n    controller:\n      name: mine\n"
     "      library: /lib/x86_64-linux-gnu/libm.so.6\n",
     7, "nodes[0].controller.library", "not a sanet controller library"},
    {"interval_below_physics_step",
     "nodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\noutputs:\n  trajectory_interval: 0.001\n", 5,
     "outputs.trajectory_interval", "at least world.physics_step"},
    {"unknown_routing", "network:\n  routing: babel\nnodes: []\n", 3, "network.routing",
     "unknown value 'babel' (expected one of: aodv, olsr, dsdv, dsr, none)"},
    {"data_rate_not_offered", "network:\n  radio: 802.11b\n  data_rate: 54\nnodes: []\n", 4, "network.data_rate",
     "802.11b offers 1, 2, 5.5, 11 Mbps"},
    {"lr_wpan_routing_explained",
     "network:\n  radio: 802.15.4\n  routing: aodv\nnodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\n", 4,
     "network.routing", "RIPng"},
    {"wifi_power_without_wifi",
     "network:\n  radio: 802.15.4\n  tx_power: 0\nnodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\n", 4,
     "network.tx_power", "lr_wpan.tx_power"},
    {"lr_wpan_section_unused",
     "network:\n  lr_wpan: {tx_power: 0}\nnodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\n", 3, "network.lr_wpan",
     "no node has an 802.15.4 radio"},
    {"backoff_exponents_crossed", "network:\n  lr_wpan: {min_be: 5, max_be: 4}\nnodes: []\n", 3,
     "network.lr_wpan.min_be", "may not exceed macMaxBE"},
    {"unknown_node_standard",
     "network: {}\nnodes:\n  - {name: a, model: mote, pose: [0, 0, 0], radio: {standard: zigbee}}\n", 4,
     "nodes[0].radio.standard", "unknown value 'zigbee'"},
    {"two_radios_one_power",
     "network: {}\nnodes:\n  - {name: a, model: omni3, pose: [0, 0, 0], radio: {standard: [802.11b, 802.15.4], "
     "tx_power: 5}}\n",
     4, "nodes[0].radio.tx_power", "two radios"},
    {"two_wifi_standards",
     "network: {radio: 802.11b}\nnodes:\n  - {name: a, model: omni3, pose: [0, 0, 0], radio: {standard: [802.11g, "
     "802.15.4]}}\n",
     4, "nodes[0].radio.standard[0]", "share one channel"},
    {"tap_without_wifi",
     "network: {radio: 802.15.4}\nloop: {network: simulated}\nnodes:\n  - {name: r, model: omni3, pose: [0, 0, 0], "
     "controller: {name: pinger}}\n",
     3, "loop.network", "no 802.11 radio"},
    {"wifi_currents_on_lr_wpan_mote",
     "network: {radio: 802.15.4}\nnodes:\n  - {name: a, model: mote, pose: [0, 0, 0], energy: {battery_j: 10, "
     "radio: cc2420}}\n",
     4, "nodes[0].energy.radio", "lr_wpan_radio"},
    {"exponent_with_friis", "network:\n  propagation: {model: friis, exponent: 2}\nnodes: []\n", 3,
     "network.propagation.exponent", "log_distance model only"},
    {"radio_without_network", "nodes:\n  - {name: a, model: mote, pose: [0, 0, 0], radio: {tx_power: 5}}\n", 3,
     "nodes[0].radio", "needs a 'network' section"},
    {"latency_with_network",
     "network: {}\nmessages: {latency: 0.1}\nnodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\n", 3,
     "messages.latency", "for runs without a network"},
    {"port_of_a_routing_protocol", "network:\n  port: 654\nnodes: []\n", 3, "network.port", "port of AODV"},
    {"random_delay_max_without_random", "network:\n  random_delay_max: 0.0001\nnodes: []\n", 3,
     "network.random_delay_max", "delay: random only"},
    {"odometry_on_a_mote",
     "nodes:\n  - name: m\n    model: mote\n    pose: [0, 0, 0]\n    sensors: {odometry: {noise: 0.1}}\n", 6,
     "nodes[0].sensors.odometry", "no odometry"},
    {"ros2_unknown_robot",
     "ros2:\n  robots:\n    - {robot: ghost, rate: 5}\nnodes:\n  - {name: a, model: omni3, pose: [0, 0, 0]}\n", 4,
     "ros2.robots[0].robot", "no robot named 'ghost'"},
    {"ros2_mote", "ros2:\n  robots:\n    - {robot: m}\nnodes:\n  - {name: m, model: mote, pose: [0, 0, 0]}\n", 4,
     "ros2.robots[0].robot", "is a mote"},
    {"ros2_bad_namespace",
     "ros2:\n  robots:\n    - {robot: a, namespace: '2fast/'}\nnodes:\n  - {name: a, model: omni3, pose: [0, 0, 0]}\n",
     4, "ros2.robots[0].namespace", "is no ROS name"},
    {"ros2_shared_namespace",
     "ros2:\n  robots:\n    - {robot: a, namespace: b}\nnodes:\n  - {name: a, model: omni3, pose: [0, 0, 0]}\n"
     "  - {name: b, model: omni3, pose: [3, 0, 0]}\n",
     4, "ros2.robots[0].namespace", "robots a and b would share the namespace 'b'"},
    {"ros2_robot_name_no_ros_name", "ros2: {rate: 5}\nnodes:\n  - {name: scout-1, model: omni3, pose: [0, 0, 0]}\n", 2,
     "ros2", "robot 'scout-1': its name is no ROS name"},
    {"ros2_domain_out_of_range", "ros2: {domain: 300}\nnodes:\n  - {name: a, model: omni3, pose: [0, 0, 0]}\n", 2,
     "ros2.domain", "between 0 and 232"},
    {"ros2_cmd_vel_type", "ros2: {cmd_vel: twistt}\nnodes:\n  - {name: a, model: omni3, pose: [0, 0, 0]}\n", 2,
     "ros2.cmd_vel", "expected one of: twist, twist_stamped"},
    {"ros2_distro", "ros2: {distro: iron}\nnodes:\n  - {name: a, model: omni3, pose: [0, 0, 0]}\n", 2, "ros2.distro",
     "unknown value 'iron' (expected one of: humble, jazzy)"},
    // energy (docs/energy.md)
    {"energy_without_capacity", "nodes:\n  - name: m\n    model: mote\n    pose: [0, 0, 0]\n    energy: {voltage: 3}\n",
     6, "nodes[0].energy", "missing required key 'battery_j'"},
    {"energy_cutoff_of_one",
     "nodes:\n  - name: m\n    model: mote\n    pose: [0, 0, 0]\n    energy: {battery_j: 10, cutoff: 1}\n", 6,
     "nodes[0].energy.cutoff", "kills the node at once"},
    {"energy_revive_below_cutoff",
     "nodes:\n  - name: m\n    model: mote\n    pose: [0, 0, 0]\n"
     "    energy: {battery_j: 10, cutoff: 0.2, revive: 0.1}\n",
     6, "nodes[0].energy.revive", "must be above the cutoff"},
    {"energy_dead_from_the_start",
     "nodes:\n  - name: m\n    model: mote\n    pose: [0, 0, 0]\n"
     "    energy: {battery_j: 10, cutoff: 0.5, initial_fraction: 0.3}\n",
     6, "nodes[0].energy.initial_fraction", "dead from the start"},
    {"energy_unknown_preset",
     "nodes:\n  - name: m\n    model: mote\n    pose: [0, 0, 0]\n    energy: {battery_j: 10, radio: cc2402}\n", 6,
     "nodes[0].energy.radio", "unknown radio preset 'cc2402' (expected one of: ns3_wifi, cc2420)"},
    {"energy_negative_current",
     "nodes:\n  - name: m\n    model: mote\n    pose: [0, 0, 0]\n"
     "    energy: {battery_j: 10, radio: {preset: cc2420, tx_a: -1}}\n",
     6, "nodes[0].energy.radio.tx_a", "must be between 0 and 1000"},
    {"voltage_of_a_li_ion_pack",
     "nodes:\n  - name: m\n    model: mote\n    pose: [0, 0, 0]\n"
     "    energy: {source: li_ion, battery_j: 20000, voltage: 3.7}\n",
     6, "nodes[0].energy.voltage", "follows its discharge curve"},
    {"battery_sensor_without_energy",
     "nodes:\n  - name: m\n    model: mote\n    pose: [0, 0, 0]\n    sensors: {battery: {}}\n", 6,
     "nodes[0].sensors.battery", "give the node `energy`"},
    {"recharge_without_energy",
     "nodes:\n  - {name: m, model: mote, pose: [0, 0, 0]}\nevents:\n  - {time: 1, node: m, action: recharge}\n", 5,
     "events[0].node", "an infinite supply takes no recharge"},
    {"energy_j_on_a_switch_off",
     "nodes:\n  - {name: m, model: mote, pose: [0, 0, 0], energy: {battery_j: 5}}\nevents:\n"
     "  - {time: 1, node: m, action: switch_off, energy_j: 3}\n",
     5, "events[0].energy_j", "is the energy of a `recharge`"},
    {"drive_costs_on_a_mote",
     "nodes:\n  - name: m\n    model: mote\n    pose: [0, 0, 0]\n"
     "    energy: {battery_j: 5, motion_efficiency: 0.5}\n",
     6, "nodes[0].energy.motion_efficiency", "a mote has no drive"},
    {"wireless_charger_without_range",
     "nodes:\n  - name: r\n    model: diffdrive\n    pose: [0, 0, 0]\n"
     "    energy: {battery_j: 5, wireless_charger: {power_w: 3}}\n",
     6, "nodes[0].energy.wireless_charger", "missing required key 'range_m'"},
    {"zero_efficiency",
     "nodes:\n  - name: r\n    model: diffdrive\n    pose: [0, 0, 0]\n"
     "    energy: {battery_j: 5, motion_efficiency: 0}\n",
     6, "nodes[0].energy.motion_efficiency", "must be"},
    {"charger_without_radius", "world:\n  chargers:\n    - {position: [0, 0], power_w: 5}\nnodes: []\n", 4,
     "world.chargers[0]", "missing required key 'radius'"},
    {"sensor_power_without_energy",
     "nodes:\n  - name: r\n    model: diffdrive\n    pose: [0, 0, 0]\n    sensors: {laser: {power_w: 2}}\n", 6,
     "nodes[0].sensors.laser.power_w", "give the node `energy`"},
    {"negative_sensor_power",
     "nodes:\n  - name: r\n    model: diffdrive\n    pose: [0, 0, 0]\n    sensors: {laser: {power_w: -1}}\n", 6,
     "nodes[0].sensors.laser.power_w", "must be between 0 and"},
};

class Malformed : public ::testing::TestWithParam<Case> {};

TEST_P(Malformed, IsRejectedWithFileLineAndField) {
  const Case& c = GetParam();
  const std::string path = ::testing::TempDir() + "/malformed-" + c.name + ".yaml";
  std::ofstream(path) << kHeader << c.yaml;
  try {
    scenario::Scenario sc = scenario::LoadScenario(path);
    scenario::CheckControllers(sc, testing::BuiltinRegistry());
    FAIL() << c.name << " was accepted";
  } catch (const scenario::ScenarioError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), c.line) << e.what();
    if (*c.field) {
      EXPECT_EQ(e.field(), c.field) << e.what();
    }
    EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind(path + ":" + std::to_string(c.line) + ": ", 0), 0u) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Scenario, Malformed, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Scenario, MissingFileIsReported) {
  EXPECT_THROW(scenario::LoadScenario("/no/such/scenario.yaml"), scenario::ScenarioError);
}

TEST(Scenario, GridPlacesNodesRowByRow) {
  const std::string path = ::testing::TempDir() + "/grid.yaml";
  std::ofstream(path)
      << "duration: 1\nnodes:\n  - grid: {name: m, rows: 2, cols: 3, origin: [10, 20], spacing: [5, 7]}\n"
         "    model: mote\n";
  const scenario::Scenario sc = scenario::LoadScenario(path);
  ASSERT_EQ(sc.run.nodes.size(), 6u);
  EXPECT_EQ(sc.run.nodes[4].name, "m4");
  EXPECT_DOUBLE_EQ(sc.run.nodes[4].pose.x, 15);
  EXPECT_DOUBLE_EQ(sc.run.nodes[4].pose.y, 27);
}

}  // namespace
}  // namespace sanet

namespace sanet {
namespace {

TEST(Scenario, DefaultSensorsFollowTheBodyAndTrueAddsOne) {
  const std::string path = ::testing::TempDir() + "/sensor-defaults.yaml";
  std::ofstream(path) << "duration: 1\nnodes:\n  - name: r\n    model: omni3\n    pose: [0, 0, 0]\n"
                         "    body: {body_radius: 0.3}\n    sensors: {laser: true, ir: {noise: 0.01}}\n";
  const scenario::Scenario sc = scenario::LoadScenario(path);
  const auto* ir = sensors::DefaultFan(sc.run.nodes[0].model, "ir");
  const auto* laser = sensors::DefaultFan(sc.run.nodes[0].model, "laser");
  ASSERT_TRUE(ir && laser);
  EXPECT_DOUBLE_EQ(ir->mount_radius, 0.3);
  EXPECT_EQ(ir->angles.size(), 6u);
  EXPECT_DOUBLE_EQ(ir->noise, 0.01);
  EXPECT_EQ(laser->angles.size(), 181u);
}

TEST(Scenario, NamedInstancesAddMoreSensorsOfAKind) {
  const std::string path = ::testing::TempDir() + "/named-sensors.yaml";
  std::ofstream(path) << "duration: 1\nnodes:\n  - name: r\n    model: diffdrive\n    pose: [0, 0, 0]\n"
                         "    sensors: {laser_rear: {kind: laser, fov: 1.5, beams: 31, mount_x: -0.2}}\n";
  const scenario::Scenario sc = scenario::LoadScenario(path);
  const robots::ModelSpec& model = sc.run.nodes[0].model;
  const auto* front = sensors::DefaultFan(model, "laser");
  const auto* rear = sensors::SettingsOf<sensors::RangeFan>(model, "laser_rear", "laser");
  ASSERT_TRUE(front && rear) << "the default laser stays beside the named one";
  EXPECT_EQ(front->angles.size(), 181u);
  EXPECT_EQ(rear->angles.size(), 31u);
  EXPECT_DOUBLE_EQ(rear->mount_x, -0.2);
  sim::World world(sc.run, testing::BuiltinRegistry());
  const auto scan = world.parts().node(0).SensorAs<RangeScan>("laser_rear");
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->ranges.size(), 31u);
  EXPECT_FALSE(world.parts().node(0).Sensor("laser_left")) << "no such instance";
}

TEST(Scenario, SensorInstancesAreCheckedByKind) {
  const std::string path = ::testing::TempDir() + "/bad-sensors.yaml";
  const auto error = [&](const std::string& sensors_yaml) {
    std::ofstream(path) << "duration: 1\nnodes:\n  - name: r\n    model: diffdrive\n    pose: [0, 0, 0]\n"
                           "    sensors: "
                        << sensors_yaml << "\n";
    try {
      scenario::LoadScenario(path);
    } catch (const scenario::ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("{radar: {max_range: 2}}").find("unknown sensor 'radar'"), std::string::npos);
  EXPECT_NE(error("{rear: {kind: radar}}").find("unknown sensor kind 'radar' (known: ir, laser"), std::string::npos);
  EXPECT_NE(error("{laser: {kind: ir}}").find("give this ir another name"), std::string::npos);
  EXPECT_NE(error("{rear: {kind: laser, colour: red}}").find("unknown key"), std::string::npos);
  EXPECT_NE(error("{ground_truth: false}")
                .find("every node has its ground_truth, which cannot be taken off; its keys are noise_position, "
                      "noise_angle"),
            std::string::npos);
  EXPECT_NE(error("{bearing: true}").find("a bearing sensor needs range: give {range: ...} instead of true"),
            std::string::npos);
  EXPECT_NE(error("{sonar: {}, sonar: {fov: 1}}").find("'nodes[0].sensors.sonar': key given twice"), std::string::npos);
  EXPECT_NE(error("{laser rear: {kind: laser}}")
                .find("a sensor's name is letters, digits and _, starting with a lower-case letter"),
            std::string::npos);
  EXPECT_NE(error("{scan: {kind: sonar}}")
                .find("'nodes[0].sensors.scan': sensors 'laser' and 'scan' would both publish /<robot>/scan: give "
                      "'scan' another name"),
            std::string::npos);
  EXPECT_EQ(error("{odometry: false, sonar_left: {kind: sonar, direction: 1.5}}"), "no error")
      << "a robot may go without odometry, and carry a second sonar";
}

TEST(Scenario, IrAnglesReplaceTheEvenRing) {
  const std::string path = ::testing::TempDir() + "/ir-angles.yaml";
  std::ofstream(path) << "duration: 1\nnodes:\n  - name: r\n    model: omni3\n    pose: [0, 0, 0]\n"
                         "    sensors: {ir: {angles: [0, 1.5708, -1.5708], max_range: 1.5}}\n";
  const scenario::Scenario sc = scenario::LoadScenario(path);
  const auto& ir = *sensors::DefaultFan(sc.run.nodes[0].model, "ir");
  ASSERT_EQ(ir.angles.size(), 3u);
  EXPECT_DOUBLE_EQ(ir.angles[2], -1.5708);
  EXPECT_DOUBLE_EQ(ir.max_range, 1.5);
}

}  // namespace
}  // namespace sanet
