#include "trace/png_export.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <vector>

extern char** environ;

namespace sanet::trace {
namespace {

// Runs a program found on PATH with its output discarded; its exit status (-1 if not started).
int RunQuietly(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t quiet;
  posix_spawn_file_actions_init(&quiet);
  posix_spawn_file_actions_addopen(&quiet, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&quiet, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int started = posix_spawnp(&pid, argv[0], &quiet, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&quiet);
  if (started != 0) return -1;
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

bool PngExportAvailable() { return RunQuietly({"rsvg-convert", "--version"}) == 0; }

bool SvgToPng(const std::string& svg, const std::string& png, double scale) {
  return RunQuietly({"rsvg-convert", "--zoom", std::to_string(scale), "--format", "png", "--output", png, svg}) == 0;
}

}  // namespace sanet::trace
