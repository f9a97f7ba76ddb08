#include "hosting/controller_host.h"

#include "core/closest_names.h"
#include "core/exception_text.h"

namespace sanet::hosting {
namespace {

// "unknown controller 'x'", with the closest names and every one the registry knows.
std::string UnknownController(const std::string& name, const Registry& registry) {
  std::vector<std::string> known;
  for (const ControllerInfo* c : registry.List()) known.push_back(c->name);
  std::string text = "unknown controller '" + name + "'";
  if (const auto close = ClosestNames(name, known); !close.empty()) text += "; did you mean " + OrList(close) + "?";
  std::string list;
  for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
  if (name.find(':') != std::string::npos) text += "; a Python controller is `python: " + name + "`, not `name:`";
  return text + " (known here: " + (list.empty() ? "none" : list) +
         "; a controller of your own comes from its library, named in `library:`; `sanet list` shows them all)";
}

}  // namespace

std::unique_ptr<Controller> MakeController(const ControllerSpec& spec, Registry& registry) {
  if (!spec.library.empty()) registry.LoadLibrary(spec.library);
  if (!spec.python.empty()) registry.LoadPython(spec);
  const ControllerInfo* info = registry.Find(spec.name);
  if (!info) throw RegistryError(UnknownController(spec.name, registry));
  std::unique_ptr<Controller> controller;
  try {
    controller = info->create(spec.params);
  } catch (const std::exception&) {
    throw;  // ParamError and the like: the loader names the field
  } catch (...) {
    throw RegistryError("controller '" + spec.name + "' could not be made: " + CurrentExceptionText());
  }
  spec.params.CheckAllUsed();
  return controller;
}

ControllerHost::ControllerHost(Node& node, std::unique_ptr<Controller> controller, double rate,
                               MessageImpairments impairments, std::uint64_t seed, HostClock& clock, Hooks hooks)
    : node_(node),
      controller_(std::move(controller)),
      rate_(rate),
      impairments_(impairments),
      impairment_stream_(seed, "messages/impairments/" + node.Name()),
      clock_(clock),
      hooks_(std::move(hooks)) {}

// Runs one call into the controller; whatever it throws (a std::exception or anything else) ends
// its run, reported once.
template <typename Call>
void ControllerHost::Guard(const char* where, Call call) {
  if (!running()) return;
  try {
    call();
  } catch (...) {
    failed_ = true;
    if (hooks_.failed)
      hooks_.failed("controller of " + node_.Name() + " failed" + where + ": " + CurrentExceptionText());
  }
}

// A switched-off node's controller finishes too (its statistics are the run's).
void ControllerHost::Finish() {
  if (!controller_ || failed_ || !started_) return;
  off_ = false;
  Guard(" to finish", [&] { controller_->Finish(node_); });
  off_ = true;
}

void ControllerHost::Start() {
  started_ = true;
  Guard(" to start", [&] { controller_->Start(node_); });
}

void ControllerHost::Step() {
  Guard("", [&] { controller_->ControlStep(node_); });
}

void ControllerHost::Receive(const Message& m) {
  if (impairments_.loss > 0 && impairment_stream_.Uniform() < impairments_.loss) {
    if (hooks_.dropped) hooks_.dropped(m);
    return;
  }
  if (impairments_.delay <= 0) return Deliver(m);
  clock_.After(impairments_.delay, [this, later = m]() mutable {
    later.time_received = clock_.Now();
    Deliver(later);
  });
}

void ControllerHost::Deliver(const Message& m) {
  if (hooks_.delivered) hooks_.delivered(m);
  Guard(" on a message", [&] { controller_->OnMessage(node_, m); });
}

}  // namespace sanet::hosting
