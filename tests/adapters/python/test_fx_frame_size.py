"""FX parameters whose default and range are written in terms of the frame's size (docs/fx.md,
"Parameters that follow the frame size"): tests/fx/frame_size/Scanlines.fx draws a dark line every
fPeriod rows of iHeight, whose default is BUFFER_HEIGHT. ReShade compiles an effect for the frame it
runs on, so by default there is one dark line per 4 rows of the picture at every size. The expected
counts are that arithmetic (height / 4, or the value set / 4), not anything pfx computes. One chain
runs frames of different sizes, as a host whose window is resized does."""

import os

import numpy as np

os.environ["PFX_FX_PATH"] = os.path.join(os.environ["PFX_SOURCE_DIR"], "tests", "fx", "frame_size")

import pfx  # noqa: E402


def dark_lines(picture):
    """Dark runs down column 5: the scanlines."""
    dark = picture[:, 5, 0] < 128
    return int(dark[0]) + int(np.sum(dark[1:] & ~dark[:-1]))


def grey(width, height):
    return np.full((height, width, 3), 128, dtype=np.uint8)


def test_listing_flags_the_parameter_and_shows_the_nominal_frame():
    effect = next(e for e in pfx.effects() if e["id"] == "fx_scanlines")
    params = {p["id"]: p for p in effect["parameters"]}
    assert params["iheight"].get("follows_frame_size") is True
    assert params["iheight"]["default"] == 1080 and params["iheight"]["display_max"] == 1080
    assert "follows_frame_size" not in params["fperiod"]  # 4.0 at every size


def test_an_unset_default_follows_every_size_in_one_chain():
    with pfx.Chain(["fx_scanlines"]) as chain:
        for width, height in ((640, 360), (320, 240), (33, 17 * 4), (640, 360)):
            assert dark_lines(chain.run(grey(width, height))) == height // 4, (width, height)


def test_a_set_value_stays_and_is_clamped_into_the_range_of_the_frame_once(capfd):
    with pfx.Chain(["fx_scanlines"]) as chain:
        chain.set("fx_scanlines.iheight", 120)
        assert dark_lines(chain.run(grey(640, 360))) == 120 // 4
        assert dark_lines(chain.run(grey(320, 240))) == 120 // 4
        chain.set("fx_scanlines.iheight", 1000)  # above a 240-row frame's range [1, 240]
        capfd.readouterr()
        assert dark_lines(chain.run(grey(320, 240))) == 240 // 4
        assert dark_lines(chain.run(grey(320, 240))) == 240 // 4
        log = capfd.readouterr().err  # the plugin's log, on stderr
        assert log.count("parameter 'iheight' = 1000 is outside its range at 320x240 [1, 240]") == 1, log
        assert dark_lines(chain.run(grey(64, 1200))) == 1000 // 4  # inside [1, 1200]: as set
