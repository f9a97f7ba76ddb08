#!/usr/bin/env bash
# A controller library built out of tree, against an installed sanet, drives a robot.
#   out_of_tree_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1
build_dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cmake --install "$build_dir" --prefix "$tmp/prefix" > /dev/null
cmake -S "$source_dir/examples/plugin" -B "$tmp/plugin" -DCMAKE_PREFIX_PATH="$tmp/prefix" > /dev/null
cmake --build "$tmp/plugin" > /dev/null
library=$(find "$tmp/plugin" -name 'libdrive_to.so')
sanet=$tmp/prefix/bin/sanet

# The library lists its controller, with the parameters it reads.
"$sanet" list --library "$library" > "$tmp/list.txt"
grep -q "drive_to" "$tmp/list.txt"
grep -Eq "^ +speed +number, default 0.4, in \[0.01, 5\]" "$tmp/list.txt" || { cat "$tmp/list.txt"; exit 1; }

cat > "$tmp/scenario.yaml" <<YAML
duration: 40
nodes:
  - name: robot
    model: diffdrive
    pose: [0, 0, 0]
    controller:
      name: drive_to
      library: plugin/$(basename "$library")
      params: {goal: [4, -3], speed: 0.5}
YAML
"$sanet" run "$tmp/scenario.yaml" -o "$tmp/results" -q

python3 - "$tmp/results" <<'PY'
import csv, math, sys
rows = [r for r in csv.DictReader(open(sys.argv[1] + "/trajectories.csv")) if r["node"] == "robot"]
x, y = float(rows[-1]["x"]), float(rows[-1]["y"])
assert math.hypot(x - 4, y + 3) < 0.5, f"the plugin's robot ended at ({x}, {y}), not at (4, -3)"
assert "robot,arrived" in open(sys.argv[1] + "/log.csv").read(), "no arrival logged"
steps = [(r["from"], r["to"]) for r in csv.DictReader(open(sys.argv[1] + "/transitions.csv"))]
assert steps[-1][1] == "arrived" and ("start", "turning") in steps, f"transitions: {steps}"
metrics = list(csv.DictReader(open(sys.argv[1] + "/metrics.csv")))
assert [m["name"] for m in metrics] == ["travel_time"] and float(metrics[0]["value"]) > 1, metrics
print(f"robot ended at ({x:.2f}, {y:.2f})")
PY

# The same library built without installing sanet, against its build folder's package.
cmake -S "$source_dir/examples/plugin" -B "$tmp/plugin-uninstalled" -Dsanet_DIR="$build_dir" > /dev/null
cmake --build "$tmp/plugin-uninstalled" > /dev/null
"$build_dir/sanet" list --library "$tmp/plugin-uninstalled/libdrive_to.so" > "$tmp/list-uninstalled.txt"
grep -q "drive_to" "$tmp/list-uninstalled.txt" ||
  { echo "the library built against the build folder does not load"; exit 1; }

# An unknown parameter of the library's controller is reported with its line.
sed 's/speed: 0.5}/speed: 0.5, sped: 1}/' "$tmp/scenario.yaml" > "$tmp/bad.yaml"
set +e
message=$("$sanet" validate "$tmp/bad.yaml" 2>&1)
status=$?
set -e
[ "$status" -eq 2 ] || { echo "validate exited $status: $message"; exit 1; }
echo "$message" | grep -q "bad.yaml:9: 'nodes\[0\].controller.params.sped': unknown parameter 'sped'" ||
  { echo "unexpected message: $message"; exit 1; }
echo "out-of-tree plugin: ok"
