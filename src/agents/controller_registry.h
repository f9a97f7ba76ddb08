// The controllers sanet knows by name: the built-in ones and those of libraries loaded from
// scenarios.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "sanet/controller.h"

namespace sanet::agents {

class RegistryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Registry : public ControllerRegistry {
 public:
  void Add(ControllerInfo info) override;
  const ControllerInfo* Find(const std::string& name) const;
  std::vector<const ControllerInfo*> List() const;

  // Loads a controller library once (later calls with the same path do nothing) and returns the
  // names it registered. Throws RegistryError saying what is wrong with the file. Libraries stay
  // loaded for the life of the process: controllers may still hold their code.
  std::vector<std::string> LoadLibrary(const std::string& path);

 private:
  std::map<std::string, ControllerInfo> controllers_;
  std::map<std::string, std::vector<std::string>> loaded_;  // path -> names it registered
};

}  // namespace sanet::agents
