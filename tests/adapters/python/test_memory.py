"""A thousand Chains made, run and closed one after the other leave the process as they found it:
the heap in use (glibc's count of bytes handed out and not freed, all arenas: mallinfo2), the
open files and the threads do not grow. Resident memory is not judged: with transparent huge
pages the kernel folds heap pages into 2 MiB ones in the background, which moves it while the
heap stays the same.

A leak of 24 bytes per chain adds 21,600 bytes over the 900 cycles measured: the bound (16 KiB)
catches it, and leaves room for what Python's allocator keeps for itself."""

import ctypes
import gc
import os

import numpy as np
import pfx

CYCLES = 1000
WARM_UP = 100  # the driver's caches, Python's free lists and numpy's fill first
BOUND = 16 * 1024


class MallInfo2(ctypes.Structure):
    _fields_ = [(name, ctypes.c_size_t) for name in
                "arena ordblks smblks hblks hblkhd usmblks fsmblks uordblks fordblks keepcost".split()]


libc = ctypes.CDLL(None)
libc.mallinfo2.restype = MallInfo2


def usage():
    gc.collect()
    info = libc.mallinfo2()
    return {"heap bytes in use": info.uordblks + info.hblkhd,
            "open files": len(os.listdir("/proc/self/fd")),
            "threads": len(os.listdir("/proc/self/task"))}


def cycle(picture):
    with pfx.Chain(["bloom"]) as chain:
        chain.set("bloom.threshold", 2.0)
        chain.run(picture)


def test_a_thousand_chains_made_run_and_closed_do_not_grow_the_process():
    picture = np.zeros((24, 40, 4), np.float32)
    picture[10, 20, :3] = 50.0
    for _ in range(WARM_UP):
        cycle(picture)
    before = usage()
    for _ in range(CYCLES - WARM_UP):
        cycle(picture)
    after = usage()
    growth = after["heap bytes in use"] - before["heap bytes in use"]
    assert growth <= BOUND, f"the heap grew by {growth} bytes over {CYCLES - WARM_UP} chains: {before} -> {after}"
    assert after["open files"] == before["open files"], f"{before} -> {after}"
    assert after["threads"] == before["threads"], f"{before} -> {after}"


def test_a_chain_left_to_the_garbage_collector_frees_its_thread():
    threads = len(os.listdir("/proc/self/task"))
    chain = pfx.Chain(["bloom"])
    assert len(os.listdir("/proc/self/task")) == threads + 1  # its GL thread
    del chain
    gc.collect()
    assert len(os.listdir("/proc/self/task")) == threads
