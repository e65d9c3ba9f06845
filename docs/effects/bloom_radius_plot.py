#!/usr/bin/env python3
"""Draws docs/effects/bloom/radius_target.png from pfx-bench runs of docs/effects/bloom_radius_suite.txt:
error against the exact Gaussian (relative to the light it adds) against time in copy passes, one
curve per sigma and downscale, each curve running over the tap counts.

usage: bloom_radius_plot.py BENCH.json [BENCH.json ...] OUT.png   (needs gnuplot)"""
import json
import re
import subprocess
import sys
from collections import defaultdict


def main(args):
    if len(args) < 2:
        sys.exit(__doc__)
    curves = defaultdict(list)
    for path in args[:-1]:
        with open(path) as f:
            bench = json.load(f)
        for row in bench["rows"]:
            settings = dict(re.findall(r"(\w+)=(\S+)", row["settings"]))
            ideal = row.get("error_ideal")
            if settings.get("mode") != "gaussian" or not ideal:
                continue
            name = "sigma %s, downscale %s" % (settings["sigma"], settings["downscale"])
            curves[name].append((row["ratio_to_copy"], ideal["change_relative_rmse"]))
    script = ["set terminal pngcairo size 900,600", "set output '%s'" % args[-1],
              "set xlabel 'time (x plain copy pass)'", "set ylabel 'RMSE vs exact Gaussian / RMS of its light'",
              "set logscale xy", "set grid", "set key outside right",
              "set title 'gaussian mode, 1280x720, llvmpipe: truncation at 1-3 sigma along each curve'"]
    names = sorted(curves, key=lambda n: [float(v) for v in re.findall(r"[\d.]+", n)])
    script.append("plot " + ", ".join("'-' using 1:2 with linespoints title '%s'" % n for n in names))
    for n in names:
        script += ["%g %g" % point for point in sorted(curves[n])] + ["e"]
    subprocess.run(["gnuplot"], input="\n".join(script) + "\n", text=True, check=True)


if __name__ == "__main__":
    main(sys.argv[1:])
