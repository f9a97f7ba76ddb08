#include "launch/run_slot.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <vector>

#include "launch/shell.h"

namespace sanet::launch {
namespace {

namespace fs = std::filesystem;

// The slot a name made by a launch belongs to: sanetN followed by "br" (the bridge), "h<id>" (a
// veth's host end), "n<id>" (its other end, before it moves into its namespace) or "-<id>" (a
// namespace); nothing for any other name.
std::optional<int> SlotOfName(const std::string& name) {
  const std::string prefix = "sanet";
  if (name.rfind(prefix, 0) != 0) return std::nullopt;
  std::size_t at = prefix.size(), digits = 0;
  while (at + digits < name.size() && std::isdigit(static_cast<unsigned char>(name[at + digits]))) ++digits;
  if (digits == 0 || digits > 2) return std::nullopt;
  const std::string rest = name.substr(at + digits);
  const bool numbered = rest.size() > 1 && (rest[0] == 'h' || rest[0] == 'n' || rest[0] == '-') &&
                        std::all_of(rest.begin() + 1, rest.end(), [](char c) { return std::isdigit(c) != 0; });
  if (rest != "br" && !numbered) return std::nullopt;
  return std::stoi(name.substr(at, digits));
}

std::vector<std::string> Entries(const fs::path& folder) {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) names.push_back(entry.path().filename().string());
  return names;
}

// Slots with interfaces (in this namespace) or namespaces left behind, each with their names.
struct Leftovers {
  std::map<int, std::vector<std::string>> namespaces, interfaces;
};

Leftovers FindLeftovers() {
  Leftovers found;
  for (const std::string& name : Entries("/var/run/netns"))
    if (const auto slot = SlotOfName(name)) found.namespaces[*slot].push_back(name);
  for (const std::string& name : Entries("/sys/class/net"))
    if (const auto slot = SlotOfName(name)) found.interfaces[*slot].push_back(name);
  return found;
}

// Interfaces first (a namespace's veth pair goes with it only when the kernel frees the namespace,
// later), then the namespaces.
void RemoveLeftovers(int slot, const Leftovers& found) {
  std::string names;
  for (const auto* kind : {&found.interfaces, &found.namespaces})
    if (const auto it = kind->find(slot); it != kind->end())
      for (const std::string& name : it->second) names += " " + name;
  if (!names.empty()) std::printf("sanet: removing what a launch that died left behind:%s\n", names.c_str());
  if (const auto it = found.interfaces.find(slot); it != found.interfaces.end())
    for (const std::string& link : it->second)
      if (fs::exists("/sys/class/net/" + link)) RunQuietly("ip link del " + link);
  if (const auto it = found.namespaces.find(slot); it != found.namespaces.end())
    for (const std::string& ns : it->second) RunQuietly("ip netns del " + ns);
}

// The folder, made if need be and writable by every user (sticky, as /tmp), so that launches of
// different users see each other's locks.
void MakeLockFolder(const std::string& folder) {
  std::error_code error;
  if (fs::create_directories(folder, error)) ::chmod(folder.c_str(), 01777);
  if (!fs::is_directory(folder))
    throw std::runtime_error("cannot make the folder of launches' locks " + folder +
                             (error ? ": " + error.message() : ""));
}

// The slot's lock if it is free (a descriptor), else -1. Read access is enough for flock, so a
// lock file another user made serves as well.
int TryLock(const std::string& folder, int slot) {
  const std::string path = folder + "/slot-" + std::to_string(slot) + ".lock";
  int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0 && errno == EACCES) fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot open the launch lock " + path + ": " + std::strerror(errno));
  ::fchmod(fd, 0666);  // for other users' launches too (fails harmlessly on another user's file)
  if (::flock(fd, LOCK_EX | LOCK_NB) == 0) return fd;
  ::close(fd);
  return -1;
}

}  // namespace

std::string RunSlot::DefaultLockFolder() {
  return fs::is_directory("/run/lock") && ::access("/run/lock", W_OK) == 0 ? "/run/lock/sanet" : "/tmp/sanet-locks";
}

RunSlot RunSlot::Take(const std::string& lock_folder) {
  MakeLockFolder(lock_folder);
  const Leftovers found = FindLeftovers();
  std::optional<RunSlot> taken;
  for (int slot = 0; slot < kSlots; ++slot) {
    const bool left = found.namespaces.count(slot) > 0 || found.interfaces.count(slot) > 0;
    if (taken && !left) continue;
    const int fd = TryLock(lock_folder, slot);
    if (fd < 0) continue;  // a live launch's
    RemoveLeftovers(slot, found);
    if (!taken) {
      taken.emplace(RunSlot(slot, fd));
    } else {
      ::close(fd);  // cleaned, and free for the next launch
    }
  }
  if (!taken)
    throw std::runtime_error("all " + std::to_string(kSlots) + " launch slots are held by running launches (locks in " +
                             lock_folder + ")");
  return std::move(*taken);
}

RunSlot::RunSlot(RunSlot&& other) noexcept : number_(other.number_), fd_(other.fd_) { other.fd_ = -1; }

RunSlot::~RunSlot() {
  if (fd_ >= 0) ::close(fd_);
}

int RunSlot::UdpBase(int scenario_base, std::size_t nodes) const {
  const std::size_t stride = std::max<std::size_t>(256, nodes);
  const std::size_t base = static_cast<std::size_t>(scenario_base) + static_cast<std::size_t>(number_) * stride;
  if (base + nodes > 65536)
    throw std::runtime_error("loop.udp_port " + std::to_string(scenario_base) + ": launch " + std::to_string(number_) +
                             " on this machine would need UDP ports up to " + std::to_string(base + nodes - 1) +
                             "; give a lower loop.udp_port");
  return static_cast<int>(base);
}

}  // namespace sanet::launch
