#include "wire/plugin_identity.h"

#include <openssl/evp.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "sanet/plugin.h"
#include "wire/message_lines.h"

namespace sanet::wire {
namespace {

std::string Sha256OfFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read the controller's file " + path + ": " + std::strerror(errno));
  EVP_MD_CTX* context = EVP_MD_CTX_new();
  EVP_DigestInit_ex(context, EVP_sha256(), nullptr);
  std::vector<char> chunk(1 << 16);
  while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0)
    EVP_DigestUpdate(context, chunk.data(), static_cast<std::size_t>(in.gcount()));
  Bytes digest(EVP_MAX_MD_SIZE);
  unsigned int length = 0;
  EVP_DigestFinal_ex(context, digest.data(), &length);
  EVP_MD_CTX_free(context);
  digest.resize(length);
  return ToHex(digest);
}

// The file a Python module "a.b" is in: a/b.py or a/b/__init__.py under the first folder that
// has one, as Python's import finds it; "" when none does.
std::string ModuleFile(const sim::ControllerSpec& controller) {
  std::string relative = controller.python.substr(0, controller.python.find(':'));
  for (char& c : relative)
    if (c == '.') c = '/';
  std::vector<std::string> folders = controller.python_path;
  if (const char* env = std::getenv("PYTHONPATH"))  // where Python looks next, for both sides
    for (std::string rest = env; !rest.empty();) {
      const auto colon = rest.find(':');
      folders.push_back(rest.substr(0, colon));
      rest = colon == std::string::npos ? "" : rest.substr(colon + 1);
    }
  for (const std::string& folder : folders)
    for (const std::string& candidate : {folder + "/" + relative + ".py", folder + "/" + relative + "/__init__.py"})
      if (std::filesystem::is_regular_file(candidate)) return std::filesystem::canonical(candidate).string();
  return "";
}

}  // namespace

PluginIdentity IdentifyPlugin(const sim::ControllerSpec& controller) {
  PluginIdentity id;
  id.controller_api = SANET_CONTROLLER_API_VERSION;
  id.python = controller.python;
  id.library = controller.python.empty() ? controller.library : ModuleFile(controller);
  if (!id.library.empty()) id.sha256 = Sha256OfFile(id.library);
  return id;
}

namespace {

std::string PythonDifference(const PluginIdentity& server, const PluginIdentity& agent) {
  if (agent.library.empty() && !server.library.empty())
    return "this agent finds no module '" + server.python.substr(0, server.python.find(':')) +
           "' (in --python-path's folders or on PYTHONPATH): give --python-path the folder that holds the server's " +
           server.library;
  if (server.sha256 != agent.sha256)
    return "Python module: the server's " + server.library + " has SHA-256 " + server.sha256.substr(0, 16) +
           "..., this computer's " + agent.library + " " + agent.sha256.substr(0, 16) +
           "... (copy the server's file here, or point --python-path at it)";
  return "";
}

}  // namespace

std::string PluginDifference(const PluginIdentity& server, const PluginIdentity& agent) {
  if (server.controller_api != agent.controller_api)
    return "controller interface version: the server's " + std::to_string(server.controller_api) + ", this agent's " +
           std::to_string(agent.controller_api);
  if (server.python != agent.python)
    return "Python controller: the server's '" + server.python + "', this agent's '" + agent.python + "'";
  if (!server.python.empty()) return PythonDifference(server, agent);
  if (server.library.empty() != agent.library.empty())
    return server.library.empty() ? "the server runs a built-in controller, this agent the library " + agent.library
                                  : "the server runs the library " + server.library + ", this agent a built-in one";
  if (server.sha256 != agent.sha256)
    return "controller library: the server's " + server.library + " has SHA-256 " + server.sha256.substr(0, 16) +
           "..., this computer's " + agent.library + " " + agent.sha256.substr(0, 16) +
           "... (install the server's build of it, or point --library at it)";
  return "";
}

}  // namespace sanet::wire
