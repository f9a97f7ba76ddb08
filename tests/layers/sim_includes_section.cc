// Compiled as part of the sim layer by tests/layers/upward_include_test.sh, which expects it to
// fail: the scenario's sections for front ends (loop, spawn) come after sim, which never sees them.
#include "sections/spawn_section.h"  // must not be found
#include "sim/driver.h"              // sim's own headers are found
