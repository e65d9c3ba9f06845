"""RetroArch as an independent runtime of libretro's GLSL presets: one preset run by RetroArch and
by pfx-render on the same picture and frames, and how far apart the two pictures are.

RetroArch (Debian's 1.14: its gl video driver and GLSL shader backend) shows the picture in its
built-in image viewer, in a window the picture's size, under its own Xvfb (xvfb-run), runs the
preset for FRAMES frames (--max-frames) and writes what its GPU drew (--max-frames-ss with
video_gpu_screenshot). At that screenshot its shaders have run FRAMES + 2 times, with FrameCount 0
to FRAMES + 1, so pfx-render runs the preset's effect over the same picture as the frames 0 to
FRAMES + 1 of a sequence, and the last one is compared. The image viewer has no content size:
pfx runs the preset over the whole picture as content, as RetroArch does.

Used by pfx-libretro-check --compare-retroarch and by the tests (tests/libretro/retroarch).
"""
import os
import subprocess

import numpy as np
import OpenImageIO as oiio

FRAMES = 4

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

# What RetroArch's log says when it did not run the preset it was given (it then falls back to its
# stock shader and still writes a screenshot).
RETROARCH_FAILURES = ("Failed to compile", "Failed to link", "Failed to load GLSL", "Failed to create GL program",
                      "Failed to initialize shader", "falling back to stock")


# The size the comparison runs at, one for every picture so that results compare: RetroArch's
# image viewer gives pfx's picture back byte for byte here, and the tests' presets agree to the
# code. RetroArch's gl driver holds a picture in a square power-of-two texture (1024x1024 here),
# pfx in one of its own size: shaders that read texture coordinates without scaling them by
# InputSize/TextureSize come out differently at any size but a square power of two.
SIZE = (640, 360)


def picture_at_size(picture, out_dir):
    """`picture` resized to SIZE (8-bit RGB) into out_dir; its path."""
    path = os.path.join(out_dir, "picture.png")
    buf = oiio.ImageBufAlgo.resize(oiio.ImageBuf(picture), roi=oiio.ROI(0, SIZE[0], 0, SIZE[1], 0, 1, 0, 3))
    write_png(path, np.clip(buf.get_pixels(oiio.UINT8)[..., :3], 0, 255))
    return path


def read_png(path):
    """A PNG's colour as written. pfx's outputs carry the alpha the last pass wrote (below 1 where a
    pass read past an edge); RetroArch's window shows colour alone, so the colour is read straight,
    not multiplied by alpha as OpenImageIO would by default."""
    config = oiio.ImageSpec()
    config.attribute("oiio:UnassociatedAlpha", 1)
    buf = oiio.ImageBuf(path, 0, 0, config)
    if buf.has_error:
        raise OSError("cannot read %s: %s" % (path, buf.geterror()))
    return buf.get_pixels(oiio.UINT8)[..., :3].astype(np.int64)


def write_png(path, pixels):
    out = oiio.ImageOutput.create(path)
    out.open(path, oiio.ImageSpec(pixels.shape[1], pixels.shape[0], 3, oiio.UINT8))
    out.write_image(np.asarray(pixels, dtype=np.uint8))
    out.close()


def _run(command, log, env, timeout):
    with open(log, "w") as out:
        try:
            result = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, env=env, timeout=timeout)
        except subprocess.TimeoutExpired:
            return "%s ran past %d s" % (os.path.basename(command[0]), timeout)
    if result.returncode != 0:
        return "%s exited %d (log: %s)" % (os.path.basename(command[0]), result.returncode, log)
    return None


def retroarch(binary, preset, picture, out_dir, timeout=300):
    """RetroArch's picture of `preset` over `picture` (a PNG), or (None, why not)."""
    size = oiio.ImageBuf(picture).spec()
    config = os.path.join(out_dir, "retroarch.cfg")
    with open(config, "w") as f:
        f.write(RETROARCH_CONFIG.format(w=size.width, h=size.height))
    shot = os.path.join(out_dir, "retroarch.png")
    if os.path.exists(shot):
        os.remove(shot)
    # Its playlists and settings stay in out_dir, not in the user's home.
    env = dict(os.environ, HOME=out_dir, XDG_CONFIG_HOME=os.path.join(out_dir, "config"))
    log = os.path.join(out_dir, "retroarch.log")
    why = _run(["xvfb-run", "-a", "-s", "-screen 0 %dx%dx24" % (max(size.width, 640), max(size.height, 480)), binary,
                "--config", config, "--verbose", "--max-frames=%d" % FRAMES, "--max-frames-ss",
                "--max-frames-ss-path=%s" % shot, "--set-shader=%s" % preset, picture], log, env, timeout)
    if why:
        return None, why
    text = open(log, errors="replace").read()
    for failure in RETROARCH_FAILURES:
        if failure in text:
            return None, "RetroArch did not run the preset (%s; log: %s)" % (failure, log)
    if not os.path.exists(shot):
        return None, "RetroArch wrote no screenshot (log: %s)" % log
    return read_png(shot), None


def pfx(render, preset, effect, picture, out_dir, timeout=600, folders=None):
    """pfx-render's picture of the effect `effect` over `picture` at the frame RetroArch's
    screenshot shows, or (None, why not). The effect is found with PFX_LIBRETRO_PATH at
    `folders` (':'-separated), by default the preset file alone (whose effect is then
    libretro_<file name>)."""
    last = FRAMES + 1
    for n in range(last + 1):
        link = os.path.join(out_dir, "in.%04d.png" % n)
        if not os.path.lexists(link):
            os.symlink(os.path.abspath(picture), link)
    env = dict(os.environ, PFX_LIBRETRO_PATH=folders or preset)
    why = _run([render, "--input", os.path.join(out_dir, "in.%04d.png"), "--frames", "0-%d" % last, "--overwrite",
                "--chain", effect, "--out", os.path.join(out_dir, "pfx.%04d.png")],
               os.path.join(out_dir, "pfx-render.log"), env, timeout)
    if why:
        return None, why
    return read_png(os.path.join(out_dir, "pfx.%04d.png" % last)), None


def difference(theirs, ours):
    """The largest and mean difference in codes, and where the largest is (x, y, channel)."""
    if theirs.shape != ours.shape:
        raise ValueError("RetroArch drew %dx%d, pfx %dx%d" % (theirs.shape[1], theirs.shape[0], ours.shape[1],
                                                             ours.shape[0]))
    diff = np.abs(theirs - ours)
    at = np.unravel_index(np.argmax(diff), diff.shape)
    return int(diff.max()), float(diff.mean()), (int(at[1]), int(at[0]), int(at[2]))
