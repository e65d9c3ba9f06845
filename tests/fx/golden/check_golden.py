#!/usr/bin/env python3
"""The FX compiler's GLSL, compared with the copies kept in the tree.

usage: check_golden.py FX_PARSE_CHECK [--update] [FILE.fx ...]
       check_golden.py FX_PARSE_CHECK --stale

For each conformance file (every file of tests/fx/conformance when none is named), runs
`FX_PARSE_CHECK --glsl` over it and compares what it prints (every pass of every technique, with
live uniforms) with tests/fx/golden/NAME.glsl, and the same in the Vulkan dialect (the GLSL that
becomes SPIR-V: `--glsl --vulkan`) with NAME.vulkan.glsl. A difference fails with a unified diff: a change
to the code generator shows up as a diff of its output, to be read before it is accepted.

--stale fails when a golden file has no conformance file. --update writes the files instead (and removes those of conformance files that are gone): run it
after changing the generator on purpose, then read `git diff tests/fx/golden` before committing.
The pictures the code draws are judged elsewhere (run_conformance.py, vkBasalt); this only says
what changed.
"""
import difflib
import glob
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CONFORMANCE = os.path.join(HERE, "..", "conformance")
INCLUDE = os.path.join(HERE, "..", "..", "..", "plugins", "fx", "include")


# The kinds of output kept: the golden file's suffix and the tool's options.
KINDS = [(".glsl", ["--glsl"]), (".vulkan.glsl", ["--glsl", "--vulkan"])]


def generated(tool, fx, options):
    # Run from the conformance folder with the file's bare name, so the output names no path of
    # this machine.
    result = subprocess.run([tool] + options + ["-I" + os.path.abspath(INCLUDE), os.path.basename(fx)],
                            cwd=os.path.dirname(os.path.abspath(fx)), capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("FAIL: %s exited with %d: %s" % (tool, result.returncode, result.stderr))
    return result.stdout


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) >= 2 else 2
    tool = os.path.abspath(argv[1])
    update = "--update" in argv[2:]
    named = [a for a in argv[2:] if a not in ("--update", "--stale")]
    files = named or sorted(glob.glob(os.path.join(CONFORMANCE, "*.fx")))
    wanted = {os.path.splitext(os.path.basename(f))[0] + suffix for f in files for suffix, _ in KINDS}
    stale = [g for g in sorted(glob.glob(os.path.join(HERE, "*.glsl"))) if os.path.basename(g) not in wanted]
    if "--stale" in argv[2:]:
        if stale:
            print("FAIL: golden files without a conformance file: %s (run %s %s --update)" % (stale, argv[0], tool))
            return 1
        print("ok: every golden file has its conformance file (%d files)" % len(files))
        return 0
    failed = []
    for fx, (suffix, options) in [(f, k) for f in files for k in KINDS]:
        name = os.path.splitext(os.path.basename(fx))[0] + suffix
        golden = os.path.join(HERE, name)
        text = generated(tool, fx, options)
        if update:
            with open(golden + ".tmp", "w") as f:
                f.write(text)
            os.replace(golden + ".tmp", golden)
            continue
        if not os.path.exists(golden):
            failed.append(name)
            print("FAIL: %s has no golden file %s (run %s %s --update)" % (name, golden, argv[0], tool))
            continue
        with open(golden) as f:
            expected = f.read()
        if text != expected:
            failed.append(name)
            diff = list(difflib.unified_diff(expected.splitlines(), text.splitlines(), golden, "generated now", lineterm=""))
            print("FAIL: the GLSL of %s changed (%d diff lines; the first 60 follow). If the change is meant, "
                  "run %s %s --update and read the diff." % (name, len(diff), argv[0], tool))
            print("\n".join(diff[:60]))
    if update and not named:
        for path in stale:
            os.remove(path)
    if update:
        print("ok: wrote the GLSL of %d files, both dialects, into %s" % (len(files), HERE))
        return 0
    if failed:
        return 1
    print("ok: the GLSL of %d files, both dialects, is as kept in %s" % (len(files), HERE))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
