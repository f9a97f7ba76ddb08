#include "launch/launch_verdict.h"

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/json_text.h"
#include "core/seconds_text.h"

namespace sanet::launch {
namespace {

using Json = nlohmann::ordered_json;

bool EndedWell(const AgentProcess& a) { return WIFEXITED(a.status) && WEXITSTATUS(a.status) == 0; }

// How the agent process ended, for summary.json.
Json AgentEnd(const AgentProcess& a) {
  Json end = {{"ended", a.stopped ? "stopped by launch at the end of the run" : HowItEnded(a.status)}};
  if (!a.stopped) end["ended_after_wall_s"] = a.ended_after;
  if (!a.last_line.empty()) end["last_stderr_line"] = a.last_line;
  return end;
}

// Why the robot was not driven to the end, if it was not and its agent is to blame; empty if all
// went well.
std::string Failure(const AgentProcess& a, const Json& driven) {
  const bool never = driven.empty();
  const bool dropped = !never && !driven.back()["to_s"].is_null();
  const bool on_its_own = a.ended && !a.stopped;
  if (!never && !(dropped && on_its_own)) return "";
  const std::string word = a.last_line.empty() ? "" : ": " + a.last_line;
  if (!on_its_own) return "robot " + a.robot + " was never driven: its agent was still running and never claimed it";
  const std::string when =
      never ? " before driving it" : " at " + SecondsText(driven.back()["to_s"].get<double>()) + " of the run";
  return "robot " + a.robot + ": its agent " + (EndedWell(a) ? "ended" : HowItEnded(a.status)) + when + word;
}

std::string Joined(const std::vector<std::string>& parts) {
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : "; ") + part;
  return text;
}

}  // namespace

std::vector<std::string> JudgeAgents(const std::string& results, const std::vector<AgentProcess>& agents) {
  const std::string path = results + "/summary.json";
  std::ifstream in(path);
  Json summary = Json::parse(in, nullptr, false);
  if (summary.is_discarded() || !summary.is_object()) return {};  // the server wrote none: it said why
  std::vector<std::string> failures;
  for (const AgentProcess& a : agents) {
    Json& robot = summary["attendance"][a.robot];
    if (!robot.contains("driven")) robot["driven"] = Json::array();
    robot["agent"] = AgentEnd(a);
    const std::string failure = Failure(a, robot["driven"]);
    if (failure.empty()) continue;
    robot["cause"] = failure;
    failures.push_back(failure);
  }
  const std::string status = summary.value("status", std::string());
  const bool server_saw_it = status == "completed" || status.rfind("failed: no client drove", 0) == 0;
  if (!failures.empty() && status != "interrupted")
    summary["status"] = server_saw_it ? "failed: " + Joined(failures) : status + "; " + Joined(failures);
  WriteFileAtomically(path, JsonText(summary, 2) + "\n");
  return failures;
}

}  // namespace sanet::launch
