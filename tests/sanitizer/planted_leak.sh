#!/usr/bin/env bash
# usage: planted_leak.sh PFX-RENDER BROKEN_LEAKS_MEMORY.so LSAN.SUPP
# Runs the sanitized pfx-render over the leaking fixture with the sanitizer pass's own LeakSanitizer
# settings and suppressions, and expects exactly the planted leak: one report, 12345 bytes, named
# by the fixture's function. Its reports go to a folder of its own, not to the pass's.
set -u
render=$1 plugin=$2 suppressions=$3
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/plugins"
cp "$plugin" "$scratch/plugins/"

ASAN_OPTIONS="log_path=$scratch/asan:detect_leaks=1" \
LSAN_OPTIONS="use_tls=0:print_suppressions=0:suppressions=$suppressions" \
  "$render" --plugins "$scratch/plugins" --demo-image --size 32x24 --chain broken_leaks_memory \
            --out "$scratch/out.exr" > "$scratch/stdout" 2>&1
status=$?
reports=("$scratch"/asan.*)
fail() { echo "FAIL: $*"; cat "$scratch/stdout"; cat "$scratch"/asan.* 2>/dev/null; exit 1; }

[[ -f "$scratch/out.exr" ]] || fail "pfx-render did not render the frame (exit $status)"
[[ $status -ne 0 ]] || fail "pfx-render exited 0: LeakSanitizer did not fail the run"
[[ -f "${reports[0]}" && ${#reports[@]} -eq 1 ]] || fail "expected one LeakSanitizer report, found ${#reports[@]}"
grep -q "Direct leak of 12345 byte(s) in 1 object(s) allocated" "${reports[0]}" || fail "the planted leak is not reported"
grep -q "planted_leak" "${reports[0]}" || fail "the report does not name the fixture's planted_leak"
grep -q "SUMMARY: AddressSanitizer: 12345 byte(s) leaked in 1 allocation(s)" "${reports[0]}" ||
  fail "more than the planted leak was reported (a driver leak tests/lsan.supp does not cover?)"
echo "pass: the planted leak (12345 bytes in planted_leak) fails the run (exit $status), nothing else is reported"
