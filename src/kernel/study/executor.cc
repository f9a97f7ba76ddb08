#include "study/executor.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace sanet::study {
namespace {

double SteadyNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// In the child: output to the log, die with the parent, become `sanet args...`.
[[noreturn]] void BecomeRun(const RunJob& job) {
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  // A process group of its own: a signal to the sweep's group (Ctrl-C, mpirun stopping its ranks)
  // reaches the run once, through the sweep, not a second time directly (which would end it at once).
  ::setpgid(0, 0);
  const int log = ::open(job.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log >= 0) {
    ::dup2(log, STDOUT_FILENO);
    ::dup2(log, STDERR_FILENO);
  }
  std::vector<std::string> args = {"sanet"};
  args.insert(args.end(), job.args.begin(), job.args.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  ::execv("/proc/self/exe", argv.data());
  std::perror("sanet sweep: cannot start a run");
  ::_exit(127);
}

// Stopped as a user stops a program (Ctrl-C, kill, a closed terminal, the sweep's own stop):
// not the run's fault; it runs again next time. 130, 143 and 129: a run that handled SIGINT,
// SIGTERM or SIGHUP and stopped. A crash (SIGSEGV, SIGABRT) or SIGKILL (the out-of-memory
// killer's) is the run's failure, recorded as such.
bool AskedToStop(int status) {
  if (WIFSIGNALED(status))
    return WTERMSIG(status) == SIGINT || WTERMSIG(status) == SIGTERM || WTERMSIG(status) == SIGHUP;
  const int code = WEXITSTATUS(status);
  return code == 128 + SIGINT || code == 128 + SIGTERM || code == 128 + SIGHUP;
}

// How a failed run's process ended, after what it printed (which may be nothing: a crash).
std::string EndOfProcess(int status) {
  if (!WIFSIGNALED(status)) return "(the run exited with status " + std::to_string(WEXITSTATUS(status)) + ")";
  const int sig = WTERMSIG(status);
  return "(the run was killed by signal " + std::to_string(sig) + ", " + ::strsignal(sig) + ")";
}

}  // namespace

std::string Tail(const std::string& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "";
  const std::streamoff size = in.tellg();
  in.seekg(size > static_cast<std::streamoff>(bytes) ? size - static_cast<std::streamoff>(bytes) : 0);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

LocalExecutor::LocalExecutor(int jobs, int rank) : jobs_(jobs), rank_(rank) {}

LocalExecutor::~LocalExecutor() {
  StopAll();
  for (auto& [pid, child] : running_) ::waitpid(pid, nullptr, 0);
}

void LocalExecutor::Start(const RunJob& job) {
  std::filesystem::create_directories(std::filesystem::path(job.log).parent_path());
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("cannot start a run: fork failed");
  if (pid == 0) BecomeRun(job);
  running_[pid] = {job, UtcNow(), SteadyNow()};
}

std::vector<JobEnd> LocalExecutor::Poll() {
  std::vector<JobEnd> ended;
  for (auto it = running_.begin(); it != running_.end();) {
    int status = 0;
    if (::waitpid(it->first, &status, WNOHANG) != it->first) {
      ++it;
      continue;
    }
    const Child& c = it->second;
    JobEnd end{c.job.name, WIFEXITED(status) && WEXITSTATUS(status) == 0,
               false,      "",
               HostName(), c.started_utc,
               UtcNow(),   SteadyNow() - c.started,
               rank_};
    end.interrupted = stopping_ || AskedToStop(status);
    if (!end.completed) {
      const std::string said = Tail(c.job.log);
      end.error = (said.empty() ? "" : said + "\n") + EndOfProcess(status);
    }
    ended.push_back(end);
    it = running_.erase(it);
  }
  return ended;
}

void LocalExecutor::StopAll() {
  stopping_ = true;
  for (auto& [pid, child] : running_) ::kill(pid, SIGTERM);
}

void LocalExecutor::StopNow() {
  stopping_ = true;
  for (auto& [pid, child] : running_) ::kill(pid, SIGKILL);
}

}  // namespace sanet::study
