#!/usr/bin/env bash
# A layer cannot include a header of a layer above it: compiling a net file that includes a sim
# header must fail because sim's headers are not on net's include root (and for no other reason).
set -u
build="$1"
out=$(cmake --build "$build" --target sanet_upward_include_probe 2>&1)
if [ $? -eq 0 ]; then
  echo "FAIL: a net file that includes sim/world.h compiled"
  exit 1
fi
# gcc and clang (the sanitize build) say it differently.
if ! grep -qE "sim/world.h: No such file or directory|'sim/world.h' file not found" <<<"$out"; then
  echo "FAIL: the probe failed for another reason:"
  echo "$out" | tail -20
  exit 1
fi
if grep -qE "net/transport.h: No such file|'net/transport.h' file not found" <<<"$out"; then
  echo "FAIL: net's own headers were not found"
  exit 1
fi
echo "ok: net cannot include sim/world.h"

# The agent's layer cannot include the robot server's headers (nor does it link its library).
out=$(cmake --build "$build" --target sanet_agent_server_probe 2>&1)
if [ $? -eq 0 ]; then
  echo "FAIL: an agent file that includes robot_server/sim_server.h compiled"
  exit 1
fi
if ! grep -qE "robot_server/sim_server.h: No such file or directory|'robot_server/sim_server.h' file not found" <<<"$out"; then
  echo "FAIL: the agent probe failed for another reason:"
  echo "$out" | tail -20
  exit 1
fi
if grep -qE "remote_agent/remote_node.h: No such file|'remote_agent/remote_node.h' file not found" <<<"$out"; then
  echo "FAIL: the agent's own headers were not found"
  exit 1
fi
echo "ok: the agent cannot include robot_server/sim_server.h"

# Front ends reach a running world through sim/driver.h only: none includes the assembly, nor
# World and the stepper and outputs behind it.
front_ends="wire robot_server remote_agent launch wss view"
found=""
for layer in $front_ends; do
  found+=$(grep -rlE '#include "sim/(assembly|stepper|outputs|world)\.h"' "$(dirname "$0")/../../src/$layer" || true)
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
check_private "ns3/" "/src/net/" "/src/sim/"
check_private "ode/" "/src/physics/ode/"
check_private "box2d/" "/src/physics/box2d/"
check_private "yaml-cpp/" "/src/scenario/"
check_private "mpi.h" "/src/study/"
check_private "plplot/" "/src/study/"
check_private "openssl/" "/src/wire/"
echo "ok: ns-3, ODE, Box2D, yaml-cpp, MPI, PLplot and OpenSSL stay in their layers"
