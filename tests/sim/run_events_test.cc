// The typed event streams a front end observes through the driver carry what the run's own
// results hold (same events, same count, same content), whether or not the trace is written,
// and watching them does not change the run.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <map>

#include "scenario/scenario_loader.h"
#include "sim/world.h"
#include "support/test_world.h"

namespace sanet {
namespace {

struct Tally {
  std::map<std::string, std::int64_t> count;
  std::int64_t frame_bytes = 0;
  std::int64_t route_hops = 0;
  double metric_sum = 0;
  std::uint64_t steps = 0;
};

// Hears every kind the results hold, on the run's bus.
class Counter {
 public:
  void Observe(sim::RunBus& bus) {
    Hear<sim::StepEnded>(bus, [this](const sim::StepEnded& e) {
      EXPECT_GE(e.world.time(), last_step_time_) << "steps come in time order";
      last_step_time_ = e.world.time();
      ++tally.steps;
    });
    Hear<net::FrameEvent>(bus, [this](const net::FrameEvent& f) {
      ++tally.count["frames"];
      tally.frame_bytes += f.bytes;
    });
    Hear<sim::MessageDelivered>(bus, [this](const sim::MessageDelivered&) { ++tally.count["delivered"]; });
    Hear<sim::MessageLost>(bus, [this](const sim::MessageLost&) { ++tally.count["lost"]; });
    Hear<sim::RouteChange>(bus, [this](const sim::RouteChange& r) {
      ++tally.count["routes"];
      tally.route_hops += r.hops;
    });
    Hear<sim::Transitioned>(bus, [this](const sim::Transitioned&) { ++tally.count["transitions"]; });
    Hear<sim::MetricReported>(bus, [this](const sim::MetricReported& e) {
      ++tally.count["metrics"];
      tally.metric_sum += e.value;
    });
    Hear<sim::LogLine>(bus, [this](const sim::LogLine&) { ++tally.count["logs"]; });
  }
  Tally tally;

 private:
  template <typename Event, typename Handler>
  void Hear(sim::RunBus& bus, Handler handler) {
    heard_.push_back(bus.On<Event>(sim::RunStage::kObserve, handler));
  }
  std::vector<Subscription> heard_;
  double last_step_time_ = 0;
};

double Query(const std::string& db, const std::string& sql) {
  sqlite3* h = nullptr;
  EXPECT_EQ(sqlite3_open_v2(db.c_str(), &h, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK) << db;
  sqlite3_stmt* st = nullptr;
  EXPECT_EQ(sqlite3_prepare_v2(h, sql.c_str(), -1, &st, nullptr), SQLITE_OK) << sql;
  EXPECT_EQ(sqlite3_step(st), SQLITE_ROW) << sql;
  const double value = sqlite3_column_double(st, 0);
  sqlite3_finalize(st);
  sqlite3_close(h);
  return value;
}

struct Observed {
  std::string fingerprint;
  Tally tally;
};

Observed RunHelpRequest(bool trace, bool observe, const std::string& dir) {
  sim::RunSpec spec = scenario::LoadScenario(SANET_SOURCE_DIR "/scenarios/help-request.yaml").run;
  spec.duration = 300;
  spec.trace = trace;
  sim::World world(spec, testing::BuiltinRegistry());
  Counter counter;
  if (observe) counter.Observe(world.driver().bus());
  sim::RunOptions options;
  options.output_dir = dir;
  return {world.Run(options).fingerprint, counter.tally};
}

TEST(RunEvents, StreamsCarryWhatTheResultsHold) {
  const std::string dir = ::testing::TempDir() + "/observer-streams";
  std::filesystem::remove_all(dir);
  const Observed seen = RunHelpRequest(true, true, dir);
  const std::string db = dir + "/trace.sqlite";
  const auto& n = seen.tally.count;
  EXPECT_GT(n.at("frames"), 1000);
  EXPECT_GT(n.at("routes"), 10);
  EXPECT_GT(n.at("transitions"), 0);
  EXPECT_GT(n.at("metrics"), 0);
  EXPECT_GT(n.at("delivered"), 10);
  EXPECT_GT(seen.tally.steps, 7000u) << "one snapshot per 5 ms physics step";
  EXPECT_EQ(n.at("frames"), Query(db, "SELECT COUNT(*) FROM frames"));
  EXPECT_EQ(seen.tally.frame_bytes, Query(db, "SELECT SUM(bytes) FROM frames"));
  EXPECT_EQ(n.at("routes"), Query(db, "SELECT COUNT(*) FROM routes"));
  EXPECT_EQ(seen.tally.route_hops, Query(db, "SELECT SUM(hops) FROM routes"));
  EXPECT_EQ(n.at("transitions"), Query(db, "SELECT COUNT(*) FROM transitions"));
  EXPECT_EQ(n.at("metrics"), Query(db, "SELECT COUNT(*) FROM metrics"));
  EXPECT_DOUBLE_EQ(seen.tally.metric_sum, Query(db, "SELECT SUM(value) FROM metrics"));
  EXPECT_EQ(n.at("delivered"), Query(db, "SELECT COUNT(*) FROM messages WHERE t_received IS NOT NULL"));
  EXPECT_EQ(n.count("lost") ? n.at("lost") : 0, Query(db, "SELECT COUNT(*) FROM messages WHERE t_received IS NULL"));
  EXPECT_EQ(n.count("logs") ? n.at("logs") : 0, Query(db, "SELECT COUNT(*) FROM events WHERE kind = 'log'"));
}

TEST(RunEvents, StreamsNeedNoTraceAndWatchingChangesNothing) {
  const std::string dir = ::testing::TempDir() + "/observer-quiet";
  const Observed traced = RunHelpRequest(true, true, dir + "-a");
  const Observed untraced = RunHelpRequest(false, true, dir + "-b");
  EXPECT_EQ(untraced.tally.count, traced.tally.count);
  EXPECT_EQ(untraced.tally.frame_bytes, traced.tally.frame_bytes);
  const Observed unwatched = RunHelpRequest(false, false, dir + "-c");
  EXPECT_EQ(unwatched.fingerprint, untraced.fingerprint);
}

}  // namespace
}  // namespace sanet
