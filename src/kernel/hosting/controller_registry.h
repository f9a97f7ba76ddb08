// The controllers sanet knows by name: the built-in ones and those of libraries loaded from
// scenarios.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "hosting/controller_spec.h"
#include "sanet/controller.h"

namespace sanet::hosting {

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

  // Controllers in Python (the python layer installs how they are made, so that this layer
  // needs no interpreter): `load` imports a spec's module and describes its class; `start_run`
  // seeds what Python holds for the whole process (random, numpy) from a run's seed.
  struct PythonSupport {
    std::function<ControllerInfo(const ControllerSpec& spec)> load;
    std::function<void(std::uint64_t seed)> start_run;
  };
  void SetPythonSupport(PythonSupport support) { python_ = std::move(support); }
  // Registers the spec's Python controller under its name, once. Throws RegistryError when this
  // sanet has no Python support, or saying what is wrong with the module (a syntax error with
  // its file and line, a missing module or class).
  void LoadPython(const ControllerSpec& spec);
  // A run's controllers are about to be made: languages with process-wide random generators
  // seed them from the run's seed, so that the same seed gives the same run.
  void StartRun(std::uint64_t seed) const;

 private:
  std::map<std::string, ControllerInfo> controllers_;
  std::map<std::string, std::vector<std::string>> loaded_;  // path -> names it registered
  PythonSupport python_;
};

}  // namespace sanet::hosting
