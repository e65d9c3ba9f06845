#!/usr/bin/env python3
"""A measurement, not a test (ctest does not run it): every FX file of shader collections that are
not part of the tree, through vkBasalt in vkcube and through pfx-render on the same frame, as
run_vkbasalt.py does for the conformance files. Prints a Markdown table, one row per file: did
vkBasalt compile it (its log), run it (vkcube exited normally and pfx's layer below it captured
frame 5), and how far its frame is from pfx-render's.

usage (from the build folder, under an X server):
  xvfb-run -a -s "-screen 0 640x480x24 -nolisten tcp" /usr/bin/python3 \\
      ../tests/fx/vkbasalt/measure_collections.py --render bin/pfx-render --layer lib/libpfxvulkanlayer.so \\
      --include ../plugins/fx/include --out vkbasalt-collections \\
      SHADER_FOLDER:TEXTURE_FOLDER [SHADER_FOLDER:TEXTURE_FOLDER...]

vkBasalt takes one include folder: pfx's own (ReShade.fxh, ReShadeUI.fxh), after the file's own
folder (a collection's own ReShade.fxh beside its files is found first, by both). pfx-render finds
textures in the collection's Textures folders by itself; vkBasalt in TEXTURE_FOLDER.
"""
import argparse
import glob
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_vkbasalt  # noqa: E402


def techniques(path):
    """Technique names in file order, outside comments (a technique inside #if is still counted:
    the table says which one ran)."""
    text = open(path, errors="replace").read()
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    return re.findall(r"^\s*technique\s+(\w+)", text, flags=re.M)


def measure(args, fx, textures):
    name = os.path.basename(fx)
    out = os.path.join(args.out, os.path.splitext(name)[0])
    os.makedirs(out, exist_ok=True)
    found = techniques(fx)
    if not found:
        return {"file": name, "note": "no technique"}
    row = {"file": name, "technique": found[0], "count": len(found)}
    run_args = argparse.Namespace(out=out, icd=args.icd, vkcube=args.vkcube)
    run_vkbasalt.write_explicit_manifest(out, os.path.abspath(args.layer))
    code, output, log = run_vkbasalt.vkcube_frame(run_args, "pristine", {"DISABLE_VKBASALT": "1"})
    if code != 0:
        row["note"] = "vkcube without vkBasalt exited with %d" % code
        return row
    config = os.path.join(out, "vkBasalt.conf")
    with open(config, "w") as f:
        f.write("effects = measured\nmeasured = %s\nreshadeIncludePath = %s\nreshadeTexturePath = %s\n"
                % (fx, os.path.abspath(args.include), textures))
    code, output, log = run_vkbasalt.vkcube_frame(run_args, "vkbasalt", {
        "ENABLE_VKBASALT": "1", "VKBASALT_CONFIG_FILE": config, "VKBASALT_LOG_LEVEL": "debug"})
    with open(os.path.join(out, "vkbasalt-output.txt"), "w") as f:
        f.write(output)
    errors = [line for line in output.splitlines()
              if line.startswith("vkBasalt err") and not re.search(r": warning X?\d*:", line)]
    crash = [line for line in output.splitlines() if "Assertion" in line or "terminate called" in line
             or "what():" in line]
    row["compiled"] = not errors and "finished creating Reshade effect" in output
    captured = os.path.exists(os.path.join(out, "vkbasalt.app.png"))
    # A file with compile errors still gives vkBasalt a module, which it runs: no comparison then.
    row["ran"] = row["compiled"] and code == 0 and captured and "applying ReshadeEffect" in output
    row["vkbasalt_says"] = (errors[0].split(": ", 1)[-1] if errors else crash[0] if crash
                            else "" if code == 0 else "vkcube exited with %d" % code)
    ours_path = os.path.join(out, "pfx-render.png")
    effect = "fx_" + re.sub(r"[^a-z0-9]+", "_", found[0].lower()).strip("_")
    result = subprocess.run([args.render, "--input", os.path.join(out, "pristine.app.png"), "--chain", effect,
                             "--out", ours_path], env=dict(os.environ, PFX_FX_PATH=fx), capture_output=True, text=True,
                            timeout=600)
    row["pfx_ran"] = result.returncode == 0
    if not row["pfx_ran"]:
        row["pfx_says"] = (result.stdout + result.stderr).strip().splitlines()[-1:]
    if row["ran"] and row["pfx_ran"]:
        ours = run_vkbasalt.read(ours_path)
        theirs = run_vkbasalt.read(os.path.join(out, "vkbasalt.app.png"))
        pristine = run_vkbasalt.read(os.path.join(out, "pristine.app.png"))
        diff = np.abs(ours - theirs).max(axis=2)
        row["max_diff"] = int(diff.max())
        row["pixels_over_1"] = int((diff > 1).sum())
        row["changed_by_pfx"] = int((np.abs(ours - pristine).max(axis=2) > 0).sum())
        row["changed_by_vkbasalt"] = int((np.abs(theirs - pristine).max(axis=2) > 0).sum())
    return row


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--render", required=True)
    parser.add_argument("--layer", required=True)
    parser.add_argument("--include", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--vkcube", default="/usr/bin/vkcube")
    parser.add_argument("--icd", default="/usr/share/vulkan/icd.d/lvp_icd.x86_64.json")
    parser.add_argument("collections", nargs="+", help="SHADER_FOLDER:TEXTURE_FOLDER")
    args = parser.parse_args()
    print("| file | technique (of n) | vkBasalt compiles | runs | pfx runs | max diff | pixels > 1 | "
          "changed by pfx / by vkBasalt | vkBasalt says |")
    print("|---|---|---|---|---|---|---|---|---|")
    for collection in args.collections:
        shaders, textures = collection.split(":")
        for fx in sorted(glob.glob(os.path.join(shaders, "*.fx"))):
            row = measure(args, fx, textures)
            yes = lambda key: "" if key not in row else "yes" if row[key] else "no"  # noqa: E731
            print("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                os.path.relpath(fx, os.path.dirname(os.path.normpath(shaders))),
                "%s (%d)" % (row["technique"], row["count"]) if "technique" in row else row.get("note", ""),
                yes("compiled"), yes("ran"), yes("pfx_ran") + (" " + str(row.get("pfx_says", "")) if "pfx_says" in row else ""),
                row.get("max_diff", ""), row.get("pixels_over_1", ""),
                "%s / %s" % (row["changed_by_pfx"], row["changed_by_vkbasalt"]) if "changed_by_pfx" in row else "",
                row.get("vkbasalt_says", "").replace("|", "\\|")[:160]), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
