#!/usr/bin/env bash
# libretro_compile_check on the small collection beside this script: three presets that compile (two
# of them with names a folder's listing tells apart by a number), one missing a pass, one whose
# shader reads its own output of this frame. Usage: compile_check.sh TOOL
set -euo pipefail
tool="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
collection="$(cd "$(dirname "$0")" && pwd)/collection"
status=0
output=$("$tool" "$collection") || status=$?
echo "$output"
fail() { echo "FAILED: $1"; exit 1; }
[[ $status == 1 ]] || fail "exit status $status, not 1 (some presets do not compile)"
grep -qxF "5 presets, 3 compiled (2 shader files)" <<< "$output" || fail "the count line"
grep -qxF "| good | 3 | 3 |" <<< "$output" || fail "the good folder's row"
grep -qxF "| broken | 0 | 2 |" <<< "$output" || fail "the broken folder's row"
grep -qF "preset: pass 1 of 2 has no 'shader1 = FILE'" <<< "$output" || fail "the missing pass"
grep -qF "sampler 'PassOutput0' reads pass 0, which has not run when pass 0 runs" <<< "$output" || fail "the read of a pass not run yet"
grep -qF "e.g. broken/noncausal.slangp: reflection: $collection/shaders/noncausal.slang:" <<< "$output" || fail "the example names the preset and the shader"
"$tool" "$collection/good" > /dev/null || fail "a folder whose presets all compile exits 0"
# A relative folder: each kind of failure is still its message alone, with no piece of a path.
relative=$(cd "$collection/.." && "$tool" collection) || true
grep -qxF "    1  preset: pass 1 of 2 has no 'shader1 = FILE'" <<< "$relative" || fail "a kind of failure with a relative path"
status=0
"$tool" /nonexistent/folder 2> /dev/null || status=$?
[[ $status == 2 ]] || fail "a folder that is not there is a usage error (2), not $status"
echo "ok"
