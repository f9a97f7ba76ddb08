#include "sim/run_warnings.h"

#include <algorithm>
#include <cstdio>

#include "core/seconds_text.h"

namespace sanet::sim {
namespace {

std::string Metres(double m) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f m", m);
  return text;
}

}  // namespace

void RunWarnings::EngineMessage(double t, const std::string& kind, const std::string& text,
                                const std::vector<std::string>& contacts) {
  auto [it, fresh] = index_.emplace(kind, kinds_.size());
  if (fresh) kinds_.push_back({text, 0, t, t, contacts});
  Kind& k = kinds_[it->second];
  ++k.count;
  k.last = t;
}

nlohmann::ordered_json RunWarnings::MovedMotes(const RunNodes& nodes, const std::vector<Pose2D>& final_poses) {
  std::vector<std::pair<double, NodeId>> moved;
  for (NodeId id = 0; id < nodes.size() && id < final_poses.size(); ++id) {
    if (robots::HasDrive(nodes[id].model)) continue;
    const double distance = Norm(final_poses[id].position() - nodes[id].pose.position());
    if (distance > kMoteMoved) moved.push_back({distance, id});
  }
  std::stable_sort(moved.begin(), moved.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& [distance, id] : moved) list.push_back({{"node", nodes[id].name}, {"moved_m", distance}});
  return list;
}

std::vector<std::string> RunWarnings::Sentences(const nlohmann::ordered_json& moved_motes) const {
  std::vector<std::string> out;
  for (const Kind& k : kinds_) {
    std::string s = k.text + " (" + std::to_string(k.count) + (k.count == 1 ? " time, at " : " times, from ") +
                    SecondsText(k.first, 3) + (k.count == 1 ? "" : " to " + SecondsText(k.last, 3)) + ")";
    if (!k.contacts.empty()) {
      s += "; in contact then:";
      for (std::size_t i = 0; i < k.contacts.size() && i < 8; ++i) s += (i ? ", " : " ") + k.contacts[i];
      if (k.contacts.size() > 8) s += " and " + std::to_string(k.contacts.size() - 8) + " more pairs";
    }
    out.push_back(s);
  }
  if (!moved_motes.empty()) {
    std::string s = std::to_string(moved_motes.size()) + (moved_motes.size() == 1 ? " mote was" : " motes were") +
                    " pushed more than " + Metres(kMoteMoved) + " from where the scenario put " +
                    (moved_motes.size() == 1 ? "it" : "them") + ":";
    for (std::size_t i = 0; i < moved_motes.size() && i < 5; ++i)
      s += (i ? ", " : " ") + moved_motes[i]["node"].get<std::string>() + " " +
           Metres(moved_motes[i]["moved_m"].get<double>());
    if (moved_motes.size() > 5) s += " and " + std::to_string(moved_motes.size() - 5) + " more";
    out.push_back(s + " (summary.json: motes_moved)");
  }
  return out;
}

}  // namespace sanet::sim
