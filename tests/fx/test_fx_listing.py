#!/usr/bin/env python3
"""The FX plugin over a folder of good and broken effects (tests/fx/listing).

usage: test_fx_listing.py PFX_RENDER LISTING_DIR OUT_DIR

Checks that pfx-render --list --json lists every technique of the good file with its file and
technique name, label and parameters; that each broken file (a type error, a syntax error, an
#include cycle) is in load_errors with its file, line and column; and that the good effect renders,
with its image texture found in the collection's Textures folder and the right way up; and that
a ReShade preset (.ini) drives pfx-render: its enabled techniques in TechniqueSorting's order with
its values, and what it names that is not there in one warning; that its PreprocessorDefinitions
reach the effect (Level.fx's #ifndef default overridden) except the RESHADE_DEPTH_* settings pfx
defines itself, which are named as ignored; that a pfx JSON preset's "source_definitions" do the
same; and that pfx-fx-check reports the folder: the three techniques compiled, ran, finite and
changing the picture, the three broken files not compiled, exit status 1.
"""
import json
import os
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def main():
    render, listing, out = sys.argv[1:4]
    os.makedirs(out, exist_ok=True)
    env = dict(os.environ, PFX_FX_PATH=os.path.join(listing, "Shaders"))
    listed = subprocess.run([render, "--list", "--json"], env=env, capture_output=True, text=True, timeout=300)
    check(listed.returncode == 0, "--list exited with %d: %s" % (listed.returncode, listed.stderr))
    data = json.loads(listed.stdout)
    effects = {e["id"]: e for p in data["plugins"] for e in p["effects"]}
    for id_, technique in (("fx_goodtint", "GoodTint"), ("fx_goodsecond", "GoodSecond")):
        e = effects.get(id_)
        check(e is not None, "%s is not listed" % id_)
        if e:
            check(e.get("fx_file", "").endswith("Shaders/Good.fx"), "%s: fx_file is %r" % (id_, e.get("fx_file")))
            check(e.get("fx_technique") == technique, "%s: fx_technique is %r" % (id_, e.get("fx_technique")))
    tint = effects.get("fx_goodtint", {})
    check(tint.get("label") == "Good tint", "the label is %r, not the technique's ui_label" % tint.get("label"))
    params = {p["id"]: p for p in tint.get("parameters", [])}
    check("amount" in params and params["amount"].get("label") == "Amount", "parameter amount missing: %s" % list(params))
    errors = data["load_errors"]
    for where in ("sub/Broken.fx:5:10: error:", "Syntax.fx:3:25: error:", "Cycle.fx:2:2: error: #include cycle"):
        check(any(where in e for e in errors), "load_errors lacks %r: %s" % (where, errors))
    check(not any("Good.fx" in e for e in errors), "Good.fx is in load_errors: %s" % errors)
    # An effect asked for by the name of a file that did not compile: the file's error, not only
    # "unknown effect".
    asked = subprocess.run([render, "--demo-image", "--size", "8x8", "--chain", "fx_broken", "--out", os.path.join(out, "b.png")],
                           env=env, capture_output=True, text=True, timeout=300)
    check(asked.returncode == 4 and "unknown effect 'fx_broken'" in asked.stderr and
          "did not compile: " in asked.stderr and "sub/Broken.fx:5:10: error:" in asked.stderr,
          "--chain fx_broken: exit %d, %s" % (asked.returncode, asked.stderr))

    # 4x4 input; the stamp's top-left texel is red, so the top-left pixel becomes half red.
    pixels = np.full((4, 4, 4), 255, dtype=np.uint8)
    pixels[..., :3] = 100
    source = os.path.join(out, "input.png")
    spec = oiio.ImageSpec(4, 4, 4, oiio.UINT8)
    image = oiio.ImageOutput.create(source)
    image.open(source, spec)
    image.write_image(pixels)
    image.close()
    for amount, expected in (("0.5", [178, 50, 50]), ("0", [100, 100, 100])):
        target = os.path.join(out, "tint_%s.png" % amount)
        run = subprocess.run([render, "--input", source, "--chain", "fx_goodtint", "--set", "fx_goodtint.amount=" + amount,
                              "--out", target], env=env, capture_output=True, text=True, timeout=300)
        check(run.returncode == 0, "rendering fx_goodtint failed: %s" % run.stderr)
        if run.returncode == 0:
            got = oiio.ImageBuf(target).get_pixels(oiio.UINT8)[0, 0, :3].astype(int)
            check(np.abs(got - np.array(expected)).max() <= 1, "amount %s: top-left pixel %s, expected %s" % (amount, got, expected))
    # A ReShade preset: GoodTint enabled with Amount 0 (the picture unchanged), GoodSecond not
    # enabled, a technique and a value that do not exist.
    preset = os.path.join(out, "look.ini")
    with open(preset, "w") as f:
        f.write("PreprocessorDefinitions=\n"
                "Techniques=Missing@Missing.fx,GoodTint@Good.fx\n"
                "TechniqueSorting=GoodTint@Good.fx,GoodSecond@Good.fx,Missing@Missing.fx\n\n"
                "[Good.fx]\nAmount=0.000000\nNoSuchValue=3\n")
    target = os.path.join(out, "preset.png")
    run = subprocess.run([render, "--input", source, "--preset", preset, "--out", target, "--json"], env=env,
                         capture_output=True, text=True, timeout=300)
    check(run.returncode == 0, "rendering with the ReShade preset failed: %s" % run.stderr)
    warnings = [line for line in run.stderr.splitlines() if "left out:" in line]
    check(len(warnings) == 1 and "fx_missing (not loaded)" in warnings[0] and
          "fx_goodtint.nosuchvalue (no such parameter)" in warnings[0],
          "expected one warning naming fx_missing and fx_goodtint.nosuchvalue with their reasons: %s" % run.stderr)
    if run.returncode == 0:
        report = json.loads(run.stdout)
        check(report.get("effects") == ["fx_goodtint"], "the chain is not [fx_goodtint]: %s" % report.get("effects"))
        got = oiio.ImageBuf(target).get_pixels(oiio.UINT8)[..., :3].astype(int)
        check(np.abs(got - 100).max() == 0, "Amount=0 from the preset did not reach the effect: %s" % got[0, 0])
    # An old-style preset (techniques without their files), a value of the wrong type and a
    # colour given one number: one warning with each reason, nothing said of a value that a
    # technique of another file has (Gain is Grade.fx's, not Other.fx's), and the rest applies.
    grade = os.path.join(out, "grade")
    os.makedirs(grade, exist_ok=True)
    with open(os.path.join(grade, "Grade.fx"), "w") as f:
        f.write('#include "ReShade.fxh"\nuniform float Gain = 1.0;\nuniform float3 Lift = float3(0, 0, 0);\n'
                'float4 Main(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target '
                '{ return float4(tex2D(ReShade::BackBuffer, uv).rgb * Gain + Lift, 1.0); }\n'
                'technique Grade { pass { VertexShader = PostProcessVS; PixelShader = Main; } }\n')
    with open(os.path.join(grade, "Other.fx"), "w") as f:
        f.write('#include "ReShade.fxh"\nuniform float Strength = 0.0;\n'
                'float4 Main(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target '
                '{ return tex2D(ReShade::BackBuffer, uv) + Strength; }\n'
                'technique Other { pass { VertexShader = PostProcessVS; PixelShader = Main; } }\n')
    old_style = os.path.join(out, "old_style.ini")
    with open(old_style, "w") as f:
        f.write("Techniques=Grade,Other\n\n[Grade.fx]\nGain=0.500000\nLift=0.1\n\n[Other.fx]\nStrength=abc\n")
    target = os.path.join(out, "old_style.png")
    run = subprocess.run([render, "--input", source, "--preset", old_style, "--out", target],
                         env=dict(os.environ, PFX_FX_PATH=grade), capture_output=True, text=True, timeout=300)
    warnings = [line for line in run.stderr.splitlines() if "left out:" in line]
    check(run.returncode == 0 and len(warnings) == 1 and "fx_grade.lift (expects 3 numbers, got 1)" in warnings[0] and
          "fx_other.strength ('abc' is not a number)" in warnings[0] and "gain" not in warnings[0],
          "the old-style preset: exit %d, %s" % (run.returncode, run.stderr))
    if run.returncode == 0:
        got = oiio.ImageBuf(target).get_pixels(oiio.UINT8)[..., :3].astype(int)
        check(np.abs(got - 50).max() <= 1, "Gain=0.5 from the old-style preset: %s, expected 50" % got[0, 0])
    # PreprocessorDefinitions: Level.fx's grey is its macro PFX_TEST_LEVEL (0.25 by default) plus
    # 0.125 times RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN, which pfx defines as 0 and a preset may not
    # change. The back buffer holds sRGB-encoded 8-bit codes and the output is encoded again, so a
    # level shows as its own 8-bit code.
    def code(level):
        return int(round(level * 255))

    defined = "PreprocessorDefinitions= PFX_TEST_LEVEL=0.75 , RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN=1,PFX_TEST_FLAG\n"
    json_preset = os.path.join(out, "level.json")
    with open(json_preset, "w") as f:
        json.dump({"pfx_preset": 1, "chain": [{"effect": "fx_definedlevel"}],
                   "source_definitions": "PFX_TEST_LEVEL=0.5"}, f)
    for name, text, expected, ignored in (
            ("level_default.ini", "PreprocessorDefinitions=\n", code(0.25), False),
            ("level_defined.ini", defined, code(0.75), True),
            ("level.json", None, code(0.5), False)):
        path = os.path.join(out, name)
        if text is not None:
            with open(path, "w") as f:
                f.write(text + "Techniques=DefinedLevel@Level.fx\nTechniqueSorting=DefinedLevel@Level.fx\n")
        target = os.path.join(out, name + ".png")
        run = subprocess.run([render, "--input", source, "--preset", path, "--out", target], env=env,
                             capture_output=True, text=True, timeout=300)
        check(run.returncode == 0, "rendering with %s failed: %s" % (name, run.stderr))
        if run.returncode == 0:
            got = oiio.ImageBuf(target).get_pixels(oiio.UINT8)[..., :3].astype(int)
            check(np.abs(got - expected).max() <= 1, "%s: the grey is %s, expected %d" % (name, got[0, 0], expected))
        named = [line for line in run.stderr.splitlines() if "ignored" in line and "RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN" in line]
        check(len(named) == (1 if ignored else 0), "%s: RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN named as ignored %d times: %s"
              % (name, len(named), run.stderr))
    malformed = os.path.join(out, "level_malformed.ini")
    with open(malformed, "w") as f:
        f.write("PreprocessorDefinitions=PFX_TEST_LEVEL=0.5,2BAD=1\nTechniques=DefinedLevel@Level.fx\n")
    run = subprocess.run([render, "--input", source, "--preset", malformed, "--out", os.path.join(out, "malformed.png")], env=env,
                         capture_output=True, text=True, timeout=300)
    check(run.returncode != 0 and "2BAD" in run.stderr and "PreprocessorDefinitions" in run.stderr,
          "a malformed PreprocessorDefinitions list is not refused naming the entry: %d %s" % (run.returncode, run.stderr))

    tool = os.path.join(os.path.dirname(render), "pfx-fx-check")
    checked = subprocess.run([tool, "--json", "--picture", source, os.path.join(listing, "Shaders")], capture_output=True, text=True,
                             timeout=600)
    check(checked.returncode == 1, "pfx-fx-check exited with %d, not 1 (broken files): %s" % (checked.returncode, checked.stderr))
    try:
        table = json.loads(checked.stdout)
        rows = {r["technique"]: r for r in table["techniques"]}
        for name in ("GoodTint", "GoodSecond", "DefinedLevel"):
            r = rows.get(name, {})
            check(r.get("ran") and r.get("finite") and r.get("changed") and r.get("compile_ms") is not None and r.get("run_ms") is not None,
                  "pfx-fx-check's row for %s: %s" % (name, r))
        check(len(rows) == 3, "pfx-fx-check's techniques: %s" % sorted(rows))
        check(len(table["files_not_compiled"]) == 3, "pfx-fx-check's files not compiled: %s" % table["files_not_compiled"])
    except (ValueError, KeyError) as e:
        check(False, "pfx-fx-check --json gave no table (%s): %s" % (e, checked.stdout[:400]))
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print("ok: listing, load errors, rendering with an image texture, a ReShade preset and its definitions, pfx-fx-check")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
