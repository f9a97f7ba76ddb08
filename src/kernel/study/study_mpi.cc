#include "study/study_mpi.h"

#include <mpi.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/json_text.h"
#include "study/folder_message.h"
#include "study/mpi_link.h"

namespace sanet::study {
namespace {

namespace fs = std::filesystem;

// kReady: a worker's number of slots; kJob: a run to do; kEnded: a run's end with its folder and
// output; kFinish: no more runs (end when yours have); kStopNow: stop your runs and end.
enum Tag : int { kReady = 1, kJob, kEnded, kFinish, kStopNow };

// How long rank 0, stopping, waits for other ranks' runs to report before it gives up on them.
constexpr double kStopGrace = 15;

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

double SteadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Rank 0: its own child processes, and the other ranks' slots as they announce them.
class MpiExecutor : public Executor {
 public:
  explicit MpiExecutor(int jobs) : local_(jobs, 0), free_(MpiSession::Get().size(), 0) {}
  ~MpiExecutor() override {  // a stopped study told the ranks in StopAll
    if (!stopping_)
      for (int r = 1; r < ranks(); ++r) link_.Send(r, kFinish, "");
  }
  int Free() const override {
    int free = local_.Free();
    for (int f : free_) free += f;
    return free;
  }
  void Start(const RunJob& job) override {
    if (local_.Free() > 0) return local_.Start(job);
    for (int r = 1; r < ranks(); ++r)
      if (free_[r] > 0) {
        --free_[r];
        remote_[job.name] = job;
        link_.Send(r, kJob, JsonText(JobJson(job)));
        return;
      }
  }
  std::vector<JobEnd> Poll() override {
    std::vector<JobEnd> ended = local_.Poll();
    while (auto m = link_.TryReceive(MPI_ANY_SOURCE, MPI_ANY_TAG)) {
      if (m->tag == kReady) free_[m->from] = std::stoi(m->bytes);
      if (m->tag != kEnded) continue;
      ended.push_back(Collect(*m));
      ++free_[m->from];  // a rank announces its slots once; each run it ends frees one
    }
    if (stopping_ && SteadySeconds() > give_up_at_) GiveUpRemoteRuns(ended);
    link_.Progress();
    return ended;
  }
  int Running() const override { return local_.Running() + static_cast<int>(remote_.size()); }
  void StopAll() override {
    stopping_ = true;
    give_up_at_ = SteadySeconds() + kStopGrace;
    local_.StopNow();  // mpirun kills the ranks a second after it stops them: no time for results
    for (int r = 1; r < ranks(); ++r) link_.Send(r, kStopNow, "");
  }
  int ranks() const { return static_cast<int>(free_.size()); }
  int jobs() const { return local_.Free() + local_.Running(); }

 private:
  // A run another rank ended: its folder and output came in one message.
  JobEnd Collect(const MpiMessage& m) {
    const UnpackedMessage message = ReadFolderMessage(m.bytes);
    JobEnd end = EndOf(message.header);
    const RunJob job = remote_.at(end.name);
    remote_.erase(end.name);
    if (end.interrupted) return end;
    try {
      WriteFolder(message, job.folder);
      fs::create_directories(fs::path(job.log).parent_path());
      std::ofstream(job.log, std::ios::binary) << message.trailer;
    } catch (const std::exception& e) {
      end.completed = false;
      end.error = std::string("its results could not be written here: ") + e.what();
    }
    return end;
  }
  // Ranks that do not answer a stop (killed with mpirun): their runs are to run again.
  void GiveUpRemoteRuns(std::vector<JobEnd>& ended) {
    for (const auto& [name, job] : remote_) ended.push_back({name, false, true, "", "", "", "", 0, -1});
    remote_.clear();
  }
  LocalExecutor local_;
  MpiLink link_;
  std::vector<int> free_;  // per rank: slots free there (0 for rank 0: local_ has its own)
  std::map<std::string, RunJob> remote_;
  bool stopping_ = false;
  double give_up_at_ = 0;
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

// A run's end, its folder and its output, to rank 0; a folder too large for one MPI message
// is reported as the run's failure rather than lost in silence.
void SendBack(MpiLink& link, JobEnd end, const fs::path& dir) {
  const std::string log = ReadWholeFile(dir / "output.txt");
  try {
    link.Send(0, kEnded, PackFolder(EndJson(end), dir / "results", log));
  } catch (const std::length_error& e) {
    end.completed = false;
    end.error = std::string("its results cannot be sent to rank 0: ") + e.what() +
                "; run this study on one machine (sanet sweep --jobs N) or with a smaller trace";
    link.Send(0, kEnded, PackFolder(EndJson(end), dir / "none", ""));
  }
  fs::remove_all(dir);
}

volatile std::sig_atomic_t g_worker_stop = 0;

// A worker's runs live in <tmp>/sanet-rank-<rank>-<pid>/ until they are sent back.
const std::string kScratchPrefix = "sanet-rank-";

// Folders of workers that were killed outright (mpirun's SIGKILL a second after a stop) and
// could not remove their own: their process is gone.
void RemoveScratchOfDeadRanks() {
  std::error_code ignored;
  for (const auto& entry : fs::directory_iterator(fs::temp_directory_path(), ignored)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(kScratchPrefix, 0) != 0) continue;
    const std::string pid = name.substr(name.rfind('-') + 1);
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if (::kill(static_cast<pid_t>(std::stol(pid)), 0) != 0 && errno == ESRCH) fs::remove_all(entry.path(), ignored);
  }
}

}  // namespace

bool UnderMpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

bool IsMpiCoordinator() { return !UnderMpi() || MpiSession::Get().rank() == 0; }

int ServeAsMpiWorker(int jobs) {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, [](int) { g_worker_stop = 1; });
  const int rank = MpiSession::Get().rank();
  RemoveScratchOfDeadRanks();
  const fs::path scratch =
      fs::temp_directory_path() / (kScratchPrefix + std::to_string(rank) + "-" + std::to_string(::getpid()));
  MpiLink link;
  {
    LocalExecutor local(jobs, rank);
    link.Send(0, kReady, std::to_string(jobs));
    bool finish = false, stopped = false, stopping = false;
    while (!finish || local.Running() > 0) {
      while (auto m = link.TryReceive(0, MPI_ANY_TAG)) {
        if (m->tag == kJob) local.Start(LocalCopy(nlohmann::json::parse(m->bytes), scratch));
        finish = finish || m->tag == kFinish || m->tag == kStopNow;
        stopped = stopped || m->tag == kStopNow;
      }
      if ((g_worker_stop || stopped) && !stopping) {
        finish = stopping = true;
        local.StopNow();  // its results would only be thrown away: the run is done again
      }
      for (const JobEnd& end : local.Poll()) SendBack(link, end, scratch / end.name);
      link.Progress();
      PollPause();
    }
  }
  fs::remove_all(scratch);
  return g_worker_stop ? 130 : 0;  // the link flushes what it still sends as it goes
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
