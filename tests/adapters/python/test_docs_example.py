"""The example of docs/python.md runs as it is printed there and writes its plot."""

import os
import subprocess
import sys

from conftest import PHOTOGRAPH, SOURCE_DIR


def test_the_sweep_example_runs_and_writes_its_plot(tmp_path):
    script = tmp_path / "sweep_bloom_threshold.py"
    extract = subprocess.run(["bash", os.path.join(SOURCE_DIR, "tests/install/doc_block.sh"),
                              os.path.join(SOURCE_DIR, "docs/python.md"), "<!-- run: sweep_bloom_threshold.py -->"],
                             capture_output=True, text=True)
    assert extract.returncode == 0, extract.stderr
    script.write_text(extract.stdout)
    plot = tmp_path / "plot.png"
    done = subprocess.run([sys.executable, str(script), PHOTOGRAPH, str(plot)], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert len(lines) == 3 * 4, done.stdout  # three modes, four thresholds
    assert all(" ms, error " in line for line in lines)
    assert plot.stat().st_size > 10000 and plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
