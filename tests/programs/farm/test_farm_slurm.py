#!/usr/bin/env python3
"""pfx-farm on a real one-node Slurm cluster (started here, in a temporary folder): a 24-frame
sequence in chunks of 5; one task is killed (SIGKILL) in the middle of its chunk and one frame
of another task is a damaged file; pfx-farm status must then name exactly the frames the kill
left and the failed frame with its reason; pfx-farm resubmit (the file mended) must run only those
two chunks again;
afterwards every output must exist and be byte for byte the file a single local pfx-render
writes for the same frame.

The task is killed midway without any hook in pfx-render: its last three frames are large
(1280x720, about half a second each here, against milliseconds for the 64x36 ones), and the test
kills it as soon as its second frame is written.

usage: test_farm_slurm.py PFX_RENDER PFX_FARM PLUGIN_DIR
Exit codes: 0 passed, 1 failed (with the reason), 77 skipped (not root, or Slurm not installed:
ctest shows SKIP with the reason).
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exr_file import write_rgb_exr  # noqa: E402
from slurm_cluster import ClusterError, SlurmCluster  # noqa: E402

FIRST, LAST, CHUNK = 1001, 1024, 5
WIDTH, HEIGHT = 64, 36
KILLED_TASK = 2                   # frames 1011-1015
SLOW = [1013, 1014, 1015]         # large frames: the kill lands in one of them
DAMAGED = 1024                    # cut short at first: task 4 fails that frame alone


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def frame_pixel(frame):
    # Every frame different (a moving bright spot bloom spreads, a ramp scaled by the frame), so
    # a task writing the wrong frame's picture cannot go unseen.
    spot = ((frame * 7) % WIDTH, (frame * 3) % HEIGHT)
    scale = 0.2 + 0.05 * (frame - FIRST)
    return lambda x, y: (60.0, 40.0, 20.0) if (x, y) == spot else (scale * x / WIDTH, scale * y / HEIGHT, 0.1)


def wait_until(condition, seconds, what, cluster, poll=0.2):
    deadline = time.time() + seconds
    while time.time() < deadline:
        if condition():
            return
        time.sleep(poll)
    raise Failure("waited %d s for %s; queue:\n%s" % (seconds, what, cluster.output(["squeue", "-r"])))


def run(command, env, expect=None):
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    if expect is not None and result.returncode not in expect:
        raise Failure("%s: exit code %d (expected %s)\nstdout:\n%s\nstderr:\n%s" % (
            " ".join(command), result.returncode, expect, result.stdout, result.stderr))
    return result


def job_done(cluster, job_id):
    return lambda: cluster.output(["squeue", "-h", "-r", "-j", job_id]).strip() == ""


def main(render, farm, plugins):
    folder = tempfile.mkdtemp(prefix="pfx-farm-test-")
    try:
        with SlurmCluster(os.path.join(folder, "slurm")) as cluster:
            print("cluster up: one node, %d CPUs, in %s" % (cluster.cpus, cluster.folder))
            scenario(cluster, folder, render, farm, plugins)
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def scenario(cluster, folder, render, farm, plugins):
    env = cluster.env
    shot = os.path.join(folder, "shot")
    os.makedirs(shot)
    for frame in range(FIRST, LAST + 1):
        if frame not in SLOW:
            write_rgb_exr(os.path.join(shot, "in.%04d.exr" % frame), WIDTH, HEIGHT, frame_pixel(frame))
    run([render, "--demo-image", "--size", "1280x720", "--chain", "", "--out", os.path.join(shot, "slow.exr")],
        cluster.env, expect=[0])
    for frame in SLOW:
        shutil.copy(os.path.join(shot, "slow.exr"), os.path.join(shot, "in.%04d.exr" % frame))
    damaged = os.path.join(shot, "in.%04d.exr" % DAMAGED)
    with open(damaged, "rb") as f:
        whole = f.read()
    with open(damaged, "wb") as f:
        f.write(whole[:len(whole) // 2])
    effects = ["--plugins", plugins, "--chain", "bloom", "--set", "bloom.threshold=1"]
    farm_args = effects + ["--input", "in.%04d.exr", "--out", "out/beauty.####.exr", "--out", "out/beauty.@@@@.png"]
    os.makedirs(os.path.join(shot, "out"))
    jobs = ["--jobs-dir", os.path.join(folder, "jobs")]

    os.chdir(shot)
    job = run([farm, "submit", "--frames", "%d-%d" % (FIRST, LAST), "--chunk", str(CHUNK), *jobs,
               "--render", render, "--"] + farm_args, env, expect=[0]).stdout.strip()
    check(job.isdigit(), "pfx-farm submit printed %r, not a job id" % job)
    print("submitted job %s" % job)

    # Task 2 has written 1011 and 1012 and is inside the large frames: kill it, the hard way.
    wait_until(lambda: os.path.exists("out/beauty.1012.png"), 120, "task 2's first two frames", cluster, poll=0.02)
    run(["scancel", "--signal=KILL", "%s_%d" % (job, KILLED_TASK)], env, expect=[0])
    wait_until(job_done(cluster, job), 120, "job %s to end" % job, cluster)

    # What the kill left: the end of task 2's chunk, from whichever large frame it was in.
    left = [f for f in range(FIRST, LAST + 1) if f != DAMAGED and not os.path.exists("out/beauty.%04d.png" % f)]
    check(not os.path.exists("out/beauty.%04d.exr" % DAMAGED), "the damaged frame %d has an output" % DAMAGED)
    check(left and left[-1] == SLOW[-1] and left == list(range(left[0], SLOW[-1] + 1)) and left[0] >= SLOW[0],
          "after killing task 2 in frames %s, the frames left should be the end of its chunk; left: %s" %
          (SLOW, left))
    result = run([farm, "status", job, *jobs], env, expect=[1])
    print(result.stdout, end="")
    listed = "%d-%d" % (left[0], left[-1]) if len(left) > 1 else str(left[0])
    check("%d done" % (LAST - FIRST - len(left)) in result.stdout and "%d missing" % len(left) in result.stdout
          and "missing  %s" % listed in result.stdout and "%d CANCELLED" % KILLED_TASK in result.stdout
          and "1 failed" in result.stdout and "frame %d: in.%d.exr: " % (DAMAGED, DAMAGED) in result.stdout
          and "4 FAILED" in result.stdout,
          "pfx-farm status after the kill should list frames %s as missing and %d as failed with its reason, "
          "task 2 cancelled and task 4 failed:\n%s" % (listed, DAMAGED, result.stdout))
    with open(damaged, "wb") as f:
        f.write(whole)
    again = run([farm, "resubmit", job, *jobs], env, expect=[0]).stdout.strip()
    check(again.isdigit() and again != job, "pfx-farm resubmit printed %r, not a new job id" % again)
    with open(os.path.join(folder, "jobs", again, "job.json")) as f:
        tasks = json.load(f)["tasks"]
    check(tasks == [KILLED_TASK, 4], "the resubmitted job should hold only tasks 2 and 4, holds %s" % tasks)
    wait_until(job_done(cluster, again), 120, "job %s to end" % again, cluster)

    result = run([farm, "status", job, *jobs], env, expect=[0])
    print(result.stdout, end="")
    check("24 done" in result.stdout, "pfx-farm status after the resubmission: " + result.stdout)
    log = os.path.join(folder, "jobs", again, "logs", "task-%d.log" % KILLED_TASK)
    with open(log) as f:
        text = f.read()
    check("%d skipped (already complete)" % (5 - len(left)) in text and "%d rendered" % len(left) in text,
          "the resubmitted task should skip the frames written before the kill and render %s; its log:\n%s" %
          (left, text))

    # The reference: one local pfx-render over the whole range, into a folder of its own.
    os.makedirs("local")
    run([render] + effects + ["--input", "in.%04d.exr", "--frames", "%d-%d" % (FIRST, LAST),
                              "--out", "local/beauty.%04d.exr", "--out", "local/beauty.%04d.png"], env, expect=[0])
    for frame in range(FIRST, LAST + 1):
        for ext in ("exr", "png"):
            with open("out/beauty.%04d.%s" % (frame, ext), "rb") as a, \
                    open("local/beauty.%04d.%s" % (frame, ext), "rb") as b:
                check(a.read() == b.read(), "frame %d: the farm's %s differs from the local render's" % (frame, ext))
    leftovers = [name for name in os.listdir("out") if not name.startswith("beauty.")]
    check(not leftovers, "files other than the outputs in out/: %s" % leftovers)
    print("24 frames from the farm equal the local render's, byte for byte (EXR and PNG)")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    if os.geteuid() != 0:
        print("SKIP: the Slurm daemons of this test run as root (SlurmUser=root); run it as root", file=sys.stderr)
        sys.exit(77)
    missing = SlurmCluster.missing_programs()
    if missing:
        print("SKIP: Slurm or munge is not installed (%s missing): ./run installs slurm-wlm, slurmctld, "
              "slurmd, munge" % ", ".join(missing), file=sys.stderr)
        sys.exit(77)
    try:
        main(*[os.path.abspath(arg) for arg in sys.argv[1:]])
    except ClusterError as error:
        print("FAILED: the test cluster could not start: %s" % error, file=sys.stderr)
        sys.exit(1)
    except Failure as error:
        print("FAILED: %s" % error, file=sys.stderr)
        sys.exit(1)
