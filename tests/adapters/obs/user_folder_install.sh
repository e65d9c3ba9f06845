#!/usr/bin/env bash
# The user-folder install of docs/hosts.md, as a user runs it: the docs' own lines copy the build
# into an empty home folder, then libobs's module search finds pfx-obs there with no environment
# variable set but HOME (and the sanitizers' options in the sanitizer pass), and the module must
# load on the libpfxhost copied beside it and offer its filters.
#
# usage: user_folder_install.sh SOURCE_DIR BUILD_DIR OBS_MODULE_SEARCH
set -euo pipefail
source_dir=$1 build_dir=$2 search=$3

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/home" "$scratch/tree"
# The docs' lines name the build folder "build", relative to the repository's root.
ln -s "$build_dir" "$scratch/tree/build"
recipe=$(bash "$source_dir/tests/install/doc_block.sh" "$source_dir/docs/hosts.md" "<!-- obs user folder -->")
(cd "$scratch/tree" && HOME="$scratch/home" bash -euo pipefail -c "$recipe")

sanitizer_options=()
for name in ASAN_OPTIONS UBSAN_OPTIONS LSAN_OPTIONS; do
  [[ -n ${!name:-} ]] && sanitizer_options+=("$name=${!name}")
done
env -i HOME="$scratch/home" PATH=/usr/bin:/bin "${sanitizer_options[@]}" \
  xvfb-run -a -s "-screen 0 640x480x24 -nolisten tcp" "$search" "$scratch/home/.config/obs-studio/plugins/pfx-obs"
