// What both the replay (`sanet view`) and the live view serve: the page and its libraries.
#pragma once

#include <httplib.h>

#include <string>

namespace sanet::view {

// Throws std::runtime_error naming the Debian package when a library the page loads is missing.
void CheckLibraries(const std::string& javascript);
// "/" and the page's files, and "/lib/..." from `javascript` (Debian's /usr/share/javascript).
void AddPageRoutes(httplib::Server& server, const std::string& javascript);

}  // namespace sanet::view
