"""Chains on different threads: each has its own context and GL thread, so two threads with a
Chain each give exactly what the two chains give one after the other, while Chain.run lets the
other thread (and Python) go on."""

import threading

import numpy as np
import pfx

from conftest import assert_same_bits


def work(effect, settings, pictures):
    chain = pfx.Chain([effect])
    for key, value in settings.items():
        chain.set(key, value)
    return chain, [chain.run(p) for p in pictures]


def test_two_threads_with_a_chain_each_give_what_one_after_the_other_gives(pictures):
    photo = pictures["photo"][1]
    demo = pictures["demo"][1]
    jobs = {
        "bloom": ("bloom", {"bloom.mode": "mgf"}, [photo, demo[..., :3].copy()] * 3),
        "glare": ("glare", {"glare.strength": 3}, [demo, photo] * 3),
    }
    alone = {name: work(*job)[1] for name, job in jobs.items()}

    together = {}
    start = threading.Barrier(len(jobs))

    def thread(name):
        start.wait()
        together[name] = work(*jobs[name])[1]

    threads = [threading.Thread(target=thread, args=(name,)) for name in jobs]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for name in jobs:
        assert len(together[name]) == len(alone[name])
        for i, (a, b) in enumerate(zip(together[name], alone[name])):
            assert_same_bits(a, b, f"{name}, picture {i}")


def test_run_lets_other_python_threads_go_on(pictures):
    # While one thread is inside run, another thread counts; with the GIL held through run it
    # could not count at all.
    photo = pictures["photo"][1]
    big = np.ascontiguousarray(np.tile(photo, (3, 3, 1)))
    chain = pfx.Chain(["bloom"])
    chain.set("bloom.mode", "gaussian")
    chain.run(big)  # programs compiled, targets made
    counted = 0
    running = threading.Event()
    done = threading.Event()

    def count():
        nonlocal counted
        running.set()
        while not done.is_set():
            counted += 1

    counter = threading.Thread(target=count)
    counter.start()
    running.wait()
    before = counted
    for _ in range(3):
        chain.run(big)
    during = counted - before
    done.set()
    counter.join()
    chain.close()
    assert during > 1000, f"the other thread counted only {during} while run worked"
