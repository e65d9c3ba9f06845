#!/usr/bin/env python3
"""Runs one GLSL-form preset through RetroArch and through pfx-render on the same picture, and
compares the two: within one code value per channel.

usage: compare_with_retroarch.py RETROARCH PFX_RENDER PRESET_DIR OUT_DIR CASE
       compare_with_retroarch.py --list          (the case names, one a line)

RetroArch (Debian's 1.14, its gl video driver and GLSL shader backend, on Mesa under Xvfb) shows
the picture in its built-in image viewer, in a window the picture's size, runs the preset for
FRAMES frames (--max-frames) and writes what its GPU drew (--max-frames-ss with
video_gpu_screenshot). At the screenshot RetroArch's shaders have run FRAMES + 2 times, with
FrameCount 0 to FRAMES + 1 (the frames case counts them by feedback and shows FrameCount), so
pfx-render runs the preset's effect (libretro_<case>_glsl) over the same picture as the frames 0
to FRAMES + 1 of a sequence, and the last one is compared. A case fails too when RetroArch did not apply the preset (a
picture that should change and did not, or a shader error in its log).
"""
import os
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

W, H = 640, 360
FRAMES = 4
CASES = ["passthrough", "scale_parameters", "pictures", "frames", "lut"]

RETROARCH_CONFIG = """video_driver = "gl"
video_gpu_screenshot = "true"
video_fullscreen = "false"
video_windowed_position_width = "{w}"
video_windowed_position_height = "{h}"
video_window_save_positions = "false"
video_scale = "1.0"
video_scale_integer = "false"
video_aspect_ratio_auto = "false"
aspect_ratio_index = "22"
video_smooth = "false"
video_vsync = "false"
video_shader_enable = "true"
video_font_enable = "false"
menu_driver = "null"
audio_driver = "null"
audio_enable = "false"
input_driver = "null"
joypad_driver = "null"
notification_show_screenshot = "false"
pause_nonactive = "false"
config_save_on_exit = "false"
builtin_imageviewer_enable = "true"
"""


def picture():
    """A picture with slopes and fine detail in every channel."""
    y, x = np.mgrid[0:H, 0:W]
    p = np.zeros((H, W, 3), dtype=np.int64)
    p[..., 0] = (x * 255) // (W - 1)
    p[..., 1] = (y * 255) // (H - 1)
    p[..., 2] = (x * 13 + y * 29 + (x * y) % 7 * 20) % 256
    return p.astype(np.uint8)


def write_png(path, pixels):
    out = oiio.ImageOutput.create(path)
    out.open(path, oiio.ImageSpec(pixels.shape[1], pixels.shape[0], 3, oiio.UINT8))
    out.write_image(pixels)
    out.close()


def read(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        sys.exit(f"cannot read {path}: {buf.geterror()}")
    return buf.get_pixels(oiio.UINT8)[..., :3].astype(np.int64)


def run(command, log, env=None):
    with open(log, "w") as out:
        result = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, env=env, timeout=300)
    if result.returncode != 0:
        sys.exit(f"{command[0]} exited {result.returncode}; see {log}:\n" + open(log).read()[-3000:])


def retroarch(binary, preset, source, out_dir):
    config = os.path.join(out_dir, "retroarch.cfg")
    with open(config, "w") as f:
        f.write(RETROARCH_CONFIG.format(w=W, h=H))
    shot = os.path.join(out_dir, "retroarch.png")
    if os.path.exists(shot):
        os.remove(shot)
    env = dict(os.environ, HOME=out_dir, XDG_CONFIG_HOME=os.path.join(out_dir, "config"))
    log = os.path.join(out_dir, "retroarch.log")
    run(["xvfb-run", "-a", "-s", "-screen 0 1024x768x24", binary, "--config", config, "--verbose",
         f"--max-frames={FRAMES}", "--max-frames-ss", f"--max-frames-ss-path={shot}", f"--set-shader={preset}",
         source], log, env)
    text = open(log, errors="replace").read()
    for bad in ("Failed to compile", "Failed to link", "Failed to load GLSL", "Failed to create GL program"):
        if bad in text:
            sys.exit(f"RetroArch did not run the preset ({bad}); see {log}")
    if not os.path.exists(shot):
        sys.exit(f"RetroArch wrote no screenshot; see {log}")
    return read(shot)


def pfx(binary, preset, case, source, out_dir):
    last = FRAMES + 1
    for n in range(0, last + 1):
        link = os.path.join(out_dir, f"in.{n:04d}.png")
        if not os.path.lexists(link):
            os.symlink(source, link)
    env = dict(os.environ, PFX_LIBRETRO_PATH=preset)
    run([binary, "--input", os.path.join(out_dir, "in.%04d.png"), "--frames", f"0-{last}", "--overwrite",
         "--chain", f"libretro_{case}_glsl", "--out", os.path.join(out_dir, "pfx.%04d.png")],
        os.path.join(out_dir, "pfx-render.log"), env)
    return read(os.path.join(out_dir, f"pfx.{last:04d}.png"))


def main():
    if sys.argv[1:] == ["--list"]:
        print("\n".join(CASES))
        return
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    retroarch_binary, pfx_render, preset_dir, out_dir, case = sys.argv[1:]
    os.makedirs(out_dir, exist_ok=True)
    source = os.path.join(out_dir, "input.png")
    original = picture()
    write_png(source, original)
    preset = os.path.join(os.path.abspath(preset_dir), case + ".glslp")
    theirs = retroarch(retroarch_binary, preset, source, out_dir)
    ours = pfx(pfx_render, preset, case, source, out_dir)
    if theirs.shape != ours.shape:
        sys.exit(f"RetroArch drew {theirs.shape[1]}x{theirs.shape[0]}, pfx {ours.shape[1]}x{ours.shape[0]}")
    changed = np.abs(theirs - original).max()
    if case == "passthrough":
        if changed != 0:
            sys.exit(f"RetroArch's pass-through differs from the picture by up to {changed} codes")
    elif changed <= 8:
        sys.exit("RetroArch's picture is the input's: it did not apply the preset")
    diff = np.abs(theirs - ours)
    worst = diff.max()
    print(f"{case}: RetroArch and pfx differ by at most {worst} codes (mean {diff.mean():.4f}); "
          f"the preset changed the picture by up to {changed} codes")
    if worst > 1:
        at = np.unravel_index(np.argmax(diff), diff.shape)
        write_png(os.path.join(out_dir, "difference.png"), np.clip(diff * 32, 0, 255).astype(np.uint8))
        sys.exit(f"{case}: more than one code apart at x={at[1]} y={at[0]} channel {at[2]}: "
                 f"RetroArch {theirs[at[0], at[1]]}, pfx {ours[at[0], at[1]]} (difference.png in {out_dir})")


if __name__ == "__main__":
    main()
