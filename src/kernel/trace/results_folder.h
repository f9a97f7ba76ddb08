// The results folder of one run. Every file in it is written whole: CSV sinks and files that
// others fill as the run goes (ns-3's pcap and FlowMonitor writers) live under temporary names
// until Commit moves them into place, so a reader never sees half a result. The folder keeps
// the list of files written. Without a folder (""), CSV rows are still hashed (for the
// fingerprint) but nothing touches the disk.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "trace/csv_sink.h"

namespace sanet::trace {

class ResultsFolder {
 public:
  // Clears what an earlier run left in `dir` (trace/earlier_run.h).
  explicit ResultsFolder(std::string dir, bool force = false);
  bool writes() const { return !dir_.empty(); }
  const std::string& dir() const { return dir_; }

  // A CSV file `name` (may hold one sub-folder, "packets/a.csv"), owned here until Commit.
  CsvSink& Csv(const std::string& name, std::string_view header, std::size_t buffer_bytes = 1 << 20);
  // The hash of a CSV opened with Csv (for the fingerprint).
  std::uint64_t CsvHash(const std::string& name) const;
  // A whole file, written now.
  void WriteWhole(const std::string& name, const std::string& content);
  // Temporary paths for files or a sub-folder that someone else writes during the run; they
  // take their names at Commit. Only when the folder writes.
  std::string TempFile(const std::string& name);
  std::string TempFolder(const std::string& name);
  // Names a file or sub-folder ("packets/") in the list without touching it.
  void Listed(const std::string& name);

  // Moves every file opened so far into place (it may be called again for files opened later).
  void Commit();
  const std::vector<std::string>& files() const { return files_; }

 private:
  std::string Path(const std::string& name) const { return dir_ + "/" + name; }
  std::string dir_;
  std::map<std::string, std::unique_ptr<CsvSink>> csv_;
  std::vector<std::string> csv_order_;  // not yet committed, in opening order
  std::vector<std::string> pending_;    // TempFile and TempFolder names, moved at Commit
  std::vector<std::string> files_;
};

}  // namespace sanet::trace
