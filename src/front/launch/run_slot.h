// One launch's share of the machine, so that any number of launches run side by side: a slot
// number N, held through a lock file for the launch's life (flock: the kernel frees it when the
// process ends, also by SIGKILL), that gives the launch names and numbers no other live launch has:
// its bridge's subnet 10.77.N.0/24, its interfaces' and namespaces' names (sanetN...), a DDS
// domain for its ROS 2 face and, without namespaces, its agents' UDP ports on loopback.
// Interfaces and namespaces named after a slot whose lock is free belong to a run that died: taking
// slots removes them, so they are never reused.
#pragma once

#include <cstdint>
#include <string>

namespace sanet::launch {

class RunSlot {
 public:
  static constexpr int kSlots = 100;  // launches at once on one machine
  // Where the lock files live: /run/lock/sanet (tmpfs, emptied at boot), else /tmp/sanet-locks.
  static std::string DefaultLockFolder();

  // Takes the lowest free slot and removes what dead runs left behind under any free slot's names.
  // Throws std::runtime_error when every slot is held or the lock folder cannot be used.
  static RunSlot Take(const std::string& lock_folder = DefaultLockFolder());

  RunSlot(RunSlot&& other) noexcept;
  RunSlot& operator=(RunSlot&&) = delete;
  RunSlot(const RunSlot&) = delete;
  ~RunSlot();  // releases the lock

  int number() const { return number_; }
  // The names of this slot's interfaces and namespaces all start with this (at most 8 characters,
  // so that interface names stay within Linux's 15).
  std::string NamePrefix() const { return NamePrefix(number_); }
  static std::string NamePrefix(int slot) { return "sanet" + std::to_string(slot); }
  std::string Subnet() const { return "10.77." + std::to_string(number_); }  // node i is Subnet().(i+1)
  std::string ServerAddress() const { return Subnet() + ".254"; }
  // ROS 2 calls domains 0 to 101 safe on Linux (their ports stay below the ephemeral range); the
  // slots take them from the top down, away from 0 and the low numbers people set by hand.
  int DdsDomain() const { return 101 - number_; }
  // The first of this slot's UDP ports for `nodes` agents on loopback, from the scenario's
  // loop.udp_port; throws std::runtime_error past 65535.
  int UdpBase(int scenario_base, std::size_t nodes) const;

 private:
  RunSlot(int number, int fd) : number_(number), fd_(fd) {}
  int number_;
  int fd_;
};

}  // namespace sanet::launch
