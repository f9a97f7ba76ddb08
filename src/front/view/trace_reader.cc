#include "view/trace_reader.h"

#include <sqlite3.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "trace/csv_rows.h"

namespace sanet::view {
namespace {

nlohmann::json Column(sqlite3_stmt* s, int i) {
  switch (sqlite3_column_type(s, i)) {
    case SQLITE_NULL:
      return nullptr;
    case SQLITE_INTEGER:
      return sqlite3_column_int64(s, i);
    case SQLITE_FLOAT:
      return sqlite3_column_double(s, i);
    default:
      return std::string(reinterpret_cast<const char*>(sqlite3_column_text(s, i)));
  }
}

// A small CSV file of the results folder as rows of named fields (no quoted commas in these).
std::optional<double> FiniteNumber(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::vector<std::map<std::string, std::string>> ReadCsv(const std::string& path) {
  std::vector<std::map<std::string, std::string>> rows;
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> header;
  const auto split = [](const std::string& text) {
    std::vector<std::string> cells;
    std::stringstream s(text);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    return cells;
  };
  if (std::getline(in, line)) header = split(line);
  while (std::getline(in, line)) {
    const auto cells = split(line);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TraceReader::TraceReader(const std::string& folder) : folder_(folder) {
  const std::string path = folder + "/trace.sqlite";
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path + " not found: run the scenario with outputs.trace on (the default up to 200 nodes)");
  if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw std::runtime_error("cannot read " + path + ": " + why);
  }
  // A trace of another format, or no trace at all, is refused now rather than by the page.
  sqlite3_stmt* s = nullptr;
  const bool ours =
      sqlite3_prepare_v2(db_, "SELECT value FROM info WHERE key = 'format'", -1, &s, nullptr) == SQLITE_OK &&
      sqlite3_step(s) == SQLITE_ROW &&
      std::string(reinterpret_cast<const char*>(sqlite3_column_text(s, 0))) == "sanet trace 1";
  sqlite3_finalize(s);
  if (!ours) {
    sqlite3_close(db_);
    throw std::runtime_error(path + " is not a sanet trace (format 'sanet trace 1'): " + sqlite3_errstr(SQLITE_NOTADB));
  }
}

TraceReader::~TraceReader() { sqlite3_close(db_); }

template <typename Row>
nlohmann::json TraceReader::Query(const std::string& sql, Row row, double a, double b) const {
  sqlite3_stmt* s = nullptr;
  if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &s, nullptr) != SQLITE_OK)
    throw std::runtime_error(std::string("trace: ") + sqlite3_errmsg(db_));
  const int parameters = sqlite3_bind_parameter_count(s);
  if (parameters >= 1) sqlite3_bind_double(s, 1, a);
  if (parameters >= 2) sqlite3_bind_double(s, 2, b);
  nlohmann::json out = nlohmann::json::array();
  while (sqlite3_step(s) == SQLITE_ROW) row(s, out);
  sqlite3_finalize(s);
  return out;
}

// Every column of every row, as an array.
static auto AllColumns() {
  return [](sqlite3_stmt* s, nlohmann::json& out) {
    nlohmann::json row = nlohmann::json::array();
    for (int i = 0; i < sqlite3_column_count(s); ++i) row.push_back(Column(s, i));
    out.push_back(row);
  };
}

nlohmann::json TraceReader::Run() const {
  nlohmann::json run;
  Query("SELECT key, value FROM info", [&](sqlite3_stmt* s, nlohmann::json&) {
    run["info"][reinterpret_cast<const char*>(sqlite3_column_text(s, 0))] = Column(s, 1);
  });
  std::map<std::string, std::map<std::string, std::string>> packets;
  for (auto& row : ReadCsv(folder_ + "/packets.csv")) packets[row["node"]] = row;
  run["nodes"] =
      Query("SELECT id, name, model, x, y, theta FROM nodes ORDER BY id", [&](sqlite3_stmt* s, nlohmann::json& out) {
        nlohmann::json node = {{"id", Column(s, 0)}, {"name", Column(s, 1)}, {"model", Column(s, 2)},
                               {"x", Column(s, 3)},  {"y", Column(s, 4)},    {"theta", Column(s, 5)}};
        const auto it = packets.find(node["name"].get<std::string>());
        if (it != packets.end())
          for (const auto& [key, value] : it->second)
            if (key != "node") node["packets"][key] = std::stoll(value);
        out.push_back(node);
      });
  run["obstacles"] = Query("SELECT kind, cx, cy, length, width, height, yaw FROM obstacles", AllColumns());
  std::ifstream summary(folder_ + "/summary.json");
  if (summary) run["summary"] = nlohmann::json::parse(summary, nullptr, false);
  return run;
}

nlohmann::json TraceReader::Poses() const {
  nlohmann::json poses = nlohmann::json::object();
  Query("SELECT node, t, x, y, theta FROM poses ORDER BY rowid", [&](sqlite3_stmt* s, nlohmann::json&) {
    poses[std::to_string(sqlite3_column_int64(s, 0))].push_back(
        {sqlite3_column_double(s, 1), sqlite3_column_double(s, 2), sqlite3_column_double(s, 3),
         sqlite3_column_double(s, 4)});
  });
  return poses;
}

nlohmann::json TraceReader::Frames(double from, double to) const {
  return Query("SELECT t, node, direction = 'tx', peer, kind FROM frames WHERE t >= ?1 AND t < ?2 ORDER BY rowid",
               AllColumns(), from, to);
}

nlohmann::json TraceReader::Messages() const {
  return Query("SELECT t_sent, t_received, from_node, to_node, delivery, bytes FROM messages ORDER BY t_sent",
               AllColumns());
}

nlohmann::json TraceReader::RoutesAt(double t) const {
  // The last change up to t of each (node, destination), kept when it is a valid route.
  return Query(
      "SELECT node, destination, next_hop, hops FROM routes r WHERE rowid = (SELECT max(rowid) FROM routes "
      "WHERE node = r.node AND destination = r.destination AND t <= ?1) AND next_hop IS NOT NULL",
      AllColumns(), t);
}

nlohmann::json TraceReader::Transitions() const {
  return Query("SELECT t, node, from_state, to_state, why FROM transitions ORDER BY rowid", AllColumns());
}

// With the kept CSV reader: a controller's metric names are free text, quoted when they hold
// commas. A row that is not time,node,name,value with numbers is left out, not the whole page.
nlohmann::json TraceReader::Metrics() const {
  nlohmann::json metrics = nlohmann::json::object();
  trace::CsvRows rows(folder_ + "/metrics.csv");
  for (std::vector<std::string> row; rows.ok() && rows.Next(row);) {
    if (row.size() != 4) continue;
    const std::optional<double> t = FiniteNumber(row[0]), value = FiniteNumber(row[3]);
    if (t && value) metrics[row[2]][row[1]].push_back({*t, *value});
  }
  return metrics;
}

nlohmann::json TraceReader::MinDistance() const {
  nlohmann::json out = nlohmann::json::array();
  for (auto& row : ReadCsv(folder_ + "/min_distance.csv"))
    out.push_back({std::stod(row["time"]), std::stod(row["min_distance"])});
  return out;
}

bool TraceReader::HasTable(const char* name) const {
  sqlite3_stmt* s = nullptr;
  sqlite3_prepare_v2(db_, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?1", -1, &s, nullptr);
  sqlite3_bind_text(s, 1, name, -1, SQLITE_STATIC);
  const bool found = sqlite3_step(s) == SQLITE_ROW;
  sqlite3_finalize(s);
  return found;
}

nlohmann::json TraceReader::Energy() const {
  nlohmann::json energy = {{"levels", nlohmann::json::object()}, {"deaths", nlohmann::json::array()}};
  if (!HasTable("energy")) return energy;
  Query("SELECT node, t, fraction FROM energy ORDER BY rowid", [&](sqlite3_stmt* s, nlohmann::json&) {
    energy["levels"][std::to_string(sqlite3_column_int64(s, 0))].push_back(
        {sqlite3_column_double(s, 1), sqlite3_column_double(s, 2)});
  });
  energy["deaths"] = Query(
      "SELECT t, node, kind = 'death' FROM events WHERE kind IN ('death', 'revival') ORDER BY rowid", AllColumns());
  return energy;
}

}  // namespace sanet::view
