// The agent processes of a launch, watched while the run lasts: what each writes on stderr goes
// on to launch's own stderr, and its last line is kept (the agent's own word on why it ended);
// each is reaped when it ends, with the time and how. Launch's verdict on the run uses both.
#pragma once

#include <sys/types.h>

#include <functional>
#include <string>
#include <vector>

namespace sanet::launch {

struct AgentProcess {
  std::string robot;
  pid_t pid = -1;
  int stderr_fd = -1;      // the read end of its stderr's pipe (-1 once it is closed)
  std::string partial;     // a line it has not finished
  std::string last_line;   // its last line on stderr that was not blank
  bool ended = false;      // reaped
  bool stopped = false;    // ended by launch at the end of the run (SIGTERM), not on its own
  int status = 0;          // the wait status, once ended
  double ended_after = 0;  // s of wall time from the launch's start to its end, once ended on its own
};

class AgentProcesses {
 public:
  AgentProcesses();
  ~AgentProcesses();
  AgentProcesses(const AgentProcesses&) = delete;
  AgentProcesses& operator=(const AgentProcesses&) = delete;

  // Forks the agent with its stderr on a pipe; `exec` runs in the child and does not return.
  // Returns its pid.
  pid_t Start(const std::string& robot, const std::function<void()>& exec);
  // Passes on what the agents wrote and reaps those that ended on their own.
  void Watch();
  // Marks the agents still running as stopped by launch and returns their pids (StopChildren ends them).
  std::vector<pid_t> StillRunning();
  // Records how a stopped one ended, and passes on what the agents wrote last.
  void Stopped(pid_t pid, int status);
  const std::vector<AgentProcess>& agents() const { return agents_; }

 private:
  void Drain(AgentProcess& a);
  std::vector<AgentProcess> agents_;
  double started_;  // monotonic s
};

// "exited with status 1", "was killed by signal 9".
std::string HowItEnded(int wait_status);

}  // namespace sanet::launch
