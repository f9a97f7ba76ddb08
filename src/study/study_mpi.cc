#include "study/study_mpi.h"

#include <mpi.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/json_text.h"

namespace sanet::study {
namespace {

namespace fs = std::filesystem;

enum Tag : int { kReady = 1, kJob, kEnded, kFiles, kFinish, kStopNow };

// MPI is started the first time it is needed and finished when the program ends.
class MpiSession {
 public:
  static MpiSession& Get() {
    static MpiSession session;
    return session;
  }
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SINGLE, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSession() { MPI_Finalize(); }
  int rank_ = 0, size_ = 1;
};

void Send(const std::string& bytes, int to, Tag tag) {
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD);
}

// The next message from `from` (or anyone) with `tag`, if one is waiting; `source` says who sent it.
bool TryReceive(int from, int tag, std::string& bytes, int* source = nullptr) {
  int waiting = 0;
  MPI_Status status;
  MPI_Iprobe(from, tag, MPI_COMM_WORLD, &waiting, &status);
  if (!waiting) return false;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  bytes.resize(static_cast<std::size_t>(count));
  MPI_Recv(bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  if (source) *source = status.MPI_SOURCE;
  return true;
}

std::string Receive(int from, int tag) {
  std::string bytes;
  while (!TryReceive(from, tag, bytes)) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  return bytes;
}

std::string ReadWhole(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A results folder as one message: a JSON index of relative paths and sizes, then the bytes.
std::pair<nlohmann::json, std::string> Pack(const fs::path& folder) {
  nlohmann::json index = nlohmann::json::array();
  std::string bytes;
  if (fs::exists(folder))
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
      if (!entry.is_regular_file()) continue;
      const std::string content = ReadWhole(entry.path());
      index.push_back({{"path", fs::relative(entry.path(), folder).string()}, {"size", content.size()}});
      bytes += content;
    }
  return {index, bytes};
}

// Writes a packed folder as `folder`, whole: beside it first, then in its place.
void Unpack(const nlohmann::json& index, const std::string& bytes, const fs::path& folder) {
  const fs::path incoming = folder.string() + ".incoming";
  fs::remove_all(incoming);
  std::size_t at = 0;
  for (const auto& f : index) {
    const fs::path p = incoming / f["path"].get<std::string>();
    fs::create_directories(p.parent_path());
    const std::size_t size = f["size"].get<std::size_t>();
    std::ofstream(p, std::ios::binary).write(bytes.data() + at, static_cast<std::streamsize>(size));
    at += size;
  }
  fs::create_directories(incoming);
  fs::remove_all(folder);
  fs::rename(incoming, folder);
}

nlohmann::json JobJson(const RunJob& j) {
  return {{"name", j.name}, {"args", j.args}, {"effective", j.effective_scenario}};
}

nlohmann::json EndJson(const JobEnd& e) {
  return {{"name", e.name}, {"completed", e.completed}, {"interrupted", e.interrupted}, {"error", e.error},
          {"host", e.host}, {"started", e.started_utc}, {"finished", e.finished_utc},   {"wall", e.wall_s},
          {"rank", e.rank}};
}

JobEnd EndOf(const nlohmann::json& j) {
  return {j["name"],    j["completed"], j["interrupted"], j["error"], j["host"],
          j["started"], j["finished"],  j["wall"],        j["rank"]};
}

// Rank 0: its own child processes, and the other ranks' slots as they announce them.
class MpiExecutor : public Executor {
 public:
  explicit MpiExecutor(int jobs) : local_(jobs, 0), free_(MpiSession::Get().size(), 0) {}
  ~MpiExecutor() override {
    for (int r = 1; r < static_cast<int>(free_.size()); ++r) Send("", r, stopping_ ? kStopNow : kFinish);
  }
  int Free() const override {
    int free = local_.Free();
    for (int f : free_) free += f;
    return free;
  }
  void Start(const RunJob& job) override {
    if (local_.Free() > 0) return local_.Start(job);
    for (int r = 1; r < static_cast<int>(free_.size()); ++r)
      if (free_[r] > 0) {
        --free_[r];
        remote_[job.name] = job;
        Send(JsonText(JobJson(job)), r, kJob);
        return;
      }
  }
  std::vector<JobEnd> Poll() override {
    std::vector<JobEnd> ended = local_.Poll();
    std::string bytes;
    int from = 0;
    while (TryReceive(MPI_ANY_SOURCE, kReady, bytes, &from)) free_[from] = std::stoi(bytes);
    while (TryReceive(MPI_ANY_SOURCE, kEnded, bytes, &from)) {
      ended.push_back(Collect(from, bytes));
      ++free_[from];  // a rank announces its slots once; each run it ends frees one
    }
    return ended;
  }
  int Running() const override { return local_.Running() + static_cast<int>(remote_.size()); }
  void StopAll() override {
    stopping_ = true;
    local_.StopAll();
    for (int r = 1; r < static_cast<int>(free_.size()); ++r) Send("", r, kStopNow);
  }
  int ranks() const { return static_cast<int>(free_.size()); }
  int jobs() const { return local_.Free() + local_.Running(); }

 private:
  // A run another rank ended: its folder and output follow in one message.
  JobEnd Collect(int from, const std::string& header) {
    const nlohmann::json h = nlohmann::json::parse(header);
    const std::string bytes = Receive(from, kFiles);
    JobEnd end = EndOf(h["end"]);
    const RunJob job = remote_.at(end.name);
    remote_.erase(end.name);
    if (!end.interrupted) {
      Unpack(h["files"], bytes.substr(0, bytes.size() - h["log_size"].get<std::size_t>()), job.folder);
      fs::create_directories(fs::path(job.log).parent_path());
      std::ofstream(job.log, std::ios::binary) << bytes.substr(bytes.size() - h["log_size"].get<std::size_t>());
    }
    return end;
  }
  LocalExecutor local_;
  std::vector<int> free_;  // per rank: slots free there (0 for rank 0: local_ has its own)
  std::map<std::string, RunJob> remote_;
  bool stopping_ = false;
};

// A worker's run: from a copy of the effective scenario, into a temporary folder.
RunJob LocalCopy(const nlohmann::json& j, const fs::path& scratch) {
  RunJob job;
  job.name = j["name"];
  const fs::path dir = scratch / job.name;
  fs::create_directories(dir);
  std::ofstream(dir / "scenario.yaml") << j["effective"].get<std::string>();
  job.args = j["args"].get<std::vector<std::string>>();
  job.args[1] = (dir / "scenario.yaml").string();
  job.folder = (dir / "results").string();
  for (std::size_t i = 0; i + 1 < job.args.size(); ++i)
    if (job.args[i] == "-o") job.args[i + 1] = job.folder;
  job.log = (dir / "output.txt").string();
  return job;
}

void SendBack(const JobEnd& end, const fs::path& dir) {
  auto [index, bytes] = Pack(dir / "results");
  const std::string log = ReadWhole(dir / "output.txt");
  const nlohmann::json header = {{"end", EndJson(end)}, {"files", index}, {"log_size", log.size()}};
  Send(JsonText(header), 0, kEnded);
  Send(bytes + log, 0, kFiles);
  fs::remove_all(dir);
}

}  // namespace

bool UnderMpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

bool IsMpiCoordinator() { return !UnderMpi() || MpiSession::Get().rank() == 0; }

int ServeAsMpiWorker(int jobs) {
  const int rank = MpiSession::Get().rank();
  LocalExecutor local(jobs, rank);
  const fs::path scratch =
      fs::temp_directory_path() / ("sanet-rank-" + std::to_string(rank) + "-" + std::to_string(::getpid()));
  Send(std::to_string(jobs), 0, kReady);
  bool finish = false;
  std::string bytes;
  while (!finish || local.Running() > 0) {
    if (TryReceive(0, kJob, bytes)) local.Start(LocalCopy(nlohmann::json::parse(bytes), scratch));
    if (TryReceive(0, kFinish, bytes)) finish = true;
    if (TryReceive(0, kStopNow, bytes)) finish = true, local.StopAll();
    for (const JobEnd& end : local.Poll()) SendBack(end, scratch / end.name);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  fs::remove_all(scratch);
  return 0;
}

std::unique_ptr<Executor> MakeExecutor(int jobs) {
  if (!UnderMpi()) return std::make_unique<LocalExecutor>(jobs);
  return std::make_unique<MpiExecutor>(jobs);
}

std::string Describe(const Executor& executor) {
  if (const auto* mpi = dynamic_cast<const MpiExecutor*>(&executor))
    return "on " + std::to_string(mpi->ranks()) + " MPI ranks, " + std::to_string(mpi->jobs()) + " at a time each";
  return std::to_string(executor.Free()) + " at a time";
}

}  // namespace sanet::study
