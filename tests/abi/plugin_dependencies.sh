#!/usr/bin/env bash
# Checks that plugin libraries depend on nothing but the C and C++ runtimes (GL comes through the
# host, never a GL or window-system library) and export exactly one symbol, pfx_get_entry.
#
# usage: plugin_dependencies.sh READELF PATH...
#   a PATH that is a directory contributes every *.so in it (found now, at test time, so a new
#   plugin is checked without touching this test); a PATH that is a file must exist.
# Fails when a check fails, a PATH is missing, or no plugin was found at all.
set -u -o pipefail

readelf=$1
shift
status=0
plugins=()
declare -A seen

for path in "$@"; do
  if [[ -d $path ]]; then
    for file in "$path"/*.so; do
      [[ -f $file ]] && plugins+=("$file")
    done
  elif [[ -f $path ]]; then
    plugins+=("$path")
  else
    echo "FAIL: $path does not exist"
    status=1
  fi
done

if (( ${#plugins[@]} == 0 )); then
  echo "FAIL: no plugin libraries found in: $*"
  exit 1
fi

allowed='^(libc|libm|libdl|libpthread|libstdc\+\+|libgcc_s)\.so(\.[0-9]+)*$|^ld-linux.*$'

checked=0
for plugin in "${plugins[@]}"; do
  real=$(realpath "$plugin")
  [[ -n ${seen[$real]:-} ]] && continue
  seen[$real]=1
  checked=$((checked + 1))
  ok=1

  if ! dynamic=$("$readelf" -d -W "$plugin" 2>&1); then
    echo "FAIL: $plugin: readelf -d failed: $dynamic"
    status=1
    continue
  fi
  while read -r library; do
    [[ -z $library ]] && continue
    if [[ ! $library =~ $allowed ]]; then
      echo "FAIL: $plugin: NEEDED $library (allowed: libc, libm, libdl, libpthread, libstdc++, libgcc_s, ld-linux)"
      ok=0
    fi
  done < <(sed -n 's/.*(NEEDED).*\[\(.*\)\].*/\1/p' <<<"$dynamic")

  if ! symbols=$("$readelf" --dyn-syms -W "$plugin" 2>&1); then
    echo "FAIL: $plugin: readelf --dyn-syms failed: $symbols"
    status=1
    continue
  fi
  # Columns: Num: Value Size Type Bind Vis Ndx Name. Undefined (UND) symbols are imports, not exports.
  exports=$(awk '$1 ~ /^[0-9]+:$/ && $7 != "UND" && $5 != "LOCAL" &&
                 ($4 == "FUNC" || $4 == "OBJECT" || $4 == "IFUNC" || $4 == "TLS" || $4 == "COMMON") &&
                 ($6 == "DEFAULT" || $6 == "PROTECTED") { sub(/@.*/, "", $8); print $8 }' <<<"$symbols")
  found_entry=0
  while read -r name; do
    [[ -z $name ]] && continue
    if [[ $name == pfx_get_entry ]]; then
      found_entry=1
    else
      echo "FAIL: $plugin: exports $name (only pfx_get_entry may leave a plugin)"
      ok=0
    fi
  done <<<"$exports"
  if (( ! found_entry )); then
    echo "FAIL: $plugin: does not export pfx_get_entry"
    ok=0
  fi

  if (( ok )); then
    echo "ok: $plugin"
  else
    status=1
  fi
done

echo "$checked plugin(s) checked"
exit $status
