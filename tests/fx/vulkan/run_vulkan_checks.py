#!/usr/bin/env python3
"""The conformance suite on Vulkan (lavapipe), through the Vulkan runtime for FX, under Khronos'
validation layer with synchronisation validation.

usage: run_vulkan_checks.py FX_VULKAN_CHECKS PFX_FX_SO

Each file of tests/fx/conformance judged on the 8-bit input picture (`// expect: checks`, the
default, `input` or `invert`; `// input: gradient` or `alpha`) is run by FX_VULKAN_CHECKS as a
Vulkan host runs an effect: through the FX plugin PFX_FX_SO's "pfx.vulkan_effects/1" factory, its
passes in the Vulkan dialect compiled to SPIR-V by glslang and run by plugins/fx/vulkan on Mesa's
lavapipe device for the file's frames, and judged as in GL: every check green, the input's bytes,
or their inverse. effects/gain.fx then shows a parameter reaching the effect: at its default the
picture is the input, at --set gain=0.25 the input's colour times 0.25. All of it twice: with the
uniforms' values compiled in as constants from the first frame (the runtime's default: every
value settled; uniforms.fx must say it compiled some in, and build no live pipeline, which no
frame runs), and with every uniform live
(PFX_FX_SPECIALISE=0): the same checks hold both ways. The files of RUN must run and pass with no message from the validation layer;
every other file must be one the runtime says it does not run yet (exit status 3), so a file that
starts to run is added to RUN rather than passing unseen. A file judged on another input (an EXR
of non-finite values) is the GL runtime's to judge.
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
CONFORMANCE = os.path.join(HERE, "..", "conformance")
INCLUDE = os.path.join(HERE, "..", "..", "..", "plugins", "fx", "include")

RUN = ["alpha.fx", "back_buffer.fx", "blending.fx", "compute.fx", "conversions.fx", "exists_and_widening.fx",
       "float_to_integer.fx", "formats.fx", "function_statics.fx", "identity.fx", "initializer_assignments.fx",
       "integer_matrices.fx", "integer_wrap.fx", "intrinsics_bits.fx", "intrinsics_math.fx", "invert.fx", "matrices.fx",
       "matrix_comparisons.fx", "matrix_swizzle_stores.fx", "mips.fx", "namespaced_constants.fx", "offsets_and_labels.fx",
       "operators.fx", "out_arguments.fx", "persistence.fx", "points.fx", "preprocessor.fx", "render_targets.fx", "reshade_language.fx",
       "samplers.fx", "size_1x1.fx", "size_constants.fx", "size_odd.fx", "stencil.fx", "stencil_back_buffer.fx",
       "texture_files.fx", "textures.fx", "uniforms.fx"]


def header(path):
    settings = {"size": "64x4", "expect": "checks", "cell": "4", "input": "gradient", "frames": "1"}
    with open(path) as f:
        for line in f:
            m = re.match(r"\s*//\s*(size|expect|cell|input|frames|technique):\s*(\S+)", line)
            if m:
                settings[m.group(1)] = m.group(2)
    return settings


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 2
    icds = sorted(glob.glob("/usr/share/vulkan/icd.d/lvp_icd.*.json"))
    if not icds:
        print("FAIL: lavapipe is not installed (/usr/share/vulkan/icd.d/lvp_icd.*.json): install mesa-vulkan-drivers")
        return 1
    layers = "/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json"
    if not os.path.exists(layers):
        print("FAIL: Khronos' validation layer is not installed (%s): install vulkan-validationlayers" % layers)
        return 1
    with tempfile.TemporaryDirectory(prefix="pfx-vulkan-checks-") as scratch:
        return run_all(argv[1], argv[2], icds[0], scratch)


def run_all(checks, plugin, icd, scratch):
    log = os.path.join(scratch, "validation.txt")
    with open(os.path.join(scratch, "vk_layer_settings.txt"), "w") as f:
        f.write("khronos_validation.report_flags = error,warn\n"
                "khronos_validation.debug_action = VK_DBG_LAYER_ACTION_LOG_MSG\n"
                "khronos_validation.log_filename = %s\n"
                "khronos_validation.enables = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT\n" % log)
    env = dict(os.environ, VK_ICD_FILENAMES=icd, VK_INSTANCE_LAYERS="VK_LAYER_KHRONOS_validation",
               VK_LAYER_SETTINGS_PATH=scratch, XDG_CACHE_HOME=scratch)  # the pipeline cache stays out of the user's
    failures, ran = [], 0
    for mode, specialise in (("specialised", "1"), ("live", "0")):
        ran += run_mode(checks, plugin, log, dict(env, PFX_FX_SPECIALISE=specialise), mode, failures)
    missing = [f for f in RUN if not os.path.exists(os.path.join(CONFORMANCE, f))]
    if missing:
        failures.append("RUN names files that are gone: %s" % missing)
    for failure in failures:
        print("FAIL: " + failure)
    if failures:
        return 1
    print("ok: %d runs of conformance files hold on Vulkan (lavapipe) as in GL, uniforms compiled in and live, "
          "with no message from the validation layer" % ran)
    return 0


def run_mode(checks, plugin, log, env, mode, failures):
    """Every file of RUN and the gain checks with `env`; returns how many files ran."""
    ran = 0
    for path in sorted(glob.glob(os.path.join(CONFORMANCE, "*.fx"))):
        name = os.path.basename(path)
        s = header(path)
        if s["expect"] not in ("checks", "input", "invert") or s["input"] not in ("gradient", "alpha"):
            continue  # judged on another input: the GL suite's business
        command = [checks, "--plugin", plugin, "-I" + os.path.abspath(INCLUDE), "--size", s["size"], "--cell", s["cell"], "--expect", s["expect"],
                   "--input", s["input"], "--frames", s["frames"]]
        if "technique" in s:
            command += ["--technique", s["technique"]]
        if os.path.exists(log):
            os.remove(log)
        result = subprocess.run(command + [path], capture_output=True, text=True, env=env, timeout=300)
        said = (result.stdout + result.stderr).strip()
        messages = open(log).read().strip() if os.path.exists(log) else ""
        if name in RUN:
            ran += 1
            if result.returncode != 0:
                failures.append("%s (%s): %s" % (name, mode, said))
            elif messages:
                failures.append("%s (%s): the validation layer said:\n%s" % (name, mode, messages[:4000]))
            elif name == "uniforms.fx" and ("values compiled in" in said) != (mode == "specialised"):
                failures.append("%s (%s): compiled values in where it should not, or not where it should: %s" % (name, mode, said))
            elif name == "uniforms.fx" and ("live pipelines built" in said) != (mode == "live"):
                failures.append("%s (%s): built live pipelines where none runs, or none where they run: %s" % (name, mode, said))
            else:
                print("%s (%s): %s" % (name, mode, said))
        elif result.returncode != 3:
            failures.append("%s ran (%s): add it to RUN in %s" % (name, said, __file__))
    gain = os.path.join(HERE, "effects", "gain.fx")
    for name, extra in (("gain at its default", ["--expect", "input"]),
                        ("gain set to 0.25", ["--set", "gain=0.25", "--expect", "gain", "--gain", "0.25"])):
        if os.path.exists(log):
            os.remove(log)
        result = subprocess.run([checks, "--plugin", plugin, "-I" + os.path.abspath(INCLUDE), "--size", "33x7", "--input", "alpha"] + extra + [gain],
                                capture_output=True, text=True, env=env, timeout=300)
        said = (result.stdout + result.stderr).strip()
        messages = open(log).read().strip() if os.path.exists(log) else ""
        if result.returncode != 0 or messages:
            failures.append("%s (%s): %s %s" % (name, mode, said, messages[:4000]))
        else:
            print("%s (%s): %s" % (name, mode, said))
    return ran


if __name__ == "__main__":
    sys.exit(main(sys.argv))
