#!/usr/bin/env python3
"""The libretro plugin as a host sees it: its listing and what it does with broken presets.

usage: test_libretro_plugin.py PFX_RENDER CONFORMANCE_DIR OUT_DIR

- `pfx-render --list --json` with PFX_LIBRETRO_PATH at the conformance folder lists every preset
  there as an effect libretro_<path> with its file (libretro_preset) and its parameters as the
  shaders declare them (label, range, step; the preset's value as the default; headings left
  out), and the presets that cannot be read in load_errors, with their files named;
- a preset referencing itself, one whose pass file is missing and one of 50,000 passes are load
  errors (the last one quickly), and stop no other preset;
- a preset whose shader does not compile and one whose lookup texture is not an image fail when
  the effect is made, with a message naming the file (and the line, for the shader; file:line:
  column for a GLSL-form shader), and pfx-render exits 4;
- a .glslp lists as libretro_<path>_glsl beside the .slangp presets; one whose pass file is
  missing is a load error; a feedback_pass that names no pass does not stop it;
- the folder given need not exist: that is a load error too.
"""
import json
import os
import subprocess
import sys
import time


def fail(message):
    sys.exit("FAIL: " + message)


def run(pfx_render, path, args, timeout=240):
    env = dict(os.environ, PFX_LIBRETRO_PATH=path)
    return subprocess.run([pfx_render] + args, env=env, capture_output=True, text=True, timeout=timeout)


def libretro_plugin(listing):
    for plugin in listing["plugins"]:
        if plugin["id"] == "org.pfx.libretro":
            return plugin
    fail("the libretro plugin is not in the listing")


def main():
    pfx_render, conformance, out_dir = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3]
    os.makedirs(out_dir, exist_ok=True)

    # The listing of the conformance folder.
    result = run(pfx_render, conformance, ["--list", "--json"])
    if result.returncode != 0:
        fail(f"--list failed: {result.stderr}")
    listing = json.loads(result.stdout)
    effects = {e["id"]: e for e in libretro_plugin(listing)["effects"]}
    presets = []
    for folder, _, files in os.walk(conformance):
        presets += [os.path.join(folder, f) for f in files if f.endswith(".slangp")]
    for preset in presets:
        relative = os.path.relpath(preset, conformance)[: -len(".slangp")]
        effect_id = "libretro_" + relative.replace("/", "_").lower()
        if relative == "broken/references_itself":
            if effect_id in effects:
                fail("a preset referencing itself is listed as an effect")
            continue
        if effect_id not in effects:
            fail(f"{relative}.slangp is not listed as {effect_id}")
        if os.path.realpath(effects[effect_id].get("libretro_preset", "")) != os.path.realpath(preset):
            fail(f"{effect_id}: libretro_preset is {effects[effect_id].get('libretro_preset')}, not {preset}")
    errors = listing["load_errors"]
    if not any("references_itself.slangp" in e for e in errors):
        fail(f"the self-reference is not a load error naming its file: {errors}")

    parameters = {p["id"]: p for p in effects["libretro_parameter"]["parameters"]}
    strength = parameters.get("strength")
    if not strength or strength["label"] != "Strength" or strength["default"] != 0.5 or strength["step"] != 0.05 or \
            strength["hard_min"] != 0 or strength["hard_max"] != 1:
        fail(f"strength is not as tint.slang declares it with the preset's 0.5: {strength}")
    if "heading" in parameters:
        fail("a heading (minimum = maximum) is offered as a parameter")
    for option in ("content_width", "content_height"):
        if parameters.get(option, {}).get("default") != 0:
            fail(f"{option} is missing or not 0 by default: {parameters.get(option)}")
    if effects["libretro_reference"]["parameters"][0]["default"] != 0.75:
        fail("the referencing preset's own value is not the default")

    # Presets that cannot be read, in a folder of their own beside a good one.
    bad = os.path.join(out_dir, "bad")
    os.makedirs(os.path.join(bad, "shaders"), exist_ok=True)
    with open(os.path.join(conformance, "shaders", "copy.slang")) as f:
        copy = f.read().replace('#include "vertex.inc"', '#include "' + os.path.join(conformance, "shaders", "vertex.inc") + '"')
    with open(os.path.join(bad, "shaders", "copy.slang"), "w") as f:
        f.write(copy)
    with open(os.path.join(bad, "good.slangp"), "w") as f:
        f.write("shaders = 1\nshader0 = shaders/copy.slang\n")
    with open(os.path.join(bad, "missing_pass.slangp"), "w") as f:
        f.write("shaders = 2\nshader0 = shaders/copy.slang\nshader1 = shaders/not_there.slang\n")
    # The GLSL form beside it: a good preset (its id gains _glsl), one whose pass file is missing.
    with open(os.path.join(conformance, "..", "retroarch", "shaders", "copy.glsl")) as f:
        copy_glsl = f.read()
    with open(os.path.join(bad, "shaders", "copy.glsl"), "w") as f:
        f.write(copy_glsl)
    with open(os.path.join(bad, "good.glslp"), "w") as f:
        f.write("shaders = 1\nshader0 = shaders/copy.glsl\nfeedback_pass = 7\n")
    with open(os.path.join(bad, "missing_glsl.glslp"), "w") as f:
        f.write("shaders = 1\nshader0 = shaders/gone.glsl\n")
    with open(os.path.join(bad, "huge.slangp"), "w") as f:
        f.write("shaders = 50000\n" + "".join(f"shader{i} = shaders/copy.slang\n" for i in range(50000)))
    start = time.monotonic()
    result = run(pfx_render, bad, ["--list", "--json"])
    took = time.monotonic() - start
    if result.returncode != 0:
        fail(f"--list over broken presets failed: {result.stderr}")
    listing = json.loads(result.stdout)
    ids = {e["id"] for e in libretro_plugin(listing)["effects"]}
    if ids != {"libretro_good", "libretro_good_glsl"}:
        fail(f"the listing of the broken folder is {sorted(ids)}, not just libretro_good and libretro_good_glsl")
    errors = "\n".join(listing["load_errors"])
    for name, words in (("missing_pass.slangp", "not_there.slang"), ("huge.slangp", "50000"),
                        ("missing_glsl.glslp", "gone.glsl")):
        if not any(name in e and words in e for e in listing["load_errors"]):
            fail(f"{name}: no load error naming {words}: {errors}")
    if took > 60:
        fail(f"listing the broken folder took {took:.0f} s")

    # Broken when made: exit 4 and the reason.
    picture = os.path.join(out_dir, "in.exr")
    result = run(pfx_render, conformance, ["--demo-image", "--size", "32x16", "--out", picture, "--chain", ""])
    if result.returncode != 0:
        fail(f"could not make the test picture: {result.stderr}")
    for effect, words in (("libretro_broken_does_not_compile", "syntax_error.slang:4"),
                          ("libretro_broken_not_an_image", "lookup texture 'Lut': cannot read")):
        result = run(pfx_render, conformance, ["--input", picture, "--chain", effect, "--out", os.path.join(out_dir, "x.exr")])
        if result.returncode != 4 or words not in result.stderr:
            fail(f"{effect}: exit {result.returncode} (not 4) or no '{words}' in:\n{result.stderr}")

    # A GLSL-form shader GL refuses: exit 4, the file, line and column of the error. A
    # feedback_pass that is not a pass is only a warning (RetroArch ignores it).
    broken_glsl = os.path.join(out_dir, "broken_glsl")
    os.makedirs(broken_glsl, exist_ok=True)
    with open(os.path.join(broken_glsl, "syntax_error.glsl"), "w") as f:
        f.write(copy_glsl.replace("  FragColor = vec4(", "  FragColor = vec4(undeclared_name + "))
    line = next(n for n, text in enumerate(open(os.path.join(broken_glsl, "syntax_error.glsl")), 1)
                if "undeclared_name" in text)
    with open(os.path.join(broken_glsl, "does_not_compile.glslp"), "w") as f:
        f.write("shaders = 1\nshader0 = syntax_error.glsl\n")
    result = run(pfx_render, broken_glsl, ["--input", picture, "--chain", "libretro_does_not_compile_glsl", "--out",
                                           os.path.join(out_dir, "x.exr")])
    words = f"syntax_error.glsl:{line}:"
    if result.returncode != 4 or words not in result.stderr or "undeclared_name" not in result.stderr:
        fail(f"the GLSL shader that does not compile: exit {result.returncode} (not 4) or no '{words}' in:\n"
             f"{result.stderr}")
    result = run(pfx_render, bad, ["--input", picture, "--chain", "libretro_good_glsl", "--out",
                                   os.path.join(out_dir, "good_glsl.exr")])
    if result.returncode != 0:
        fail(f"the good GLSL preset with a feedback_pass that is not a pass did not run: {result.stderr}")

    # A folder that does not exist.
    result = run(pfx_render, os.path.join(out_dir, "nowhere"), ["--list", "--json"])
    if not any("nowhere" in e for e in json.loads(result.stdout)["load_errors"]):
        fail("a PFX_LIBRETRO_PATH folder that does not exist is not named in load_errors")
    print("the listing and the broken presets are as expected")


if __name__ == "__main__":
    main()
