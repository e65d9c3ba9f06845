"""fx_peer_table.py --from-json (host/programs/bench): the table of FX techniques' cost in pfx against
vkBasalt, built from files in the shapes pfx-render --list --json, pfx-bench and pfx-adapter-bench
write (taken from real runs, trimmed): the rows both sides ran with their ratios, the median and
the worst ratio worked out here, and every effect one side only ran listed with its reason and kept
out of the ratios.
"""
import json
import os
import subprocess
import sys

import pytest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "host", "programs", "bench",
                      "fx_peer_table.py")
SHADERS = "/shaders/Shaders"
RENDERER = "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6"

# file -> its techniques' effect ids in file order (pfx-render --list lists them so).
TECHNIQUES = {"Alpha.fx": ["fx_alpha", "fx_alphasecond"], "Beta.fx": ["fx_beta"], "Gamma.fx": ["fx_gamma"],
              "sub/Zeta.fx": ["fx_zeta"], "Delta.fx": ["fx_delta"], "Eps.fx": ["fx_eps"]}
# pfx-bench's ratio_to_copy per effect it measured (fx_eps failed: a note instead).
PFX = {"fx_alpha": 3.47, "fx_alphasecond": 1.5, "fx_beta": 2.32, "fx_gamma": 2.21, "fx_zeta": 4.0, "fx_delta": 1.9}
PFX_FAILED = {"fx_eps": "effect 'fx_eps' pass 'begin' failed (status -5)"}
LOAD_ERROR = "/shaders/Shaders/Broken.fx:3:25: error: expected a name, found ';'"
# pfx-adapter-bench: the copy pass, vkcube alone, and added ms per file (None: vkBasalt could not compile it).
COPY_MS, ALONE_MS = 21.204415, 10.035464
PEER = {"Alpha.fx": 60.698107, "Beta.fx": 37.171057, "Broken.fx": 12.5, "Delta.fx": None, "Eps.fx": 19.0,
        "Gamma.fx": 19.812633, "Zeta.fx": 50.1}
PEER_ERROR = "/shaders/Shaders/Delta.fx(2, 23): error X3000: syntax error: unexpected ';'"


def listing():
    effects = [{"id": effect, "label": effect, "description": "", "parameters": [],
                "fx_file": "%s/%s" % (SHADERS, path), "fx_technique": effect[3:]}
               for path, ids in sorted(TECHNIQUES.items()) for effect in ids]
    plugins = [{"id": "org.pfx.bloom", "name": "pfx bloom", "version": "0.1.0", "path": "/b/pfx_bloom.so", "abi": "1.6",
                "effects": [{"id": "bloom", "label": "Bloom", "description": "", "parameters": []}]},
               {"id": "org.pfx.fx", "name": "pfx fx", "version": "0.1.0", "path": "/b/fx/pfx_fx.so", "abi": "1.6",
                "effects": effects}]
    return {"plugins": plugins, "load_errors": ["no effect from " + LOAD_ERROR]}


def bench_row(effect, ratio):
    copy = 9.0
    return {"effect": effect, "settings": "defaults", "width": 1920, "height": 1080, "median_ms": ratio * copy,
            "copy_ms": copy, "ratio_to_copy": ratio, "peak_target_bytes": 0, "pass_count": 3,
            "passes": [{"pass": "begin", "median_ms": 0.06}, {"pass": "pass0", "median_ms": ratio * copy - 9.1},
                       {"pass": "finish", "median_ms": 9.0}], "error_model": None, "error_ideal": None}


def bench():
    notes = ["row '%s defaults' at 1920x1080 failed: %s" % item for item in PFX_FAILED.items()]
    return {"renderer": RENDERER, "timing": "finish+clock", "frames": 7, "warmup": 2,
            "units": [{"width": 1920, "height": 1080, "source": "/tmp/bench1080.png (8-bit, as hosts hand it over)",
                       "copy_ms": 8.947342}],
            "rows": [bench_row(effect, ratio) for effect, ratio in PFX.items()],
            "notes": notes + ["no effect has an ideal CPU reference yet: no error-against-time plot"]}


def peer_files():
    """pfx-adapter-bench's JSON and its printed table (the one place with vkBasalt's error)."""
    rows = [{"host": "vkcube", "filter": "alone (layers off)", "ms_per_frame": ALONE_MS, "added_ms": 0.0}]
    lines = ["renderer: " + RENDERER, "size: 1920x1080, frames 10 and 40, median of 3 runs; copy pass 21.20 ms "
             "(19.63 before, 22.78 after)", "", "| host | filter | frames/s | ms a frame | added ms a frame | "
             "added, in copy passes |", "|---|---|---|---|---|---|",
             "| vkcube | alone (layers off) | 99.6 | 10.0 |  |  |"]
    for name, added in PEER.items():
        if added is None:
            rows.append({"host": "vkcube", "filter": "vkBasalt " + name, "not_run": True})
            lines.append("| vkcube | vkBasalt %s | | | | not measured:   %s |" % (name, PEER_ERROR))
        else:
            rows.append({"host": "vkcube", "filter": "vkBasalt " + name, "ms_per_frame": ALONE_MS + added,
                         "added_ms": added})
            lines.append("| vkcube | vkBasalt %s | 14.1 | %.1f | %.3f | %.3f |" % (name, ALONE_MS + added, added,
                                                                                 added / COPY_MS))
    peer = {"renderer": RENDERER, "size": "1920x1080", "copy_pass_ms": COPY_MS, "rows": rows}
    return peer, "\n".join(lines) + "\n"


def run_table(folder, with_log=True, extra=()):
    """Writes the inputs into folder, runs the script on them; its stdout and table.json."""
    paths = {name: str(folder / name) for name in ("listing.json", "bench.json", "vkbasalt.json", "vkbasalt.txt")}
    peer, log = peer_files()
    for name, content in (("listing.json", listing()), ("bench.json", bench()), ("vkbasalt.json", peer)):
        (folder / name).write_text(json.dumps(content))
    if with_log:
        (folder / "vkbasalt.txt").write_text(log)
    out = folder / "out"
    done = subprocess.run([sys.executable, SCRIPT, "--from-json", paths["bench.json"], paths["vkbasalt.json"],
                           "--listing", paths["listing.json"], "--out", str(out)] + list(extra),
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    return done.stdout, json.loads((out / "table.json").read_text()), (out / "table.md").read_text()


def compared_expected():
    """The effects both sides ran (their file's first technique, measured by both) and their ratios."""
    expected = {}
    for path, ids in TECHNIQUES.items():
        added = PEER.get(os.path.basename(path))
        if ids[0] in PFX and added is not None:
            expected[ids[0]] = (PFX[ids[0]], added / COPY_MS, PFX[ids[0]] / (added / COPY_MS))
    return expected


def median(values):
    ordered = sorted(values)
    middle = len(ordered) // 2
    return ordered[middle] if len(ordered) % 2 else (ordered[middle - 1] + ordered[middle]) / 2


@pytest.fixture
def table(tmp_path):
    return run_table(tmp_path)


def test_rows_are_the_effects_both_ran_with_their_ratios(table):
    _, result, _ = table
    expected = compared_expected()
    assert sorted(expected) == ["fx_alpha", "fx_beta", "fx_gamma", "fx_zeta"]
    assert sorted(row["effect"] for row in result["rows"]) == sorted(expected)
    for row in result["rows"]:
        pfx, vkbasalt, ratio = expected[row["effect"]]
        assert row["pfx_copy_passes"] == pytest.approx(pfx)
        assert row["vkbasalt_copy_passes"] == pytest.approx(vkbasalt)
        assert row["ratio"] == pytest.approx(ratio)
    zeta = next(row for row in result["rows"] if row["effect"] == "fx_zeta")
    assert zeta["fx_file"] == SHADERS + "/sub/Zeta.fx"  # a file in a sub-folder, matched by its name


def test_median_and_worst_ratio(table):
    _, result, text = table
    ratios = {effect: figures[2] for effect, figures in compared_expected().items()}
    worst = max(ratios, key=ratios.get)
    assert result["summary"]["count"] == 4
    assert result["summary"]["median_ratio"] == pytest.approx(median(ratios.values()))
    assert result["summary"]["worst_ratio"] == pytest.approx(ratios[worst])
    assert result["summary"]["worst_effect"] == worst
    assert "median pfx / vkBasalt %.2f, worst %.2f (%s)" % (median(ratios.values()), ratios[worst], worst) in text


def test_one_side_only_is_listed_with_its_reason(table):
    _, result, _ = table
    why = {(row["effect"], os.path.basename(row["fx_file"])): row["why"] for row in result["not_compared"]}
    assert set(why) == {("fx_alphasecond", "Alpha.fx"), ("fx_delta", "Delta.fx"), ("fx_eps", "Eps.fx"),
                        (None, "Broken.fx")}
    assert "not its file's first technique" in why[("fx_alphasecond", "Alpha.fx")]
    assert PEER_ERROR in why[("fx_delta", "Delta.fx")]  # vkBasalt's compile error, from its printed table
    assert PFX_FAILED["fx_eps"] in why[("fx_eps", "Eps.fx")]  # pfx-bench's note
    assert LOAD_ERROR in why[(None, "Broken.fx")]  # pfx's load error
    ratios = {row["effect"] for row in result["rows"]}
    assert not ratios & {"fx_alphasecond", "fx_delta", "fx_eps", None}
    sides = {row["effect"]: row for row in result["not_compared"]}
    assert sides["fx_delta"]["vkbasalt_copy_passes"] is None and sides["fx_delta"]["pfx_copy_passes"] == 1.9
    assert sides[None]["vkbasalt_copy_passes"] == pytest.approx(PEER["Broken.fx"] / COPY_MS)


def test_printed_table_is_table_md_with_header(table):
    stdout, result, text = table
    assert stdout == text
    assert RENDERER in text.splitlines()[2] and result["facts"]["date"] in text.splitlines()[2]
    assert "| fx_alpha | Alpha.fx | 3.47 | %.2f | %.2f |" % compared_expected()["fx_alpha"][1:] in text
    assert "| fx_delta | Delta.fx | pfx only | 1.90 |  | vkBasalt: " + PEER_ERROR + " |" in text


def test_without_the_printed_table_the_reason_says_so(tmp_path):
    _, result, _ = run_table(tmp_path, with_log=False)
    delta = next(row for row in result["not_compared"] if row["effect"] == "fx_delta")
    assert "vkBasalt" in delta["why"] and "JSON keeps no reason" in delta["why"]
    assert result["summary"]["count"] == 4


def test_effects_keeps_only_those(tmp_path):
    _, result, _ = run_table(tmp_path, extra=["--effects", "fx_alpha,fx_delta"])
    assert [row["effect"] for row in result["rows"]] == ["fx_alpha"]
    assert [row["effect"] for row in result["not_compared"]] == ["fx_delta"]
    assert result["summary"]["median_ratio"] == pytest.approx(compared_expected()["fx_alpha"][2])


def test_help_names_every_option():
    done = subprocess.run([sys.executable, SCRIPT, "--help"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0
    for option in ("--shaders", "--input", "--textures", "--include", "--size", "--bin", "--out", "--effects",
                   "--from-json", "--listing", "--vkbasalt-log"):
        assert option in done.stdout
