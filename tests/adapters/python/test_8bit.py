"""8-bit pictures (what PIL, imageio and OpenCV hand out) run through Chain.run as pfx-render runs
an 8-bit PNG: decoded as display-referred sRGB (or linear with transfer="linear"), the display
defaults applied, the result encoded back to uint8 of the picture's shape. The reference is
pfx-render's PNG read back with PIL (straight alpha, as PNG stores it), bit for bit."""

import os
import shutil
import subprocess
import sys

import numpy as np
import pfx
import pytest
from PIL import Image

from conftest import PHOTOGRAPH, SOURCE_DIR, render


def read_png(path):
    """An 8-bit PNG as uint8 H x W x C, top row first, alpha straight as the file holds it (PIL;
    OpenImageIO would premultiply)."""
    with Image.open(path) as image:
        return np.ascontiguousarray(np.asarray(image), dtype=np.uint8)


def write_png(path, pixels):
    Image.fromarray(pixels).save(path)


@pytest.fixture(scope="module")
def photographs(tmp_path_factory):
    """Debian's photograph at an odd size, as RGB and as RGBA with a soft alpha ramp."""
    folder = tmp_path_factory.mktemp("photographs")
    rgb = read_png(PHOTOGRAPH)[:201, :317, :3].copy()
    alpha = np.linspace(40, 255, rgb.shape[1]).astype(np.uint8)[None, :, None].repeat(rgb.shape[0], 0)
    rgba = np.ascontiguousarray(np.concatenate([rgb, alpha], axis=2))
    found = {}
    for name, pixels in (("rgb", rgb), ("rgba", rgba)):
        path = folder / f"{name}.png"
        write_png(path, pixels)
        found[name] = (path, read_png(path))
    return found


def pfx_render_png(tmp_path, *args):
    out = tmp_path / "expected.png"
    render(*args, "--out", out)
    return read_png(out)


def assert_same_bytes(actual, expected, what):
    assert actual.dtype == np.uint8 and actual.shape == expected.shape, f"{what}: {actual.dtype} {actual.shape}"
    differ = np.argwhere(actual != expected)
    assert differ.size == 0, (f"{what}: {len(differ)} values differ, the first at {tuple(differ[0])}: "
                              f"{actual[tuple(differ[0])]} instead of {expected[tuple(differ[0])]}")


@pytest.mark.parametrize("layout", ["rgb", "rgba"])
@pytest.mark.parametrize("chain", [["bloom"], ["glare"], ["bloom", "glare"]])
def test_an_8_bit_picture_gives_pfx_render_s_png_bit_for_bit(photographs, tmp_path, layout, chain):
    path, pixels = photographs[layout]
    expected = pfx_render_png(tmp_path, "--input", path, "--chain", ",".join(chain))
    with pfx.Chain(chain) as effects:
        actual = effects.run(pixels)
    assert_same_bytes(actual, expected, f"{chain} on {layout}")
    assert not np.array_equal(actual, pixels), "the display defaults changed nothing: the comparison would prove nothing"


def test_transfer_linear_gives_pfx_render_s_transfer_linear(photographs, tmp_path):
    path, pixels = photographs["rgb"]
    expected = pfx_render_png(tmp_path, "--input", path, "--chain", "bloom", "--transfer", "linear")
    with pfx.Chain(["bloom"]) as chain:
        actual = chain.run(pixels, transfer="linear")
        as_srgb = chain.run(pixels)
    assert_same_bytes(actual, expected, "bloom with transfer linear")
    assert not np.array_equal(actual, as_srgb), "the transfer made no difference"


def test_values_set_hold_for_8_bit_pictures_as_in_pfx_render(photographs, tmp_path):
    path, pixels = photographs["rgb"]
    expected = pfx_render_png(tmp_path, "--input", path, "--chain", "bloom", "--set", "bloom.mode=gaussian",
                              "--set", "bloom.threshold=0.3")
    with pfx.Chain(["bloom"]) as chain:
        chain.set("bloom.mode", "gaussian")
        chain.set("bloom.threshold", 0.3)
        assert_same_bytes(chain.run(pixels), expected, "bloom gaussian, threshold 0.3")


def display_and_scene_default(effect_id, parameter_id):
    effect = next(e for e in pfx.effects() if e["id"] == effect_id)
    parameter = next(p for p in effect["parameters"] if p["id"] == parameter_id)
    return parameter["display_default"], parameter["default"]


def test_unset_values_follow_each_picture_s_dtype_and_set_ones_stay():
    display, scene = display_and_scene_default("bloom", "threshold")
    assert display != scene
    picture = np.full((6, 10, 3), 200, np.uint8)
    with pfx.Chain(["bloom"]) as chain:
        assert chain.get("bloom.threshold") == scene  # before any picture: the scene-referred defaults
        chain.run(picture)
        assert chain.get("bloom.threshold") == display
        chain.run(picture.astype(np.float32) / 255)
        assert chain.get("bloom.threshold") == scene
        chain.set("bloom.strength", 0.25)
        chain.run(picture)
        assert chain.get("bloom.threshold") == display and chain.get("bloom.strength") == 0.25
    with pfx.Chain(["bloom"], defaults="scene") as chain:
        chain.run(picture)
        assert chain.get("bloom.threshold") == scene


def test_pictures_of_changing_sizes_each_give_what_they_give_alone(photographs):
    _, pixels = photographs["rgb"]
    crops = [pixels[:1, :1], pixels[:5, :3], pixels, pixels[:5, :3], pixels]
    crops = [np.ascontiguousarray(c) for c in crops]
    with pfx.Chain(["bloom"]) as chain:
        in_turn = [chain.run(c) for c in crops]
    for crop, result in zip(crops, in_turn):
        with pfx.Chain(["bloom"]) as alone:
            assert_same_bytes(result, alone.run(crop), f"a {crop.shape} picture after others")


def test_float_pictures_of_changing_sizes_and_depth_reuse_nothing_stale():
    rng = np.random.default_rng(7)
    pictures = [rng.random((h, w, 4), np.float32) * 4 for h, w in ((9, 14), (9, 14), (4, 3), (9, 14))]
    depth = np.full((9, 14), 5.0, np.float32)
    with pfx.Chain(["bloom"]) as chain:
        in_turn = [chain.run(p) for p in pictures]
        with_depth = chain.run(pictures[0], depth=depth)
    with pfx.Chain(["bloom"]) as alone:
        for picture, result in zip(pictures, in_turn):
            assert np.array_equal(result, alone.run(picture), equal_nan=True)
    assert np.array_equal(with_depth, in_turn[0])


def test_the_pil_example_of_the_docs_runs_and_writes_bloom(tmp_path):
    extract = subprocess.run(["bash", os.path.join(SOURCE_DIR, "tests/install/doc_block.sh"),
                              os.path.join(SOURCE_DIR, "docs/python.md"), "<!-- run: bloom_photo.py -->"],
                             capture_output=True, text=True)
    assert extract.returncode == 0, extract.stderr
    (tmp_path / "bloom_photo.py").write_text(extract.stdout)
    shutil.copy(PHOTOGRAPH, tmp_path / "photo.png")
    done = subprocess.run([sys.executable, "bloom_photo.py"], cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    before, after = read_png(tmp_path / "photo.png")[..., :3], read_png(tmp_path / "photo-bloom.png")
    assert after.shape == before.shape and not np.array_equal(after, before)
