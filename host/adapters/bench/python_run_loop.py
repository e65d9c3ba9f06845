"""Chain.run in a loop, as a script over the frames of a video runs it: the time a call of the
Python module costs beside the chain's own passes. Prints the median time a call over blocks of
calls, for a float picture and an 8-bit one (where the module takes them), each with the empty
chain (what pfx moves around the effects), with bloom and with bloom twice; what a call adds beyond
its passes (for bloom: its time less what a second bloom adds, so no pass timer is trusted), in
copy passes of the same size timed on the chain's context before and after (Chain.copy_pass_ms,
where the module has it). Compare two modules by running both in the same hour on an idle machine.

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
    with pfx.Chain([]) as chain:
        timed_copy = hasattr(chain, "copy_pass_ms")
        units = [chain.copy_pass_ms(width, height)] if timed_copy else []
    rows = []
    for name, picture in pictures.items():
        ms = {}
        for effects in ([], ["bloom"], ["bloom", "bloom"]):
            with pfx.Chain(effects, timing="off") as chain:
                ms[len(effects)] = time_calls(chain, picture, args.calls, args.blocks) * 1e3
        rows.append((name, "(empty chain)", ms[0], 0.0))
        rows.append((name, "bloom", ms[1], ms[2] - ms[1]))
        rows.append((name, "bloom,bloom", ms[2], None))
    if timed_copy:
        with pfx.Chain([]) as chain:
            units.append(chain.copy_pass_ms(width, height))
    unit = statistics.median(units) if units else 0.0
    print(f"{width}x{height}, median of {args.blocks} blocks of {args.calls // args.blocks} calls")
    print("| picture | chain | ms a call | its passes, ms | added, ms | added, in copy passes |")
    print("|---|---|---:|---:|---:|---:|")
    for name, label, call_ms, pass_ms in rows:
        if pass_ms is None:
            print(f"| {name} | {label} | {call_ms:.3f} | | | |")
            continue
        added = call_ms - pass_ms
        in_copies = f"{added / unit:.2f}" if unit > 0 else "-"
        print(f"| {name} | {label} | {call_ms:.3f} | {pass_ms:.3f} | {added:.3f} | {in_copies} |")
    if units:
        print("copy pass (the unit): " + ", ".join(f"{u:.3f}" for u in units) + " ms (before, after)")
    print(f"renderer: {pfx.Chain([]).renderer}")


if __name__ == "__main__":
    main()
