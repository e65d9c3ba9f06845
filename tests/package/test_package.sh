#!/usr/bin/env bash
# The Debian package as a user gets it: installed with dpkg into a root made for this test, then,
# with no environment variable set, every host finds what it installed where that host looks:
# pfx-render its plugins, GStreamer the element, ffmpeg the frei0r plugin, Debian's python3 the
# module, libobs the OBS module, pfx-inject its library, Vulkan's loader the layer, pkg-config the
# SDK. Then dpkg -r removes
# every file it installed. Last, lintian: an error of lintian's fails the pass, warnings are shown.
#
# The root: this machine's own root seen through an overlay whose upper layer is a scratch tmpfs,
# in a mount namespace of the test's own. The dependencies the package names are there (they are
# this machine's packages), the package database changes only in the scratch layer, and the source
# and build trees, /usr/local, /home, /root and /tmp are hidden behind empty folders, so nothing is
# found that the package did not bring. Needs root (the tests run as root here, as ./run does).
#
# usage: test_package.sh PFX.deb BUILD_DIR   (BUILD_DIR: the test build, for obs-module-search)
# Prints "ok: CHECK" or "FAILED: CHECK" per check and "package: N passed, M failed" last.
set -uo pipefail

deb=$(realpath "$1")
build_dir=$(realpath "$2")
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
triplet=$(dpkg-architecture -qDEB_HOST_MULTIARCH)

if [[ $(id -u) -ne 0 ]]; then
  echo "FAILED: the package test installs into a root of its own and needs root"
  echo "package: 0 passed, 1 failed"
  exit 1
fi

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp "$deb" "$scratch/pfx.deb"
cp "$build_dir/bin/obs-module-search" "$scratch/" 2>/dev/null || true
# A GLSL-form preset written for the RetroArch comparison, for pfx-libretro-check in the root.
mkdir "$scratch/libretro"
cp -r "$source_dir/tests/libretro/retroarch/shaders" "$source_dir/tests/libretro/retroarch/pictures.glslp" "$scratch/libretro/"

# Inside a mount namespace of its own: the root, the checks, and the package's removal.
cat > "$scratch/in_root.sh" <<'INNER'
set -uo pipefail
scratch=$1 source_dir=$2 build_dir=$3 triplet=$4
root=$scratch/root
mkdir -p "$scratch/layer" "$root"
mount -t tmpfs -o size=4g layer "$scratch/layer"
mkdir "$scratch/layer/upper" "$scratch/layer/work"
mount -t overlay overlay -o "lowerdir=/,upperdir=$scratch/layer/upper,workdir=$scratch/layer/work" "$root"
mount -t proc proc "$root/proc"
mount --rbind /dev "$root/dev"
mount --rbind /sys "$root/sys"
for hidden in /tmp /root /home /usr/local /run "$source_dir" "$build_dir"; do
  [[ -d "$root$hidden" ]] && mount -t tmpfs -o mode=0755 empty "$root$hidden"
done
chmod 1777 "$root/tmp"
cp "$scratch/pfx.deb" "$root/tmp/"
[[ -f "$scratch/obs-module-search" ]] && cp "$scratch/obs-module-search" "$root/tmp/"
cp -r "$scratch/libretro" "$root/tmp/"

passed=0 failed=0
# check NAME COMMAND: COMMAND (a shell line) in the root with nothing in the environment but
# PATH and HOME; its output is shown when it fails.
check() {
  local name=$1 command=$2 output
  if output=$(chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
                /bin/bash -o pipefail -c "$command" 2>&1); then
    passed=$((passed + 1))
    echo "ok: $name"
  else
    failed=$((failed + 1))
    echo "FAILED: $name"
    echo "$output" | tail -25 | sed 's/^/    /'
  fi
}

check "dpkg -i installs the package with its dependencies present" "dpkg -i /tmp/pfx.deb"
dpkg_files=$(chroot "$root" dpkg-query -L pfx)

check "pfx-render --list finds the plugins in /usr/lib/pfx/plugins" \
  "pfx-render --list --json > /tmp/list.json && python3 -c \"
import json; listing = json.load(open('/tmp/list.json'))
ids = {e['id'] for p in listing['plugins'] for e in p['effects']}
assert {'bloom', 'glare', 'dof', 'tiledlights'} <= ids, ids
assert all(p['path'].startswith('/usr/lib/pfx/plugins/') for p in listing['plugins']), listing['plugins']
assert not listing['load_errors'], listing['load_errors']\""
check "pfx-render renders the demo scene" "pfx-render --demo --size 96x64 --out /tmp/demo.png && test -s /tmp/demo.png"
check "gst-inspect-1.0 pfxfilter finds the element, MIT-licensed, in GStreamer's folder" \
  "gst-inspect-1.0 pfxfilter > /tmp/gst.txt && grep -Eq ' (/usr)?/lib/$triplet/gstreamer-1.0/libgstpfx.so$' /tmp/gst.txt &&
   grep -Eq 'License +MIT/X11' /tmp/gst.txt"
check "ffmpeg -vf frei0r=filter_name=pfx_chain runs and changes the frame" \
  "ffmpeg -v error -f lavfi -i testsrc2=size=96x64 -frames:v 1 -vf frei0r=filter_name=pfx_chain -update 1 /tmp/chain.png &&
   ffmpeg -v error -f lavfi -i testsrc2=size=96x64 -frames:v 1 -update 1 /tmp/plain.png && ! cmp -s /tmp/chain.png /tmp/plain.png"
check "python3 imports pfx from /usr/lib/python3/dist-packages and runs bloom" \
  "cd / && python3 -c \"
import importlib.metadata, numpy as np, pfx
assert pfx.__file__.startswith('/usr/lib/python3/dist-packages/'), pfx.__file__
assert importlib.metadata.metadata('pfx')['License'] == 'MIT' and pfx.__license__ == 'MIT'
picture = np.full((48, 64, 3), 40, np.uint8); picture[16:32, 24:40] = 255
with pfx.Chain(['bloom']) as chain:
    result = chain.run(picture)
assert result.dtype == np.uint8 and (result != picture).any()\""
if [[ -f "$root/tmp/obs-module-search" ]]; then
  check "libobs's module search finds pfx-obs in OBS's folder and it loads on the package's libpfxhost" \
    "xvfb-run -a -s '-screen 0 640x480x24 -nolisten tcp' /tmp/obs-module-search /usr/lib/$triplet"
else
  failed=$((failed + 1))
  echo "FAILED: obs-module-search was not built in $build_dir/bin: the OBS check cannot run"
fi
check "pfx-inject runs bloom in glxgears with its installed library" \
  "xvfb-run -a -s '-screen 0 320x240x24 -nolisten tcp' pfx-inject --chain bloom --quit-after 3 -- glxgears"
check "the Vulkan loader finds the layer's manifest in /usr/share/vulkan and its library" \
  "python3 -c \"
import json; layer = json.load(open('/usr/share/vulkan/implicit_layer.d/pfx_layer.json'))['layer']
import os; assert os.path.isfile(layer['library_path']), layer\" &&
   { ENABLE_PFX_VULKAN=1 vulkaninfo --summary > /tmp/vulkaninfo.txt 2>&1 || true; } &&
   grep -q VK_LAYER_PFX_post_effects /tmp/vulkaninfo.txt"
check "pfx-fx-check --compare-vkbasalt finds its oracle in /usr/share/pfx, the installed layer and headers" \
  "mkdir -p /tmp/fx && printf '%s\\n' '#include \"ReShade.fxh\"' \
     'float4 Invert(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target { return float4(1.0 - tex2D(ReShade::BackBuffer, uv).rgb, 1.0); }' \
     'technique Invert { pass { VertexShader = PostProcessVS; PixelShader = Invert; } }' > /tmp/fx/Invert.fx &&
   xvfb-run -a -s '-screen 0 640x480x24 -nolisten tcp' pfx-fx-check --compare-vkbasalt --json /tmp/fx > /tmp/compare.json &&
   python3 -c \"
import json; row = json.load(open('/tmp/compare.json'))['files'][0]
assert row['vkbasalt_ran'] and row['pfx_ran'] and row['max_diff'] <= 1, row\""
check "pfx-libretro-check --compare-retroarch finds its oracle in /usr/share/pfx and the installed libretro plugin" \
  "pfx-libretro-check --compare-retroarch --json /tmp/libretro > /tmp/libretro.json &&
   python3 -c \"
import json; row = json.load(open('/tmp/libretro.json'))['presets'][0]
assert row['ran'] and row['changed'] and row['retroarch']['matches'], row\""
check "man finds a manual page for every program in /usr/bin" \
  "for program in \$(dpkg-query -L pfx | grep '^/usr/bin/'); do
     page=\$(man -w \"\$(basename \"\$program\")\") && test \"\$page\" = /usr/share/man/man1/\$(basename \"\$program\").1.gz ||
       { echo \"no manual page for \$program (\$page)\"; exit 1; }
   done"
check "pkg-config and the licence: the SDK's pfx.pc, /usr/share/doc/pfx/copyright" \
  "test \"\$(pkg-config --variable=plugindir pfx)\" = /usr/lib/pfx/plugins && pkg-config --libs pfx | grep -q -- -lpfxhost &&
   test -s /usr/share/doc/pfx/copyright && test -s /usr/share/doc/pfx/LICENSE"

# Every file and link the package installed is gone after dpkg -r (folders other packages share,
# such as /usr/lib/frei0r-1, stay).
check "dpkg -r removes the package" "dpkg -r pfx"
left=()
while IFS= read -r path; do
  [[ -z "$path" || -d "$root$path" ]] && continue
  if [[ -e "$root$path" || -L "$root$path" ]]; then left+=("$path"); fi
done <<< "$dpkg_files"
if ((${#left[@]} == 0)) && [[ -n "$dpkg_files" ]]; then
  passed=$((passed + 1))
  echo "ok: dpkg -r removes every file it installed ($(grep -c . <<< "$dpkg_files") paths listed)"
else
  failed=$((failed + 1))
  echo "FAILED: dpkg -r left ${#left[@]} installed files: ${left[*]:0:10}"
fi
echo "$passed $failed" > "$scratch/counts"
INNER

unshare --mount --propagation private bash "$scratch/in_root.sh" "$scratch" "$source_dir" "$build_dir" "$triplet"
read -r passed failed < "$scratch/counts" 2>/dev/null || { passed=0 failed=1; echo "FAILED: the root could not be made"; }

# lintian: its errors fail the pass; its warnings are listed (the closing note of a change that
# touches packaging quotes them).
if command -v lintian > /dev/null; then
  lintian_output=$(lintian --tag-display-limit 0 "$deb" 2>&1)
  echo "$lintian_output" | sed 's/^/    lintian: /'
  if grep -q '^E: ' <<< "$lintian_output"; then
    failed=$((failed + 1))
    echo "FAILED: lintian reports errors"
  else
    passed=$((passed + 1))
    echo "ok: lintian reports no error ($(grep -c '^W: ' <<< "$lintian_output") warnings)"
  fi
else
  failed=$((failed + 1))
  echo "FAILED: lintian is not installed (./run installs it)"
fi

echo "package: $passed passed, $failed failed"
((failed == 0))
