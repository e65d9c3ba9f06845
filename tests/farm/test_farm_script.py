#!/usr/bin/env python3
"""pfx-farm without a cluster: its frame names match pfx-render's for every token form, chunks
cover the range once, and usage errors exit 2 with a message (never a Python traceback).

usage: test_farm_script.py PFX_FARM
"""

import importlib.machinery
import importlib.util
import subprocess
import sys


def load(path):
    loader = importlib.machinery.SourceFileLoader("pfx_farm", path)
    spec = importlib.util.spec_from_loader("pfx_farm", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def main(farm_path):
    farm = load(farm_path)
    failures = []

    def check(condition, message):
        if not condition:
            failures.append(message)

    # The same names tests/render/test_render_sequences.cpp expects from pfx-render.
    for pattern, frame, name in [("shot.%04d.exr", 7, "shot.0007.exr"), ("shot.%d.exr", 7, "shot.7.exr"),
                                 ("a/shot.####.exr", 1001, "a/shot.1001.exr"), ("s.@@@@@@.png", 42, "s.000042.png"),
                                 ("s.@.exr", 1234, "s.1234.exr"), ("s_##.exr", 12345, "s_12345.exr"),
                                 ("100%%.#.exr", 3, "100%.3.exr")]:
        got = farm.frame_path(pattern, frame)
        check(got == name, "frame_path(%r, %d) = %r, pfx-render writes %r" % (pattern, frame, got, name))

    job = {"first": 1001, "last": 1024, "step": 1, "chunk": 5}
    chunks = farm.chunk_ranges(job)
    check([c[0] for c in chunks] == [1001, 1006, 1011, 1016, 1021] and chunks[-1] == [1021, 1022, 1023, 1024],
          "chunks of 1001-1024 by 5: %s" % chunks)
    stepped = farm.chunk_ranges({"first": 1, "last": 20, "step": 3, "chunk": 2})
    check(sum(stepped, []) == list(range(1, 21, 3)), "chunks of 1-20x3 by 2: %s" % stepped)
    check(farm.ranges_text([1, 2, 3, 7, 9, 10]) == "1-3 7 9-10", "ranges_text: %s" % farm.ranges_text([1, 2, 3, 7, 9, 10]))

    for args, message in [(["submit", "--frames", "1-10", "--chunk", "5"], "give the pfx-render arguments after --"),
                          (["submit", "--frames", "10-1", "--chunk", "5", "--", "--input", "a.#.exr", "--out", "b.#.exr"],
                           "--frames 10-1"),
                          (["submit", "--frames", "1-10", "--chunk", "0", "--", "--input", "a.#.exr", "--out", "b.#.exr"],
                           "--chunk 0"),
                          (["submit", "--frames", "1-10", "--chunk", "5", "--", "--input", "a.#.exr"],
                           "need --input PATTERN and --out PATTERN"),
                          (["submit", "--frames", "1-10", "--chunk", "5", "--", "--input", "a.#.exr", "--out", "b.#.exr",
                            "--frames", "1-3"], "must not hold --frames"),
                          (["frobnicate"], "unknown command 'frobnicate'")]:
        result = subprocess.run([sys.executable, farm_path] + args, capture_output=True, text=True)
        check(result.returncode == 2 and message in result.stderr and "Traceback" not in result.stderr,
              "pfx-farm %s: exit %d, stderr:\n%s" % (" ".join(args), result.returncode, result.stderr))

    for failure in failures:
        print("FAILED: " + failure, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
