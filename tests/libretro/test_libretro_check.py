#!/usr/bin/env python3
"""pfx-libretro-check over the small collection beside this script (collection/: three presets that
run, two of them with names a folder's listing tells apart only by a number, one missing a pass,
one whose shader reads its own output of this frame): its rows, its
summary per folder, its exit status, and that --jobs and --every change how much runs at once and
how much is checked, not what a row says, and that --timeout stops a preset that hangs.

usage: test_libretro_check.py PFX-LIBRETRO-CHECK"""
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
COLLECTION = os.path.join(HERE, "collection")
failures = []


def check(condition, what):
    print("%s: %s" % ("ok" if condition else "FAILED", what))
    if not condition:
        failures.append(what)


def run(tool, *args):
    result = subprocess.run([tool] + list(args), capture_output=True, text=True)
    return result.returncode, result.stdout, result.stderr


def rows_of(stdout):
    report = json.loads(stdout)
    return report, {os.path.relpath(r["preset"], COLLECTION): r for r in report["presets"]}


def main():
    tool = sys.argv[1]
    status, out, err = run(tool, "--json", COLLECTION)
    check(status == 1, "a collection with a preset that does not run exits 1 (got %d)" % status)
    report, rows = rows_of(out)
    # The listing has the two presets it could read; the one missing a pass is named as not read.
    check(sorted(rows) == ["broken/noncausal.slangp", "good/darken.slangp", "good/twice+dark.slangp",
                           "good/twice-dark.slangp"], "rows for the presets listed: %s" % sorted(rows))
    check(any("missing-pass.slangp" in e for e in report["not_read"]), "the preset missing a pass is named as not read")
    good = rows.get("good/darken.slangp", {})
    check(good.get("ran") and good.get("finite") and good.get("changed"),
          "darken ran, gave finite colour and changed the picture: %s" % good)
    # Run with its file alone on the path, the row still names the effect as the folder lists it.
    check(good.get("effect") == "libretro_good_darken", "the row's effect is the folder's id: %s" % good.get("effect"))
    check(good.get("folder") == "good", "the row's folder is its top-level folder")
    check(isinstance(good.get("compile_ms"), float) and good["compile_ms"] > 0, "darken's compile time is given")
    # Alone on the path both are libretro_twice_dark; the rows keep the folder's ids.
    twins = [rows.get("good/twice+dark.slangp", {}), rows.get("good/twice-dark.slangp", {})]
    check([t.get("effect") for t in twins] == ["libretro_good_twice_dark", "libretro_good_twice_dark_2"] and
          all(t.get("ran") and t.get("changed") for t in twins),
          "two presets whose ids the folder's listing numbers both run: %s" % [t.get("error") for t in twins])
    bad = rows.get("broken/noncausal.slangp", {})
    check(bad.get("ran") is False and "PassOutput0" in bad.get("error", ""),
          "the non-causal preset did not run, and the row says why: %s" % bad.get("error"))
    check(report["folders"] == {"broken": {"presets": 1, "ran": 0, "finite": 0, "changed": 0},
                                "good": {"presets": 3, "ran": 3, "finite": 3, "changed": 3}},
          "the summary per folder: %s" % report["folders"])

    # Two at a time: the same rows in the same order, times aside.
    status2, out2, _ = run(tool, "--json", "--jobs", "2", COLLECTION)
    same = lambda r: {k: v for k, v in r.items() if k not in ("compile_ms", "run_ms")}
    check(status2 == 1 and [same(r) for r in json.loads(out2)["presets"]] == [same(r) for r in report["presets"]],
          "--jobs 2 gives the rows --jobs 1 gives")

    # Every second preset: the first and the third of the listing's order.
    _, out3, _ = run(tool, "--json", "--every", "2", COLLECTION)
    checked = [r["effect"] for r in json.loads(out3)["presets"]]
    check(checked == [report["presets"][0]["effect"], report["presets"][2]["effect"]],
          "--every 2 checks the first and third of four presets: %s" % checked)

    # The table a person reads, and the good folder alone exits 0.
    status4, out4, _ = run(tool, os.path.join(COLLECTION, "good"))
    check(status4 == 0 and "3 presets: 3 ran, 3 finite, 3 changed the picture; 0 could not be read" in out4,
          "a folder whose presets all run exits 0 with its count line")
    # A pfx-render that hangs on an effect (as a GL compiler can): the row says it was stopped.
    with tempfile.TemporaryDirectory() as folder:
        hanging = os.path.join(folder, "pfx-render")
        with open(hanging, "w") as f:
            f.write("#!/bin/sh\nfor a in \"$@\"; do case \"$a\" in libretro_*) sleep 60;; esac; done\n"
                    "exec '%s' \"$@\"\n" % os.path.join(os.path.dirname(os.path.abspath(tool)), "pfx-render"))
        os.chmod(hanging, 0o755)
        started = time.monotonic()
        status6, out6, _ = run(tool, "--json", "--timeout", "2", "--render", hanging, os.path.join(COLLECTION, "good"))
        took = time.monotonic() - started
        row = json.loads(out6)["presets"][0] if status6 == 1 else {}
        check(not row.get("ran") and "ran past 2 s" in row.get("error", "") and took < 50,
              "--timeout 2 stops a pfx-render that hangs and says so (%.0f s): %s" % (took, row.get("error")))
    for bad_args in (["--jobs", "0"], ["--every", "none"], ["--timeout", "-1"], ["/nonexistent/folder"]):
        status5, _, err5 = run(tool, *bad_args + ([COLLECTION] if bad_args[0].startswith("--") else []))
        check(status5 == 2 and "pfx-libretro-check:" in err5,
              "%s is a usage error (2, got %d)" % (" ".join(bad_args), status5))

    print("%d failed" % len(failures) if failures else "all passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
