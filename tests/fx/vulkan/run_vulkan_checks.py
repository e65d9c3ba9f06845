#!/usr/bin/env python3
"""The conformance suite through SPIR-V on Vulkan (lavapipe).

usage: run_vulkan_checks.py FX_VULKAN_CHECKS

Each file of tests/fx/conformance judged on the 8-bit gradient (`// expect: checks`, the default,
`input` or `invert`) is run by FX_VULKAN_CHECKS: its pass in the Vulkan dialect, compiled to
SPIR-V by glslang, drawn on Mesa's lavapipe device over a gradient back buffer, and judged as in
GL: every check green, the input's bytes, or their inverse. The files of RUN must run and pass;
every other file must be one the tool does not run yet (more than one pass, textures other than
the back buffer, compute, blending, stencil: what needs the Vulkan runtime for FX), so a file
that starts to run is added to RUN rather than passing unseen. Files judged on another input (an
alpha that the runtime keeps, an EXR of non-finite values) are the GL runtime's to judge.
"""
import glob
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CONFORMANCE = os.path.join(HERE, "..", "conformance")
INCLUDE = os.path.join(HERE, "..", "..", "..", "plugins", "fx", "include")

RUN = ["identity.fx", "invert.fx", "size_1x1.fx", "conversions.fx", "exists_and_widening.fx", "float_to_integer.fx", "function_statics.fx",
       "initializer_assignments.fx", "integer_matrices.fx", "integer_wrap.fx", "intrinsics_bits.fx",
       "intrinsics_math.fx", "matrices.fx", "matrix_comparisons.fx", "matrix_swizzle_stores.fx",
       "namespaced_constants.fx", "operators.fx", "out_arguments.fx", "preprocessor.fx", "uniforms.fx"]


def header(path):
    settings = {"size": "64x4", "expect": "checks", "cell": "4", "input": "gradient"}
    with open(path) as f:
        for line in f:
            m = re.match(r"\s*//\s*(size|expect|cell|input):\s*(\S+)", line)
            if m:
                settings[m.group(1)] = m.group(2)
    return settings


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 2
    icds = sorted(glob.glob("/usr/share/vulkan/icd.d/lvp_icd.*.json"))
    if not icds:
        print("FAIL: lavapipe is not installed (/usr/share/vulkan/icd.d/lvp_icd.*.json): install mesa-vulkan-drivers")
        return 1
    env = dict(os.environ, VK_ICD_FILENAMES=icds[0])
    failures, ran = [], 0
    for path in sorted(glob.glob(os.path.join(CONFORMANCE, "*.fx"))):
        name = os.path.basename(path)
        s = header(path)
        if s["expect"] not in ("checks", "input", "invert") or s["input"] != "gradient":
            continue  # judged on another input or by what the runtime keeps: the GL suite's business
        result = subprocess.run([argv[1], "-I" + os.path.abspath(INCLUDE), "--size", s["size"], "--cell", s["cell"],
                                 "--expect", s["expect"], path],
                                capture_output=True, text=True, env=env, timeout=300)
        said = (result.stdout + result.stderr).strip()
        if name in RUN:
            ran += 1
            if result.returncode != 0:
                failures.append("%s: %s" % (name, said))
            else:
                print("%s: %s" % (name, said))
        elif result.returncode != 3:
            failures.append("%s ran (%s): add it to RUN in %s" % (name, said, __file__))
    missing = [f for f in RUN if not os.path.exists(os.path.join(CONFORMANCE, f))]
    if missing:
        failures.append("RUN names files that are gone: %s" % missing)
    for failure in failures:
        print("FAIL: " + failure)
    if failures:
        return 1
    print("ok: %d conformance files hold on Vulkan (lavapipe) as in GL" % ran)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
