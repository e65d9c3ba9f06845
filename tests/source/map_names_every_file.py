#!/usr/bin/env python3
"""Fails when a folder or file of the product code is not named in the map (docs/architecture.md).

What counts as named, so that the map cannot fall behind the code:
- a folder: its path from the root, or a longer path through it, written in backticks or bold
  (`host/lib/gl`, **sdk/include/pfx/** names sdk/include too), or its own name with a trailing
  slash (`parser/`) when its parent folder is named;
- a file: its name, or its name without the extension, in backticks or bold (`fx_stencil` names
  fx_stencil.hpp and fx_stencil.cpp; `lexer.cpp` names lexer.hpp), a pattern that matches it
  (`analyze_*`: three characters or more before the '*'), or being a folder's CMakeLists.txt;
- everything under a folder the map describes as a whole: a folder in the first column of one of
  the map's tables ("Where each program lives"), whose row says what the folder is.

usage: map_names_every_file.py ROOT MAP FOLDER...
"""

import fnmatch
import os
import re
import subprocess
import sys

MARKED = re.compile(r"`([^`\n]+)`|\*\*([^*\n]+)\*\*")
# A pattern that names files: a prefix of three characters or more before its '*' (`analyze_*`),
# so that a '*' in code quoted on the page (`a * b`) names nothing.
PATTERN = re.compile(r"^[A-Za-z0-9_]{3,}\*")
TABLE_FIRST_CELL = re.compile(r"^\|\s*`([^`]+)`\s*\|", re.MULTILINE)


def names_in(map_text):
    """Every word the map marks as a name: backticked and bold text, split at spaces and commas."""
    names = set()
    for match in MARKED.finditer(map_text):
        for word in re.split(r"[\s,]+", match.group(1) or match.group(2)):
            word = word.strip("()[]:;.'\"")
            if word:
                names.add(word)
    return names


def product_files(root, folders):
    """The files under the folders that git tracks or would track (a new file not yet added counts,
    a build tree or what .gitignore names does not); every file under them when the root is not a
    git checkout (a source tarball)."""
    listed = subprocess.run(["git", "-C", root, "ls-files", "--cached", "--others", "--exclude-standard", "--",
                             *folders], capture_output=True, text=True)
    if listed.returncode == 0:
        return sorted(path for path in listed.stdout.split("\n") if path)
    found = []
    for folder in folders:
        for directory, _, names in os.walk(os.path.join(root, folder)):
            found += [os.path.relpath(os.path.join(directory, name), root) for name in names]
    return sorted(found)


def folder_named(folder, names):
    if any(name.rstrip("/") == folder or name.startswith(folder + "/") for name in names):
        return True
    parent, own = os.path.split(folder)
    return own + "/" in names and bool(parent) and folder_named(parent, names)


def file_named(path, names):
    name = os.path.basename(path)
    stem = name.split(".")[0]
    if name == "CMakeLists.txt" or path in names or stem in {named.split(".")[0] for named in names}:
        return True
    return any(PATTERN.match(pattern) and fnmatch.fnmatch(stem, pattern.split(".")[0]) for pattern in names)


def main():
    if len(sys.argv) < 4:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    root, map_path, folders = sys.argv[1], sys.argv[2], sys.argv[3:]
    with open(os.path.join(root, map_path), encoding="utf-8") as f:
        map_text = f.read()
    names = names_in(map_text)
    wholes = [cell.rstrip("/") for cell in TABLE_FIRST_CELL.findall(map_text)]

    def under_whole(path):
        return any(path == whole or path.startswith(whole + "/") for whole in wholes)

    files = product_files(root, folders)
    if not files:
        print(f"no file under {', '.join(folders)} in {root}: is the root right?", file=sys.stderr)
        return 2
    unnamed = []
    seen_folders = set()
    for path in files:
        folder = os.path.dirname(path)
        while folder and folder not in seen_folders:
            seen_folders.add(folder)
            if folder not in folders and not under_whole(folder) and not folder_named(folder, names):
                unnamed.append(f"{folder}/ (folder)")
            folder = os.path.dirname(folder)
        if not under_whole(path) and not file_named(path, names):
            unnamed.append(path)
    for item in sorted(unnamed):
        print(f"{map_path} does not name {item}")
    print(f"{len(files)} files in {len(seen_folders)} folders of {', '.join(folders)}; "
          f"folders described as a whole: {len(wholes)}; not named: {len(unnamed)}")
    return 1 if unnamed else 0


if __name__ == "__main__":
    sys.exit(main())
