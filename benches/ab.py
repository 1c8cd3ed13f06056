#!/usr/bin/env python3
"""Two builds of a chapter binary, side by side: the same arguments, their runs alternated.

    python3 benches/ab.py OLD_BINARY NEW_BINARY [--runs N] [--threads T] -- ARGS...

Runs OLD and NEW in turns (A B, then B A, ...) after one unmeasured run of each, so a drift
of the machine's speed weighs on both alike, and prints each one's median wall time (the whole
process, as a user waits for it), the ratio of the medians (NEW / OLD: below 1 is faster), and
the median and range of the runs' own ratios; then the same for the CPU time the process used
(user + system), which other work on a shared machine disturbs less than the wall time. `-o` is
pointed at a temporary file (removed at the end) unless ARGS give one. With --threads,
RAYON_NUM_THREADS is set for both.
"""
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time


def main(argv):
    if "--" not in argv or len(argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    split = argv.index("--")
    head, args = argv[:split], argv[split + 1:]
    runs, threads, binaries = 11, None, []
    i = 0
    while i < len(head):
        if head[i] == "--runs":
            runs = int(head[i + 1])
            i += 2
        elif head[i] == "--threads":
            threads = head[i + 1]
            i += 2
        else:
            binaries.append(head[i])
            i += 1
    if len(binaries) != 2 or runs < 1:
        print("error: give exactly two binaries and --runs of at least 1", file=sys.stderr)
        return 2
    env = dict(os.environ)
    if threads:
        env["RAYON_NUM_THREADS"] = threads
    with tempfile.TemporaryDirectory(prefix="whitted-ab-") as tmp:
        if "-o" not in args:
            args = args + ["-o", os.path.join(tmp, "out.png")]
        return measure(binaries, args, env, runs)


def measure(binaries, args, env, runs):
    """Runs the two binaries in turns and prints the medians; 0."""

    def cpu():
        used = resource.getrusage(resource.RUSAGE_CHILDREN)
        return used.ru_utime + used.ru_stime

    def once(binary):
        """The run's wall time and CPU time, in seconds."""
        start, start_cpu = time.perf_counter(), cpu()
        subprocess.run([binary] + args + ["-q"], env=env, check=True)
        return time.perf_counter() - start, cpu() - start_cpu

    for b in binaries:
        once(b)  # unmeasured: caches, page faults, frequency
    times = {b: [] for b in binaries}
    for r in range(runs):
        order = binaries if r % 2 == 0 else binaries[::-1]
        for b in order:
            times[b].append(once(b))
    old, new = binaries
    print(f"args: {' '.join(args)}  ({runs} runs each, alternated)")
    for k, what in enumerate(["wall", "cpu"]):
        t_old = [t[k] for t in times[old]]
        t_new = [t[k] for t in times[new]]
        m_old, m_new = statistics.median(t_old), statistics.median(t_new)
        ratios = [n / o for o, n in zip(t_old, t_new)]
        print(f"  {what}: median {m_old:.4f} s  old  {old}")
        print(f"  {what}: median {m_new:.4f} s  new  {new}")
        print(f"  {what}: new / old: {m_new / m_old:.3f} (median of run ratios "
              f"{statistics.median(ratios):.3f}, range {min(ratios):.3f} to {max(ratios):.3f})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
