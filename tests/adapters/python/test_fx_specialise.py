"""FX uniforms that hold still are compiled into the programs as constants, and moving ones stay
live (docs/fx.md, "Uniforms as constants"): tests/fx/presets/Shaders/Grade.fx has four parameters,
a float3, a float, a combo and a bool. The report of each run says how many uniforms the running
programs hold as constants. Whatever the programs are, the picture for the same values is that of
a chain that keeps every uniform live (PFX_FX_SPECIALISE=0), within one 8-bit code: GLSL lets the
driver rearrange arithmetic on constants (llvmpipe folds 1 - (1 - c) * k + l into another order),
which moves a rounding. The conformance suite holds the two to the same bytes."""

import os
import time

import numpy as np

os.environ["PFX_FX_PATH"] = os.path.join(os.environ["PFX_SOURCE_DIR"], "tests", "fx", "presets", "Shaders")

import pfx  # noqa: E402

SETTLE_SECONDS = 0.5  # SettledValues::kSettleSeconds


def picture():
    y, x = np.mgrid[0:48, 0:64]
    return np.stack([(x * 4) % 256, (y * 5) % 256, (x + y) % 256], axis=-1).astype(np.uint8)


def same(a, b):
    """The same picture within one 8-bit code (see above)."""
    return a.shape == b.shape and int(np.abs(a.astype(int) - b.astype(int)).max()) <= 1


def constants(chain):
    return chain.report["effect_reports"]["fx_grade"]["uniforms_as_constants"]


def live_picture(values):
    """The picture of a chain whose uniforms are never constants."""
    os.environ["PFX_FX_SPECIALISE"] = "0"
    try:
        with pfx.Chain(["fx_grade"]) as chain:
            for key, value in values.items():
                chain.set(key, value)
            result = chain.run(picture())
            assert constants(chain) == 0
            return result
    finally:
        del os.environ["PFX_FX_SPECIALISE"]


def test_values_that_hold_still_are_constants_and_a_moving_value_is_live():
    with pfx.Chain(["fx_grade"]) as chain:
        first = chain.run(picture())
        assert constants(chain) == 4  # from the first frame: nothing has moved yet
        chain.set("fx_grade.gain", 0.5)
        moving = chain.run(picture())
        assert constants(chain) == 0  # just moved: live, no compile for each value of a drag
        chain.set("fx_grade.gain", 0.4)
        chain.set("fx_grade.mode", 1)
        still_moving = chain.run(picture())
        assert constants(chain) == 0
        time.sleep(SETTLE_SECONDS + 0.2)
        settled = chain.run(picture())
        assert constants(chain) == 4  # held still long enough: specialised for these values
    assert not same(first, moving) and not same(moving, still_moving)
    assert same(settled, still_moving)
    assert same(first, live_picture({}))
    assert np.array_equal(moving, live_picture({"fx_grade.gain": 0.5}))  # live both times
    assert same(settled, live_picture({"fx_grade.gain": 0.4, "fx_grade.mode": 1}))


def test_every_kind_of_value_set_gives_the_live_picture():
    values = {"fx_grade.lift": (0.1, -0.2, 0.05), "fx_grade.gain": 1.7, "fx_grade.mode": 1, "fx_grade.invert": True}
    with pfx.Chain(["fx_grade"]) as chain:
        for key, value in values.items():
            chain.set(key, value)
        specialised = chain.run(picture())
        assert constants(chain) == 4
    assert same(specialised, live_picture(values))
