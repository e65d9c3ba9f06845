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


def test_a_context_the_caller_made_current_stays_current():
    # A script with GL of its own (a window, moderngl) has its context current on its thread; the
    # chain works on a thread of its own and leaves it alone. Made here with EGL through ctypes.
    import ctypes
    egl = ctypes.CDLL("libEGL.so.1")
    egl.eglGetProcAddress.restype = ctypes.c_void_p
    for name in ("eglGetCurrentContext", "eglCreateContext"):
        getattr(egl, name).restype = ctypes.c_void_p
    get_platform_display = ctypes.CFUNCTYPE(ctypes.c_void_p, ctypes.c_uint, ctypes.c_void_p, ctypes.c_void_p)(
        egl.eglGetProcAddress(b"eglGetPlatformDisplayEXT"))
    display = ctypes.c_void_p(get_platform_display(0x31DD, None, None))  # EGL_PLATFORM_SURFACELESS_MESA
    assert egl.eglInitialize(display, None, None)
    assert egl.eglBindAPI(0x30A2)  # EGL_OPENGL_API
    context = ctypes.c_void_p(egl.eglCreateContext(display, None, None, None))
    assert context.value
    assert egl.eglMakeCurrent(display, None, None, context)
    try:
        with pfx.Chain(["bloom"]) as chain:
            chain.run(np.full((8, 8, 4), 5.0, np.float32))
        assert egl.eglGetCurrentContext() == context.value
    finally:
        egl.eglMakeCurrent(display, None, None, None)
        egl.eglDestroyContext(display, context)


def test_two_chains_alive_at_once_keep_working_when_one_closes(pictures):
    # Each chain loads the plugins for itself; the second one alive gets its own copy of each
    # library, so closing one (its plugins' deinit) leaves the other's plugins as they were.
    photo = pictures["photo"][1]
    first = pfx.Chain(["bloom", "glare"])
    expected = first.run(photo)
    second = pfx.Chain(["bloom", "glare"])
    assert_same_bits(second.run(photo), expected, "the second chain")
    second.close()
    assert_same_bits(first.run(photo), expected, "the first chain after the second closed")
    first.close()
