#!/usr/bin/env python3
"""SPIR-V of the conformance suite, judged by spirv-val.

usage: check_spirv.py FX_SPIRV_CHECK SPIRV_VAL OUT_DIR [FILE.fx ...]

Runs FX_SPIRV_CHECK over each conformance file (every file of tests/fx/conformance when none is
named): every pass of every technique in the Vulkan dialect, each stage compiled to SPIR-V by
glslang. Then SPIRV_VAL (Khronos' validator, Debian's spirv-tools) checks each module against
Vulkan 1.0's rules. Fails when a file does not compile, glslang refuses a stage, or a module is
invalid; the Vulkan GLSL of each module is left beside it in OUT_DIR.
"""
import glob
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CONFORMANCE = os.path.join(HERE, "..", "conformance")
INCLUDE = os.path.join(HERE, "..", "..", "..", "plugins", "fx", "include")


def main(argv):
    if len(argv) < 4:
        print(__doc__)
        return 2
    tool, validator, out = argv[1], argv[2], argv[3]
    files = argv[4:] or sorted(glob.glob(os.path.join(CONFORMANCE, "*.fx")))
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    generated = subprocess.run([tool, "-I" + os.path.abspath(INCLUDE), out] + files, capture_output=True, text=True)
    print(generated.stdout.strip())
    if generated.returncode != 0:
        print("FAIL: %s exited with %d: %s" % (tool, generated.returncode, generated.stderr))
        return 1
    modules = sorted(glob.glob(os.path.join(out, "*.spv")))
    if not modules:
        print("FAIL: no module in %s" % out)
        return 1
    invalid = []
    for module in modules:
        checked = subprocess.run([validator, "--target-env", "vulkan1.0", module], capture_output=True, text=True)
        if checked.returncode != 0:
            invalid.append(module)
            print("FAIL: spirv-val: %s (its GLSL: %s):\n%s%s" % (module, module[:-4] + ".glsl", checked.stdout, checked.stderr))
    if invalid:
        print("FAIL: %d of %d modules invalid" % (len(invalid), len(modules)))
        return 1
    print("ok: spirv-val passes all %d modules of %d files (Vulkan 1.0)" % (len(modules), len(files)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
