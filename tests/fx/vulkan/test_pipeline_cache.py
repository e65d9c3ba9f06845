#!/usr/bin/env python3
"""The Vulkan runtime's pipeline cache file, as a user meets it across starts.

usage: test_pipeline_cache.py FX_VULKAN_CHECKS

Runs a conformance file through FX_VULKAN_CHECKS on lavapipe with XDG_CACHE_HOME in a scratch
folder: a cold start starts empty and writes the file; a warm one starts from it; a damaged file
(payload bytes flipped) and a stale one (whole, but its Vulkan header names another device) are
ignored and written again; PFX_FX_CACHE=0 writes nothing. Every run must still pass its checks.
"""
import glob
import os
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
FX = os.path.join(HERE, "..", "conformance", "mips.fx")
INCLUDE = os.path.join(HERE, "..", "..", "..", "plugins", "fx", "include")
MAGIC = b"PFXVKPC1"


def fnv1a(data):
    h = 0xCBF29CE484222325
    for b in data:
        h = ((h ^ b) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 2
    icds = sorted(glob.glob("/usr/share/vulkan/icd.d/lvp_icd.*.json"))
    if not icds:
        print("FAIL: lavapipe is not installed: install mesa-vulkan-drivers")
        return 1
    failures = []

    def check(ok, message):
        if not ok:
            failures.append(message)

    with tempfile.TemporaryDirectory(prefix="pfx-vk-cache-") as cache:
        folder = os.path.join(cache, "pfx", "fx-vulkan")
        files = lambda: sorted(glob.glob(os.path.join(folder, "*.bin")))

        def run(name, **extra):
            env = dict(os.environ, VK_ICD_FILENAMES=icds[0], XDG_CACHE_HOME=cache, **extra)
            done = subprocess.run([argv[1], "--report-cache", "-I" + INCLUDE, "--size", "32x2", FX], env=env,
                                  capture_output=True, text=True, timeout=300)
            said = done.stdout + done.stderr
            check(done.returncode == 0 and "ok:" in said, "%s: the checks failed: %s" % (name, said))
            return "from the file" in said, said

        loaded, said = run("cold")
        check(not loaded, "a cold start read a cache: " + said)
        check(len(files()) == 1, "the cold start wrote %s" % files())
        loaded, said = run("warm")
        check(loaded, "a warm start did not read the cache: " + said)
        if files():
            path = files()[0]
            data = bytearray(open(path, "rb").read())
            check(data[:8] == MAGIC and struct.unpack("<Q", data[8:16])[0] == fnv1a(data[16:]),
                  "the file is not magic, checksum and payload")
            damaged = bytearray(data)
            for i in range(16, len(damaged)):
                damaged[i] ^= 0xFF
            open(path, "wb").write(bytes(damaged))
            loaded, said = run("damaged")
            check(not loaded, "a damaged file was read: " + said)
            check(open(path, "rb").read() == bytes(data), "the damaged file was not written again whole")
            stale = bytearray(data[16:])
            stale[12:16] = struct.pack("<I", struct.unpack("<I", stale[12:16])[0] ^ 0x5A5A)  # another device id
            open(path, "wb").write(MAGIC + struct.pack("<Q", fnv1a(stale)) + bytes(stale))
            loaded, said = run("stale")
            check(not loaded, "a file naming another device was read: " + said)
            check(open(path, "rb").read() == bytes(data), "the stale file was not written again")
        for path in files():
            os.remove(path)
        loaded, said = run("off", PFX_FX_CACHE="0")
        check(not loaded and not files() and "(off)" in said, "PFX_FX_CACHE=0: %s %s" % (files(), said))
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print("ok: cold, warm, damaged, stale, off")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
