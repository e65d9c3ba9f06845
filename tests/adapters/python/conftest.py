"""What the Python module's tests share: the programs they compare against (pfx-render,
pfx-import, from the same build), pictures read and written with OpenImageIO (OpenEXR's reader,
not pfx's), and the pictures themselves: the demo image, a real photograph and a frame with depth.

The build passes the paths in the environment (tests/adapters/python/CMakeLists.txt)."""

import json
import os
import subprocess

import numpy as np
import OpenImageIO as oiio
import pytest

RENDER = os.environ["PFX_RENDER"]
IMPORT = os.environ["PFX_IMPORT"]
PHOTOGRAPH = os.environ["PFX_TEST_PHOTOGRAPH"]
SOURCE_DIR = os.environ["PFX_SOURCE_DIR"]


def run_program(*args):
    """Runs one of pfx's programs; its stdout, or a test failure carrying its stderr."""
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    assert done.returncode == 0, f"{' '.join(map(str, args))} failed ({done.returncode}):\n{done.stderr}"
    return done.stdout


def render(*args):
    """pfx-render with the given arguments and --json: its report."""
    return json.loads(run_program(RENDER, *args, "--json"))


def read_image(path):
    """A picture file as float32 H x W x C, top row first, through OpenImageIO."""
    image = oiio.ImageInput.open(str(path))
    assert image, oiio.geterror()
    pixels = image.read_image(format="float")
    image.close()
    return np.ascontiguousarray(pixels, dtype=np.float32)


def write_exr(path, pixels, channels=None):
    """A half-float EXR of float pixels (H x W x C; channel names R, G, B, A or the ones given)."""
    height, width, count = pixels.shape
    spec = oiio.ImageSpec(width, height, count, "half")
    if channels:
        spec.channelnames = channels
    out = oiio.ImageOutput.create(str(path))
    assert out and out.open(str(path), spec), oiio.geterror()
    assert out.write_image(pixels.astype(np.float32))
    out.close()


def as_half(pixels):
    """What a half-float EXR of these values holds, as float32."""
    return pixels.astype(np.float16).astype(np.float32)


def assert_same_bits(actual, expected, what):
    """Equal bit for bit, NaN included; the first differing pixel named otherwise."""
    assert actual.shape == expected.shape, f"{what}: shape {actual.shape} != {expected.shape}"
    same = actual.view(np.uint32) == expected.view(np.uint32)
    if not same.all():
        y, x, c = np.argwhere(~same)[0]
        pytest.fail(f"{what}: {np.count_nonzero(~same)} values differ; first at row {y}, column {x}, channel {c}: "
                    f"{actual[y, x, c]!r} != {expected[y, x, c]!r}")


@pytest.fixture(scope="session")
def pictures(tmp_path_factory):
    """The three pictures of the comparison tests, as half EXR files and as numpy float32 arrays."""
    folder = tmp_path_factory.mktemp("pictures")
    found = {}
    # The demo image pfx-render makes (bright spots, fine detail), passed through a bloom that does
    # nothing (strength 0), so the file holds exactly the colour pfx-render starts from.
    demo = folder / "demo.exr"
    render("--demo-image", "--size", "192x108", "--chain", "bloom", "--set", "bloom.strength=0", "--out", demo)
    found["demo"] = (demo, read_image(demo))
    # A real photograph (Debian's glmark2-data), linearised and lifted 4x so that its stars pass
    # bloom's scene-referred threshold; an odd size on purpose.
    photo = read_image(PHOTOGRAPH)[:201, :317, :3]
    linear = np.where(photo <= 0.04045, photo / 12.92, ((photo + 0.055) / 1.055) ** 2.4) * 4.0
    path = folder / "photo.exr"
    write_exr(path, linear)
    found["photo"] = (path, read_image(path))
    return found


@pytest.fixture(scope="session")
def depth_frame(tmp_path_factory):
    """A frame with depth: colour (bright dots on a gradient) and linear depth from 0.5 m at the top
    to 40 m at the bottom, with a near block at the left; both as half EXR files and arrays."""
    folder = tmp_path_factory.mktemp("depth")
    height, width = 90, 160
    y, x = np.mgrid[0:height, 0:width].astype(np.float32)
    colour = np.stack([x / width, y / height, 0.25 + 0 * x], axis=-1)
    colour[::9, ::11] = 8.0
    depth = (0.5 + 39.5 * y / (height - 1))
    depth[20:60, 10:50] = 1.2
    colour_path, depth_path = folder / "colour.exr", folder / "depth.exr"
    write_exr(colour_path, colour)
    write_exr(depth_path, depth[..., None], channels=["Z"])
    return colour_path, depth_path, read_image(colour_path), read_image(depth_path)[..., 0].copy()
