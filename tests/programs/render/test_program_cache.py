#!/usr/bin/env python3
"""A plugin's cache of compiled programs (the FX plugin's, docs/fx.md; the libretro plugin's,
docs/libretro.md): a second start takes programs of an effect from the cache and gives the same
picture; damaged cache files are ignored, rebuilt and written again; the folder is held to 256 MiB,
the programs used longest ago deleted first; OFF_VARIABLE=0 writes nothing.

usage: test_program_cache.py PFX_RENDER EFFECT PICTURE OUT_DIR PATH_VARIABLE=PATH KIND OFF_VARIABLE
  EFFECT: the effect's id; PATH_VARIABLE=PATH: where the plugin finds it (PFX_FX_PATH=file.fx);
  KIND: the cache's folder under $XDG_CACHE_HOME/pfx (fx-programs); OFF_VARIABLE: PFX_FX_CACHE
"""
import glob
import json
import os
import shutil
import subprocess
import sys

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def main():
    render, effect, picture, out, path_setting, kind, off_variable = sys.argv[1:8]
    path_variable, effect_path = path_setting.split("=", 1)
    shutil.rmtree(out, ignore_errors=True)
    cache = os.path.join(out, "cache")
    os.makedirs(out)

    def run(name, **extra):
        env = dict(os.environ, XDG_CACHE_HOME=cache, **extra)
        env[path_variable] = effect_path
        target = os.path.join(out, name + ".png")
        done = subprocess.run([render, "--input", picture, "--chain", effect, "--out", target, "--json"], env=env,
                              capture_output=True, text=True, timeout=300)
        check(done.returncode == 0, "%s: pfx-render failed: %s" % (name, done.stderr))
        report = json.loads(done.stdout) if done.returncode == 0 else {}
        own = report.get("effect_reports", {}).get(effect, {})
        return own.get("programs_from_cache"), open(target, "rb").read() if done.returncode == 0 else b""

    files = lambda: sorted(glob.glob(os.path.join(cache, "pfx", kind, "*.bin")))
    hits, cold = run("cold")
    check(hits == 0, "a cold start took %r programs from an empty cache" % hits)
    check(len(files()) >= 1, "nothing was written to the cache: %s" % files())
    hits, warm = run("warm")
    check(hits is not None and hits >= 1, "a second start took %r programs from the cache" % hits)
    check(warm == cold, "the cached programs gave another picture")
    for path in files():  # damaged: every byte after the header flipped
        data = bytearray(open(path, "rb").read())
        for i in range(20, len(data)):
            data[i] ^= 0xFF
        open(path, "wb").write(bytes(data))
    hits, damaged = run("damaged")
    check(hits == 0, "damaged cache files were used (%r programs)" % hits)
    check(damaged == cold, "after damaged cache files the picture differs")
    hits, _ = run("rewritten")
    check(hits is not None and hits >= 1, "the damaged files were not written again (%r from the cache)" % hits)
    # Over the bound: three old files of 100 MiB each (sparse: their size, not the disk's) and the
    # effect's own, just used. The next store deletes the oldest until 3/4 of 256 MiB remain.
    folder = os.path.join(cache, "pfx", kind)
    own = files()
    for i, age in enumerate((3000, 2000, 1000)):
        path = os.path.join(folder, "old%d.bin" % i)
        with open(path, "wb") as f:
            f.truncate(100 << 20)
        os.utime(path, (os.path.getmtime(own[0]) - age,) * 2)
    for path in own:  # the effect's programs are stored again
        os.remove(path)
    run("bounded")
    left = files()
    total = sum(os.path.getsize(path) for path in left)
    check(total <= 192 << 20, "the cache holds %d bytes past its bound: %s" % (total, left))
    check(not os.path.exists(os.path.join(folder, "old0.bin")) and not os.path.exists(os.path.join(folder, "old1.bin")),
          "the programs used longest ago were not the ones deleted: %s" % left)
    check(os.path.exists(os.path.join(folder, "old2.bin")), "more than needed was deleted: %s" % left)
    check(len([p for p in left if "old" not in p]) >= 1, "the program just stored was deleted: %s" % left)
    shutil.rmtree(cache)
    run("off", **{off_variable: "0"})
    check(not files(), "%s=0 wrote %s" % (off_variable, files()))
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print("ok: cold, warm, damaged, rewritten, bounded, off")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
