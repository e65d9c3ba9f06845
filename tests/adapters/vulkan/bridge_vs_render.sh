#!/bin/sh
# The bridge's C test program against pfx-render: pfx-render runs CHAIN over IN.png into the
# expected picture, then bridge_c_test runs the same chain over the same picture in a VkImage
# through the bridge and compares (bridge_c_test.c says how).
#   bridge_vs_render.sh PFX_RENDER BRIDGE_C_TEST PLUGIN_DIR IN.png CHAIN rgba|bgra|a2b10g10r10|a2r10g10b10 shared|host WORK_DIR [SET]
# SET: one "effect.param=value" assignment, given to both.
set -eu
render=$1 program=$2 plugins=$3 input=$4 chain=$5 order=$6 path=$7 work=$8 set=${9:-}
mkdir -p "$work"
expected="$work/expected-$chain.png"
if [ "$chain" = none ]; then
  expected=$input
elif [ -n "$set" ]; then
  "$render" --plugins "$plugins" --input "$input" --chain "$chain" --set "$set" --out "$expected"
  exec "$program" "$input" "$expected" "$plugins" "$chain" "$order" "$path" "$set"
else
  "$render" --plugins "$plugins" --input "$input" --chain "$chain" --out "$expected"
fi
exec "$program" "$input" "$expected" "$plugins" "$chain" "$order" "$path"
