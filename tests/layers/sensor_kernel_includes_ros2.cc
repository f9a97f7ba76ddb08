// Compiled as part of the sensors layer by tests/layers/upward_include_test.sh, which expects it
// to fail: a sensor kind's kernel part cannot include its ROS 2 part (sensors/<kind>/*_ros2.h,
// layer sim), though both sit in the kind's folder.
#include "sensors/laser/laser_ros2.h"  // must not be found
#include "sensors/range_fan.h"         // the kernel part's own headers are found
