// Compiled as part of the sim layer by tests/layers/upward_include_test.sh, which expects it to
// fail: the kernel knows no ROS 2 message layout (those come after sim, in ros2msg and
// ros2_presentation, which turn the run's events into ROS 2 messages).
#include "ros2msg/codec.h"  // must not be found
#include "sim/driver.h"     // sim's own headers are found
