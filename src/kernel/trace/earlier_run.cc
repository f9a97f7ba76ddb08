#include "trace/earlier_run.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

namespace sanet::trace {
namespace {

namespace fs = std::filesystem;

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The names (first path component) an earlier run in `dir` says it wrote; empty if none did.
std::set<std::string> EarlierRunFiles(const fs::path& dir) {
  std::set<std::string> names;
  const bool started = fs::exists(dir / "provenance.json");
  if (std::ifstream in(dir / "summary.json"); in) {
    try {
      const auto summary = nlohmann::json::parse(in);
      for (const auto& f : summary.at("files")) {
        const std::string name = f.get<std::string>();
        names.insert(name.substr(0, name.find('/')));
      }
      names.insert("summary.json");
    } catch (const std::exception&) {
      // Not a summary of ours: its files are nobody's we know.
    }
  }
  if (started || !names.empty()) names.insert({"provenance.json", "scenario.yaml"});
  return names;
}

// A folder a stopped run was filling (packets/ with its NODE.csv.tmp files): temporary files only.
bool OnlyTemporaryFiles(const fs::path& dir) {
  if (!fs::is_directory(dir)) return false;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (!entry.is_directory() && !EndsWith(entry.path().filename().string(), ".tmp")) return false;
  return true;
}

}  // namespace

void ClearEarlierRun(const std::string& dir, bool force) {
  const fs::path path(dir);
  if (fs::exists(path) && !fs::is_directory(path))
    throw FolderRefused("the results folder " + dir + " is a file: give another folder with -o");
  if (!fs::exists(path)) return;
  const std::set<std::string> ours = EarlierRunFiles(path);
  const bool earlier_run = !ours.empty();
  std::vector<fs::path> remove;
  std::vector<std::string> foreign;
  for (const auto& entry : fs::directory_iterator(path)) {
    const std::string name = entry.path().filename().string();
    // A stopped run's temporary files end in .tmp (and a run leaves nothing else half-written).
    if (ours.count(name) || (earlier_run && (EndsWith(name, ".tmp") || OnlyTemporaryFiles(entry.path()))))
      remove.push_back(entry.path());
    else
      foreign.push_back(name);
  }
  if (!foreign.empty() && !force) {
    std::string some;
    for (std::size_t i = 0; i < foreign.size() && i < 3; ++i) some += (i ? ", " : "") + foreign[i];
    if (foreign.size() > 3) some += " and " + std::to_string(foreign.size() - 3) + " more";
    throw FolderRefused("the results folder " + dir + " holds files that no sanet run wrote (" + some +
                        "): give another folder with -o, or --force to write beside them");
  }
  for (const fs::path& p : remove) fs::remove_all(p);
}

void ExpectEarlierKind(const std::string& dir, const std::string& mode) {
  std::ifstream in(fs::path(dir) / "summary.json");
  if (!in) return;
  std::string found;
  try {
    const auto summary = nlohmann::json::parse(in);
    if (!summary.contains("files")) return;  // no summary of ours: ClearEarlierRun decides
    found = summary.value("mode", "");
  } catch (const std::exception&) {
    return;
  }
  if (found == mode) return;
  const auto kind = [](const std::string& m) {
    return m.empty() ? std::string("a simulation's run") : m == "ros2" ? "an agent's on a ROS 2 robot" : "a " + m;
  };
  throw FolderRefused("the results folder " + dir + " holds the results of " + kind(found) + ", not of " + kind(mode) +
                      ": give another folder with -o");
}

}  // namespace sanet::trace
