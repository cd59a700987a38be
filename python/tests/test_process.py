"""The module in a long-running process: the GIL is released while a frame renders, threads
share the one GL context, and 1,000 renders leave the memory where it was."""
import os
import threading
import time

import numpy as np

import plumbago as pg


def rss_mb():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


def small_scene(size=(64, 48)):
    s = pg.Scene("builtin:torus")
    s.size = size
    return s


def test_other_threads_run_while_a_frame_renders():
    s = small_scene((320, 320))
    s.set("contour.copies", 5)
    worker = threading.Thread(target=s.render, args=("reference",))
    ticks = 0
    worker.start()
    while worker.is_alive():
        ticks += 1
        time.sleep(0.001)
    assert ticks > 10


def test_threads_share_the_gpu():
    s = small_scene()
    expected = s.render("gpu")
    results = [None] * 4

    def render(i):
        results[i] = s.render("gpu")

    threads = [threading.Thread(target=render, args=(i,)) for i in range(len(results))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(np.array_equal(r, expected) for r in results)


def test_a_thousand_renders_do_not_leak():
    s = small_scene()
    for key, value in (("pencil_textures.size", 16), ("pencil_textures.layers", 2), ("contour.texture_layer", 0)):
        s.set(key, value)  # the contour texture, made anew by every render, in a few ms
    for backend in ("gpu", "reference"):  # the first frames make what lives as long as the process
        for _ in range(20):
            s.render(backend, linear=True)
    before = rss_mb()
    for i in range(1000):
        img = s.render("gpu" if i % 2 else "reference", linear=True)
        assert img.shape == (48, 64, 3)
    del img
    grown = rss_mb() - before
    assert grown < 32, "%.1f MB more after 1,000 renders" % grown
