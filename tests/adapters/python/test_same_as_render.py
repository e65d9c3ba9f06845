"""Chain.run gives what pfx-render writes, bit for bit, on the same pictures and settings: the demo
image, a real photograph, a frame with depth and a picture of hard values; bloom in every mode,
depth of field in every mode, and a chain with two instances of one effect. pfx-render's output
is read back with OpenImageIO, not with pfx's own reader."""

import numpy as np
import pfx
import pytest

from conftest import assert_same_bits, read_image, render, write_exr


def enum_items(effect_id, parameter_id):
    """The items of an enum parameter, from the effects' own descriptions."""
    effect = next(e for e in pfx.effects() if e["id"] == effect_id)
    return [item["id"] for item in next(p for p in effect["parameters"] if p["id"] == parameter_id)["items"]]


def pfx_render(tmp_path, *args):
    out = tmp_path / "expected.exr"
    render(*args, "--out", out)
    return read_image(out)


@pytest.mark.parametrize("picture", ["demo", "photo"])
@pytest.mark.parametrize("mode", enum_items("bloom", "mode"))
def test_bloom_in_every_mode_equals_pfx_render(pictures, tmp_path, picture, mode):
    path, pixels = pictures[picture]
    expected = pfx_render(tmp_path, "--input", path, "--chain", "bloom", "--set", f"bloom.mode={mode}")
    with pfx.Chain(["bloom"]) as chain:
        chain.set("bloom.mode", mode)
        actual = chain.run(pixels)
    # pfx-render writes RGBA; a three-channel picture comes back with three.
    assert_same_bits(actual, expected[..., :pixels.shape[2]], f"bloom {mode} on {picture}")
    assert not np.array_equal(actual, pixels), "bloom changed nothing: the comparison would prove nothing"


@pytest.mark.parametrize("mode", enum_items("dof", "mode"))
def test_depth_of_field_with_depth_equals_pfx_render(depth_frame, tmp_path, mode):
    colour_path, depth_path, colour, depth = depth_frame
    expected = pfx_render(tmp_path, "--input", colour_path, "--depth", depth_path, "--chain", "dof",
                          "--camera", "fovy=40,near=0.1,far=100", "--set", f"dof.mode={mode}",
                          "--set", "dof.focus_distance=1.2")
    with pfx.Chain(["dof"]) as chain:
        chain.set("dof.mode", mode)
        chain.set("dof.focus_distance", 1.2)
        actual = chain.run(colour, depth=depth, camera=pfx.Camera(fovy=40, near=0.1, far=100))
    assert_same_bits(actual, expected[..., :3], f"dof {mode}")
    assert not np.array_equal(actual, colour), "depth of field changed nothing"


def test_two_instances_of_one_effect_keep_their_values_as_in_pfx_render(pictures, tmp_path):
    path, pixels = pictures["photo"]
    sets = ["bloom.strength=0.5", "bloom#2.mode=gaussian", "bloom#2.threshold=3", "glare.strength=2"]
    expected = pfx_render(tmp_path, "--input", path, "--chain", "bloom,glare,bloom",
                          *[arg for s in sets for arg in ("--set", s)])
    with pfx.Chain(["bloom", "glare", "bloom"]) as chain:
        assert chain.effects == ["bloom", "glare", "bloom#2"]
        for s in sets:
            key, value = s.split("=")
            chain.set(key, value)
        assert chain.get("bloom.mode") == "chain" and chain.get("bloom#2.mode") == "gaussian"
        actual = chain.run(pixels)
    assert_same_bits(actual, expected[..., :3], "bloom, glare, bloom#2")


def test_float16_pictures_give_float16_results_of_the_same_values(pictures, tmp_path):
    path, pixels = pictures["demo"]
    expected = pfx_render(tmp_path, "--input", path, "--chain", "glare")
    with pfx.Chain(["glare"]) as chain:
        actual = chain.run(pixels.astype(np.float16))
    assert actual.dtype == np.float16 and actual.shape == pixels.shape
    assert_same_bits(actual.astype(np.float32), expected, "glare on float16")


@pytest.mark.parametrize("height, width", [(1, 1), (3, 5), (7, 2)])
def test_hard_values_and_tiny_sizes_give_what_pfx_render_gives(tmp_path, height, width):
    # NaN, both infinities, past half's largest value, negative colour and zero, in every channel.
    hard = np.array([np.nan, np.inf, -np.inf, 70000.0, -1.0, 0.0, 5.0, 65504.0], np.float32)
    pixels = np.resize(hard, (height, width, 4)).astype(np.float32)
    path = tmp_path / "hard.exr"
    write_exr(path, pixels)
    pixels = read_image(path)  # as half, what pfx-render reads
    expected = pfx_render(tmp_path, "--input", path, "--chain", "bloom,glare")
    with pfx.Chain(["bloom", "glare"]) as chain:
        actual = chain.run(pixels)
    assert_same_bits(actual, expected, f"bloom and glare on hard values, {width}x{height}")


def test_the_top_row_stays_the_top_row():
    # One bright pixel near the top left of an otherwise black picture: bloom spreads it around
    # where it is. A flip on the way in without one on the way out would move it to the bottom.
    pixels = np.zeros((40, 64, 4), np.float32)
    pixels[3, 5, :3] = 100.0
    with pfx.Chain(["bloom"]) as chain:
        out = chain.run(pixels)
    assert np.unravel_index(np.argmax(out[..., 0]), out.shape[:2]) == (3, 5)
    assert out[:20, :32, 0].sum() > 100 * out[20:, :, 0].sum()
