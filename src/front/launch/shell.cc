#include "launch/shell.h"

#include <cstdlib>

namespace sanet::launch {

int RunQuietly(const std::string& command) { return std::system((command + " >/dev/null 2>&1").c_str()); }

}  // namespace sanet::launch
