#!/usr/bin/env python3
"""Writes the pfx headers as another minor version would have them, for the growth-rule fixtures.

usage: make_versioned_headers.py SDK_INCLUDE_DIR OUT_DIR old|future

old     ABI 1.0: every field marked "/* since 1.N */" removed, PFX_ABI_MINOR 0. Plugins and hosts
        built against it are what users built before 1.1 and still run.
future  ABI 1.99: two fields appended to every sized struct (and to pfx_light, which the frame's
        light_struct_size steps), PFX_ABI_MINOR 99: what a later minor version may legally do.

The headers are derived from the real ones, so the fixtures always test today's ABI against its
neighbours, and a field appended without its "since" mark shows up as an old fixture that no longer
matches the 1.0 sizes the tests pin.
"""
import os
import re
import sys

FUTURE_FIELDS = ("  uint64_t future_count; /* since 1.99 (fixture headers only) */\n"
                 "  const char* future_name; /* since 1.99 (fixture headers only) */\n")


def old_version(text):
    # A field may span lines: the lines before its last start with a name and end with a comma.
    text = re.sub(r"^(?:[ \t]*[A-Za-z_][^\n;{}]*,\n)*[^\n]*;\s*/\* since 1\.\d+ \*/\n", "", text, flags=re.M)
    return text.replace("#define PFX_ABI_MINOR 9u", "#define PFX_ABI_MINOR 0u")


def future_version(text):
    def grow(match):
        name, body = match.group(1), match.group(2)
        sized = body.lstrip().startswith("uint32_t struct_size;") or name == "pfx_light"
        return "typedef struct %s {%s%s} %s;" % (name, body, FUTURE_FIELDS if sized else "", name)

    text = re.sub(r"typedef struct (pfx_\w+) \{(.*?)\} \1;", grow, text, flags=re.S)
    return text.replace("#define PFX_ABI_MINOR 9u", "#define PFX_ABI_MINOR 99u")


def main():
    source, out, version = sys.argv[1:4]
    transform = {"old": old_version, "future": future_version}[version]
    os.makedirs(os.path.join(out, "pfx"), exist_ok=True)
    for name in sorted(os.listdir(os.path.join(source, "pfx"))):
        if not name.endswith(".h"):
            continue
        with open(os.path.join(source, "pfx", name)) as f:
            text = f.read()
        if "#define PFX_ABI_MINOR" in text and "#define PFX_ABI_MINOR 9u" not in text:
            sys.exit("make_versioned_headers.py: core.h's PFX_ABI_MINOR changed; update this script")
        with open(os.path.join(out, "pfx", name), "w") as f:
            f.write(transform(text))


if __name__ == "__main__":
    main()
