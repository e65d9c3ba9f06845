#!/usr/bin/env python3
"""pfx-fx-check --compare-vkbasalt as a user runs it, on a folder of three FX files whose outcome is
known: invert.fx (both compilers run it and agree: 255 - x), intrinsics_bits.fx (vkBasalt 0.3.2.8
does not know countbits and the other bit intrinsics, so it does not run; pfx does), and a file
whose two techniques differ only in which comes first (vkBasalt runs a file's first technique:
the row names it). The table's JSON says so, and the exit status is 0: every file both ran agrees.

usage (under an X server): test_fx_check_compare.py PFX_FX_CHECK CONFORMANCE_FOLDER OUT_DIR
"""
import json
import os
import shutil
import subprocess
import sys


def main():
    tool, conformance, out = sys.argv[1:4]
    shutil.rmtree(out, ignore_errors=True)
    shaders = os.path.join(out, "Shaders")
    os.makedirs(shaders)
    for name in ("invert.fx", "intrinsics_bits.fx"):
        shutil.copy(os.path.join(conformance, name), shaders)
    shutil.copytree(os.path.join(conformance, "include"), os.path.join(shaders, "include"))
    with open(os.path.join(shaders, "Two.fx"), "w") as f:
        f.write('#include "ReShade.fxh"\n'
                'float4 Dark(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target { return tex2D(ReShade::BackBuffer, uv) * 0.5; }\n'
                'technique Halve { pass { VertexShader = PostProcessVS; PixelShader = Dark; } }\n'
                'technique AlsoHalve { pass { VertexShader = PostProcessVS; PixelShader = Dark; } }\n')
    result = subprocess.run([tool, "--compare-vkbasalt", "--json", "--out", os.path.join(out, "work"), shaders],
                            capture_output=True, text=True, timeout=600)
    failures = []
    try:
        rows = {os.path.basename(r["file"]): r for r in json.loads(result.stdout)["files"]}
    except (ValueError, KeyError) as e:
        print("FAIL: no JSON table (%s)\n%s%s" % (e, result.stdout[-2000:], result.stderr[-2000:]))
        return 1
    if result.returncode != 0:
        failures.append("exit status %d, not 0\n%s" % (result.returncode, result.stderr[-2000:]))
    invert = rows.get("invert.fx", {})
    if not (invert.get("vkbasalt_ran") and invert.get("pfx_ran") and invert.get("max_diff", 99) <= 1):
        failures.append("invert.fx: both should run and agree within one code: %s" % invert)
    bits = rows.get("intrinsics_bits.fx", {})
    if bits.get("vkbasalt_ran") or not bits.get("pfx_ran") or not bits.get("vkbasalt_says"):
        failures.append("intrinsics_bits.fx: vkBasalt should fail with its reason, pfx run: %s" % bits)
    two = rows.get("Two.fx", {})
    if two.get("technique") != "Halve" or two.get("techniques") != 2 or two.get("max_diff", 99) > 1:
        failures.append("Two.fx: the first technique, Halve, of 2, within one code: %s" % two)
    if sorted(rows) != ["Two.fx", "intrinsics_bits.fx", "invert.fx"]:
        failures.append("rows for %s" % sorted(rows))
    table = subprocess.run([tool, "--compare-vkbasalt", shaders], capture_output=True, text=True, timeout=600)
    if "3 files: vkBasalt ran 2, pfx ran 3; of the 2 both ran, 2 agree within one code value" not in table.stdout:
        failures.append("the table's summary line:\n" + table.stdout[-1500:])
    for failure in failures:
        print("FAIL: " + failure)
    if not failures:
        print("ok: pfx-fx-check --compare-vkbasalt: invert.fx agrees, intrinsics_bits.fx refused by vkBasalt with its "
              "reason, Two.fx compared on its first technique")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
