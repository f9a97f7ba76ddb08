#include "ros2_agent/team_timeline.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "core/statistics.h"
#include "trace/csv_rows.h"
#include "trace/earlier_run.h"
#include "trace/result_headers.h"
#include "trace/results_folder.h"

namespace sanet::ros2_agent {
namespace {

constexpr const char* kSentHeader = "time_sent,from,to,delivery,bytes";

struct AgentFolder {
  std::string dir, robot, scenario, clock, ended_by, fingerprint;
  std::optional<double> time_zero_unix;
  double ended_at = 0;  // s, on its clock
  double offset = 0;    // added to this agent's times to put them on the team's
};

std::string Field(const nlohmann::json& j, const std::string& key, const std::string& where) {
  if (!j.contains(key) || !j[key].is_string())
    throw TeamFolderError(where + ": '" + key + "' is missing: is this an agent's folder (sanet agent --ros2 -o)?");
  return j[key].get<std::string>();
}

AgentFolder ReadAgentFolder(const std::string& dir) {
  const std::string where = dir + "/summary.json";
  std::ifstream in(where);
  if (!in) throw TeamFolderError(where + ": cannot read it: is this an agent's folder (sanet agent --ros2 -o)?");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw TeamFolderError(where + ": not JSON: " + e.what());
  }
  if (!j.is_object() || j.value("mode", "") != "ros2")
    throw TeamFolderError(where +
                          ": not an agent's summary ('mode' is not \"ros2\"): sanet merge takes the folders "
                          "of sanet agent --ros2");
  AgentFolder a;
  a.dir = dir;
  a.robot = Field(j, "robot", where);
  a.scenario = Field(j, "scenario", where);
  a.clock = Field(j, "clock", where);
  a.ended_by = Field(j, "ended_by", where);
  a.fingerprint = j.value("scenario_fingerprint", "");
  a.ended_at = j.value("ended_at_s", 0.0);
  if (j.contains("time_zero_unix_s") && j["time_zero_unix_s"].is_number())
    a.time_zero_unix = j["time_zero_unix_s"].get<double>();
  else if (a.clock == "this computer's")
    throw TeamFolderError(where + ": 'time_zero_unix_s' is missing: the agent's times cannot be placed");
  return a;
}

// On computers' clocks: every agent ran while another did (folders of two runs of one team are
// not one time line).
void CheckTheyRanTogether(const std::vector<AgentFolder>& team) {
  for (const AgentFolder& a : team) {
    bool overlaps = team.size() == 1;
    for (const AgentFolder& b : team)
      if (&a != &b && a.offset <= b.offset + b.ended_at && b.offset <= a.offset + a.ended_at) overlaps = true;
    if (!overlaps)
      throw TeamFolderError(a.dir + "/summary.json: this agent ran from " + std::to_string(a.offset) + " s to " +
                            std::to_string(a.offset + a.ended_at) +
                            " s of the team's time line, while no other agent ran: the folders are of "
                            "different runs");
  }
}

// Checks that the folders are one team's and gives each the offset onto the team's time line.
std::vector<AgentFolder> ReadTeam(const std::vector<std::string>& dirs) {
  if (dirs.empty()) throw TeamFolderError("no folders: give the agents' results folders");
  std::vector<AgentFolder> team;
  for (const std::string& dir : dirs) {
    AgentFolder a = ReadAgentFolder(dir);
    for (const AgentFolder& b : team) {
      if (a.robot == b.robot)
        throw TeamFolderError(dir + "/summary.json: robot '" + a.robot + "' again (also " + b.dir + ")");
      if (a.fingerprint != b.fingerprint && !a.fingerprint.empty() && !b.fingerprint.empty())
        throw TeamFolderError(dir + "/summary.json: scenario fingerprint " + a.fingerprint + ", but " + b.dir +
                              " ran " + b.fingerprint +
                              ": the agents ran different scenario files (one file for "
                              "the whole team)");
      if (a.scenario != b.scenario || a.clock != b.clock)
        throw TeamFolderError(dir + "/summary.json: scenario '" + a.scenario + "' on " + a.clock + " clock, but " +
                              b.dir + " has scenario '" + b.scenario + "' on " + b.clock +
                              " clock: the folders must be one team's");
    }
    team.push_back(a);
  }
  if (team.front().time_zero_unix) {
    double zero = *team.front().time_zero_unix;
    for (const AgentFolder& a : team) zero = std::min(zero, *a.time_zero_unix);
    for (AgentFolder& a : team) a.offset = *a.time_zero_unix - zero;
    CheckTheyRanTogether(team);
  }
  return team;
}

double Number(const std::string& text, const std::string& where, const std::string& field) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value))
    throw TeamFolderError(where + ": '" + field + "' is not a number: '" + text + "'");
  return value;
}

// A row of the team's file, with the time it is sorted by.
struct TimedRow {
  double time;
  std::vector<std::string> fields;
};

// Reads `file` of an agent's folder, checking its header; calls `take` with each row and where it is.
template <typename Take>
void ReadRows(const AgentFolder& a, const std::string& file, const std::string& header, Take take) {
  const std::string path = a.dir + "/" + file;
  trace::CsvRows rows(path);
  if (!rows.ok()) throw TeamFolderError(path + ": cannot read it (an agent writes it at its end)");
  std::string seen;
  for (const std::string& h : rows.header()) seen += (seen.empty() ? "" : ",") + h;
  if (seen != header) throw TeamFolderError(path + ": header '" + seen + "', expected '" + header + "'");
  const std::size_t columns = rows.header().size();
  std::vector<std::string> row;
  for (std::size_t n = 2; rows.Next(row); ++n) {
    const std::string where = path + ": row " + std::to_string(n);
    if (row.size() != columns)
      throw TeamFolderError(where + ": " + std::to_string(row.size()) + " fields, expected " + std::to_string(columns));
    take(row, where);
  }
}

// log, transitions, metrics and sent: the time in the first column moves by the agent's offset.
std::vector<TimedRow> ShiftedRows(const std::vector<AgentFolder>& team, const std::string& file,
                                  const std::string& header) {
  std::vector<TimedRow> out;
  for (const AgentFolder& a : team)
    ReadRows(a, file, header, [&](std::vector<std::string>& row, const std::string& where) {
      const double t = Number(row[0], where, header.substr(0, header.find(','))) + a.offset;
      if (file == "sent.csv") Number(row[4], where, "bytes");
      row[0] = trace::CsvTime(t);
      out.push_back({t, row});
    });
  std::stable_sort(out.begin(), out.end(), [](const TimedRow& x, const TimedRow& y) { return x.time < y.time; });
  return out;
}

const AgentFolder* Find(const std::vector<AgentFolder>& team, const std::string& robot) {
  for (const AgentFolder& a : team)
    if (a.robot == robot) return &a;
  return nullptr;
}

// messages.csv: sent on the sender's clock, received on the receiver's; both move, the delay follows.
std::vector<TimedRow> ShiftedMessages(const std::vector<AgentFolder>& team) {
  std::vector<TimedRow> out;
  for (const AgentFolder& a : team)
    ReadRows(a, "messages.csv", trace::kMessagesHeader, [&](std::vector<std::string>& row, const std::string& where) {
      const AgentFolder* sender = Find(team, row[1]);
      const double sent = Number(row[0], where, "time_sent") + (sender ? sender->offset : 0);
      const double received = Number(row[5], where, "time_received") + a.offset;
      Number(row[4], where, "bytes");
      row[0] = trace::CsvTime(sent);
      row[5] = trace::CsvTime(received);
      row[6] = trace::CsvTime(received - sent);
      out.push_back({received, row});
    });
  std::stable_sort(out.begin(), out.end(), [](const TimedRow& x, const TimedRow& y) { return x.time < y.time; });
  return out;
}

void Write(trace::ResultsFolder& folder, const std::string& name, const std::string& header,
           const std::vector<TimedRow>& rows) {
  trace::CsvSink& sink = folder.Csv(name, header);
  for (const TimedRow& r : rows) {
    std::string line;
    for (const std::string& f : r.fields) line += (line.empty() ? "" : ",") + trace::CsvField(f);
    sink.Row(line);
  }
}

// One link: a sender, a receiver and the way (a broadcast's receivers are each a link).
using LinkKey = std::tuple<std::string, std::string, std::string>;

struct Link {
  std::size_t sent = 0;
  std::vector<double> delays;
};

std::map<LinkKey, Link> Links(const std::vector<TimedRow>& sent, const std::vector<TimedRow>& messages) {
  std::map<LinkKey, std::size_t> sends;  // broadcasts and floods under the receiver "all"
  for (const TimedRow& r : sent) ++sends[{r.fields[1], r.fields[2], r.fields[3]}];
  std::map<LinkKey, Link> links;
  for (const TimedRow& r : messages)
    links[{r.fields[1], r.fields[2], r.fields[3]}].delays.push_back(std::stod(r.fields[6]));
  for (const auto& [key, count] : sends)
    if (std::get<1>(key) != "all") links[key].sent = count;
  for (auto& [key, link] : links) {
    const auto& [from, to, way] = key;
    if (to == "all") continue;
    if (const auto it = sends.find({from, "all", way}); way != "unicast" && it != sends.end()) link.sent = it->second;
  }
  return links;
}

void WriteLinks(trace::ResultsFolder& folder, const std::map<LinkKey, Link>& links) {
  trace::CsvSink& sink = folder.Csv("links.csv", "from,to,delivery,sent,received,delay_min,delay_median,delay_max");
  for (const auto& [key, link] : links) {
    const auto& [from, to, way] = key;
    std::string line =
        from + "," + to + "," + way + "," + std::to_string(link.sent) + "," + std::to_string(link.delays.size());
    const nlohmann::ordered_json q = Quartiles(link.delays);
    for (const char* k : {"min", "median", "max"})
      line += "," + (link.delays.empty() ? "" : trace::CsvTime(q[k].get<double>()));
    sink.Row(line);
  }
}

// What the messages say of the clocks: a smallest delay below zero bounds the disagreement
// from below; a pair that sent both ways gives half the difference of the smallest delays.
nlohmann::ordered_json ClockCheck(const std::vector<AgentFolder>& team, const std::map<LinkKey, Link>& links) {
  std::map<std::pair<std::string, std::string>, double> smallest;
  for (const auto& [key, link] : links)
    if (!link.delays.empty()) {
      const auto& [from, to, way] = key;
      const double d = *std::min_element(link.delays.begin(), link.delays.end());
      auto [it, fresh] = smallest.emplace(std::make_pair(from, to), d);
      if (!fresh) it->second = std::min(it->second, d);
    }
  nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
  for (const auto& [pair, d] : smallest) {
    nlohmann::ordered_json p = {{"from", pair.first}, {"to", pair.second}, {"smallest_delay_s", d}};
    if (const auto back = smallest.find({pair.second, pair.first}); back != smallest.end())
      p["to_clock_ahead_by_s"] = (d - back->second) / 2;
    pairs.push_back(p);
  }
  nlohmann::ordered_json offsets;
  for (const AgentFolder& a : team) offsets[a.robot] = a.offset;
  const bool shared = !team.front().time_zero_unix;
  if (shared)
    for (auto& p : pairs) p["note"] = "on /clock, agents read neighbouring samples: up to one /clock period apart";
  return {{"kind", team.front().clock},
          {"trusted_as", shared ? "one /clock, read by every agent: times are taken as they are"
                                : "each computer's clock from the Unix time of its agent's time 0: what NTP or PTP "
                                  "leaves between the computers stays in every time and delay"},
          {"moved_by_s", offsets},
          {"from_messages", pairs}};
}

nlohmann::ordered_json Summary(const std::vector<AgentFolder>& team, const std::map<LinkKey, Link>& links,
                               std::size_t messages) {
  nlohmann::ordered_json agents = nlohmann::ordered_json::array();
  for (const AgentFolder& a : team) agents.push_back({{"robot", a.robot}, {"folder", a.dir}, {"ended_by", a.ended_by}});
  std::size_t sent = 0;
  std::vector<double> delays;
  for (const auto& [key, link] : links) {
    if (std::get<2>(key) == "unicast") sent += link.sent;
    delays.insert(delays.end(), link.delays.begin(), link.delays.end());
  }
  return {{"scenario", team.front().scenario},
          {"mode", "ros2 team"},
          {"agents", agents},
          {"messages", {{"received", messages}, {"unicast_sent", sent}, {"delay_s", Quartiles(delays)}}},
          {"clocks", ClockCheck(team, links)}};
}

}  // namespace

nlohmann::ordered_json MergeTeam(const std::vector<std::string>& agent_folders, const std::string& out, bool force) {
  const std::vector<AgentFolder> team = ReadTeam(agent_folders);
  for (const AgentFolder& a : team)
    if (std::filesystem::exists(out) && std::filesystem::equivalent(a.dir, out))
      throw trace::FolderRefused("-o " + out + " is one of the agents' folders: give the team's folder another name");
  trace::ExpectEarlierKind(out, "ros2 team");
  const std::vector<TimedRow> sent = ShiftedRows(team, "sent.csv", kSentHeader);
  const std::vector<TimedRow> messages = ShiftedMessages(team);
  const std::map<LinkKey, Link> links = Links(sent, messages);
  trace::ResultsFolder folder(out, force);
  Write(folder, "log.csv", trace::kLogHeader, ShiftedRows(team, "log.csv", trace::kLogHeader));
  Write(folder, "transitions.csv", trace::kTransitionsHeader,
        ShiftedRows(team, "transitions.csv", trace::kTransitionsHeader));
  Write(folder, "metrics.csv", trace::kMetricsHeader, ShiftedRows(team, "metrics.csv", trace::kMetricsHeader));
  Write(folder, "messages.csv", trace::kMessagesHeader, messages);
  Write(folder, "sent.csv", kSentHeader, sent);
  WriteLinks(folder, links);
  nlohmann::ordered_json summary = Summary(team, links, messages.size());
  folder.Commit();
  std::vector<std::string> files = folder.files();
  files.push_back("summary.json");
  summary["files"] = files;
  folder.WriteWhole("summary.json", summary.dump(2) + "\n");
  return summary;
}

}  // namespace sanet::ros2_agent
