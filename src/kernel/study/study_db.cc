#include "study/study_db.h"

#include <sqlite3.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "trace/csv_rows.h"

namespace sanet::study {
namespace {

// One prepared statement, finalised when it goes.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK)
      throw StudyDbError(std::string("study database: ") + sqlite3_errmsg(db) + " in: " + sql);
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& Bind(int i, const std::string& text) {
    sqlite3_bind_text(stmt_, i, text.c_str(), static_cast<int>(text.size()), SQLITE_TRANSIENT);
    return *this;
  }
  Statement& Bind(int i, double v) {
    sqlite3_bind_double(stmt_, i, v);
    return *this;
  }
  Statement& Bind(int i, long v) {
    sqlite3_bind_int64(stmt_, i, v);
    return *this;
  }
  Statement& BindNull(int i) {
    sqlite3_bind_null(stmt_, i);
    return *this;
  }
  // A value as its type reads: a number where the whole text is one.
  Statement& BindValue(int i, const std::string& text) {
    if (text.empty()) return BindNull(i);
    const std::optional<double> number = NumberIn(text);
    return number ? Bind(i, *number) : Bind(i, text);
  }
  bool Step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) throw StudyDbError(std::string("study database: ") + sqlite3_errmsg(db_));
    return false;
  }
  void Run() {
    Step();
    sqlite3_reset(stmt_);
    sqlite3_clear_bindings(stmt_);
  }
  std::string Text(int col) const {
    const unsigned char* t = sqlite3_column_text(stmt_, col);
    return t ? reinterpret_cast<const char*>(t) : "";
  }
  long Long(int col) const { return sqlite3_column_int64(stmt_, col); }

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

void Flatten(const nlohmann::json& j, const std::string& prefix, std::vector<std::pair<std::string, double>>& out) {
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) Flatten(value, prefix.empty() ? key : prefix + "." + key, out);
  } else if (j.is_number()) {
    out.emplace_back(prefix, j.get<double>());
  } else if (j.is_boolean()) {
    out.emplace_back(prefix, j.get<bool>() ? 1.0 : 0.0);
  }
}

std::string Quoted(const std::string& name) {
  std::string q = "\"";
  for (char c : name) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string JoinLines(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += s + "\n";
  return out;
}

// A list kept a line per item, as one line: "a=1 b=2", or "none".
std::string OneLine(std::string lines) {
  while (!lines.empty() && lines.back() == '\n') lines.pop_back();
  std::replace(lines.begin(), lines.end(), '\n', ' ');
  return lines.empty() ? "none" : lines;
}

}  // namespace

std::vector<std::pair<std::string, double>> Numbers(const nlohmann::json& j) {
  std::vector<std::pair<std::string, double>> out;
  Flatten(j, "", out);
  return out;
}

std::vector<std::string> NodeNames(const nlohmann::json& summary) {
  std::vector<std::string> names;
  if (summary.is_object() && summary.contains("nodes") && summary["nodes"].is_array())
    for (const auto& n : summary["nodes"])
      if (n.is_object() && n.contains("name") && n["name"].is_string()) names.push_back(n["name"].get<std::string>());
  return names;
}

StudyDb::StudyDb(const std::string& path) : path_(path) {
  if (sqlite3_open(path.c_str(), &db_) != SQLITE_OK) {
    const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw StudyDbError("cannot open " + path + ": " + why);
  }
  sqlite3_busy_timeout(db_, 10000);   // a reader (sanet report, pandas) may hold it for a moment
  Exec("PRAGMA synchronous = FULL");  // a finished run, once recorded, survives a power loss
  CreateSchema();
}

StudyDb::~StudyDb() { sqlite3_close(db_); }

void StudyDb::Exec(const std::string& sql) const {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string why = error ? error : "unknown error";
    sqlite3_free(error);
    throw StudyDbError(path_ + ": " + why);
  }
}

void StudyDb::CreateSchema() {
  Exec(R"(CREATE TABLE IF NOT EXISTS study(key TEXT PRIMARY KEY, value TEXT);
CREATE TABLE IF NOT EXISTS runs(
  id INTEGER PRIMARY KEY, name TEXT UNIQUE NOT NULL, seed INTEGER NOT NULL, status TEXT NOT NULL,
  fingerprint TEXT, scenario_fingerprint TEXT, wall_s REAL, simulated_s REAL, ended_by TEXT, ended_at_s REAL,
  started_utc TEXT, finished_utc TEXT, host TEXT, rank INTEGER, folder TEXT NOT NULL, error TEXT);
CREATE TABLE IF NOT EXISTS parameters(run INTEGER NOT NULL REFERENCES runs(id), name TEXT NOT NULL, value TEXT,
  number REAL, PRIMARY KEY(run, name));
CREATE TABLE IF NOT EXISTS scalars(run INTEGER NOT NULL REFERENCES runs(id), name TEXT NOT NULL, value REAL,
  PRIMARY KEY(run, name));
CREATE INDEX IF NOT EXISTS scalars_by_name ON scalars(name);
CREATE TABLE IF NOT EXISTS nodes(run INTEGER NOT NULL REFERENCES runs(id), name TEXT NOT NULL, PRIMARY KEY(run, name));)");
}

std::string StudyDb::Get(const std::string& key) const {
  Statement s(db_, "SELECT value FROM study WHERE key = ?");
  s.Bind(1, key);
  return s.Step() ? s.Text(0) : "";
}

void StudyDb::Describe(const StudyInfo& info) {
  const std::vector<std::pair<std::string, std::string>> identity = {
      {"scenario", info.scenario}, {"sets", JoinLines(info.sets)}, {"parameters", JoinLines(info.parameters)}};
  if (!Get("scenario").empty()) {
    for (const auto& [key, value] : identity)
      if (Get(key) != value)
        throw OtherStudy(path_ + " holds a study with other " + key + " (" + OneLine(Get(key)) + ", not " +
                         OneLine(value) + "): give this study another folder with -o");
    return CreateResultsView(info.parameters);
  }
  Statement put(db_, "INSERT OR REPLACE INTO study(key, value) VALUES (?, ?)");
  for (const auto& [key, value] : identity) put.Bind(1, key).Bind(2, value).Run();
  put.Bind(1, std::string("command")).Bind(2, info.command).Run();
  put.Bind(1, std::string("tables")).Bind(2, JoinLines(info.tables)).Run();
  CreateResultsView(info.parameters);
}

void StudyDb::CreateResultsView(const std::vector<std::string>& parameters) {
  // Made again each time (a study begun by an earlier sanet named the id `run` and the name
  // `name`), in one transaction so that a reader never finds it missing.
  Exec("BEGIN");
  Exec("DROP VIEW IF EXISTS results");
  std::string sql = "CREATE VIEW results AS SELECT runs.id AS run_id, runs.name AS run_name, runs.seed, runs.status";
  for (const std::string& p : parameters)
    sql +=
        ", (SELECT coalesce(number, value) FROM parameters WHERE run = runs.id AND name = '" + p + "') AS " + Quoted(p);
  sql += ", runs.fingerprint, runs.wall_s, runs.ended_by, runs.ended_at_s FROM runs";
  Exec(sql);
  Exec("COMMIT");
}

std::vector<std::string> StudyDb::Tables() const {
  std::vector<std::string> tables;
  std::string text = Get("tables");
  for (std::size_t at = 0, nl; (nl = text.find('\n', at)) != std::string::npos; at = nl + 1)
    tables.push_back(text.substr(at, nl - at));
  return tables;
}

void StudyDb::Plan(const std::vector<RunPoint>& runs) {
  Exec("BEGIN");
  Statement add(db_, "INSERT OR IGNORE INTO runs(name, seed, status, folder) VALUES (?, ?, 'pending', ?)");
  Statement value(db_, "INSERT OR IGNORE INTO parameters(run, name, value, number) VALUES (?, ?, ?, ?)");
  for (const RunPoint& r : runs) {
    add.Bind(1, r.name).Bind(2, static_cast<long>(r.seed)).Bind(3, "runs/" + r.name).Run();
    if (sqlite3_changes(db_) == 0) continue;
    const long id = static_cast<long>(sqlite3_last_insert_rowid(db_));
    for (const auto& [path, text] : r.values) {
      value.Bind(1, id).Bind(2, path).Bind(3, text);
      if (const std::optional<double> number = NumberIn(text))
        value.Bind(4, *number);
      else
        value.BindNull(4);
      value.Run();
    }
  }
  Exec("COMMIT");
}

long StudyDb::RunId(const std::string& name) const {
  Statement s(db_, "SELECT id FROM runs WHERE name = ?");
  s.Bind(1, name);
  if (!s.Step()) throw StudyDbError(path_ + ": no run named " + name);
  return s.Long(0);
}

std::string StudyDb::Status(const std::string& name) const {
  Statement s(db_, "SELECT status FROM runs WHERE name = ?");
  s.Bind(1, name);
  return s.Step() ? s.Text(0) : "";
}

std::string StudyDb::ScenarioFingerprintOf(const std::string& name) const {
  Statement s(db_, "SELECT scenario_fingerprint FROM runs WHERE name = ?");
  s.Bind(1, name);
  return s.Step() ? s.Text(0) : "";
}

void StudyDb::Started(const std::string& name, const std::string& started_utc) {
  Statement s(db_, "UPDATE runs SET status = 'running', started_utc = ? WHERE name = ?");
  s.Bind(1, started_utc).Bind(2, name).Run();
}

void StudyDb::Pending(const std::string& name) {
  Statement s(db_, "UPDATE runs SET status = 'pending' WHERE name = ?");
  s.Bind(1, name).Run();
}

int StudyDb::Count(const std::string& status) const {
  Statement s(db_, "SELECT count(*) FROM runs WHERE status = ?");
  s.Bind(1, status);
  s.Step();
  return static_cast<int>(s.Long(0));
}

void StudyDb::Scalars(long run, const nlohmann::json& summary) {
  Statement put(db_, "INSERT OR REPLACE INTO scalars(run, name, value) VALUES (?, ?, ?)");
  for (const auto& [name, value] : Numbers(summary)) put.Bind(1, run).Bind(2, name).Bind(3, value).Run();
  Statement node(db_, "INSERT OR REPLACE INTO nodes(run, name) VALUES (?, ?)");
  for (const std::string& name : NodeNames(summary)) node.Bind(1, run).Bind(2, name).Run();
}

void StudyDb::ImportCsv(long run, const std::string& table, const std::string& path) {
  trace::CsvRows rows(path);
  if (!rows.ok()) return;  // this run wrote no such file (no network, no packet log)
  std::string columns = "run INTEGER", marks = "?";
  for (const std::string& c : rows.header()) columns += ", " + Quoted(c), marks += ", ?";
  Exec("CREATE TABLE IF NOT EXISTS " + Quoted(table) + "(" + columns + ")");
  Statement put(db_, "INSERT INTO " + Quoted(table) + " VALUES (" + marks + ")");
  for (std::vector<std::string> row; rows.Next(row);) {
    put.Bind(1, run);
    for (std::size_t i = 0; i < rows.header().size(); ++i)
      put.BindValue(static_cast<int>(i) + 2, i < row.size() ? row[i] : "");
    put.Run();
  }
}

void StudyDb::Finished(const std::string& name, const RunOutcome& o, const nlohmann::json& summary,
                       const std::string& folder) {
  const long id = RunId(name);
  Exec("BEGIN");
  try {
    Statement s(db_,
                "UPDATE runs SET status = ?, fingerprint = ?, scenario_fingerprint = ?, wall_s = ?, simulated_s = ?, "
                "ended_by = ?, ended_at_s = ?, started_utc = ?, finished_utc = ?, host = ?, rank = ?, error = ? "
                "WHERE id = ?");
    s.Bind(1, o.status).Bind(2, o.fingerprint).Bind(3, o.scenario_fingerprint).Bind(4, o.wall_s);
    s.Bind(5, o.simulated_s).Bind(6, o.ended_by).Bind(7, o.ended_at_s).Bind(8, o.started_utc);
    s.Bind(9, o.finished_utc).Bind(10, o.host).Bind(11, static_cast<long>(o.rank)).Bind(12, o.error).Bind(13, id);
    s.Run();
    Exec("DELETE FROM scalars WHERE run = " + std::to_string(id));
    Exec("DELETE FROM nodes WHERE run = " + std::to_string(id));
    if (o.status == "completed") {
      Scalars(id, summary);
      for (const std::string& table : Tables()) {
        if (HasTable(table)) Exec("DELETE FROM " + Quoted(table) + " WHERE run = " + std::to_string(id));
        ImportCsv(id, table, folder + "/" + table + ".csv");
      }
    }
    Exec("COMMIT");
  } catch (...) {
    Exec("ROLLBACK");
    throw;
  }
}

bool StudyDb::HasTable(const std::string& table) const {
  Statement s(db_, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?");
  s.Bind(1, table);
  return s.Step();
}

}  // namespace sanet::study
