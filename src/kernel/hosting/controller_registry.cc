#include "hosting/controller_registry.h"

#include <dlfcn.h>

#include "core/exception_text.h"
#include "sanet/plugin.h"

namespace sanet::hosting {

void Registry::Add(ControllerInfo info) {
  if (info.name.empty() || !info.create) throw RegistryError("a controller needs a name and a factory");
  if (controllers_.count(info.name)) throw RegistryError("controller '" + info.name + "' is registered twice");
  controllers_.emplace(info.name, std::move(info));
}

const ControllerInfo* Registry::Find(const std::string& name) const {
  auto it = controllers_.find(name);
  return it == controllers_.end() ? nullptr : &it->second;
}

std::vector<const ControllerInfo*> Registry::List() const {
  std::vector<const ControllerInfo*> out;
  for (const auto& [name, info] : controllers_) out.push_back(&info);
  return out;
}

std::vector<std::string> Registry::LoadLibrary(const std::string& path) {
  if (auto it = loaded_.find(path); it != loaded_.end()) return it->second;
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw RegistryError(std::string("cannot load controller library: ") + dlerror());
  using VersionFn = int (*)();
  using RegisterFn = void (*)(ControllerRegistry&);
  auto version = reinterpret_cast<VersionFn>(dlsym(handle, "sanet_controller_api_version"));
  auto registrar = reinterpret_cast<RegisterFn>(dlsym(handle, "sanet_register_controllers"));
  if (!version || !registrar) {
    dlclose(handle);
    throw RegistryError(path + " is not a sanet controller library (no SANET_CONTROLLER_PLUGIN entry point)");
  }
  if (version() != SANET_CONTROLLER_API_VERSION) {
    const int v = version();
    dlclose(handle);
    throw RegistryError(path + " was built against controller API version " + std::to_string(v) +
                        ", this sanet has version " + std::to_string(SANET_CONTROLLER_API_VERSION) + ": rebuild it");
  }
  const auto before = controllers_;
  try {
    registrar(*this);
  } catch (...) {
    controllers_ = before;
    throw RegistryError(path + ": " + CurrentExceptionText());
  }
  std::vector<std::string> added;
  for (const auto& [name, info] : controllers_)
    if (!before.count(name)) added.push_back(name);
  loaded_[path] = added;
  return added;
}

void Registry::LoadPython(const ControllerSpec& spec) {
  if (controllers_.count(spec.name)) return;
  if (!python_.load)
    throw RegistryError("Python controller '" + spec.python + "': this sanet was built without Python support");
  Add(python_.load(spec));
}

void Registry::StartRun(std::uint64_t seed) const {
  if (python_.start_run) python_.start_run(seed);
}

}  // namespace sanet::hosting
