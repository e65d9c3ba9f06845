"""vkBasalt as an independent compiler of the same FX source, beside pfx: pfx-fx-check
--compare-vkbasalt and the tests (tests/fx/vkbasalt) run an FX file through vkBasalt in vkcube and
through pfx-render on the same frame, and compare the two pictures.

vkcube turns its cube by a fixed step per frame, so its frame 5 is the same picture on every run.
Two runs of vkcube, with pfx's Vulkan layer capturing frame 5 and running no effect:
  1. without vkBasalt: the pristine frame;
  2. with vkBasalt running the file. vkBasalt is an implicit layer and pfx's layer is enabled here
     as an explicit one, which the loader puts below every implicit layer: nearer the driver, so
     pfx's layer receives vkBasalt's output (its capture's .app.png).
pfx-render then runs the same technique on the pristine frame, and pfx's layer runs it natively in a
third run of vkcube (on the application's device, as vkBasalt does). vkBasalt runs only a file's
first technique, at vkcube's size (320x240).
"""
import os
import re
import subprocess

import numpy as np
import OpenImageIO as oiio

VKBASALT_MANIFEST = "/usr/share/vulkan/implicit_layer.d/vkBasalt.json"
WIDTH, HEIGHT = 320, 240
CAPTURED_FRAME = 5


def techniques(path):
    """Technique names in file order, outside comments (one inside #if is still counted)."""
    text = open(path, errors="replace").read()
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    return re.findall(r"^\s*technique\s+(\w+)", text, flags=re.M)


def effect_id(technique):
    """pfx's id of an FX technique: fx_ and the name in lower case, other characters one '_'."""
    return "fx_" + re.sub(r"[^a-z0-9]+", "_", technique.lower()).strip("_")


def read(path):
    return oiio.ImageBuf(path).get_pixels(oiio.UINT8).astype(int)[..., :3]


def write_explicit_manifest(folder, layer):
    """pfx's layer through a manifest of the explicit kind, so that VK_INSTANCE_LAYERS enables it and
    the loader puts it below every implicit layer: below vkBasalt, nearer the driver."""
    with open(os.path.join(folder, "pfx_explicit.json"), "w") as f:
        f.write('{"file_format_version": "1.0.0", "layer": {"name": "VK_LAYER_PFX_post_effects", '
                '"type": "GLOBAL", "library_path": "%s", "api_version": "1.3.0", "implementation_version": "1", '
                '"description": "pfx", "functions": {"vkGetInstanceProcAddr": "pfx_layer_GetInstanceProcAddr", '
                '"vkGetDeviceProcAddr": "pfx_layer_GetDeviceProcAddr"}}}\n' % os.path.abspath(layer))


class Oracle:
    """vkcube runs in `out` (its manifest, logs and captures), with pfx's layer `layer` below.
    `fx_path` is what the layer's FX plugin lists (the layer captures nothing without an effect
    offered; its chain is none, so nothing runs). `icd`: a Vulkan driver's manifest, or None for
    the system's."""

    def __init__(self, out, layer, vkcube, icd, fx_path):
        self.out, self.layer, self.vkcube, self.icd, self.fx_path = out, layer, vkcube, icd, fx_path
        os.makedirs(out, exist_ok=True)
        write_explicit_manifest(out, layer)

    def frame(self, name, settings):
        """vkcube for 8 frames with pfx's layer capturing frame 5 as OUT/name.png (what it presents)
        and OUT/name.app.png (what reached it). Returns (exit code, vkcube's output, pfx's log)."""
        out = self.out
        env = dict(os.environ)
        for key in ("ENABLE_VKBASALT", "DISABLE_VKBASALT", "VKBASALT_CONFIG_FILE", "VK_INSTANCE_LAYERS",
                    "VK_LOADER_LAYERS_ENABLE", "PFX_INJECT_CHAIN", "PFX_INJECT_PRESET"):
            env.pop(key, None)
        if self.icd:
            env.update({"VK_ICD_FILENAMES": self.icd, "VK_DRIVER_FILES": self.icd})
        env.update({
            # Only the explicit manifest finds pfx's layer: no implicit one of a build's or a user's.
            "XDG_DATA_HOME": out, "VK_LAYER_PATH": out, "VK_INSTANCE_LAYERS": "VK_LAYER_PFX_post_effects",
            "ENABLE_PFX_VULKAN": "1", "PFX_INJECT_CHAIN": "none", "PFX_FX_PATH": self.fx_path,
            "PFX_INJECT_LOG": os.path.join(out, name + ".log"),
            "PFX_INJECT_CAPTURE": "%d:%s" % (CAPTURED_FRAME, os.path.join(out, name)),
        })
        env.update(settings)
        for stale in (name + ".png", name + ".app.png", name + ".log"):
            if os.path.exists(os.path.join(out, stale)):
                os.remove(os.path.join(out, stale))
        result = subprocess.run([self.vkcube, "--c", "8", "--width", str(WIDTH), "--height", str(HEIGHT)], env=env,
                                capture_output=True, text=True, errors="replace", timeout=300)
        log_path = os.path.join(out, name + ".log")
        log = open(log_path, errors="replace").read() if os.path.exists(log_path) else ""
        return result.returncode, result.stdout + result.stderr, log

    def pristine(self):
        """The frame without vkBasalt (OUT/pristine.app.png), or an error message."""
        code, output, log = self.frame("pristine", {"DISABLE_VKBASALT": "1"})
        if code != 0 or not os.path.exists(os.path.join(self.out, "pristine.app.png")):
            return None, "vkcube without vkBasalt exited with %d and captured %s\n%s%s" % (
                code, "frame %d" % CAPTURED_FRAME if code == 0 else "nothing", output[-2000:], log[-2000:])
        return os.path.join(self.out, "pristine.app.png"), ""

    def vkbasalt(self, name, fx, include, textures):
        """vkBasalt running `fx` (its first technique) with one include folder and one texture folder.
        Returns a dict: compiled, ran (a frame of vkBasalt's reached pfx's layer), says (its first
        error, a crash, or vkcube's exit), picture (the path), passed_through (pfx's layer presented
        what it received, as it must with chain none)."""
        config = os.path.join(self.out, name + ".conf")
        with open(config, "w") as f:
            f.write("effects = under_test\nunder_test = %s\nreshadeIncludePath = %s\nreshadeTexturePath = %s\n"
                    % (os.path.abspath(fx), os.path.abspath(include), os.path.abspath(textures)))
        code, output, log = self.frame(name, {"ENABLE_VKBASALT": "1", "VKBASALT_CONFIG_FILE": config,
                                              "VKBASALT_LOG_LEVEL": "debug"})
        with open(os.path.join(self.out, name + "-vkbasalt-output.txt"), "w") as f:
            f.write(output)
        # vkBasalt prints its compiler's warnings at its error level too: only errors count.
        errors = [line for line in output.splitlines()
                  if line.startswith("vkBasalt err") and not re.search(r": warning X?\d*:", line)]
        crash = [line for line in output.splitlines()
                 if "Assertion" in line or "terminate called" in line or "what():" in line]
        picture = os.path.join(self.out, name + ".app.png")
        result = {"compiled": not errors and "finished creating Reshade effect" in output, "picture": picture,
                  "log": log, "output": output}
        # A file with compile errors still gives vkBasalt a module, which it runs: no comparison then.
        result["ran"] = (result["compiled"] and code == 0 and os.path.exists(picture)
                         and "applying ReshadeEffect" in output)
        result["says"] = (errors[0].split(": ", 1)[-1] if errors else crash[0] if crash
                          else "" if code == 0 else "vkcube exited with %d" % code)
        presented = os.path.join(self.out, name + ".png")
        result["passed_through"] = (result["ran"] and os.path.exists(presented)
                                    and np.abs(read(presented) - read(picture)).max() == 0)
        return result


    def native(self, name, fx, technique):
        """pfx's layer running `technique` of `fx` natively on vkcube's device, without vkBasalt:
        (OUT/name.png, what it presented) or (None, why not)."""
        code, output, log = self.frame(name, {"DISABLE_VKBASALT": "1", "PFX_FX_PATH": os.path.abspath(fx),
                                              "PFX_INJECT_CHAIN": effect_id(technique)})
        picture = os.path.join(self.out, name + ".png")
        if code != 0 or not os.path.exists(picture) or "the chain runs natively" not in log:
            return None, "vkcube with pfx's layer exited with %d (%s)\n%s%s" % (
                code, "captured" if os.path.exists(picture) else "no capture", output[-2000:], log[-2000:])
        return picture, ""


def pfx_render(render, fx_path, technique, pristine, out_path, timeout=600):
    """pfx-render running `technique` of the FX files `fx_path` finds on the pristine frame.
    Returns (ran, the last line of its output when it did not)."""
    if os.path.exists(out_path):
        os.remove(out_path)
    result = subprocess.run([render, "--input", pristine, "--chain", effect_id(technique), "--out", out_path],
                            env=dict(os.environ, PFX_FX_PATH=fx_path), capture_output=True, text=True, errors="replace",
                            timeout=timeout)
    if result.returncode == 0:
        return True, ""
    lines = (result.stdout + result.stderr).strip().splitlines()
    return False, lines[-1] if lines else "pfx-render exited with %d" % result.returncode


def difference(ours_path, theirs_path):
    """Per pixel, the largest difference of the two pictures' 8-bit codes (R, G, B)."""
    ours, theirs = read(ours_path), read(theirs_path)
    if ours.shape != theirs.shape:
        raise ValueError("pictures of sizes %s and %s" % (ours.shape, theirs.shape))
    return np.abs(ours - theirs).max(axis=2)
