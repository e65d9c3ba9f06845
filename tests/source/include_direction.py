#!/usr/bin/env python3
"""Fails when code includes from a folder it must not reach: the arrows of the layout run one way.

- sdk/ (the C ABI, libpfxhost, the helpers) reaches nothing of host/, plugins/ or tools/;
- plugins/ reach nothing of host/ (a plugin meets hosts only at sdk/include/pfx);
- host/ reaches nothing of plugins/ (a benchmark that needs a plugin's internals lives beside it).

Two ways in are checked for every compiled file: the include folders its compile command names
(compile_commands.json of a build tree), and every quoted #include with a relative path, resolved
from the including file's folder (so headers are checked too).

usage: include_direction.py ROOT COMPILE_COMMANDS_JSON
"""

import json
import os
import re
import shlex
import sys

# Which top folders each top folder may not reach.
FORBIDDEN = {
    "sdk": ("host", "plugins", "tools"),
    "plugins": ("host",),
    "host": ("plugins",),
}
QUOTED_INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)
SOURCE_SUFFIXES = (".c", ".cpp", ".h", ".hpp")


def top_folder(root, path):
    relative = os.path.relpath(os.path.realpath(path), root)
    return None if relative.startswith("..") else relative.split(os.sep)[0]


def include_folders(command):
    args = shlex.split(command)
    folders = []
    for i, arg in enumerate(args):
        if arg in ("-I", "-isystem", "-iquote") and i + 1 < len(args):
            folders.append(args[i + 1])
        elif arg.startswith("-I") and len(arg) > 2:
            folders.append(arg[2:])
    return folders


def wrong_way(root, source, target):
    """The complaint when `source` reaching `target` runs against the layout, else None."""
    source_top, target_top = top_folder(root, source), top_folder(root, target)
    if target_top in FORBIDDEN.get(source_top, ()):
        return f"{os.path.relpath(source, root)} reaches {os.path.relpath(os.path.realpath(target), root)}"
    return None


def check_compile_commands(root, entries):
    problems = set()
    for entry in entries:
        source = os.path.join(entry.get("directory", root), entry["file"])
        command = entry.get("command") or " ".join(shlex.quote(a) for a in entry.get("arguments", []))
        for folder in include_folders(command):
            folder = os.path.join(entry.get("directory", root), folder)
            problem = wrong_way(root, source, folder)
            if problem:
                problems.add(problem + " (an include folder of its compile command)")
    return problems


def check_relative_includes(root):
    problems = set()
    for top in FORBIDDEN:
        for folder, _, files in os.walk(os.path.join(root, top)):
            for name in files:
                if not name.endswith(SOURCE_SUFFIXES):
                    continue
                path = os.path.join(folder, name)
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = f.read()
                for included in QUOTED_INCLUDE.findall(text):
                    if "/" not in included:
                        continue
                    target = os.path.normpath(os.path.join(folder, included))
                    problem = wrong_way(root, path, target) if os.path.exists(target) else None
                    if problem:
                        problems.add(problem + f' (#include "{included}")')
    return problems


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    root = os.path.realpath(sys.argv[1])
    with open(sys.argv[2], encoding="utf-8") as f:
        entries = json.load(f)
    problems = check_compile_commands(root, entries) | check_relative_includes(root)
    for problem in sorted(problems):
        print(problem)
    if problems:
        print(f"{len(problems)} include(s) run against the layout (docs/architecture.md)")
        return 1
    print(f"every include of {len(entries)} compiled files runs the layout's way")
    return 0


if __name__ == "__main__":
    sys.exit(main())
