#include "trace/run_trace.h"

#include <sqlite3.h>

#include <stdexcept>

namespace sanet::trace {
namespace {

constexpr std::uint64_t kRowsPerTransaction = 50000;

// Tables first, indexes for a viewer's time windows after; WITHOUT ROWID is not used: rows are
// appended in time order, which the implicit rowid keeps cheapest.
constexpr const char* kSchema = R"sql(
CREATE TABLE info(key TEXT PRIMARY KEY, value TEXT);
CREATE TABLE nodes(id INTEGER PRIMARY KEY, name TEXT, model TEXT, x REAL, y REAL, theta REAL);
CREATE TABLE obstacles(kind TEXT, cx REAL, cy REAL, length REAL, width REAL, height REAL, yaw REAL);
CREATE TABLE poses(t REAL, node INTEGER, x REAL, y REAL, theta REAL);
CREATE TABLE frames(t REAL, node INTEGER, direction TEXT, peer INTEGER, kind TEXT, bytes INTEGER);
CREATE TABLE messages(t_sent REAL, t_received REAL, from_node INTEGER, to_node INTEGER, delivery TEXT,
                      bytes INTEGER, hops INTEGER);
CREATE TABLE routes(t REAL, node INTEGER, destination INTEGER, next_hop INTEGER, hops INTEGER);
CREATE TABLE transitions(t REAL, node INTEGER, from_state TEXT, to_state TEXT, why TEXT);
CREATE TABLE metrics(t REAL, node INTEGER, name TEXT, value REAL);
CREATE TABLE events(t REAL, node INTEGER, kind TEXT, detail TEXT);
)sql";

constexpr const char* kIndexes = R"sql(
CREATE INDEX poses_t ON poses(t);
CREATE INDEX frames_t ON frames(t);
CREATE INDEX messages_t ON messages(t_sent);
CREATE INDEX routes_t ON routes(t);
)sql";

// Only in a run with batteries (RunTrace::Energy).
constexpr const char* kEnergySchema =
    "CREATE TABLE energy(t REAL, node INTEGER, remaining_j REAL, fraction REAL, power_w REAL)";
constexpr const char* kEnergyIndex = "CREATE INDEX energy_t ON energy(t)";

void BindOptional(sqlite3_stmt* s, int column, std::optional<double> value) {
  value ? sqlite3_bind_double(s, column, *value) : sqlite3_bind_null(s, column);
}

}  // namespace

RunTrace::RunTrace(const std::string& path) {
  if (sqlite3_open(path.c_str(), &db_) != SQLITE_OK) {
    const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw std::runtime_error("cannot create the trace " + path + ": " + why);
  }
  // A scratch file until the run ends: nothing to recover from a crash, so no journal.
  Exec("PRAGMA journal_mode = OFF; PRAGMA synchronous = OFF;");
  Exec(kSchema);
  info_ = Prepare("INSERT INTO info VALUES (?, ?)");
  node_ = Prepare("INSERT OR REPLACE INTO nodes VALUES (?, ?, ?, ?, ?, ?)");
  obstacle_ = Prepare("INSERT INTO obstacles VALUES (?, ?, ?, ?, ?, ?, ?)");
  pose_ = Prepare("INSERT INTO poses VALUES (?, ?, ?, ?, ?)");
  frame_ = Prepare("INSERT INTO frames VALUES (?, ?, ?, ?, ?, ?)");
  message_ = Prepare("INSERT INTO messages VALUES (?, ?, ?, ?, ?, ?, ?)");
  route_ = Prepare("INSERT INTO routes VALUES (?, ?, ?, ?, ?)");
  transition_ = Prepare("INSERT INTO transitions VALUES (?, ?, ?, ?, ?)");
  metric_ = Prepare("INSERT INTO metrics VALUES (?, ?, ?, ?)");
  event_ = Prepare("INSERT INTO events VALUES (?, ?, ?, ?)");
  Exec("BEGIN");
}

RunTrace::~RunTrace() { Close(); }

void RunTrace::Close() {
  if (!db_) return;
  Exec("COMMIT");
  Exec(kIndexes);
  if (energy_) Exec(kEnergyIndex);
  for (sqlite3_stmt* s :
       {info_, node_, obstacle_, pose_, frame_, message_, route_, transition_, metric_, event_, energy_})
    sqlite3_finalize(s);
  sqlite3_close(db_);
  db_ = nullptr;
}

sqlite3_stmt* RunTrace::Prepare(const char* sql) {
  sqlite3_stmt* s = nullptr;
  if (sqlite3_prepare_v2(db_, sql, -1, &s, nullptr) != SQLITE_OK)
    throw std::runtime_error(std::string("trace: ") + sqlite3_errmsg(db_));
  return s;
}

void RunTrace::Exec(const char* sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string why = error ? error : "unknown error";
    sqlite3_free(error);
    throw std::runtime_error("trace: " + why);
  }
}

void RunTrace::Step(sqlite3_stmt* s) {
  const int status = sqlite3_step(s);
  sqlite3_reset(s);
  if (status != SQLITE_DONE) throw std::runtime_error(std::string("trace: ") + sqlite3_errmsg(db_));
  if (++rows_in_transaction_ >= kRowsPerTransaction) {
    Exec("COMMIT; BEGIN");
    rows_in_transaction_ = 0;
  }
}

void RunTrace::Info(const std::string& key, const std::string& value) {
  sqlite3_bind_text(info_, 1, key.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(info_, 2, value.c_str(), -1, SQLITE_TRANSIENT);
  Step(info_);
}

void RunTrace::Node(std::uint32_t id, const std::string& name, const std::string& model, double x, double y,
                    double theta) {
  sqlite3_bind_int64(node_, 1, id);
  sqlite3_bind_text(node_, 2, name.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(node_, 3, model.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_double(node_, 4, x);
  sqlite3_bind_double(node_, 5, y);
  sqlite3_bind_double(node_, 6, theta);
  Step(node_);
}

void RunTrace::Obstacle(const std::string& kind, double cx, double cy, double length, double width, double height,
                        double yaw) {
  sqlite3_bind_text(obstacle_, 1, kind.c_str(), -1, SQLITE_TRANSIENT);
  int column = 2;
  for (double v : {cx, cy, length, width, height, yaw}) sqlite3_bind_double(obstacle_, column++, v);
  Step(obstacle_);
}

void RunTrace::Pose(double t, std::uint32_t node, double x, double y, double theta) {
  sqlite3_bind_double(pose_, 1, t);
  sqlite3_bind_int64(pose_, 2, node);
  sqlite3_bind_double(pose_, 3, x);
  sqlite3_bind_double(pose_, 4, y);
  sqlite3_bind_double(pose_, 5, theta);
  Step(pose_);
}

void RunTrace::Frame(double t, std::uint32_t node, bool sent, std::optional<std::uint32_t> peer, const char* kind,
                     std::uint32_t bytes) {
  sqlite3_bind_double(frame_, 1, t);
  sqlite3_bind_int64(frame_, 2, node);
  sqlite3_bind_text(frame_, 3, sent ? "tx" : "rx", -1, SQLITE_STATIC);
  peer ? sqlite3_bind_int64(frame_, 4, *peer) : sqlite3_bind_null(frame_, 4);
  sqlite3_bind_text(frame_, 5, kind, -1, SQLITE_STATIC);
  sqlite3_bind_int64(frame_, 6, bytes);
  Step(frame_);
}

void RunTrace::Message(double sent, std::optional<double> received, std::uint32_t from, std::uint32_t to,
                       const char* delivery, std::uint32_t bytes, std::optional<int> hops) {
  sqlite3_bind_double(message_, 1, sent);
  BindOptional(message_, 2, received);
  sqlite3_bind_int64(message_, 3, from);
  sqlite3_bind_int64(message_, 4, to);
  sqlite3_bind_text(message_, 5, delivery, -1, SQLITE_STATIC);
  sqlite3_bind_int64(message_, 6, bytes);
  hops ? sqlite3_bind_int(message_, 7, *hops) : sqlite3_bind_null(message_, 7);
  Step(message_);
}

void RunTrace::Route(double t, std::uint32_t node, std::uint32_t destination, std::optional<std::uint32_t> next_hop,
                     int hops) {
  sqlite3_bind_double(route_, 1, t);
  sqlite3_bind_int64(route_, 2, node);
  sqlite3_bind_int64(route_, 3, destination);
  next_hop ? sqlite3_bind_int64(route_, 4, *next_hop) : sqlite3_bind_null(route_, 4);
  next_hop ? sqlite3_bind_int(route_, 5, hops) : sqlite3_bind_null(route_, 5);
  Step(route_);
}

void RunTrace::Transition(double t, std::uint32_t node, const std::string& from, const std::string& to,
                          const std::string& why) {
  sqlite3_bind_double(transition_, 1, t);
  sqlite3_bind_int64(transition_, 2, node);
  sqlite3_bind_text(transition_, 3, from.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(transition_, 4, to.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(transition_, 5, why.c_str(), -1, SQLITE_TRANSIENT);
  Step(transition_);
}

void RunTrace::Metric(double t, std::uint32_t node, const std::string& name, double value) {
  sqlite3_bind_double(metric_, 1, t);
  sqlite3_bind_int64(metric_, 2, node);
  sqlite3_bind_text(metric_, 3, name.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_double(metric_, 4, value);
  Step(metric_);
}

void RunTrace::Event(double t, std::uint32_t node, const char* kind, const std::string& detail) {
  sqlite3_bind_double(event_, 1, t);
  sqlite3_bind_int64(event_, 2, node);
  sqlite3_bind_text(event_, 3, kind, -1, SQLITE_STATIC);
  sqlite3_bind_text(event_, 4, detail.c_str(), -1, SQLITE_TRANSIENT);
  Step(event_);
}

void RunTrace::Energy(double t, std::uint32_t node, double remaining_j, double fraction, double power_w) {
  if (!energy_) {
    Exec(kEnergySchema);
    energy_ = Prepare("INSERT INTO energy VALUES (?, ?, ?, ?, ?)");
  }
  sqlite3_bind_double(energy_, 1, t);
  sqlite3_bind_int64(energy_, 2, node);
  sqlite3_bind_double(energy_, 3, remaining_j);
  sqlite3_bind_double(energy_, 4, fraction);
  sqlite3_bind_double(energy_, 5, power_w);
  Step(energy_);
}

}  // namespace sanet::trace
