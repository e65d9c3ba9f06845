#!/usr/bin/env bash
# Prints the fenced code block that follows the marker line in a Markdown file, without the fences,
# so code shown in the docs can be compared with the tree or compiled.
#
# usage: doc_block.sh DOC.md MARKER
#   MARKER is matched as a fixed string anywhere in a line (an HTML comment such as
#   "<!-- source: tests/fixtures/minimal/minimal.c -->"); the first ``` fence after it opens the block.
# Fails when the marker or a complete block after it is missing.
set -u -o pipefail

doc=$1
marker=$2
[[ -f $doc ]] || { echo "doc_block.sh: $doc: no such file" >&2; exit 1; }

# state 0: looking for the marker, 1: looking for the opening fence, 2: inside, 3: closed.
awk -v marker="$marker" '
  state == 0 { if (index($0, marker)) state = 1; next }
  state == 1 { if ($0 ~ /^```/) state = 2; next }
  state == 2 { if ($0 ~ /^```[ \t]*$/) { state = 3; exit } print; next }
  END { exit state == 3 ? 0 : 1 }
' "$doc" || { echo "doc_block.sh: $doc: no complete code block after '$marker'" >&2; exit 1; }
