"""Chain.run in a loop, as a script over the frames of a video runs it: the time a call of the
Python module costs beside the chain's own passes, and what keeping the textures between calls
saves. Prints the median time a call over blocks of calls, for a float picture and an 8-bit one
(where the module takes them), each with the empty chain (what pfx moves around the effects) and
with bloom. Compare two modules by running both in the same hour on an idle machine.

usage: PYTHONPATH=build/python /usr/bin/python3 host/adapters/bench/python_run_loop.py \
           [--calls 1000] [--size 640x360] [--blocks 5]
"""

import argparse
import statistics
import time

import numpy as np
import pfx


def time_calls(chain, picture, calls, blocks):
    """The median over `blocks` of the mean time a call in a block of calls / blocks calls."""
    per_block = max(1, calls // blocks)
    chain.run(picture)  # programs and textures made before the clock starts
    means = []
    for _ in range(blocks):
        start = time.perf_counter()
        for _ in range(per_block):
            chain.run(picture)
        means.append((time.perf_counter() - start) / per_block)
    return statistics.median(means)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--calls", type=int, default=1000)
    parser.add_argument("--size", default="640x360")
    parser.add_argument("--blocks", type=int, default=5)
    args = parser.parse_args()
    width, height = map(int, args.size.split("x"))
    rng = np.random.default_rng(1)
    pictures = {"float32": (rng.random((height, width, 4)) * 2).astype(np.float32)}
    try:
        pictures["uint8"] = rng.integers(0, 256, (height, width, 3), dtype=np.uint8)
        pfx.Chain([]).run(pictures["uint8"][:1, :1])
    except TypeError:
        del pictures["uint8"]  # a module that takes no 8-bit pictures
    for name, picture in pictures.items():
        for effects in ([], ["bloom"]):
            with pfx.Chain(effects, timing="off") as chain:
                seconds = time_calls(chain, picture, args.calls, args.blocks)
            label = ",".join(effects) or "(empty chain)"
            print(f"{name:8s} {label:14s} {width}x{height}: {seconds * 1e3:8.3f} ms a call "
                  f"(median of {args.blocks} blocks of {args.calls // args.blocks})")
    print(f"renderer: {pfx.Chain([]).renderer}")


if __name__ == "__main__":
    main()
