#!/usr/bin/env python3
"""RetroArch as the oracle of the GLSL form: one preset of this folder (presets and shaders
written here) run by RetroArch and by pfx-render on the same picture and frames must come out
within one code value per channel.

usage: compare_with_retroarch.py RETROARCH PFX_RENDER PRESET_DIR OUT_DIR CASE
       compare_with_retroarch.py --list          (the case names, one a line)

How the two pictures are made: host/programs/libretro_check/retroarch_oracle.py (which
pfx-libretro-check --compare-retroarch uses too). A case fails too when RetroArch did not apply
the preset (a picture that should change and did not, or a shader error in its log), and the
pass-through must give the picture back byte for byte on both sides.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "host", "programs",
                                "libretro_check"))
import retroarch_oracle as oracle  # noqa: E402

W, H = 640, 360
CASES = ["passthrough", "scale_parameters", "pictures", "frames", "lut", "unnamed_sampler", "vertex_coord"]


def picture():
    """A picture with slopes and fine detail in every channel."""
    y, x = np.mgrid[0:H, 0:W]
    p = np.zeros((H, W, 3), dtype=np.int64)
    p[..., 0] = (x * 255) // (W - 1)
    p[..., 1] = (y * 255) // (H - 1)
    p[..., 2] = (x * 13 + y * 29 + (x * y) % 7 * 20) % 256
    return p


def main():
    if sys.argv[1:] == ["--list"]:
        print("\n".join(CASES))
        return
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    retroarch, render, preset_dir, out_dir, case = sys.argv[1:]
    os.makedirs(out_dir, exist_ok=True)
    source = os.path.join(out_dir, "input.png")
    original = picture()
    oracle.write_png(source, original)
    preset = os.path.join(os.path.abspath(preset_dir), case + ".glslp")
    theirs, why = oracle.retroarch(retroarch, preset, source, out_dir)
    if why:
        sys.exit(why)
    ours, why = oracle.pfx(render, preset, "libretro_%s_glsl" % case, source, out_dir)
    if why:
        sys.exit(why)
    changed = int(np.abs(theirs - original).max())
    if case == "passthrough":
        if changed != 0 or np.abs(ours - original).max() != 0:
            sys.exit("the pass-through changed the picture (RetroArch by up to %d codes)" % changed)
    elif changed <= 8:
        sys.exit("RetroArch's picture is the input's: it did not apply the preset")
    worst, mean, (x, y, channel) = oracle.difference(theirs, ours)
    print("%s: RetroArch and pfx differ by at most %d codes (mean %.4f); the preset changed the picture by up to "
          "%d codes" % (case, worst, mean, changed))
    if worst > 1:
        oracle.write_png(os.path.join(out_dir, "difference.png"), np.clip(np.abs(theirs - ours) * 32, 0, 255))
        sys.exit("%s: more than one code apart at x=%d y=%d channel %d: RetroArch %s, pfx %s (difference.png in %s)"
                 % (case, x, y, channel, theirs[y, x], ours[y, x], out_dir))


if __name__ == "__main__":
    main()
