// What both the replay (`sanet view`) and the live view serve: the page and its libraries.
#pragma once

#include <httplib.h>

#include <string>

namespace sanet::view {

// Throws std::runtime_error naming the Debian package when a library the page loads is missing.
void CheckLibraries(const std::string& javascript);
// "/" and the page's files, and "/lib/..." from `javascript` (Debian's /usr/share/javascript).
void AddPageRoutes(httplib::Server& server, const std::string& javascript);

// cpp-httplib's default socket options include SO_REUSEPORT, with which a second process would
// listen on the same port and share its connections: only SO_REUSEADDR, so that a port in use is
// an error.
void ListenAlone(httplib::Server& server);

}  // namespace sanet::view
