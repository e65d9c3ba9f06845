#!/usr/bin/env python3
"""Every ReShade FX technique of some folders through both of pfx's runtimes, side by side.

usage: compare_collections.py --render PFX_RENDER --checks FX_VULKAN_CHECKS --include FOLDER
                              --picture IMAGE [--size WxH] [--out DIR] FOLDER...

By hand, over collections that are not part of the tree (SweetFX, reshade-shaders): each technique
pfx-render lists runs once on IMAGE (scaled to --size, default 320x180) through pfx-render (the GL
runtime, in the FX plugin) and through FX_VULKAN_CHECKS (the Vulkan runtime, on the Vulkan device
the loader gives: lavapipe with VK_ICD_FILENAMES), and the two pictures are compared: the largest
difference in 8-bit codes and how many pixels differ by more than one code. Techniques that read
uniform sources this program holds at 0 (random, date...) are marked: their pictures may differ
for that alone. Needs /usr/bin/python3 with numpy and OpenImageIO. Exit status 0 when every
technique that ran on both is within one code.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

# What the FX plugin defines for every file (plugins/fx/runtime/fx_catalog.cpp, compile_options).
DEFINES = ["RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN=0", "RESHADE_DEPTH_INPUT_IS_REVERSED=0", "RESHADE_DEPTH_INPUT_IS_LOGARITHMIC=0",
           "RESHADE_DEPTH_MULTIPLIER=1", "RESHADE_DEPTH_LINEARIZATION_FAR_PLANE=1000.0"]


def read_png(path):
    config = oiio.ImageSpec()
    config.attribute("oiio:UnassociatedAlpha", 1)
    image = oiio.ImageInput.open(path, config)
    pixels = image.read_image(format=oiio.UINT8)
    image.close()
    if pixels.shape[2] == 3:
        pixels = np.concatenate([pixels, np.full(pixels.shape[:2] + (1,), 255, np.uint8)], axis=2)
    return pixels


def scaled_input(picture, width, height, path):
    source = oiio.ImageBuf(picture)
    resized = oiio.ImageBufAlgo.resize(source, roi=oiio.ROI(0, width, 0, height, 0, 1, 0, source.nchannels))
    resized.write(path, oiio.UINT8)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--render", required=True)
    parser.add_argument("--checks", required=True)
    parser.add_argument("--include", required=True)
    parser.add_argument("--picture", required=True)
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--out")
    parser.add_argument("folders", nargs="+")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    env = dict(os.environ, PFX_FX_PATH=":".join(os.path.abspath(f) for f in args.folders))
    listed = subprocess.run([args.render, "--list", "--json"], env=env, capture_output=True, text=True)
    effects = [e for p in json.loads(listed.stdout)["plugins"] for e in p["effects"] if "fx_file" in e]
    work = args.out or tempfile.mkdtemp(prefix="pfx-fx-compare-")
    os.makedirs(work, exist_ok=True)
    picture = os.path.join(work, "in.png")
    scaled_input(args.picture, width, height, picture)
    rows = []
    for n, effect in enumerate(effects):
        sys.stderr.write("\r[%d/%d] %s\033[K" % (n + 1, len(effects), effect["id"]))
        gl_out, vk_out = os.path.join(work, effect["id"] + ".gl.png"), os.path.join(work, effect["id"] + ".vk.rgba")
        gl = subprocess.run([args.render, "--input", picture, "--chain", effect["id"], "--out", gl_out], env=env,
                            capture_output=True, text=True, timeout=600)
        command = [args.checks, "-I" + os.path.abspath(args.include)] + ["-D" + d for d in DEFINES] + [
            "--size", args.size, "--input", picture, "--expect", "none", "--raw-out", vk_out, "--technique",
            effect["fx_technique"], effect["fx_file"]]
        vk = subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)
        said = (vk.stdout + vk.stderr).strip()
        row = {"effect": effect["id"], "gl": gl.returncode == 0, "vk": vk.returncode, "said": said.splitlines()[-1] if said else "",
               "zeroed": next((line for line in said.splitlines() if line.startswith("sources given as 0")), "")}
        if row["gl"] and vk.returncode == 0:
            a = read_png(gl_out).astype(np.int32)
            b = np.fromfile(vk_out, dtype=np.uint8).reshape(height, width, 4).astype(np.int32)
            difference = np.abs(a - b)
            row["max"] = int(difference.max())
            row["over_one"] = int((difference.max(axis=2) > 1).sum())
        rows.append(row)
    sys.stderr.write("\r\033[K")
    print("%-40s %-4s %-12s %8s %10s  %s" % ("effect", "gl", "vulkan", "max diff", "px > 1", "note"))
    for r in rows:
        vk = "ran" if r["vk"] == 0 else "not run" if r["vk"] == 3 else "FAILED"
        print("%-40s %-4s %-12s %8s %10s  %s" % (r["effect"][:40], "ran" if r["gl"] else "FAIL", vk, r.get("max", "-"),
                                                r.get("over_one", "-"), r["zeroed"] or (r["said"] if r["vk"] != 0 else "")))
    both = [r for r in rows if "max" in r]
    within = [r for r in both if r["max"] <= 1]
    print("%d techniques: %d ran on both, %d within one code (%d of those read sources held at 0); %d not run on Vulkan, "
          "%d failed there" % (len(rows), len(both), len(within), sum(1 for r in both if r["zeroed"]),
                               sum(1 for r in rows if r["vk"] == 3), sum(1 for r in rows if r["vk"] not in (0, 3))))
    return 0 if len(within) == len(both) else 1


if __name__ == "__main__":
    sys.exit(main())
