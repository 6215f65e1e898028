"""The CPU time of every test, as the suite runs: a pytest plugin and its summary.

On a machine shared with other work the wall time of a test says little; its CPU seconds (this
process's and those of the processes it started and waited for) do.  Each finished test appends one
line ``cpu<TAB>wall<TAB>node id`` to the file named by ``CPU_PER_TEST_OUT`` (default
``cpu_per_test.tsv``), so a run cut short still leaves what it measured:

    PYTHONPATH=tools CPU_PER_TEST_OUT=/tmp/search.tsv python -m pytest tests/search -n 0 \\
        -p cpu_per_test
    python tools/cpu_per_test.py /tmp/search.tsv          # per file and the slowest tests

A test's CPU includes its fixtures' setup (a module fixture counts in its module's first test).
"""

from __future__ import annotations

import argparse
import os
import resource
import time
from collections import defaultdict

import pytest


def _cpu() -> float:
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time() + children.ru_utime + children.ru_stime


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    cpu, wall = _cpu(), time.perf_counter()
    yield
    line = f"{_cpu() - cpu:.3f}\t{time.perf_counter() - wall:.3f}\t{item.nodeid}\n"
    with open(os.environ.get("CPU_PER_TEST_OUT", "cpu_per_test.tsv"), "a", encoding="utf-8") as f:
        f.write(line)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description="CPU seconds per test file and the slowest tests")
    ap.add_argument("files", nargs="+", help="tab-separated files the plugin wrote")
    ap.add_argument("--top", type=int, default=30, help="how many tests to list")
    args = ap.parse_args(argv)
    rows = []
    for name in args.files:
        with open(name, encoding="utf-8") as f:
            for line in f:
                cpu, wall, node = line.rstrip("\n").split("\t", 2)
                rows.append((float(cpu), float(wall), node))
    per_file: dict = defaultdict(lambda: [0.0, 0])
    for cpu, _, node in rows:
        per_file[node.split("::")[0]][0] += cpu
        per_file[node.split("::")[0]][1] += 1
    print(f"{sum(r[0] for r in rows):.1f} CPU-s in {len(rows)} tests")
    for path, (cpu, n) in sorted(per_file.items(), key=lambda kv: -kv[1][0])[: args.top]:
        print(f"{cpu:8.1f} {n:5d}  {path}")
    print()
    for cpu, _, node in sorted(rows, reverse=True)[: args.top]:
        print(f"{cpu:8.1f}  {node}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
