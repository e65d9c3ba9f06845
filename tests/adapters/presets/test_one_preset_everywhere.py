"""One preset, one picture, in every host: presets in the shapes users share them give pfx-render's
bytes in pfx-view, Python, ffmpeg and melt (frei0r), GStreamer's pfxfilter (within one code: GL
converts there), pfx-inject (glxgears) and the Vulkan layer (vkcube), and each host names what it
left out in one warning per load (docs/fx.md, "Presets").

The presets are written here: a ReShade preset as one arrives from another machine (a byte-order
mark, CRLF line ends, comments, a key given twice, hundreds of sections for techniques that are
switched off, a technique whose file is not there, a value the effect lacks, a value of the wrong
type and one of the wrong size), an old preset that names techniques without their files, and a
pfx preset naming an effect and values that are not there. The effects are the two FX files of
tests/fx/presets/Shaders. pfx-render's own picture is checked against the picture of the values
that apply given on its command line, so the hosts are compared with the preset policy's meaning,
not only with each other.

The build passes the programs' paths in the environment (tests/adapters/presets/CMakeLists.txt)."""

import os
import subprocess
import warnings

import numpy as np
import OpenImageIO as oiio
import pytest

SHADERS = os.path.join(os.environ["PFX_SOURCE_DIR"], "tests", "fx", "presets", "Shaders")
os.environ["PFX_FX_PATH"] = SHADERS  # before pfx is imported: the FX plugin reads its folders once

import pfx  # noqa: E402

PHOTOGRAPH = os.environ["PFX_TEST_PHOTOGRAPH"]
RENDER = os.environ["PFX_RENDER"]
VIEW = os.environ["PFX_VIEW"]
INJECT = os.environ["PFX_INJECT"]
FFMPEG, MELT, GST_LAUNCH = os.environ["PFX_FFMPEG"], os.environ["PFX_MELT"], os.environ["PFX_GST_LAUNCH"]
GLXGEARS, VKCUBE = os.environ["PFX_GLXGEARS"], os.environ["PFX_VKCUBE"]
XVFB = [os.environ["PFX_XVFB_RUN"], "-a", "-s", "-screen 0 640x480x24 -nolisten tcp"]
LEFT_OUT = "left out:"

# Written with the byte-order mark and CRLF ends a Windows editor gives it.
SHARED_INI = "\r\n".join([
    "\ufeff// exported from ReShade on another machine",
    "PreprocessorDefinitions=",
    "Techniques=Grade@Grade.fx,Bogus@Bogus.fx,Edge@Edge.fx",
    "TechniqueSorting=Edge@Edge.fx,Bogus@Bogus.fx,Grade@Grade.fx,Off@Off.fx",
    "",
    "[Grade.fx]",
    "; a little lift in red",
    "Lift=0.100000,0.000000,-0.050000",
    "Gain=0.800000",
    "Gain=1.500000",
    "Mode=1",
    "Invert=0",
    "Foo=3",
    "",
    "[Edge.fx]",
    "# far too strong, and not a number anyway",
    "Strength=abc",
    "",
] + [f"[Off{i}.fx]\r\nAmount={i / 300:.6f}\r\nColor=1.000000,0.500000,0.250000\r\n" for i in range(300)]) + "\r\n"

# Lift given one number where the effect has three: left out, not splat over the three.
SHORT_INI = "Techniques=Grade@Grade.fx\nTechniqueSorting=Grade@Grade.fx\n\n[Grade.fx]\nLift=0.2\nGain=0.6\n"

OLD_STYLE_INI = "Techniques=Edge,Grade\n\n[Edge.fx]\nStrength=0.500000\n\n[Grade.fx]\nGain=1.300000\nInvert=1\n"

PFX_JSON = """{"pfx_preset": 1,
  "chain": [{"effect": "fx_grade"}, {"effect": "fx_missing"}, {"effect": "fx_edge", "enabled": false}],
  "parameters": {"fx_grade": {"gain": 0.7, "lift": [0, 0.1, 0], "invert": "perhaps"},
                 "fx_missing": {"x": 1}}}"""

# name: (text, what the one warning names, the command line giving what applies)
PRESETS = {
    "shared.ini": (SHARED_INI,
                   ["fx_bogus (not loaded)", "fx_edge.strength ('abc' is not a number)", "fx_grade.foo (no such parameter)"],
                   ["--chain", "fx_edge,fx_grade", "--set", "fx_grade.lift=0.1,0,-0.05", "--set", "fx_grade.gain=0.8",
                    "--set", "fx_grade.mode=1", "--set", "fx_grade.invert=0"]),
    "short.ini": (SHORT_INI, ["fx_grade.lift (expects 3 numbers, got 1)"],
                  ["--chain", "fx_grade", "--set", "fx_grade.gain=0.6"]),
    "old_style.ini": (OLD_STYLE_INI, [],
                      ["--chain", "fx_edge,fx_grade", "--set", "fx_edge.strength=0.5", "--set", "fx_grade.gain=1.3",
                       "--set", "fx_grade.invert=1"]),
    "look.json": (PFX_JSON, ["fx_missing (not loaded)", "fx_grade.invert", "fx_missing.x (not loaded)"],
                  ["--chain", "fx_grade", "--set", "fx_grade.gain=0.7", "--set", "fx_grade.lift=0,0.1,0"]),
}


def run(*args, env=None):
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, **(env or {})))
    output = done.stdout + done.stderr
    assert done.returncode == 0, f"{' '.join(map(str, args))} failed ({done.returncode}):\n{output}"
    return output


def read_rgb(path):
    """An 8-bit picture's R, G, B codes, top row first (OpenImageIO, not pfx's reader)."""
    image = oiio.ImageInput.open(str(path))
    assert image, oiio.geterror()
    pixels = image.read_image(format="uint8")
    image.close()
    return np.ascontiguousarray(pixels[..., :3])


def write_rgb_png(path, rgb):
    out = oiio.ImageOutput.create(str(path))
    assert out and out.open(str(path), oiio.ImageSpec(rgb.shape[1], rgb.shape[0], 3, "uint8"))
    assert out.write_image(rgb)
    out.close()


def srgb_codes(linear):
    """Linear light to 8-bit sRGB codes with the exact piecewise curve (IEC 61966-2-1)."""
    c = np.clip(linear, 0.0, 1.0)
    encoded = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
    return np.round(encoded * 255).astype(np.uint8)


def worst(a, b):
    assert a.shape == b.shape, (a.shape, b.shape)
    return int(np.abs(a.astype(int) - b.astype(int)).max())


def one_warning(output, preset, named):
    """The host said what it left out in one warning naming each item, or said nothing."""
    count = output.count(LEFT_OUT)
    if not named:
        assert count == 0, output
        return
    assert count == 1, f"{count} warnings:\n{output}"
    line = next(line for line in output.splitlines() if LEFT_OUT in line)
    assert preset in line, line
    for item in named:
        assert item in line, f"{item!r} not in {line!r}"


@pytest.fixture(scope="module")
def presets(tmp_path_factory):
    folder = tmp_path_factory.mktemp("presets")
    paths = {}
    for name, (text, _, _) in PRESETS.items():
        path = folder / name
        path.write_bytes(text.encode("utf-8"))
        paths[name] = str(path)
    return paths


def pfx_render(preset, picture, out):
    output = run(RENDER, "--input", picture, "--preset", preset, "--out", out)
    return read_rgb(out), output


@pytest.mark.parametrize("name", PRESETS)
def test_pfx_render_applies_what_fits_and_names_the_rest_once(name, presets, tmp_path):
    _, named, meaning = PRESETS[name]
    picture, output = pfx_render(presets[name], PHOTOGRAPH, tmp_path / "preset.png")
    one_warning(output, presets[name], named)
    # The policy's meaning: exactly the values that apply, given by hand.
    run(RENDER, "--input", PHOTOGRAPH, *meaning, "--out", tmp_path / "by-hand.png")
    assert np.array_equal(picture, read_rgb(tmp_path / "by-hand.png")), "not the picture of the values that apply"
    assert worst(picture, read_rgb(PHOTOGRAPH)) > 16, "the preset changed nothing: the comparisons would prove nothing"


@pytest.mark.parametrize("name", PRESETS)
def test_pfx_view_python_ffmpeg_melt_and_gstreamer_give_pfx_render_s_picture(name, presets, tmp_path):
    preset = presets[name]
    _, named, _ = PRESETS[name]
    expected, _ = pfx_render(preset, PHOTOGRAPH, tmp_path / "render.png")

    output = run(*XVFB, VIEW, "--input", PHOTOGRAPH, "--preset", preset, "--frames", "2",
                 "--screenshot", tmp_path / "view.png")
    one_warning(output, preset, named)
    assert np.array_equal(read_rgb(tmp_path / "view.png"), expected), "pfx-view"

    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        chain = pfx.Chain(preset=preset)
    one_warning("\n".join(str(w.message) for w in said if LEFT_OUT in str(w.message)), preset, named)
    with chain:
        assert np.array_equal(chain.run(read_rgb(PHOTOGRAPH).copy()), expected), "Python"

    # frei0r's pfx_chain: the preset alone (an empty chain) is the chain.
    output = run(FFMPEG, "-hide_banner", "-loglevel", "warning", "-y", "-i", PHOTOGRAPH, "-vf",
                 f"frei0r=filter_name=pfx_chain:filter_params=|||{preset}", "-frames:v", "1", "-update", "1",
                 tmp_path / "ffmpeg.png")
    one_warning(output, preset, named)
    assert np.array_equal(read_rgb(tmp_path / "ffmpeg.png"), expected), "ffmpeg"

    profile = tmp_path / "square.profile"
    profile.write_text("description=square pixels\nframe_rate_num=25\nframe_rate_den=1\nwidth=512\nheight=512\nprogressive=1\n"
                       "sample_aspect_num=1\nsample_aspect_den=1\ndisplay_aspect_num=1\ndisplay_aspect_den=1\n"
                       "colorspace=709\n")
    output = run(MELT, "-quiet", "-profile", profile, "avformat:" + PHOTOGRAPH, "out=0", "-filter", "frei0r.pfx_chain",
                 f"preset={preset}", "-consumer", f"avformat:{tmp_path / 'melt.png'}", "vcodec=png", "pix_fmt=rgba",
                 "mlt_image_format=rgba", "update=1", "real_time=0")
    one_warning(output, preset, named)
    assert np.array_equal(read_rgb(tmp_path / "melt.png"), expected), "melt"

    # pfxfilter: the preset alone is the chain.
    output = run(GST_LAUNCH, "filesrc", f"location={PHOTOGRAPH}", "!", "pngdec", "!", "videoconvert", "!",
                 "video/x-raw,format=RGBA", "!", "glupload", "!", "pfxfilter", f"preset={preset}", "!", "gldownload", "!",
                 "video/x-raw,format=RGBA", "!", "pngenc", "!", "filesink", f"location={tmp_path / 'gst.png'}")
    one_warning(output, preset, named)
    assert worst(read_rgb(tmp_path / "gst.png"), expected) <= 1, "GStreamer's pfxfilter"


@pytest.mark.parametrize("name", PRESETS)
def test_pfx_inject_and_the_vulkan_layer_present_pfx_render_s_picture_of_the_application_s_frame(name, presets, tmp_path):
    preset = presets[name]
    _, named, _ = PRESETS[name]
    output = run(*XVFB, INJECT, "--preset", preset, "--quit-after", "3", "--capture", f"3:{tmp_path / 'gl'}", "--",
                 GLXGEARS)
    one_warning(output, preset, named)
    # What glxgears drew, as the chain received it (decoded exactly, half float), back in codes.
    image = oiio.ImageInput.open(str(tmp_path / "gl.app.exr"))
    received = image.read_image(format="float")
    image.close()
    write_rgb_png(tmp_path / "gl-app.png", srgb_codes(received[..., :3]))
    expected, _ = pfx_render(preset, tmp_path / "gl-app.png", tmp_path / "gl-render.png")
    assert np.array_equal(read_rgb(tmp_path / "gl.png"), expected), "pfx-inject"

    # The layer runs an all-FX chain natively on vkcube's device (what a user gets), and through the
    # GL when asked (PFX_VK_NATIVE=0), which is pfx-render's code. A tie between two 8-bit codes
    # (Edge.fx at strength 0.5 makes many: 1.5 c - 0.125 n in code units) may round the other way
    # on Vulkan, by one code, and Grade's gain of 1.3 after it can make that two: the native path
    # is held to two codes (one per effect) on at most 1 pixel in 100 (a value that did not reach
    # the effect moves most of the pixels it changes), the GL path to one.
    for path, extra, bar in (("native", {}, 2), ("gl", {"PFX_VK_NATIVE": "0"}, 1)):
        output = run(*XVFB, VKCUBE, "--c", "3", "--width", "160", "--height", "120",
                     env=dict({"ENABLE_PFX_VULKAN": "1", "XDG_DATA_HOME": os.environ["PFX_BUILD_SHARE"],
                               "PFX_INJECT_PRESET": preset, "PFX_INJECT_CAPTURE": f"3:{tmp_path / path}",
                               "PFX_INJECT_QUIT_AFTER": "3"}, **extra))
        one_warning(output, preset, named)
        assert ("the chain runs natively" in output) == (path == "native"), output
        expected, _ = pfx_render(preset, tmp_path / f"{path}.app.png", tmp_path / f"{path}-render.png")
        presented = read_rgb(tmp_path / f"{path}.png")
        assert worst(presented, expected) <= bar, f"the Vulkan layer, {path}"
        if path == "native":
            differing = int((np.abs(presented.astype(int) - expected.astype(int)).max(axis=2) > 0).sum())
            assert differing * 100 <= presented.shape[0] * presented.shape[1], f"the Vulkan layer natively: {differing}"
