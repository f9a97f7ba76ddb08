#!/usr/bin/env bash
# A layer cannot include a header of a layer above it: compiling a net file that includes a sim
# header must fail because sim's headers are not on net's include root (and for no other reason).
set -u
build="$1"

# expect_not_found PROBE_TARGET LAYER FORBIDDEN_HEADER OWN_HEADER: the probe must fail to compile
# because FORBIDDEN_HEADER is not on LAYER's include root, and for no other reason.
expect_not_found() {
  local target=$1 layer=$2 forbidden=$3 own=$4 out
  out=$(cmake --build "$build" --target "$target" 2>&1)
  if [ $? -eq 0 ]; then
    echo "FAIL: a $layer file that includes $forbidden compiled"
    exit 1
  fi
  # gcc and clang (the sanitize build) say it differently.
  if ! grep -qE "$forbidden: No such file or directory|'$forbidden' file not found" <<<"$out"; then
    echo "FAIL: the $layer probe failed for another reason:"
    echo "$out" | tail -20
    exit 1
  fi
  if grep -qE "$own: No such file|'$own' file not found" <<<"$out"; then
    echo "FAIL: $layer's own headers were not found"
    exit 1
  fi
  echo "ok: $layer cannot include $forbidden"
}

expect_not_found sanet_upward_include_probe net sim/world.h net/transport.h
# The agent's layer cannot include the robot server's headers (nor does it link its library:
# checked when configuring).
expect_not_found sanet_agent_server_probe usarsim_agent robot_server/sim_server.h usarsim_agent/remote_node.h
# sim never sees the scenario's sections for front ends (loop, spawn).
expect_not_found sanet_sim_section_probe sim sections/spawn_section.h sim/driver.h
# sim knows no ROS 2 message: the run's events become ROS 2 messages in ros2_presentation, above it.
expect_not_found sanet_sim_ros2msg_probe sim ros2msg/codec.h sim/driver.h
# A sensor kind's folder holds files of several layers; each layer sees only its own and those
# below (src/CMakeLists.txt, sanet_part_links): the kernel part cannot include the ROS 2 part.
expect_not_found sanet_sensor_part_probe sensors sensors/laser/laser_ros2.h sensors/range_fan.h
# ... and no sim file includes a ROS 2 header at all (nor its generated messages).
if grep -rlE '#include "(ros2msg|ros2_presentation)/' "$(dirname "$0")/../../src/kernel/sim"; then
  echo "FAIL: sim includes ROS 2 messages"
  exit 1
fi
echo "ok: sim includes nothing of ros2msg or ros2_presentation"

# Front ends reach a running world through sim/driver.h only: none includes the assembly, nor
# World and the stepper and outputs behind it.
front_ends="wire robot_server usarsim_agent launch wss view foxglove ros2_face ros2_agent python_controllers"
found=""
for layer in $front_ends; do
  found+=$(grep -rlE '#include "sim/(assembly|stepper|outputs|world)\.h"' "$(dirname "$0")/../../src/front/$layer" || true)
done
if [ -n "$found" ]; then
  echo "FAIL: front ends include the assembly, World, the stepper or the outputs: $found"
  exit 1
fi
echo "ok: front ends ($front_ends) include no sim/assembly.h, stepper.h, outputs.h or world.h"

# The libraries sanet keeps private are system headers here: check that only their layers
# include them.
src="$(dirname "$0")/../../src"
check_private() {  # check_private PATTERN ALLOWED_DIRS...
  local pattern=$1; shift
  local found
  found=$(grep -rlE "#include <$pattern" "$src" | grep -vE "$(printf '%s|' "$@" | sed 's/|$//')" || true)
  if [ -n "$found" ]; then
    echo "FAIL: <$pattern...> included outside $*: $found"
    exit 1
  fi
}
check_private "ns3/" "/src/kernel/net/" "/src/kernel/energy/" "/src/kernel/sim/"
check_private "ode/" "/src/kernel/physics/ode/"
check_private "box2d/" "/src/kernel/physics/box2d/"
check_private "yaml-cpp/" "/src/kernel/scenario/"
check_private "mpi.h" "/src/kernel/study/"
check_private "plplot/" "/src/kernel/study/"
check_private "openssl/" "/src/front/wire/"
echo "ok: ns-3, ODE, Box2D, yaml-cpp, MPI, PLplot and OpenSSL stay in their layers"
