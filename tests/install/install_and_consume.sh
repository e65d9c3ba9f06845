#!/usr/bin/env bash
# Installs the current build tree into a fresh prefix and uses it the way another engine would:
# find_package(pfx) and pkg-config builds of a small consumer, an out-of-tree plugin built with the
# installed SDK and loaded by the installed runtime, the docs' embedding listing compiled, the
# installed pfx-render run and the installed Python module imported. Any failing step fails the test.
#
# Everything comes from the environment (set by tests/install/CMakeLists.txt):
#   PFX_CMAKE PFX_SOURCE_DIR PFX_BUILD_DIR PFX_C_COMPILER PFX_CXX_COMPILER
#   PFX_BINDIR PFX_LIBDIR PFX_INCLUDEDIR PFX_PLUGINDIR    install layout, relative to the prefix
#   PFX_PLUGIN_BUILD_DIR                                  build/plugins: what must be installed
#   PFX_GLAD_DIR                                          the generated glad, as "the author's own loader"
#   PFX_PKG_CONFIG                                        pkg-config or pkgconf
#   PFX_PYTHON PFX_PYTHONDIR                              the interpreter; the module's folder in the prefix
set -u -o pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/pfx-install-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
log=$work/step.log
failures=0

# step NAME COMMAND...: runs the command quietly; on failure prints its output and counts it.
step() {
  local name=$1
  shift
  if "$@" >"$log" 2>&1; then
    echo "ok: $name"
    return 0
  fi
  echo "FAIL: $name"
  echo "  command: $*"
  sed 's/^/  | /' "$log"
  failures=$((failures + 1))
  return 1
}
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
# Stops here: later steps depend on this one.
require() { step "$@" || finish; }
finish() {
  if ((failures)); then
    echo "$failures step(s) failed"
    exit 1
  fi
  echo "all steps passed"
  exit 0
}

# ---- 1. Install ----------------------------------------------------------------------------------
require "cmake --install into a fresh prefix" "$PFX_CMAKE" --install "$PFX_BUILD_DIR" --prefix "$prefix"

# ---- 2. The layout -------------------------------------------------------------------------------
for file in "$PFX_INCLUDEDIR/pfx/pfx.h" "$PFX_INCLUDEDIR/pfx/core.h" "$PFX_INCLUDEDIR/pfx/effect.h" \
            "$PFX_INCLUDEDIR/pfx/host/chain.hpp" "$PFX_INCLUDEDIR/pfx/host/plugin_registry.hpp" \
            "$PFX_LIBDIR/cmake/pfx/pfxConfig.cmake" "$PFX_LIBDIR/cmake/pfx/pfxConfigVersion.cmake" \
            "$PFX_LIBDIR/cmake/pfx/plugin.map" "$PFX_LIBDIR/pkgconfig/pfx.pc" "$PFX_BINDIR/pfx-render"; do
  [[ -f $prefix/$file ]] || fail "installed file $file is missing"
done
# The development link, the soname link and the real file, as a distribution would lay them out.
[[ -L $prefix/$PFX_LIBDIR/libpfxhost.so ]] || fail "$PFX_LIBDIR/libpfxhost.so is not a symlink"
soname=$(readelf -d "$prefix/$PFX_LIBDIR/libpfxhost.so" 2>/dev/null | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')
[[ -n $soname && -L $prefix/$PFX_LIBDIR/$soname ]] || fail "soname link $PFX_LIBDIR/${soname:-(no SONAME)} is missing"
# The OBS module where OBS looks for modules under the prefix, with its data folder beside OBS's
# own, when the build made it (it needs libobs-dev).
if [[ -f $PFX_BUILD_DIR/lib/obs-plugins/pfx-obs.so ]]; then
  [[ -f $prefix/$PFX_LIBDIR/obs-plugins/pfx-obs.so ]] || fail "$PFX_LIBDIR/obs-plugins/pfx-obs.so is missing"
  [[ -d $prefix/share/obs/obs-plugins/pfx-obs ]] || fail "share/obs/obs-plugins/pfx-obs is missing"
fi
# glad is a build detail of our own targets; a consumer brings their own loader.
[[ ! -e $prefix/$PFX_INCLUDEDIR/glad ]] || fail "glad headers were installed"

# Every shipped plugin is installed, and nothing else (no test fixture) is.
[[ -d $prefix/$PFX_PLUGINDIR ]] || fail "plugin folder $PFX_PLUGINDIR is missing"
shipped=0
for plugin in "$PFX_PLUGIN_BUILD_DIR"/*.so; do
  [[ -f $plugin ]] || continue
  shipped=$((shipped + 1))
  [[ -f $prefix/$PFX_PLUGINDIR/$(basename "$plugin") ]] || fail "plugin $(basename "$plugin") was not installed"
done
for plugin in "$prefix/$PFX_PLUGINDIR"/*; do
  [[ -e $plugin ]] || continue
  # A plugin's data folder beside it (the FX plugin's fx/include) is shipped as the build has it.
  [[ -d $plugin && -d $PFX_PLUGIN_BUILD_DIR/$(basename "$plugin") ]] && continue
  [[ -f $PFX_PLUGIN_BUILD_DIR/$(basename "$plugin") ]] || fail "$PFX_PLUGINDIR/$(basename "$plugin") is not a shipped plugin"
done
# The FX plugin's own ReShade.fxh, which effects that include it need.
[[ ! -f $PFX_PLUGIN_BUILD_DIR/pfx_fx.so || -f $prefix/$PFX_PLUGINDIR/fx/include/ReShade.fxh ]] || fail "fx/include/ReShade.fxh was not installed"
echo "ok: layout checked ($shipped shipped plugin(s))"

# ---- 3. find_package(pfx) ------------------------------------------------------------------------
embed_source=$work/embed_example.cpp
if ! bash "$here/doc_block.sh" "$PFX_SOURCE_DIR/docs/sdk.md" "<!-- compiled: embed_example.cpp -->" >"$embed_source"; then
  fail "docs/sdk.md has no listing after '<!-- compiled: embed_example.cpp -->'"
  finish
fi

consumer=$work/consumer-build
# Only the prefix: no package registry, so a stray build tree can never stand in for the install.
require "consumer configures with find_package(pfx)" \
  "$PFX_CMAKE" -S "$here/consumer" -B "$consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER="$PFX_C_COMPILER" -DCMAKE_CXX_COMPILER="$PFX_CXX_COMPILER" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
  -DPFX_EMBED_EXAMPLE="$embed_source" \
  -DPFX_PLUGIN_SOURCE="$PFX_SOURCE_DIR/tests/fixtures/minimal/minimal.c" -DPFX_GLAD_DIR="$PFX_GLAD_DIR"
pfx_dir=$(sed -n 's/^pfx_DIR:[A-Z]*=//p' "$consumer/CMakeCache.txt")
[[ $pfx_dir == "$prefix"/* ]] || fail "find_package found pfx in '$pfx_dir', not in the prefix"
require "consumer builds (list_plugins, abi_check, docs' embed_example, out-of-tree plugin)" \
  "$PFX_CMAKE" --build "$consumer" -j 2

step "C program against pfx::sdk runs" "$consumer/abi_check"
step "C++ program against pfx::host loads the installed plugin folder" "$consumer/list_plugins" &&
  { grep -q "^pfx ABI [0-9]*\.[0-9]*$" "$log" || fail "list_plugins printed no ABI version"; }
# The consumer must run on the installed runtime, not the build tree's.
host_lib=$(ldd "$consumer/list_plugins" | sed -n 's/.*libpfxhost[^ ]* => \([^ ]*\).*/\1/p')
[[ $host_lib == "$prefix"/* ]] || fail "list_plugins uses libpfxhost from '${host_lib:-nowhere}', not the prefix"

# The out-of-tree plugin: built with the installed SDK and version script, loaded by the installed runtime.
# An empty folder instead of the installed one: a shipped plugin may not clash with its ids.
plugin=$consumer/minimal.so
mkdir -p "$work/no-plugins"
if step "installed runtime loads the plugin built against the installed SDK" \
  "$consumer/list_plugins" --dir "$work/no-plugins" "$plugin"; then
  grep -q "^effect gain " "$log" && grep -q "^effect boxblur " "$log" ||
    fail "the out-of-tree plugin's effects were not listed: $(tr '\n' ' ' <"$log")"
fi
exports=$(nm -D --defined-only "$plugin" | awk '{print $NF}' | sort | tr '\n' ' ')
[[ $exports == "pfx_get_entry " ]] || fail "out-of-tree plugin exports '$exports', expected only pfx_get_entry"
if readelf -d "$plugin" | grep -E 'NEEDED.*\[lib(GL|EGL|OpenGL|glfw|GLX)' >"$log"; then
  fail "out-of-tree plugin links a GL or window library: $(cat "$log")"
fi

# ---- 4. pkg-config ------------------------------------------------------------------------------
export PKG_CONFIG_PATH=$prefix/$PFX_LIBDIR/pkgconfig
if require "pkg-config finds pfx in the prefix" "$PFX_PKG_CONFIG" --exists --print-errors pfx; then
  cflags=$("$PFX_PKG_CONFIG" --cflags pfx)
  libs=$("$PFX_PKG_CONFIG" --libs pfx)
  libdir=$("$PFX_PKG_CONFIG" --variable=libdir pfx)
  plugindir=$("$PFX_PKG_CONFIG" --variable=plugindir pfx)
  [[ $(realpath -m "$libdir") == $(realpath "$prefix/$PFX_LIBDIR") ]] || fail "pfx.pc libdir is '$libdir'"
  [[ -d $plugindir ]] || fail "pfx.pc plugindir '$plugindir' is not a folder"
  # shellcheck disable=SC2086  # the flags are words
  step "C file builds with pkg-config --cflags pfx" "$PFX_C_COMPILER" -std=c99 -pedantic -Wall -Wextra -Werror \
    $cflags "$here/consumer/abi_check.c" -o "$work/abi_check_pc" &&
    step "pkg-config C program runs" "$work/abi_check_pc"
  # shellcheck disable=SC2086
  step "C++ program links with pkg-config --libs pfx" "$PFX_CXX_COMPILER" -std=c++17 -Wall -Wextra -Werror \
    $cflags "-DPFX_INSTALLED_PLUGIN_DIR=\"$plugindir\"" "$here/consumer/list_plugins.cpp" \
    -o "$work/list_plugins_pc" $libs "-Wl,-rpath,$libdir" &&
    step "pkg-config C++ program runs" "$work/list_plugins_pc"
fi

# ---- 5. The installed programs and headers --------------------------------------------------------
# LD_LIBRARY_PATH unset: the program must find its libpfxhost through its own RPATH.
step "installed pfx-render --help exits 0" env -u LD_LIBRARY_PATH "$prefix/$PFX_BINDIR/pfx-render" --help
host_lib=$(env -u LD_LIBRARY_PATH ldd "$prefix/$PFX_BINDIR/pfx-render" | sed -n 's/.*libpfxhost[^ ]* => \([^ ]*\).*/\1/p')
[[ $host_lib == "$prefix"/* ]] || fail "installed pfx-render uses libpfxhost from '${host_lib:-nowhere}', not the prefix"

# ---- 6. The Python module --------------------------------------------------------------------------
# Imported from the prefix's package folder, it must run on the prefix's libpfxhost and find the
# prefix's plugins, not the build tree's.
python_check='import pfx, numpy, sys
prefix = sys.argv[1]
assert pfx.__file__.startswith(prefix), pfx.__file__
paths = {e["plugin_path"] for e in pfx.effects()}
assert paths and all(p.startswith(prefix) for p in paths), paths
with pfx.Chain(["bloom"]) as chain:
    assert chain.run(numpy.full((4, 4, 4), 9, numpy.float32)).shape == (4, 4, 4)
host = [line for line in open("/proc/self/maps") if "libpfxhost" in line]
assert host and all(prefix in line for line in host), host'
step "installed Python module imports from the prefix and runs a chain with the prefix's plugins" \
  env -u LD_LIBRARY_PATH -u PFX_PLUGIN_PATH PYTHONPATH="$prefix/$PFX_PYTHONDIR" "$PFX_PYTHON" -c "$python_check" "$prefix"

finish
