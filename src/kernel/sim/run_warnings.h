// What a run's reader should know although nothing failed: the physics engine's messages (ODE's
// "LCP internal error" when bodies are stuck in each other), counted by kind with the bodies in
// contact when the first came, and motes that robots pushed away from where the scenario put
// them. They go to summary.json's "warnings" and to the command, never into log.csv (which the
// fingerprint covers: a warning must not change a run's identity).
#pragma once

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sanet/geometry.h"
#include "sim/run_nodes.h"

namespace sanet::sim {

class RunWarnings {
 public:
  // A mote that ends farther than this from its start was pushed (m): less, a robot brushing past,
  // changes no radio link's length that matters.
  static constexpr double kMoteMoved = 0.25;

  // The engine's message `text` of kind `kind` at simulated time `t`; `contacts` names the bodies
  // touching then ("r1 and world.obstacles[0]"), for the first of its kind.
  void EngineMessage(double t, const std::string& kind, const std::string& text,
                     const std::vector<std::string>& contacts);
  // Motes more than kMoteMoved from their start at the end: {node, moved_m}, farthest first.
  static nlohmann::ordered_json MovedMotes(const RunNodes& nodes, const std::vector<Pose2D>& final_poses);
  // One sentence per warning, in the order they first happened.
  std::vector<std::string> Sentences(const nlohmann::ordered_json& moved_motes) const;

 private:
  struct Kind {
    std::string text;  // the first message's
    std::uint64_t count = 0;
    double first = 0, last = 0;  // s
    std::vector<std::string> contacts;
  };
  std::vector<Kind> kinds_;
  std::map<std::string, std::size_t> index_;  // kind -> position in kinds_
};

}  // namespace sanet::sim
