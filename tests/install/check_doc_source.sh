#!/usr/bin/env bash
# Fails when the code block the doc shows after "<!-- source: PATH -->" differs from PATH, so the
# listing in docs/sdk.md can never drift from the plugin the tests build and run.
#
# usage: check_doc_source.sh REPO_ROOT DOC.md PATH
set -u -o pipefail

root=$1
doc=$2
path=$3
here=$(dirname "${BASH_SOURCE[0]}")
marker="<!-- source: $path -->"

[[ -f $root/$path ]] || { echo "FAIL: $root/$path does not exist"; exit 1; }
shown=$(mktemp)
trap 'rm -f "$shown"' EXIT
if ! bash "$here/doc_block.sh" "$doc" "$marker" >"$shown"; then
  echo "FAIL: $doc has no code block after the line '$marker'"
  exit 1
fi
if ! diff -u --label "$path (in the tree)" --label "$doc (shown)" "$root/$path" "$shown"; then
  echo "FAIL: $doc shows a different $path; paste the file into the block after '$marker'"
  exit 1
fi
echo "ok: $doc shows $path verbatim ($(wc -l <"$root/$path") lines)"
