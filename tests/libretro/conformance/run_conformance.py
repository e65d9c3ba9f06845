#!/usr/bin/env python3
"""Runs one libretro conformance case through pfx-render and the libretro plugin, and judges it.

usage: run_conformance.py PFX_RENDER CONFORMANCE_DIR OUT_DIR CASE
       run_conformance.py --list          (the case names, one a line)

Each case is a preset of CONFORMANCE_DIR (the effect libretro_<preset>) run over a picture made
here, with the parameters and frames the case gives. Every expected picture is worked out below
with numpy from the rules of libretro's format (the preset's sizes, filters, wrap modes, formats,
history and feedback) and the arithmetic of the conformance shaders, never from the plugin. Values
are 8-bit codes; a case allows at most `tolerance` codes of difference (0: byte for byte).
"""
import os
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

W, H = 15, 9  # odd on purpose


def gradient(w, h, shift=0):
    y, x = np.mgrid[0:h, 0:w]
    p = np.zeros((h, w, 3), dtype=np.int64)
    p[..., 0] = (x * 37 + y * 11 + shift) % 256
    p[..., 1] = (x * 5 + y * 67 + 2 * shift) % 256
    p[..., 2] = (x * 13 + y * 29 + 7 + 3 * shift) % 256
    return p


def write_png(path, pixels):
    out = oiio.ImageOutput.create(path)
    out.open(path, oiio.ImageSpec(pixels.shape[1], pixels.shape[0], 3, oiio.UINT8))
    out.write_image(pixels.astype(np.uint8))
    out.close()


def read(path, fmt=oiio.UINT8):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        sys.exit(f"cannot read {path}: {buf.geterror()}")
    return buf.get_pixels(fmt)[..., :3]


def rint(v):
    return np.floor(np.asarray(v, dtype=np.float64) + 0.5).astype(np.int64)


def srgb_encode(v):
    return np.where(v <= 0.0031308, v * 12.92, 1.055 * np.power(np.maximum(v, 0), 1 / 2.4) - 0.055)


def srgb_decode(v):
    return np.where(v <= 0.04045, v / 12.92, np.power((v + 0.055) / 1.055, 2.4))


# ---- expected pictures, from the input picture(s) ----------------------------------------------

def nearest_thirds(p):
    # Down to a third with nearest sampling (texel 3i+1), up again with nearest (texel x // 3).
    h, w = p.shape[:2]
    ys, xs = 3 * (np.arange(h) // 3) + 1, 3 * (np.arange(w) // 3) + 1
    return p[np.ix_(ys, xs)]


def wrapped(p, mode):
    # Column k = 2x - 7 of the source (x * 2 - 0.5 in texture coordinates, 15 texels).
    h, w = p.shape[:2]
    out = np.zeros_like(p)
    for x in range(w):
        k = 2 * x - 7
        if 0 <= k < w:
            src = k
        elif mode == "clamp_to_border":
            continue
        elif mode == "clamp_to_edge":
            src = min(max(k, 0), w - 1)
        elif mode == "repeat":
            src = k % w
        else:  # mirrored_repeat
            period = k % (2 * w)
            src = period if period < w else 2 * w - 1 - period
        out[:, x] = p[:, src]
    return out


def quarter_right(p):
    right = np.concatenate([p[:, 1:], p[:, -1:]], axis=1)
    return rint(0.75 * p + 0.25 * right)


def mip_level1(p):
    h, w = p.shape[:2]
    level = p.reshape(h // 2, 2, w // 2, 2, 3).mean(axis=(1, 3))
    return rint(level[np.ix_(np.arange(h) // 2, np.arange(w) // 2)])


def unorm_clamped(p):
    stored = rint(np.clip(p / 255 * 4 - 1.5, 0, 1) * 255) / 255
    return rint(np.clip((stored + 1.5) / 4, 0, 1) * 255)


def srgb_round_trip(p, stored_offset=0):
    # The framebuffer holds sRGB codes of c / 16; the next pass reads them decoded and multiplies
    # by 16, so one code of the encoder's rounding is several codes out: judged as a band over
    # the stored code +-1 (srgb_band).
    stored = (rint(srgb_encode(p / 255 / 16) * 255) + stored_offset) / 255
    return rint(np.clip(srgb_decode(stored) * 16, 0, 1) * 255)


def unorm_round_trip(p):
    # What the same passes give through an 8-bit UNORM framebuffer: c / 16 kept in 1/255 steps.
    return rint(np.clip(rint(p / 16) / 255 * 16, 0, 1) * 255)


def aliases(p):
    first = rint(p * 0.6)
    out = np.zeros_like(p)
    out[..., 0] = first[..., 0]
    out[..., 1] = 255 - first[..., 1]
    out[..., 2] = p[..., 2]
    return out


def solid(h, w, rgb):
    return np.broadcast_to(np.array(rgb, dtype=np.int64), (h, w, 3)).copy()


def halves(h, w, top_rows):
    out = solid(h, w, (0, 0, 255))
    out[:top_rows] = (255, 0, 0)
    return out


def lut_over(h, w):
    # lut.png, top row first, as it is stored.
    lut = np.array([[[255, 0, 0], [0, 255, 0], [0, 0, 255]], [[40, 80, 120], [160, 200, 240], [10, 20, 30]],
                    [[255, 255, 255], [128, 64, 32], [0, 0, 0]]], dtype=np.int64)
    rows = np.floor((np.arange(h) + 0.5) / h * 3).astype(int)
    cols = np.floor((np.arange(w) + 0.5) / w * 3).astype(int)
    return lut[np.ix_(rows, cols)]


def sizes(h, w, original, viewport, output, source):
    # Pass 0 (sizes.slang) at `output`; its rows whose TexCoord.y is below 0.45 hold the first colour.
    top = np.array([original[0], original[1], viewport[0]])
    bottom = np.array([output[0], output[1], source[0]])
    out = np.zeros((h, w, 3), dtype=np.int64)
    for y in range(h):
        row = int(np.floor((y + 0.5) / h * output[1]))  # the copy pass's nearest sample
        out[y] = top if (row + 0.5) / output[1] < 0.45 else bottom
    return out


def block_means(p, bw, bh):
    h, w = p.shape[:2]
    means = p.reshape(h // bh, bh, w // bw, bw, 3).mean(axis=(1, 3))
    return rint(means[np.ix_(np.arange(h) // bh, np.arange(w) // bw)])


def same(p):
    return p


# name: preset, picture size, frames, --set values, expected(last input) or per-frame check, tolerance
CASES = {
    "passthrough": dict(preset="passthrough", expect=same, tolerance=0),
    "passthrough_1x1": dict(preset="passthrough", size=(1, 1), expect=same, tolerance=0),
    "passthrough_even": dict(preset="passthrough", size=(16, 8), expect=same, tolerance=0),
    "scale_source": dict(preset="scale_source", expect=nearest_thirds, tolerance=0),
    "scale_viewport": dict(preset="scale_viewport", expect=nearest_thirds, tolerance=0),
    "scale_absolute": dict(preset="scale_absolute", expect=nearest_thirds, tolerance=0),
    "scale_source_1x1": dict(preset="scale_source", size=(1, 1), expect=same, tolerance=0),
    "wrap_clamp_to_border": dict(preset="wrap_clamp_to_border", expect=lambda p: wrapped(p, "clamp_to_border"), tolerance=0),
    "wrap_clamp_to_edge": dict(preset="wrap_clamp_to_edge", expect=lambda p: wrapped(p, "clamp_to_edge"), tolerance=0),
    "wrap_repeat": dict(preset="wrap_repeat", expect=lambda p: wrapped(p, "repeat"), tolerance=0),
    "wrap_mirrored_repeat": dict(preset="wrap_mirrored_repeat", expect=lambda p: wrapped(p, "mirrored_repeat"), tolerance=0),
    "filter_linear": dict(preset="filter_linear", expect=quarter_right, tolerance=1),
    "mipmap_input": dict(preset="mipmap_input", size=(16, 8), expect=mip_level1, tolerance=1),
    "float_framebuffer": dict(preset="float_framebuffer", expect=same, tolerance=1),
    "unorm_framebuffer": dict(preset="unorm_framebuffer", expect=unorm_clamped, tolerance=1),
    "srgb_framebuffer": dict(preset="srgb_framebuffer", band=[lambda p, k=k: srgb_round_trip(p, k) for k in (-1, 0, 1)],
                             unlike=unorm_round_trip, tolerance=1),
    "aliases": dict(preset="aliases", expect=aliases, tolerance=1),
    "parameter_from_preset": dict(preset="parameter", expect=lambda p: rint(p * 0.5), tolerance=1),
    "parameter_out_of_range": dict(preset="parameter", sets=["strength=5"], expect=lambda p: np.zeros_like(p), tolerance=0),
    "parameter_set": dict(preset="parameter", sets=["strength=0.1"], expect=lambda p: rint(p * 0.9), tolerance=1),
    "reference": dict(preset="reference", expect=lambda p: rint(p * 0.25), tolerance=1),
    "lut": dict(preset="lut", expect=lambda p: lut_over(*p.shape[:2]), tolerance=0),
    "sizes": dict(preset="sizes", expect=lambda p: sizes(H, W, (W, H), (W, H), (3 * W, 3 * H), (W, H)), tolerance=0),
    "sizes_with_content": dict(preset="sizes", sets=["content_width=5", "content_height=3"],
                               expect=lambda p: sizes(H, W, (5, 3), (W, H), (15, 9), (5, 3)), tolerance=0),
    "content_size": dict(preset="passthrough", sets=["content_width=5", "content_height=3"],
                         expect=lambda p: block_means(p, 3, 3), tolerance=1),
    # HDR off (BrightnessNits 200, the other HDR names 0), one sub-frame, the first, no rotation.
    "fixed_values": dict(preset="fixed_values", expect=lambda p: solid(H, W, (200, 8, 30)), tolerance=0),
    "top_by_texcoord": dict(preset="top_by_texcoord", expect=lambda p: halves(H, W, 4), tolerance=0),
    "top_by_fragcoord_last": dict(preset="top_by_fragcoord_last", expect=lambda p: halves(H, W, 4), tolerance=0),
    "top_by_fragcoord_chain": dict(preset="top_by_fragcoord_chain", expect=lambda p: halves(H, W, 4), tolerance=0),
    # An EXR holding NaN, +-Inf, 70000 and -1 among ordinary values: the host hands the effect
    # 8-bit codes, so the output is finite and within [0, 1].
    "nan_in_frame": dict(preset="passthrough", nan=True),
    # Sequences: frames 1..5, frame k's picture shifted by k; each frame judged.
    "history": dict(preset="history", frames=5,
                    expect_frame=lambda k, inputs: inputs[k - 2] if k >= 3 else np.zeros_like(inputs[1]), tolerance=0),
    "feedback": dict(preset="feedback", frames=5, expect_frame=lambda k, inputs: solid(H, W, [16 * k] * 3), tolerance=0),
    "feedback_alias": dict(preset="feedback_alias", frames=5,
                           expect_frame=lambda k, inputs: solid(H, W, [16 * k] * 3), tolerance=0),
    "frame_count": dict(preset="frame_count", frames=5, expect_frame=lambda k, inputs: solid(H, W, [k, 0, 0]), tolerance=0),
    "frame_count_mod": dict(preset="frame_count_mod", frames=5,
                            expect_frame=lambda k, inputs: solid(H, W, [k % 3, 0, 0]), tolerance=0),
}
# The cases the preset folder's presets must cover; the rest of the folder is for other tests.
BROKEN = "broken"


def render(pfx_render, conformance, out_dir, case, args):
    env = dict(os.environ, PFX_LIBRETRO_PATH=conformance)
    command = [pfx_render] + args + ["--chain", "libretro_" + case["preset"]]
    for s in case.get("sets", []):
        command += ["--set", f"libretro_{case['preset']}.{s}"]
    result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=240)
    with open(os.path.join(out_dir, "log.txt"), "w") as log:
        log.write(" ".join(command) + "\n" + result.stdout + result.stderr)
    if result.returncode != 0:
        sys.exit(f"pfx-render failed ({result.returncode}):\n{result.stdout}{result.stderr}")


def judge(name, got, want, tolerance):
    if got.shape != want.shape:
        sys.exit(f"{name}: the output is {got.shape}, expected {want.shape}")
    diff = np.abs(got.astype(np.int64) - want)
    if diff.max() > tolerance:
        y, x, c = np.unravel_index(np.argmax(diff), diff.shape)
        sys.exit(f"{name}: {np.count_nonzero(diff.max(axis=2) > tolerance)} pixels differ by more than {tolerance} "
                 f"code(s); the worst at x={x} y={y} channel {c}: {got[y, x].tolist()} against {want[y, x].tolist()}")


def main():
    if sys.argv[1:] == ["--list"]:
        print("\n".join(CASES))
        return
    if len(sys.argv) != 5 or sys.argv[4] not in CASES:
        sys.exit(__doc__)
    pfx_render, conformance, out_dir, name = sys.argv[1:]
    case = CASES[name]
    os.makedirs(out_dir, exist_ok=True)
    w, h = case.get("size", (W, H))
    if case.get("nan"):
        values = np.array([np.nan, np.inf, -np.inf, 70000.0, -1.0, 0.5, 0.0, 1.0], dtype=np.float32)
        y, x = np.mgrid[0:h, 0:w]
        pixels = np.ones((h, w, 4), dtype=np.float32)
        pixels[..., :3] = values[(x + y) % len(values)][..., None]
        path = os.path.join(out_dir, "in.exr")
        out = oiio.ImageOutput.create(path)
        out.open(path, oiio.ImageSpec(w, h, 4, oiio.FLOAT))
        out.write_image(pixels)
        out.close()
        render(pfx_render, conformance, out_dir, case, ["--input", path, "--out", os.path.join(out_dir, "out.exr")])
        got = read(os.path.join(out_dir, "out.exr"), oiio.FLOAT)
        if not np.isfinite(got).all() or got.min() < 0 or got.max() > 1:
            sys.exit(f"{name}: the output holds values that are not finite or outside [0, 1]: {got.min()} .. {got.max()}")
    elif "frames" in case:
        frames = case["frames"]
        inputs = {k: gradient(w, h, 40 * k) for k in range(1, frames + 1)}
        for k, p in inputs.items():
            write_png(os.path.join(out_dir, f"in.{k:04d}.png"), p)
        render(pfx_render, conformance, out_dir, case,
               ["--input", os.path.join(out_dir, "in.%04d.png"), "--frames", f"1-{frames}", "--overwrite",
                "--out", os.path.join(out_dir, "out.%04d.png")])
        for k in range(1, frames + 1):
            judge(f"{name} frame {k}", read(os.path.join(out_dir, f"out.{k:04d}.png")), case["expect_frame"](k, inputs),
                  case["tolerance"])
    else:
        p = gradient(w, h)
        write_png(os.path.join(out_dir, "in.png"), p)
        render(pfx_render, conformance, out_dir, case,
               ["--input", os.path.join(out_dir, "in.png"), "--out", os.path.join(out_dir, "out.png")])
        got = read(os.path.join(out_dir, "out.png"))
        if "band" in case:
            # Within [lowest - tolerance, highest + tolerance] of the pictures the band allows, and
            # unlike the picture a plainer implementation would give.
            band = np.stack([f(p) for f in case["band"]])
            low, high = band.min(axis=0) - case["tolerance"], band.max(axis=0) + case["tolerance"]
            outside = (got < low) | (got > high)
            if outside.any():
                y, x, c = np.argwhere(outside)[0]
                sys.exit(f"{name}: {np.count_nonzero(outside.any(axis=2))} pixels outside the expected band; x={x} y={y} "
                         f"channel {c}: {got[y, x, c]} not in [{low[y, x, c]}, {high[y, x, c]}]")
            if np.abs(got.astype(np.int64) - case["unlike"](p)).max() <= case["tolerance"]:
                sys.exit(f"{name}: the output is what an 8-bit UNORM framebuffer gives")
        else:
            judge(name, got, case["expect"](p), case["tolerance"])
    print(f"{name}: as expected")


if __name__ == "__main__":
    main()
