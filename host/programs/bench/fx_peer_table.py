#!/usr/bin/env python3
"""fx_peer_table.py: one table of what every ReShade FX technique of a shader folder costs through
pfx and under vkBasalt (the peer), both measured in the same run, in copy passes.

usage: fx_peer_table.py --shaders DIR --input PICTURE.png [--textures DIR] [--include DIR]
                        [--size WxH] [--bin BUILD_BIN_DIR] [--out DIR] [--effects ID,ID...]
       fx_peer_table.py --from-json PFX_BENCH.json VKBASALT.json [--listing LISTING.json]
                        [--vkbasalt-log VKBASALT.txt] [--effects ID,ID...] [--out DIR]

Three steps, each a program of the build (--bin, default: build/bin of this checkout):
  1. pfx-render --list --json, with PFX_FX_PATH=DIR: every technique of every .fx file under DIR
     (searched with its sub-folders), its effect id (fx_lumasharpen) and file, and the files pfx
     could not load (OUT/listing.json).
  2. pfx-bench, one run over every technique (or the --effects), on PICTURE as an 8-bit frame, as
     video hosts and the Vulkan layer hand theirs over: median of 7 frames after 2 warm-up frames,
     over a plain full-frame copy pass timed in the same process (OUT/bench.json, OUT/bench.md).
  3. pfx-adapter-bench --vkbasalt-fx, one run over every .fx file under DIR (or the files whose
     first technique is among the --effects): vkcube alone, then vkcube under vkBasalt running each
     file's first technique, frames 10 and 40, median of 3 runs, on an Xvfb screen of the frame's
     size (OUT/vkbasalt.json, its printed table OUT/vkbasalt.txt, which alone keeps vkBasalt's
     compile errors). vkBasalt's cost: vkcube's time a frame under vkBasalt less vkcube alone,
     over the copy pass that program times before and after its rows.
Progress goes to stderr; these runs take minutes (about 10 s a file under vkBasalt on lavapipe).

The table (printed, OUT/table.md, OUT/table.json): one row per effect both sides ran (effect, FX
file, pfx copy passes, vkBasalt copy passes, pfx / vkBasalt), the median and the worst (largest)
ratio over those rows, then every effect or file only one side ran (or neither), with why:
vkBasalt's compile error, pfx's load error or pfx-bench's note, or "not its file's first
technique" (vkBasalt runs only a file's first technique).

  --shaders DIR      the shader folder (PFX_FX_PATH for pfx, the files for vkBasalt)
  --input PIC.png    the 8-bit frame pfx-bench measures on; its size is vkcube's size
  --textures DIR     where both sides find the files' textures: PFX_FX_TEXTURE_PATH for pfx,
                     reshadeTexturePath for vkBasalt (default: pfx's own search, a Textures folder
                     beside the effect; for vkBasalt, each file's folder)
  --include DIR      vkBasalt's reshadeIncludePath, a folder with ReShade.fxh (default:
                     pfx-adapter-bench's, pfx's own headers, which pfx uses too)
  --size WxH         the frame size; must be the picture's (the default), so that both sides
                     measure the same frame
  --bin DIR          the folder with pfx-render, pfx-bench and pfx-adapter-bench
  --out DIR          where every file above goes (default out/fx-peer)
  --effects LIST     only these effect ids (and, for vkBasalt, the files whose first technique
                     they include); with --from-json, the table keeps only these
  --from-json PFX_BENCH.json VKBASALT.json
                     run nothing: build the table from a pfx-bench JSON and a pfx-adapter-bench
                     JSON written before (OUT/bench.json and OUT/vkbasalt.json of a run). The
                     effects' files come from --listing (default: listing.json beside
                     PFX_BENCH.json), vkBasalt's compile errors from --vkbasalt-log (default:
                     VKBASALT.json's name with .txt, when it exists; without it the reason says
                     only that vkBasalt did not run the file)
The date in the header is when PFX_BENCH.json was written. Vulkan driver: VK_ICD_FILENAMES when
set, else Mesa's lavapipe. Exit status: 0 the table was made, 1 a program failed, 2 usage error.
"""
import datetime
import json
import os
import re
import statistics
import struct
import subprocess
import sys
import time

PFX_FRAMES, PFX_WARMUP = 7, 2  # pfx-bench's medians: enough on a software renderer, under a minute each
PEER_FRAMES, PEER_RUNS = "10,40", 3  # pfx-adapter-bench's short and long vkcube runs, and their repeats
LAVAPIPE_ICD = "/usr/share/vulkan/icd.d/lvp_icd.%s.json" % os.uname().machine
BASELINE = "alone (layers off)"  # pfx-adapter-bench's row of vkcube without vkBasalt
PEER_PREFIX = "vkBasalt "  # pfx-adapter-bench names a file's row "vkBasalt NAME.fx"


class UsageError(Exception):
    pass


def progress(message):
    sys.stderr.write("fx_peer_table: %s\n" % message)
    sys.stderr.flush()


# ---------------------------------------------------------------- options


def parse(argv):
    """The options as a dict; UsageError for anything wrong. By hand, so that --help is the
    docstring above, the one place the options are described."""
    options = {"shaders": None, "input": None, "textures": None, "include": None, "size": None, "bin": None,
               "out": "out/fx-peer", "effects": None, "from_json": None, "listing": None, "vkbasalt_log": None}
    i = 0
    while i < len(argv):
        arg = argv[i]
        if arg in ("-h", "--help"):
            print(__doc__.strip())
            sys.exit(0)
        key = arg[2:].replace("-", "_")
        if not arg.startswith("--") or key not in options:
            raise UsageError("unknown option %s" % arg)
        count = 2 if key == "from_json" else 1
        values = argv[i + 1:i + 1 + count]
        if len(values) < count:
            raise UsageError("%s needs %s" % (arg, "two files" if count > 1 else "a value"))
        options[key] = values if count > 1 else values[0]
        i += 1 + count
    if options["effects"] is not None:
        options["effects"] = [e for e in options["effects"].split(",") if e]
    check_options(options)
    return options


def check_options(options):
    if options["from_json"]:
        for path in options["from_json"]:
            if not os.path.isfile(path):
                raise UsageError("%s: no such file" % path)
        return
    if not options["shaders"] or not os.path.isdir(options["shaders"]):
        raise UsageError("--shaders DIR: a shader folder is needed")
    if not options["input"] or not options["input"].lower().endswith(".png") or not os.path.isfile(options["input"]):
        raise UsageError("--input PICTURE.png: an 8-bit PNG is needed")
    size = png_size(options["input"])
    if options["size"] and options["size"] != "%dx%d" % size:
        raise UsageError("--size %s is not the picture's size (%dx%d): both sides must measure one frame size"
                         % (options["size"], size[0], size[1]))
    options["size"] = "%dx%d" % size
    options["bin"] = options["bin"] or default_bin()
    for program in ("pfx-render", "pfx-bench", "pfx-adapter-bench"):
        if not os.access(os.path.join(options["bin"], program), os.X_OK):
            raise UsageError("%s not found in %s (--bin)" % (program, options["bin"]))


def png_size(path):
    """Width and height from the PNG's IHDR chunk, which the format puts first."""
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        raise UsageError("%s is not a PNG" % path)
    return struct.unpack(">II", head[16:24])


def default_bin():
    # This script sits in host/programs/bench of the checkout; the build is build/ beside host/.
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
    return os.path.join(root, "build", "bin")


# ---------------------------------------------------------------- running the programs


def pfx_environment(options):
    """PFX_FX_PATH names the one folder, absolute, so that the listing's files are absolute paths."""
    env = dict(os.environ, PFX_FX_PATH=os.path.abspath(options["shaders"]))
    if options["textures"]:
        env["PFX_FX_TEXTURE_PATH"] = os.path.abspath(options["textures"])
    return env


def run_listing(options):
    progress("1/3 pfx-render --list: the techniques of %s" % options["shaders"])
    command = [os.path.join(options["bin"], "pfx-render"), "--list", "--json"]
    done = subprocess.run(command, env=pfx_environment(options), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          text=True)
    if done.returncode != 0:
        raise RuntimeError("pfx-render --list failed (%d): %s" % (done.returncode, done.stderr.strip()))
    path = os.path.join(options["out"], "listing.json")
    with open(path, "w") as f:
        f.write(done.stdout)
    return json.loads(done.stdout)


def run_pfx_bench(options, effect_ids):
    progress("2/3 pfx-bench: %d effects on %s (%d frames after %d each)"
             % (len(effect_ids), options["input"], PFX_FRAMES, PFX_WARMUP))
    command = [os.path.join(options["bin"], "pfx-bench"), "--effects", ",".join(effect_ids),
               "--input", options["input"], "--frames", str(PFX_FRAMES), "--warmup", str(PFX_WARMUP), "--no-shift",
               "--out", options["out"]]
    # Its own per-row lines on stderr are the progress; its stdout repeats bench.md.
    done = subprocess.run(command, env=pfx_environment(options), stdout=subprocess.DEVNULL)
    if done.returncode != 0:
        raise RuntimeError("pfx-bench failed with exit status %d" % done.returncode)
    return os.path.join(options["out"], "bench.json")


def run_peer_bench(options, files):
    progress("3/3 pfx-adapter-bench: vkcube alone and under vkBasalt with %d FX files (minutes)" % len(files))
    json_path = os.path.join(options["out"], "vkbasalt.json")
    log_path = os.path.join(options["out"], "vkbasalt.txt")
    command = ["xvfb-run", "-a", "-s", "-screen 0 %sx24" % options["size"],
               os.path.join(options["bin"], "pfx-adapter-bench"), "--size", options["size"],
               "--frames", PEER_FRAMES, "--runs", str(PEER_RUNS), "--json", json_path]
    for path in files:
        command += ["--vkbasalt-fx", path]
    if options["include"]:
        command += ["--reshade-include", options["include"]]
    if options["textures"]:
        command += ["--reshade-textures", options["textures"]]
    env = dict(os.environ)
    env.setdefault("VK_ICD_FILENAMES", LAVAPIPE_ICD)
    # Its stdout is the printed table, the one place with vkBasalt's compile errors: kept.
    with open(log_path, "w") as log:
        done = subprocess.run(command, env=env, stdout=log)
    if done.returncode != 0:
        raise RuntimeError("pfx-adapter-bench failed with exit status %d (its output: %s)"
                           % (done.returncode, log_path))
    return json_path, log_path


def fx_files_under(folder):
    """Every .fx file under the folder, sorted: the files pfx's FX plugin reads (fx_catalog.cpp)."""
    found = []
    for directory, _, names in os.walk(os.path.abspath(folder)):
        found += [os.path.join(directory, name) for name in names if name.endswith(".fx")]
    return sorted(found)


def run_all(options):
    """The three steps; the paths of the listing, pfx-bench's JSON and the peer's JSON and log."""
    os.makedirs(options["out"], exist_ok=True)
    listing = run_listing(options)
    effects = fx_effects(listing)
    ids = [e["id"] for e in effects]
    unknown = [e for e in options["effects"] or [] if e not in ids]
    if unknown:
        raise UsageError("not an FX effect of %s: %s (it has: %s)"
                         % (options["shaders"], ", ".join(unknown), ", ".join(ids)))
    chosen = options["effects"] or ids
    if not chosen:
        raise UsageError("%s holds no FX technique pfx could load" % options["shaders"])
    firsts = first_techniques(effects)
    if options["effects"]:
        files = sorted(f for f, first in firsts.items() if first in chosen)
    else:
        files = fx_files_under(options["shaders"])
    started = time.time()
    bench = run_pfx_bench(options, chosen)
    progress("pfx-bench done in %.0f s" % (time.time() - started))
    peer = run_peer_bench(options, files) if files else (None, None)
    return listing, bench, peer[0], peer[1]


# ---------------------------------------------------------------- reading the programs' JSON


def fx_effects(listing):
    """The FX plugin's effects in listing order (files sorted, each file's techniques in order):
    id, file, technique."""
    found = []
    for plugin in listing.get("plugins", []):
        for effect in plugin.get("effects", []):
            if "fx_file" in effect:
                found.append({"id": effect["id"], "file": effect["fx_file"], "technique": effect["fx_technique"]})
    return found


def first_techniques(effects):
    """Each file's first technique's effect id: the one vkBasalt runs."""
    firsts = {}
    for effect in effects:
        firsts.setdefault(effect["file"], effect["id"])
    return firsts


def load_errors(listing):
    """pfx's load errors ("no effect from FILE:LINE:COL: error: ...") by file; the rest apart."""
    by_file, other = {}, []
    for message in listing.get("load_errors", []):
        match = re.match(r"no effect from (.+?\.fx):", message)
        if match:
            by_file[match.group(1)] = message[len("no effect from "):]
        else:
            other.append(message)
    return by_file, other


def read_pfx_bench(bench):
    """pfx-bench's cost of each effect (ratio_to_copy of its 'defaults' row) and, for an effect with
    no row, its note ("row 'ID SETTINGS' skipped: WHY" or "... at WxH failed: WHY")."""
    costs, errors = {}, {}
    for row in bench.get("rows", []):
        if row["effect"] not in costs or row.get("settings") == "defaults":
            costs[row["effect"]] = row["ratio_to_copy"]
    for note in bench.get("notes", []):
        match = re.match(r"row '(\S+) [^']*'(?: at \d+x\d+)? (?:skipped|failed): (.*)$", note, re.S)
        if match and match.group(1) not in costs:
            errors[match.group(1)] = match.group(2)
    return costs, errors


def peer_log_reasons(text):
    """vkBasalt's compile errors from pfx-adapter-bench's printed table, by row name, in order:
    "| vkcube | vkBasalt NAME.fx | | | | not measured: WHY |"."""
    reasons = {}
    for line in text.splitlines():
        match = re.match(r"\| vkcube \| (.+?) \| \| \| \| not measured:(.*) \|$", line)
        if match:
            reasons.setdefault(match.group(1), []).append(match.group(2).strip())
    return reasons


def read_peer(peer, log_text):
    """pfx-adapter-bench's rows as (file name, cost in copy passes or None, why not measured)."""
    copy = peer["copy_pass_ms"]
    reasons = peer_log_reasons(log_text) if log_text is not None else {}
    rows = []
    for row in peer.get("rows", []):
        if not row["filter"].startswith(PEER_PREFIX):
            continue
        name = row["filter"][len(PEER_PREFIX):]
        if row.get("not_run"):
            queue = reasons.get(row["filter"], [])
            why = queue.pop(0) if queue else ("vkBasalt did not run it (pfx-adapter-bench's JSON keeps no reason; "
                                              "its printed table does)")
            rows.append((name, None, "vkBasalt: " + why))
        else:
            rows.append((name, row["added_ms"] / copy, None))
    return rows


def baseline_ms(peer):
    return next((row.get("ms_per_frame") for row in peer.get("rows", []) if row["filter"] == BASELINE), None)


# ---------------------------------------------------------------- the table


def match_peer_files(peer_rows, known_files):
    """Each peer row's file: pfx-adapter-bench names a row by the file's name only, so a name is
    matched to the known files of that name in sorted order, the order a run passes them in. A
    name no known file has (pfx listed nothing from it) stays a bare name."""
    by_name = {}
    for path in sorted(known_files):
        by_name.setdefault(os.path.basename(path), []).append(path)
    matched = {}
    for name, cost, why in peer_rows:
        queue = by_name.get(name, [])
        matched[queue.pop(0) if queue else name] = (cost, why)
    return matched


def pfx_reason(effect, pfx_errors):
    if effect in pfx_errors:
        return "pfx-bench: " + pfx_errors[effect]
    return "pfx-bench gave no row for it"


def peer_reason(effect, firsts, peer):
    """Why vkBasalt has no figure for the effect; None when it has one."""
    first = firsts[effect["file"]]
    if first != effect["id"]:
        return "not its file's first technique (vkBasalt runs only %s)" % first
    cost, why = peer.get(effect["file"], (None, "vkBasalt was not run on the file"))
    if why:
        return why
    if cost <= 0:
        return "vkBasalt's added time is not above vkcube alone: below the noise, no ratio"
    return None


def effect_entry(effect, firsts, pfx_costs, pfx_errors, peer):
    """One effect: its figures, and why it is not compared (None when both sides have a figure)."""
    pfx = pfx_costs.get(effect["id"])
    first = firsts[effect["file"]] == effect["id"]
    vk = peer.get(effect["file"], (None, None))[0] if first else None
    reasons = [] if pfx is not None else [pfx_reason(effect["id"], pfx_errors)]
    vk_why = peer_reason(effect, firsts, peer)
    reasons += [vk_why] if vk_why else []
    return {"effect": effect["id"], "fx_file": effect["file"], "pfx_copy_passes": pfx,
            "vkbasalt_copy_passes": vk, "why": "; ".join(reasons) or None}


def file_entry(path, cost, why, pfx_file_errors):
    """A file vkBasalt was given that pfx made no effect of."""
    reasons = ["pfx could not load it: " + pfx_file_errors[path] if path in pfx_file_errors
               else "pfx made no effect of it (no technique)"]
    reasons += [why] if why else []
    return {"effect": None, "fx_file": path, "pfx_copy_passes": None, "vkbasalt_copy_passes": cost,
            "why": "; ".join(reasons)}


def wanted_effects(effects, firsts, pfx_costs, pfx_errors, peer, only):
    """The effects the table is about: --effects when given, else every effect either side tried."""
    if only:
        return [e for e in effects if e["id"] in only]
    return [e for e in effects if e["id"] in pfx_costs or e["id"] in pfx_errors
            or (firsts[e["file"]] == e["id"] and e["file"] in peer)]


def entries(listing, bench, peer_rows, only=None):
    """Every effect and every file of the runs, each with its figures and why it is not compared."""
    effects = fx_effects(listing)
    firsts = first_techniques(effects)
    file_errors, _ = load_errors(listing)
    pfx_costs, pfx_errors = read_pfx_bench(bench)
    peer = match_peer_files(peer_rows, set(firsts) | set(file_errors))
    chosen = wanted_effects(effects, firsts, pfx_costs, pfx_errors, peer, only)
    result = [effect_entry(e, firsts, pfx_costs, pfx_errors, peer) for e in chosen]
    if not only:
        result += [file_entry(path, cost, why, file_errors) for path, (cost, why) in sorted(peer.items())
                   if path not in firsts]
    for entry in result:
        entry["ratio"] = entry["pfx_copy_passes"] / entry["vkbasalt_copy_passes"] if entry["why"] is None else None
    return result


def summary(compared):
    """Median and worst (largest) pfx / vkBasalt over the effects both sides ran."""
    if not compared:
        return {"count": 0, "median_ratio": None, "worst_ratio": None, "worst_effect": None}
    worst = max(compared, key=lambda e: e["ratio"])
    return {"count": len(compared), "median_ratio": statistics.median(e["ratio"] for e in compared),
            "worst_ratio": worst["ratio"], "worst_effect": worst["effect"]}


def facts(bench, bench_path, peer):
    """What the header says: when, on what, at what size, the units of both sides."""
    unit = (bench.get("units") or [{}])[0]
    written = datetime.datetime.fromtimestamp(os.path.getmtime(bench_path))
    return {"date": written.strftime("%Y-%m-%d %H:%M"), "renderer": bench.get("renderer"),
            "pfx_timing": bench.get("timing"), "pfx_frames": bench.get("frames"), "pfx_warmup": bench.get("warmup"),
            "pfx_size": "%sx%s" % (unit.get("width"), unit.get("height")), "pfx_source": unit.get("source"),
            "pfx_copy_pass_ms": unit.get("copy_ms"), "vkbasalt_size": peer.get("size"),
            "vkbasalt_copy_pass_ms": peer.get("copy_pass_ms"), "vkbasalt_copy_renderer": peer.get("renderer"),
            "vkcube_alone_ms": baseline_ms(peer)}


def build_table(listing, bench, bench_path, peer, log_text, only=None):
    """The table as one dict: header facts, compared rows, summary, the rest with why."""
    all_entries = entries(listing, bench, read_peer(peer, log_text), only)
    compared = [e for e in all_entries if e["why"] is None]
    table = {"facts": facts(bench, bench_path, peer), "rows": compared, "summary": summary(compared),
             "not_compared": [e for e in all_entries if e["why"] is not None],
             "notes": load_errors(listing)[1]}
    if table["facts"]["pfx_size"] != table["facts"]["vkbasalt_size"]:
        table["notes"].append("the two sides measured different frame sizes: %s (pfx) and %s (vkBasalt)"
                              % (table["facts"]["pfx_size"], table["facts"]["vkbasalt_size"]))
    return table


# ---------------------------------------------------------------- Markdown


def cell(value, digits=2):
    if value is None:
        return ""
    if isinstance(value, float):
        return "%.*f" % (digits, value)
    # A message may hold '|' or new lines, which would break the row.
    return str(value).replace("|", "\\|").replace("\n", " / ")


def shown_file(path, table):
    """A file relative to the folder all the table's files share, so that rows stay short."""
    paths = [e["fx_file"] for e in table["rows"] + table["not_compared"] if os.path.isabs(e["fx_file"])]
    root = os.path.commonpath([os.path.dirname(p) for p in paths]) if paths else ""
    return os.path.relpath(path, root) if root and os.path.isabs(path) else path


def header_lines(f):
    return ["# FX techniques: pfx against vkBasalt", "",
            "Date: %s (when pfx-bench's JSON was written). Renderer: %s." % (f["date"], f["renderer"]),
            "pfx: pfx-bench, %s, %s, median of %s frames after %s (%s), copy pass %s ms." % (
                f["pfx_size"], f["pfx_source"], f["pfx_frames"], f["pfx_warmup"], f["pfx_timing"],
                cell(f["pfx_copy_pass_ms"], 3)),
            "vkBasalt: pfx-adapter-bench, vkcube %s, %s ms a frame alone; copy pass %s ms on %s." % (
                f["vkbasalt_size"], cell(f["vkcube_alone_ms"], 1), cell(f["vkbasalt_copy_pass_ms"], 3),
                f["vkbasalt_copy_renderer"]),
            "Costs in copy passes: an effect's time a frame over a full-frame copy pass timed by the same "
            "program; vkBasalt's is vkcube's time under vkBasalt less vkcube alone.", ""]


def compared_lines(table):
    lines = ["| effect | FX file | pfx (copy passes) | vkBasalt (copy passes) | pfx / vkBasalt |",
             "|---|---|---:|---:|---:|"]
    for e in table["rows"]:
        lines.append("| %s | %s | %s | %s | %s |" % (e["effect"], cell(shown_file(e["fx_file"], table)),
                                                    cell(e["pfx_copy_passes"]), cell(e["vkbasalt_copy_passes"]),
                                                    cell(e["ratio"])))
    s = table["summary"]
    if s["count"]:
        lines += ["", "Over the %d effects both ran: median pfx / vkBasalt %.2f, worst %.2f (%s)."
                  % (s["count"], s["median_ratio"], s["worst_ratio"], s["worst_effect"])]
    else:
        lines += ["", "No effect ran on both sides: no ratio."]
    return lines


def side(entry):
    has_pfx, has_vk = entry["pfx_copy_passes"] is not None, entry["vkbasalt_copy_passes"] is not None
    return "pfx only" if has_pfx and not has_vk else "vkBasalt only" if has_vk and not has_pfx else \
        "both, no ratio" if has_pfx else "neither"


def not_compared_lines(table):
    if not table["not_compared"] and not table["notes"]:
        return []
    lines = ["", "## Not compared", "", "| effect | FX file | ran | pfx (copy passes) | vkBasalt (copy passes) | why |",
             "|---|---|---|---:|---:|---|"]
    for e in table["not_compared"]:
        lines.append("| %s | %s | %s | %s | %s | %s |" % (
            cell(e["effect"]), cell(shown_file(e["fx_file"], table)), side(e), cell(e["pfx_copy_passes"]),
            cell(e["vkbasalt_copy_passes"]), cell(e["why"])))
    if table["notes"]:
        lines += [""] + ["- %s" % cell(note) for note in table["notes"]]
    return lines


def markdown(table):
    return "\n".join(header_lines(table["facts"]) + compared_lines(table) + not_compared_lines(table)) + "\n"


# ---------------------------------------------------------------- main


def read_json(path):
    with open(path) as f:
        return json.load(f)


def from_json_inputs(options):
    """The listing, pfx-bench's JSON and path, the peer's JSON and log text of an earlier run."""
    bench_path, peer_path = options["from_json"]
    listing_path = options["listing"] or os.path.join(os.path.dirname(os.path.abspath(bench_path)), "listing.json")
    if not os.path.isfile(listing_path):
        raise UsageError("%s: no listing (pfx-render --list --json) to find the effects' files; give --listing"
                         % listing_path)
    log_path = options["vkbasalt_log"] or os.path.splitext(peer_path)[0] + ".txt"
    log_text = open(log_path).read() if os.path.isfile(log_path) else None
    return read_json(listing_path), read_json(bench_path), bench_path, read_json(peer_path), log_text


def inputs(options):
    if options["from_json"]:
        return from_json_inputs(options)
    listing, bench_path, peer_path, log_path = run_all(options)
    if peer_path is None:  # no file for vkBasalt: its side is empty
        peer = {"rows": [], "copy_pass_ms": None, "size": options["size"]}
        return listing, read_json(bench_path), bench_path, peer, ""
    return listing, read_json(bench_path), bench_path, read_json(peer_path), open(log_path).read()


def write_outputs(table, text, out):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "table.md"), "w") as f:
        f.write(text)
    with open(os.path.join(out, "table.json"), "w") as f:
        json.dump(table, f, indent=2)
        f.write("\n")
    progress("wrote %s and %s" % (os.path.join(out, "table.md"), os.path.join(out, "table.json")))


def main(argv):
    try:
        options = parse(argv)
        listing, bench, bench_path, peer, log_text = inputs(options)
    except UsageError as error:
        sys.stderr.write("fx_peer_table: %s\n(fx_peer_table.py --help for usage)\n" % error)
        return 2
    except (RuntimeError, OSError, ValueError) as error:
        sys.stderr.write("fx_peer_table: %s\n" % error)
        return 1
    try:
        table = build_table(listing, bench, bench_path, peer, log_text, options["effects"])
    except (KeyError, TypeError, ZeroDivisionError) as error:
        sys.stderr.write("fx_peer_table: not the JSON pfx-bench and pfx-adapter-bench write: %r\n" % error)
        return 1
    text = markdown(table)
    sys.stdout.write(text)
    write_outputs(table, text, options["out"])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
