// One run's trace of both worlds on the simulation clock, written to an SQLite database
// (trace.sqlite): the nodes and obstacles, body poses whenever a body moved, every radio frame
// sent and received, every application message, routing-table changes, controller transitions
// and metrics, events (log lines, switch-offs, spawns, deaths, revivals) and, in a run with
// batteries, their charge at every sample. Each table is in time order.
// SQLite because it is one file any language reads (Python's standard library, the sqlite3
// shell), holds numbers compactly, and lets a viewer ask for a time window without reading the
// rest. docs/trace.md describes every table. Rows go in large transactions; the file is written
// under a temporary name and takes its name when the results are committed.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

struct sqlite3;
struct sqlite3_stmt;

namespace sanet::trace {

class RunTrace {
 public:
  explicit RunTrace(const std::string& path);  // creates the database; throws std::runtime_error
  ~RunTrace();
  RunTrace(const RunTrace&) = delete;
  RunTrace& operator=(const RunTrace&) = delete;

  void Info(const std::string& key, const std::string& value);
  void Node(std::uint32_t id, const std::string& name, const std::string& model, double x, double y, double theta);
  void Obstacle(const std::string& kind, double cx, double cy, double length, double width, double height, double yaw);
  void Pose(double t, std::uint32_t node, double x, double y, double theta);
  // A frame `node`'s radio sent (or received) to (or from) `peer` (empty: broadcast or unknown).
  void Frame(double t, std::uint32_t node, bool sent, std::optional<std::uint32_t> peer, const char* kind,
             std::uint32_t bytes);
  void Message(double sent, std::optional<double> received, std::uint32_t from, std::uint32_t to, const char* delivery,
               std::uint32_t bytes, std::optional<int> hops);
  // `node`'s route to `destination` now goes through `next_hop` in `hops` hops, or (empty) is gone.
  void Route(double t, std::uint32_t node, std::uint32_t destination, std::optional<std::uint32_t> next_hop, int hops);
  void Transition(double t, std::uint32_t node, const std::string& from, const std::string& to, const std::string& why);
  void Metric(double t, std::uint32_t node, const std::string& name, double value);
  void Event(double t, std::uint32_t node, const char* kind, const std::string& detail);
  // A battery's sample. The table `energy` is made with the first one, so that a run without
  // energy writes the same file as before there was energy.
  void Energy(double t, std::uint32_t node, double remaining_j, double fraction, double power_w);
  // Ends the last transaction and closes the file (also done on destruction).
  void Close();

 private:
  sqlite3_stmt* Prepare(const char* sql);
  void Step(sqlite3_stmt* statement);
  void Exec(const char* sql);

  sqlite3* db_ = nullptr;
  sqlite3_stmt *info_, *node_, *obstacle_, *pose_, *frame_, *message_, *route_, *transition_, *metric_, *event_;
  sqlite3_stmt* energy_ = nullptr;  // with the table, at the first sample
  std::uint64_t rows_in_transaction_ = 0;
};

}  // namespace sanet::trace
