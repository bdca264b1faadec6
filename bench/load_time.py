#!/usr/bin/env python3
"""Paired load-time benchmark (not run by the tests; see bench/README_mesh.md).

Usage: bench/load_time.py RUNS 'label|rtrace|octree|folder' ...

Runs `rtrace -h OCTREE < /dev/null` (load and accelerator build, then exit) in FOLDER for
each configuration in turn, RUNS rounds, so that a busy machine slows all alike; prints
the median, minimum and maximum wall time (perf_counter) and peak resident memory (the
child's ru_maxrss from wait4) of each.
"""
import os
import statistics
import subprocess
import sys
import time


def main():
    runs = int(sys.argv[1])
    configs = [c.split("|") for c in sys.argv[2:]]
    results = {c[0]: ([], []) for c in configs}
    for _ in range(runs):
        for label, rtrace, octree, folder in configs:
            start = time.perf_counter()
            child = subprocess.Popen([rtrace, "-h", octree], cwd=folder,
                                     stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                     stderr=subprocess.DEVNULL)
            _, status, usage = os.wait4(child.pid, 0)
            seconds = time.perf_counter() - start
            if status != 0:
                sys.exit("%s: rtrace failed (status %d)" % (label, status))
            results[label][0].append(seconds)
            results[label][1].append(usage.ru_maxrss / 1024)
    for label, _, _, _ in configs:
        t, m = results[label]
        print("%-14s n=%d median %.4f s (min %.4f max %.4f)  peak %.1f MB (min %.1f max %.1f)"
              % (label, len(t), statistics.median(t), min(t), max(t), statistics.median(m),
                 min(m), max(m)))


if __name__ == "__main__":
    main()
