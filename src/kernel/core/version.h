// Which sanet this is: its version and the git commit it was built from ("-modified" when the
// checkout had uncommitted changes). Generated at build time (cmake/version_info.cmake).
#pragma once

namespace sanet {

const char* SanetVersion();
const char* SanetCommit();

}  // namespace sanet
