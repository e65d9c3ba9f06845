#!/usr/bin/env python3
"""pfx-farm without a cluster: the frames, chunks and file names it works with are pfx-render's
own (from pfx-render --print-frames), a frame is done when pfx-render would skip it, and usage
errors exit 2 with a message (never a Python traceback), pfx-render's own included.

usage: test_farm_script.py PFX_FARM PFX_RENDER
"""

import importlib.machinery
import importlib.util
import os
import shutil
import subprocess
import sys
import tempfile


def load(path):
    loader = importlib.machinery.SourceFileLoader("pfx_farm", path)
    spec = importlib.util.spec_from_loader("pfx_farm", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def main(farm_path, render):
    farm = load(farm_path)
    failures = []

    def check(condition, message):
        if not condition:
            failures.append(message)

    folder = tempfile.mkdtemp(prefix="pfx-farm-test-")
    try:
        # The job as pfx-farm keeps it, in a folder where frames 1006 and 1024 are written.
        job = {"frames": "1001-1024", "chunk": 5, "render": render, "cwd": folder,
               "render_args": ["--input", "shot.%04d.exr", "--out", "a/out.####.exr", "--out", "b.@@@@@@.png"],
               "reports": os.path.join(folder, "r.%d.json")}
        os.makedirs(os.path.join(folder, "a"))
        for name in ("a/out.1006.exr", "b.001006.png", "a/out.1024.exr", "b.001024.png", "a/out.1007.exr"):
            open(os.path.join(folder, name), "w").close()
        plan = farm.job_plan(job)
        frames = plan["frames"]
        check([f["frame"] for f in frames] == list(range(1001, 1025)), "frames of 1001-1024: %s" % frames)
        check(plan["chunks"] == 5 and [f["chunk"] for f in frames] == [i // 5 for i in range(24)],
              "chunks of 1001-1024 by 5: %s" % [f["chunk"] for f in frames])
        check(frames[5]["outputs"] == ["a/out.1006.exr", "b.001006.png"] and frames[5]["input"] == "shot.1006.exr"
              and frames[5]["report"] == os.path.join(folder, "r.1006.json"), "frame 1006's files: %s" % frames[5])
        # Done: every output there (1007 has only its EXR).
        check([f["frame"] for f in frames if f["done"]] == [1006, 1024], "done: %s" % [f for f in frames if f["done"]])
        states, _, tasks = farm.frame_states(plan, {1: "RUNNING"})
        check(states[1006] == "done" and states[1007] == "running" and states[1001] == "missing"
              and states[1024] == "done" and tasks[1021] == 4, "frame states: %s" % states)

        stepped = farm.job_plan(dict(job, frames="1-20x3", chunk=2))
        check([f["frame"] for f in stepped["frames"]] == list(range(1, 21, 3)) and stepped["chunks"] == 4
              and [f["chunk"] for f in stepped["frames"]] == [0, 0, 1, 1, 2, 2, 3],
              "chunks of 1-20x3 by 2: %s" % stepped)
        check(farm.frames_text({"first": 1, "last": 20, "step": 3}) == "1-20x3",
              "a job.json of an earlier pfx-farm (first, last, step): %s" % farm.frames_text({"first": 1, "last": 20,
                                                                                            "step": 3}))
    finally:
        shutil.rmtree(folder)
    check(farm.ranges_text([1, 2, 3, 7, 9, 10]) == "1-3 7 9-10", "ranges_text: %s" % farm.ranges_text([1, 2, 3, 7, 9, 10]))

    render_option = ["--render", render]
    for args, message in [(["submit", "--frames", "1-10", "--chunk", "5"], "give the pfx-render arguments after --"),
                          (["submit", "--frames", "10-1", "--chunk", "5", *render_option, "--", "--input", "a.#.exr",
                            "--out", "b.#.exr"], "--frames 10-1: the last frame comes before the first"),
                          (["submit", "--frames", "1-10", "--chunk", "0", *render_option, "--", "--input", "a.#.exr",
                            "--out", "b.#.exr"], "--chunk 0: expected a whole number"),
                          (["submit", "--frames", "1-10", "--chunk", "5", *render_option, "--", "--input", "a.exr",
                            "--out", "b.#.exr"], "--input a.exr: no frame number in the name"),
                          (["submit", "--frames", "1-10", "--chunk", "5", "--", "--input", "a.#.exr"],
                           "need --input PATTERN and --out PATTERN"),
                          (["submit", "--frames", "1-10", "--chunk", "5", "--", "--input", "a.#.exr", "--out", "b.#.exr",
                            "--frames", "1-3"], "must not hold --frames"),
                          (["submit", "--frames", "1-10", "--chunk", "5", "--", "--input", "a.#.exr", "--out", "b.#.exr",
                            "--chunk-index", "1"], "must not hold --chunk-index"),
                          (["frobnicate"], "unknown command 'frobnicate'")]:
        result = subprocess.run([sys.executable, farm_path] + args, capture_output=True, text=True)
        check(result.returncode == 2 and message in result.stderr and "Traceback" not in result.stderr,
              "pfx-farm %s: exit %d, stderr:\n%s" % (" ".join(args), result.returncode, result.stderr))

    for failure in failures:
        print("FAILED: " + failure, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
