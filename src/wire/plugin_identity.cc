#include "wire/plugin_identity.h"

#include <openssl/evp.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "sanet/plugin.h"
#include "wire/message_lines.h"

namespace sanet::hil {
namespace {

std::string Sha256OfFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read the controller library " + path + ": " + std::strerror(errno));
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

}  // namespace

PluginIdentity IdentifyPlugin(const sim::ControllerSpec& controller) {
  PluginIdentity id;
  id.controller_api = SANET_CONTROLLER_API_VERSION;
  if (controller.library.empty()) return id;
  id.library = controller.library;
  id.sha256 = Sha256OfFile(controller.library);
  return id;
}

std::string PluginDifference(const PluginIdentity& server, const PluginIdentity& agent) {
  if (server.controller_api != agent.controller_api)
    return "controller interface version: the server's " + std::to_string(server.controller_api) + ", this agent's " +
           std::to_string(agent.controller_api);
  if (server.library.empty() != agent.library.empty())
    return server.library.empty() ? "the server runs a built-in controller, this agent the library " + agent.library
                                  : "the server runs the library " + server.library + ", this agent a built-in one";
  if (server.sha256 != agent.sha256)
    return "controller library: the server's " + server.library + " has SHA-256 " + server.sha256.substr(0, 16) +
           "..., this computer's " + agent.library + " " + agent.sha256.substr(0, 16) +
           "... (install the server's build of it, or point --library at it)";
  return "";
}

}  // namespace sanet::hil
