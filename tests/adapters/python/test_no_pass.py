"""A chain that would change nothing (no effect, or only effects whose values add nothing) runs
no pass and touches no GL: an 8-bit picture comes back as it came, a float one at the precision of
the chain's colour (half float, rounded to the nearest as numpy's float16 is), and the report
says that nothing ran."""

import numpy as np
import pfx
import pytest


def picture_8bit(layout):
    rng = np.random.default_rng(7)
    return rng.integers(0, 256, (21, 37, 4 if layout == "rgba" else 3), dtype=np.uint8)


def assert_nothing_ran(report, skipped):
    assert report["passes"] == [] and report["effects"] == [] and report["effects_skipped"] == skipped
    assert report["peak_target_bytes"] == 0


@pytest.mark.parametrize("layout", ["rgb", "rgba"])
def test_an_8_bit_picture_comes_back_as_it_came(layout):
    pixels = picture_8bit(layout)
    with pfx.Chain([]) as empty:
        assert np.array_equal(empty.run(pixels), pixels)
        assert_nothing_ran(empty.report, [])
    with pfx.Chain(["bloom", "glare"]) as no_ops:
        no_ops.set("bloom.strength", 0)
        no_ops.set("glare.strength", 0)
        for transfer in ("srgb", "linear"):
            out = no_ops.run(pixels, transfer=transfer)
            assert out.dtype == np.uint8 and np.array_equal(out, pixels), transfer
            assert_nothing_ran(no_ops.report, ["bloom", "glare"])


def test_a_float_picture_comes_back_at_half_float_precision():
    rng = np.random.default_rng(8)
    picture = (rng.random((19, 23, 4)) * 4).astype(np.float32)
    # Values a half cannot hold: one to round, one past its largest (65504), not-a-number.
    picture[0, 0, 0] = 1.0 + 3 * 2.0**-12  # three quarters of a half ulp: nearest rounds up, toward zero down
    picture[0, 1, 1] = 1e6
    picture[0, 2, 2] = np.nan
    expected = picture.astype(np.float16).astype(np.float32)
    with pfx.Chain(["bloom"]) as no_op:
        no_op.set("bloom.strength", 0)
        out = no_op.run(picture)
        assert_nothing_ran(no_op.report, ["bloom"])
    assert out.dtype == np.float32 and out.shape == picture.shape
    assert np.array_equal(out, expected, equal_nan=True)
    assert out[0, 0, 0] != picture[0, 0, 0] and np.isinf(out[0, 1, 1])
    # float16 in, float16 out: nothing to round.
    with pfx.Chain([]) as empty:
        half = picture.astype(np.float16)
        assert np.array_equal(empty.run(half), half, equal_nan=True)
