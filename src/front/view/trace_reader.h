// Reads a run's results folder for the viewer: trace.sqlite (docs/trace.md) and the summary, packet
// counts and metrics beside it, answered as JSON for the page.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

struct sqlite3;

namespace sanet::view {

class TraceReader {
 public:
  // Opens `folder`/trace.sqlite read-only; throws std::runtime_error saying what is missing.
  explicit TraceReader(const std::string& folder);
  ~TraceReader();
  TraceReader(const TraceReader&) = delete;
  TraceReader& operator=(const TraceReader&) = delete;

  // The run: info, nodes (with their packet counts from packets.csv), obstacles, duration, the
  // summary's figures.
  nlohmann::json Run() const;
  // Every pose row, per node: {node: [[t, x, y, theta], ...]}.
  nlohmann::json Poses() const;
  // Frames with from <= t < to: [[t, node, tx (1/0), peer or null, kind], ...].
  nlohmann::json Frames(double from, double to) const;
  // Every message: [[t_sent, t_received or null, from, to, delivery, bytes], ...].
  nlohmann::json Messages() const;
  // Each node's valid routes at time t: [[node, destination, next_hop, hops], ...].
  nlohmann::json RoutesAt(double t) const;
  // Transitions: [[t, node, from, to, why], ...]; and min_distance.csv rows if any.
  nlohmann::json Transitions() const;
  nlohmann::json MinDistance() const;
  // The batteries (trace.sqlite's energy table and death and revival events), for runs with
  // energy: {"levels": {node: [[t, fraction], ...]}, "deaths": [[t, node, dead (1/0)], ...]}; both
  // empty for a run without energy, whose trace has no energy table.
  nlohmann::json Energy() const;
  // The controllers' metrics (metrics.csv, Node::Metric): {name: {node: [[t, value], ...]}}, in
  // the order of the file; empty when the run has none.
  nlohmann::json Metrics() const;

 private:
  bool HasTable(const char* name) const;
  template <typename Row>
  nlohmann::json Query(const std::string& sql, Row row, double a = 0, double b = 0) const;
  std::string folder_;
  sqlite3* db_ = nullptr;
};

}  // namespace sanet::view
