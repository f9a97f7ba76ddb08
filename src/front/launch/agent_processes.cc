#include "launch/agent_processes.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <stdexcept>

namespace sanet::launch {
namespace {

double Now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

}  // namespace

std::string HowItEnded(int wait_status) {
  if (WIFEXITED(wait_status)) return "exited with status " + std::to_string(WEXITSTATUS(wait_status));
  if (WIFSIGNALED(wait_status)) return "was killed by signal " + std::to_string(WTERMSIG(wait_status));
  return "ended";
}

AgentProcesses::AgentProcesses() : started_(Now()) {}

AgentProcesses::~AgentProcesses() {
  for (AgentProcess& a : agents_)
    if (a.stderr_fd >= 0) ::close(a.stderr_fd);
}

pid_t AgentProcesses::Start(const std::string& robot, const std::function<void()>& exec) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("cannot make a pipe for agent " + robot + "'s stderr");
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(fds[1], STDERR_FILENO);  // dup2 clears close-on-exec on the copy
    exec();
  }
  ::close(fds[1]);
  ::fcntl(fds[0], F_SETFL, O_NONBLOCK);
  AgentProcess a;
  a.robot = robot;
  a.pid = pid;
  a.stderr_fd = fds[0];
  agents_.push_back(std::move(a));
  return pid;
}

// Whole lines go on to launch's stderr as they come; the last that is not blank is kept.
void AgentProcesses::Drain(AgentProcess& a) {
  char buffer[4096];
  while (a.stderr_fd >= 0) {
    const ssize_t n = ::read(a.stderr_fd, buffer, sizeof buffer);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;
    if (n <= 0) {  // every writer has closed it
      ::close(a.stderr_fd);
      a.stderr_fd = -1;
      if (!a.partial.empty()) a.partial += '\n';
    } else {
      a.partial.append(buffer, static_cast<std::size_t>(n));
    }
    for (std::size_t end; (end = a.partial.find('\n')) != std::string::npos; a.partial.erase(0, end + 1)) {
      const std::string line = a.partial.substr(0, end);
      std::fprintf(stderr, "%s\n", line.c_str());
      if (line.find_first_not_of(" \t\r") != std::string::npos) a.last_line = line;
    }
  }
}

void AgentProcesses::Watch() {
  for (AgentProcess& a : agents_) {
    Drain(a);
    if (a.ended || ::waitpid(a.pid, &a.status, WNOHANG) != a.pid) continue;
    a.ended = true;
    a.ended_after = Now() - started_;
    // At the run's end an agent exits 0 (the server ended it); otherwise the run has lost its robot.
    if (!WIFEXITED(a.status) || WEXITSTATUS(a.status) != 0)
      std::fprintf(stderr,
                   "sanet: the agent of %s %s: the run goes on without %s and will end failed (Ctrl-C ends it "
                   "now, with its results)\n",
                   a.robot.c_str(), HowItEnded(a.status).c_str(), a.robot.c_str());
  }
  std::fflush(stderr);
}

std::vector<pid_t> AgentProcesses::StillRunning() {
  Watch();
  std::vector<pid_t> running;
  for (AgentProcess& a : agents_)
    if (!a.ended) a.stopped = true, running.push_back(a.pid);
  return running;
}

void AgentProcesses::Stopped(pid_t pid, int status) {
  for (AgentProcess& a : agents_) {
    if (a.pid != pid) continue;
    a.ended = true;
    a.status = status;
    Drain(a);
  }
  std::fflush(stderr);
}

}  // namespace sanet::launch
