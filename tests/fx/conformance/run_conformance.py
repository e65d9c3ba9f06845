#!/usr/bin/env python3
"""Runs one FX conformance file through pfx-render and judges the picture it makes.

usage: run_conformance.py PFX_RENDER FILE.fx OUT_DIR

The file says in its header comments how it is judged; every expected value comes from the file
(numbers worked out by hand) or from numpy here, never from the compiler under test:

  // technique: NAME          the technique to run (default: the file's name)
  // size: WxH                the input picture's size (default 64x4)
  // input: gradient|alpha|nan  the input: an 8-bit gradient PNG (default), the same with an alpha
                              that varies, or an EXR holding NaN, +Inf, -Inf, 70000, -1 and
                              ordinary values
  // expect: checks           every pixel green: the shader checked its own results (default).
                              Check i covers the pixel columns [i*CELL, (i+1)*CELL); a red one
                              names the check that failed.
  // expect: input            the output equals the input, byte for byte (alpha too)
  // expect: invert           the output is 255 - the input in R, G and B
  // expect: finite           the output (EXR) is finite everywhere and in [0, 1]
  // cell: N                  columns per check (default 4)
  // frames: N                render N frames of a sequence (the last is judged)

Every file is rendered twice: with the uniforms that hold still compiled in as constants (the FX
plugin's default) and with every uniform live (PFX_FX_SPECIALISE=0). The two pictures must be the
same bytes: specialising a program must never change what it computes.
"""
import os
import re
import shutil
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio


def header(path):
    settings = {"size": "64x4", "input": "gradient", "expect": "checks", "cell": "4", "frames": "1"}
    with open(path) as f:
        for line in f:
            m = re.match(r"\s*//\s*(technique|size|input|expect|cell|frames):\s*(\S+)", line)
            if m:
                settings[m.group(1)] = m.group(2)
    settings.setdefault("technique", os.path.splitext(os.path.basename(path))[0])
    return settings


def write(path, pixels, fmt):
    spec = oiio.ImageSpec(pixels.shape[1], pixels.shape[0], pixels.shape[2], fmt)
    spec.attribute("oiio:UnassociatedAlpha", 1)  # the values as given, not divided by alpha
    out = oiio.ImageOutput.create(path)
    out.open(path, spec)
    out.write_image(pixels)
    out.close()


def read(path, fmt):
    # As stored: OpenImageIO would otherwise multiply a PNG's colour by its alpha on reading.
    config = oiio.ImageSpec()
    config.attribute("oiio:UnassociatedAlpha", 1)
    buf = oiio.ImageBuf(path, 0, 0, config)
    return buf.get_pixels(fmt)


def make_input(settings, folder):
    w, h = (int(v) for v in settings["size"].split("x"))
    if settings["input"] == "nan":
        values = np.array([np.nan, np.inf, -np.inf, 70000.0, -1.0, 0.5, 0.0, 1.0], dtype=np.float32)
        pixels = np.zeros((h, w, 4), dtype=np.float32)
        for y in range(h):
            for x in range(w):
                pixels[y, x, :3] = values[(x + y) % len(values)]
                pixels[y, x, 3] = 1.0
        path = os.path.join(folder, "input.exr")
        write(path, pixels, oiio.FLOAT)
        return path, pixels
    y, x = np.mgrid[0:h, 0:w]
    pixels = np.zeros((h, w, 4), dtype=np.uint8)
    pixels[..., 0] = (x * 37 + y * 11) % 256
    pixels[..., 1] = (x * 5 + y * 67) % 256
    pixels[..., 2] = (x * 3 + 128) % 256
    pixels[..., 3] = (x * 7 + y * 13) % 256 if settings["input"] == "alpha" else 255
    path = os.path.join(folder, "input.png")
    write(path, pixels, oiio.UINT8)
    return path, pixels


def run_render(render, settings, input_path, technique, frames, prefix, env):
    """Renders the input (a sequence of it with frames > 1) through the technique; the path of the
    picture judged, or None after saying why pfx-render failed."""
    exr = settings["expect"] == "finite"
    out_path = prefix + (".exr" if exr else ".png")
    command = [render, "--input", input_path, "--chain", technique, "--out", out_path]
    if frames > 1:
        # A sequence of the same picture: the effect sees frame indices 0 .. N-1.
        pattern = os.path.join(os.path.dirname(prefix), "seq.%04d" + os.path.splitext(input_path)[1])
        for i in range(frames):
            shutil.copyfile(input_path, pattern % i)
        out_pattern = prefix + ".%04d" + os.path.splitext(out_path)[1]
        command = [render, "--input", pattern, "--frames", "0-%d" % (frames - 1), "--overwrite", "--chain", technique,
                   "--out", out_pattern]
        out_path = out_pattern % (frames - 1)
    result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)
    if result.returncode != 0:
        print(" ".join(command))
        print(result.stdout + result.stderr)
        print("FAIL: pfx-render exited with %d" % result.returncode)
        return None
    return out_path


def main():
    render, fx_file, folder = sys.argv[1:4]
    settings = header(fx_file)
    os.makedirs(folder, exist_ok=True)
    input_path, input_pixels = make_input(settings, folder)
    env = dict(os.environ, PFX_FX_PATH=fx_file)
    technique = "fx_" + re.sub(r"[^a-z0-9]+", "_", settings["technique"].lower()).strip("_")
    frames = int(settings["frames"])
    out_path = run_render(render, settings, input_path, technique, frames, os.path.join(folder, "specialised"), env)
    live_path = run_render(render, settings, input_path, technique, frames, os.path.join(folder, "live"),
                           dict(env, PFX_FX_SPECIALISE="0"))
    if not out_path or not live_path:
        return 1
    with open(out_path, "rb") as a, open(live_path, "rb") as b:
        if a.read() != b.read():
            print("FAIL: the specialised programs' picture (%s) differs from the live ones' (%s)" % (out_path, live_path))
            return 1
    if settings["expect"] == "finite":
        out = read(out_path, oiio.FLOAT)[..., :3]
        bad = ~np.isfinite(out) | (out < 0) | (out > 1)
        if bad.any():
            print("FAIL: %d values not finite or outside [0, 1], e.g. %s" % (bad.sum(), out[bad][:8]))
            return 1
        print("ok: every value finite and in [0, 1]")
        return 0
    out = read(out_path, oiio.UINT8).astype(int)
    if settings["expect"] == "input" or settings["expect"] == "invert":
        channels = 4 if settings["expect"] == "input" else 3
        want = input_pixels[..., :channels].astype(int)
        if settings["expect"] == "invert":
            want = 255 - want
        diff = np.abs(out[..., :channels] - want)
        if diff.max() > 0:
            ys, xs = np.nonzero(diff.max(axis=2))
            print("FAIL: %d pixels differ, up to %d codes; first at (%d, %d): %s, expected %s"
                  % (len(xs), diff.max(), xs[0], ys[0], out[ys[0], xs[0], :channels], want[ys[0], xs[0]]))
            return 1
        print("ok: %s, byte for byte" % settings["expect"])
        return 0
    cell = int(settings["cell"])
    green = (out[..., 1] > 200) & (out[..., 0] < 50)
    failed = sorted(set(int(x) // cell for x in np.nonzero(~green)[1]))
    checks = out.shape[1] // cell
    if failed:
        print("FAIL: checks %s of %d (columns of %d pixels; see the comments in %s)" % (failed, checks, cell, fx_file))
        return 1
    print("ok: %d checks" % checks)
    return 0


if __name__ == "__main__":
    sys.exit(main())
