// Compiled as part of the net layer by tests/layers/upward_include_test.sh, which expects it to
// fail: net comes before sim, so sim's headers are not on net's include root.
#include "net/transport.h"  // a layer's own and lower headers are found
#include "sim/world.h"      // must not be found
