"""Every bad input raises the exception docs/python.md names, with pfx's message, and never takes
the interpreter down: unknown effects and parameters, refused values, wrong arrays, a missing
depth, a bad camera, a closed chain, plugins that do not load, and no OpenGL at all."""

import os
import subprocess
import sys

import numpy as np
import pfx
import pytest

PICTURE = np.zeros((8, 12, 4), np.float32)


@pytest.fixture(scope="module")
def bloom():
    with pfx.Chain(["bloom"]) as chain:
        yield chain


def test_an_unknown_effect_names_the_loaded_ones():
    with pytest.raises(pfx.Error, match=r"unknown effect 'blom' \(loaded: .*bloom"):
        pfx.Chain(["blom"])


@pytest.mark.parametrize("key, value, message", [
    ("bloom.nope", 1, "has no parameter 'nope'"),
    ("bloom#2.threshold", 1, "bloom#2"),
    ("threshold", 1, ""),
    ("bloom.threshold", float("nan"), "NaN"),
    ("bloom.threshold", "bright", ""),
    ("bloom.mode", "best", "best"),
    ("bloom.tint", (1, 2), ""),
])
def test_a_value_the_store_refuses_raises_parameter_error(bloom, key, value, message):
    before = bloom.params()
    with pytest.raises(pfx.ParameterError, match=message):
        bloom.set(key, value)
    assert bloom.params() == before, "a refused value changed something"


def test_parameter_error_is_a_pfx_error(bloom):
    with pytest.raises(pfx.Error):
        bloom.set("bloom.nope", 1)


def test_a_value_outside_the_range_is_clamped_with_a_warning(bloom):
    with pytest.warns(RuntimeWarning, match="clamped"):
        bloom.set("bloom.strength", 1e9)
    assert bloom.get("bloom.strength") == bloom.params()["bloom"]["strength"]["hard_max"]


def test_a_value_of_no_parameter_type_raises_type_error(bloom):
    with pytest.raises(TypeError, match="parameter value"):
        bloom.set("bloom.threshold", {"a": 1})


@pytest.mark.parametrize("dtype", [np.float64, np.int32, np.int8, np.uint16])
def test_a_picture_of_another_dtype_raises_type_error(bloom, dtype):
    with pytest.raises(TypeError, match="uint8 .display-referred., float16 or float32"):
        bloom.run(PICTURE.astype(dtype))


def test_depth_must_be_float_even_beside_an_8_bit_picture(bloom):
    with pytest.raises(TypeError, match="depth must be float16 or float32"):
        bloom.run(np.zeros((12, 8, 4), np.uint8), depth=np.zeros((12, 8), np.uint8))


def test_an_unknown_transfer_raises_value_error(bloom):
    with pytest.raises(ValueError, match="transfer"):
        bloom.run(np.zeros((12, 8, 4), np.uint8), transfer="gamma")


@pytest.mark.parametrize("shape", [(8, 12), (8, 12, 2), (8, 12, 5), (0, 12, 4), (8, 0, 3), (2, 8, 12, 4)])
def test_a_picture_of_another_shape_raises_value_error(bloom, shape):
    with pytest.raises(ValueError, match="rgba"):
        bloom.run(np.zeros(shape, np.float32))


def test_a_picture_not_in_c_order_raises_value_error(bloom):
    with pytest.raises(ValueError, match="C-contiguous"):
        bloom.run(np.zeros((12, 8, 4), np.float32).transpose(1, 0, 2))
    with pytest.raises(ValueError, match="C-contiguous"):
        bloom.run(PICTURE[:, :, :3])


def test_a_list_is_not_a_picture(bloom):
    with pytest.raises(TypeError, match="uint8 .display-referred., float16 or float32"):
        bloom.run([[[0.0, 0.0, 0.0, 1.0]]])


def test_depth_of_another_size_raises_value_error():
    with pfx.Chain(["dof"]) as dof:
        with pytest.raises(ValueError, match="depth must be H x W"):
            dof.run(PICTURE, depth=np.ones((8, 11), np.float32))
        with pytest.raises(TypeError, match="depth must be float16 or float32"):
            dof.run(PICTURE, depth=np.ones((8, 12), np.float64))


def test_an_effect_that_needs_depth_says_how_to_give_it():
    with pfx.Chain(["dof"]) as dof:
        with pytest.raises(pfx.Error, match="dof needs depth.*depth="):
            dof.run(PICTURE)


def test_a_bad_depth_encoding_raises_value_error(bloom):
    with pytest.raises(ValueError, match="depth_encoding"):
        bloom.run(PICTURE, depth=np.ones((8, 12), np.float32), depth_encoding="reversed")


@pytest.mark.parametrize("arguments, message", [
    ({"fovy": 0}, "fovy"), ({"fovy": 180}, "fovy"), ({"near": 0}, "near"), ({"near": -1}, "near"),
    ({"near": float("inf")}, "near"), ({"near": 5, "far": 5}, "far"), ({"far": float("nan")}, "far"),
])
def test_a_degenerate_camera_raises_value_error(arguments, message):
    with pytest.raises(ValueError, match=message):
        pfx.Camera(**arguments)


def test_an_infinite_far_plane_is_a_camera():
    assert pfx.Camera(far=float("inf")).far == float("inf")


def test_bad_defaults_and_timing_are_refused():
    with pytest.raises(ValueError, match="defaults"):
        pfx.Chain(["bloom"], defaults="hdr")
    with pytest.raises(pfx.Error, match="timing 'fast'"):
        pfx.Chain(["bloom"], timing="fast")


def test_a_closed_chain_raises_and_closing_twice_is_harmless():
    chain = pfx.Chain(["bloom"])
    chain.close()
    chain.close()
    for call in (lambda: chain.run(PICTURE), lambda: chain.set("bloom.threshold", 1), chain.params):
        with pytest.raises(pfx.Error, match="closed"):
            call()


def test_plugins_that_do_not_load_raise(tmp_path):
    with pytest.raises(pfx.Error, match="no-such-plugin.so"):
        pfx.Chain(["bloom"], plugins=[str(tmp_path / "no-such-plugin.so")])
    not_a_plugin = tmp_path / "empty.so"
    not_a_plugin.write_bytes(b"not an ELF file")
    with pytest.raises(pfx.Error, match="empty.so"):
        pfx.effects(plugins=[str(not_a_plugin)])


def test_without_opengl_the_chain_raises_and_the_interpreter_goes_on():
    # EGL's vendor libraries are found through glvnd's JSON files: with none, there is no EGL
    # platform at all. In a child interpreter, so that this one keeps its OpenGL.
    script = ("import pfx, numpy\n"
              "try:\n"
              "    pfx.Chain(['bloom'])\n"
              "except pfx.Error as e:\n"
              "    print('raised:', e)\n"
              "print('still running')\n")
    env = dict(os.environ, __EGL_VENDOR_LIBRARY_FILENAMES="/nonexistent/egl_vendor.json")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "raised: cannot create a headless OpenGL 4.5 core context" in done.stdout, done.stdout + done.stderr
    assert "still running" in done.stdout
