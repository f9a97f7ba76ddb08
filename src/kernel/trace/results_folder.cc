#include "trace/results_folder.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "core/atomic_file.h"
#include "trace/earlier_run.h"

namespace sanet::trace {
namespace fs = std::filesystem;

ResultsFolder::ResultsFolder(std::string dir, bool force) : dir_(std::move(dir)) {
  if (!writes()) return;
  ClearEarlierRun(dir_, force);
  fs::create_directories(dir_);
}

void ResultsFolder::Listed(const std::string& name) {
  if (writes() && std::find(files_.begin(), files_.end(), name) == files_.end()) files_.push_back(name);
}

CsvSink& ResultsFolder::Csv(const std::string& name, std::string_view header, std::size_t buffer_bytes) {
  if (csv_.count(name)) throw std::logic_error("results file opened twice: " + name);
  std::optional<std::string> path;
  if (writes()) {
    path = Path(name);
    fs::create_directories(fs::path(*path).parent_path());
  }
  csv_order_.push_back(name);
  return *(csv_[name] = std::make_unique<CsvSink>(path, header, buffer_bytes));
}

std::uint64_t ResultsFolder::CsvHash(const std::string& name) const { return csv_.at(name)->hash(); }

void ResultsFolder::WriteWhole(const std::string& name, const std::string& content) {
  if (!writes()) return;
  WriteFileAtomically(Path(name), content);
  Listed(name);
}

// A temporary name starts empty: a run that was killed may have left one behind (trace.sqlite.tmp
// with its tables, which the next run's trace could not create again).
std::string ResultsFolder::TempFile(const std::string& name) {
  if (!writes()) throw std::logic_error("no results folder for " + name);
  pending_.push_back(name);
  const std::string tmp = Path(name) + ".tmp";
  fs::remove_all(tmp);
  return tmp;
}

std::string ResultsFolder::TempFolder(const std::string& name) {
  const std::string tmp = TempFile(name);
  fs::create_directories(tmp);
  return tmp;
}

void ResultsFolder::Commit() {
  for (const std::string& name : csv_order_) {  // those opened since the last Commit
    csv_.at(name)->Commit();
    const auto slash = name.find('/');
    Listed(slash == std::string::npos ? name : name.substr(0, slash + 1));
  }
  for (const std::string& name : pending_) {
    if (!fs::exists(Path(name) + ".tmp")) continue;  // its writer never opened it
    fs::remove_all(Path(name));
    fs::rename(Path(name) + ".tmp", Path(name));
    Listed(fs::is_directory(Path(name)) ? name + "/" : name);
  }
  pending_.clear();
  csv_order_.clear();
}

}  // namespace sanet::trace
