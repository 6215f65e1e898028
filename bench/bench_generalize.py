"""Wall time and outcome of `axisopt solve` on axes written outside the project (a benchmark, not a
test).

    python bench/bench_generalize.py [--cases 300] [--seed 0] [--workers 2] [--timeout 60] [--compare 20]
                                     [--keep DIR] [--only 12,40]

Each case of bench/axis_generator.py runs as a user runs it: a fresh
``python -m axisopt solve FILE --json F`` process (sensitivities and advice on, the default time
limit).  Prints the wall and CPU time's p50 / p95 / max (the CPU time, user + system of the solve's
process, is what load on a shared machine changes least), feasible (exit 0) and infeasible (exit 1)
apart, the slowest ten, and every crash: a traceback on stderr, or an exit code other than 0 (a
design), 1 (infeasible, explained) or 2 (a one-line input error, e.g. a unit slip the readers
refuse).  The machine is shared: a reference problem (problems/teaching_problem.yaml) is solved the
same way before and after the cases, and the figures are also printed as multiples of its time.

``--compare N``: of the cases with a design or proven infeasible whose certificate counts at most
10^6 combinations, the first N are solved again with ``--method exhaustive`` and the optimum's
objective compared (Pareto cases compare their fronts' points).
"""  # noqa: E501

from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))

from axis_generator import generate  # noqa: E402

REFERENCE = ROOT / "problems" / "teaching_problem.yaml"


def solve(path: Path, out: Path, *extra: str, timeout: float = 60.0) -> dict:
    cmd = [sys.executable, "-m", "axisopt", "solve", str(path), "--json", str(out), *extra]
    t0 = time.perf_counter()
    u0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, cwd=path.parent)
        rc, err, text = p.returncode, p.stderr, p.stdout
    except subprocess.TimeoutExpired:
        rc, err, text = None, "", ""
    wall = time.perf_counter() - t0
    # the one child this process ran (reaped): its CPU time
    u1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (u1.ru_utime - u0.ru_utime) + (u1.ru_stime - u0.ru_stime)
    result = None
    if rc in (0, 1) and out.exists():
        try:
            result = json.loads(out.read_text())
        except ValueError:
            result = None
    return {"rc": rc, "wall": wall, "cpu": cpu, "stderr": err, "stdout": text, "result": result}


def run_case(job):
    seed, index, text, name, timeout = job
    with tempfile.TemporaryDirectory(prefix="gen-") as d:
        f = Path(d) / f"{name}.yaml"
        f.write_text(text)
        r = solve(f, Path(d) / "r.json", timeout=timeout)
    res = r.pop("result")
    r["status"] = res["status"] if res else None
    cert = (res or {}).get("certificate") or {}
    r["combinations"] = cert.get("combinations")
    obj = (res or {}).get("objective")
    # a scalar answer's objective is a dict (label, unit, value); a Pareto answer's names its goals
    r["objective"] = obj.get("value") if isinstance(obj, dict) else None
    # what the closest design of an infeasible answer misses (the check names)
    closest = ((res or {}).get("infeasibility") or {}).get("closest") or []
    r["misses"] = sorted((closest[0].get("misses") or {}) if closest else {})
    r["pareto"] = bool((res or {}).get("pareto"))
    r["index"], r["name"], r["text"] = index, name, text
    r["crash"] = ("Traceback" in r["stderr"]) or r["rc"] not in (0, 1, 2, None)
    r["stdout"] = r["stdout"][-2000:]
    return r


def compare_case(job):
    name, text, default_obj, status = job
    with tempfile.TemporaryDirectory(prefix="gex-") as d:
        f = Path(d) / f"{name}.yaml"
        f.write_text(text)
        r = solve(
            f,
            Path(d) / "r.json",
            "--method",
            "exhaustive",
            "--no-sensitivity",
            "--time-limit",
            "3600",
            timeout=3600,
        )
        e = r["result"] or {}
    e_obj = (e.get("objective") or {}).get("value")
    same = e.get("status") in ("optimal", "infeasible") and (
        (status == "infeasible" and e.get("status") == "infeasible")
        or (
            e_obj is not None
            and default_obj is not None
            and abs(e_obj - default_obj) <= 1e-6 * max(1.0, abs(e_obj))
        )
    )
    return {
        "name": name,
        "default": default_obj,
        "exhaustive": e_obj,
        "status": status,
        "exhaustive_status": e.get("status"),
        "same": same,
        "wall": r["wall"],
    }


def pct(xs, q):
    if not xs:
        return float("nan")
    xs = sorted(xs)
    k = min(len(xs) - 1, max(0, int(round(q * (len(xs) - 1)))))
    return xs[k]


def reference_time(repeat=3) -> tuple:
    """(wall, CPU) medians of the reference problem's solve [s]."""
    with tempfile.TemporaryDirectory(prefix="ref-") as d:
        rs = [solve(REFERENCE, Path(d) / "r.json") for _ in range(repeat)]
    return statistics.median(r["wall"] for r in rs), statistics.median(r["cpu"] for r in rs)


def line(label, xs, ref):
    if not xs:
        return f"  {label:<11} n=0"
    return (
        f"  {label:<11} n={len(xs):<4} p50 {pct(xs, 0.5):5.2f} s  p95 {pct(xs, 0.95):5.2f} s  max "
        f"{max(xs):5.2f} s   (x reference: {pct(xs, 0.5) / ref:4.1f} / {pct(xs, 0.95) / ref:4.1f} "
        f"/ {max(xs) / ref:4.1f})"
    )


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", type=int, default=300)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument(
        "--timeout",
        type=float,
        default=600.0,
        help="wall seconds before a case counts as a hang "
        "(generous: a loaded machine stretches wall time ten-fold)",
    )
    ap.add_argument(
        "--compare", type=int, default=20, help="cases compared with --method exhaustive"
    )
    ap.add_argument("--keep", type=Path, help="write every case's YAML and the results (JSON) here")
    ap.add_argument("--only", help="comma-separated case indices")
    a = ap.parse_args(argv)
    cases = generate(a.cases, a.seed)
    if a.only:
        keep = {int(i) for i in a.only.split(",")}
        cases = [c for i, c in enumerate(cases) if i in keep]
    ref0 = reference_time()
    print(
        f"reference (teaching problem, fresh process): wall {ref0[0]:.2f} s, CPU {ref0[1]:.2f} s",
        flush=True,
    )
    jobs = [(a.seed, int(c.name.split("-")[2]), c.text, c.name, a.timeout) for c in cases]
    t0 = time.perf_counter()
    with mp.Pool(a.workers) as pool:
        rs = []
        for r in pool.imap_unordered(run_case, jobs):
            rs.append(r)
            if len(rs) % 25 == 0:
                print(
                    f"  {len(rs)}/{len(jobs)} cases, {time.perf_counter() - t0:.0f} s", flush=True
                )
    total = time.perf_counter() - t0
    ref1 = reference_time()
    rs.sort(key=lambda r: r["index"])
    errs = [r for r in rs if r["rc"] == 2]
    crashes = [r for r in rs if r["crash"]]
    print(
        f"\n{len(rs)} cases in {total:.0f} s on {a.workers} workers; reference wall {ref0[0]:.2f} "
        f"s before, {ref1[0]:.2f} s after (CPU {ref0[1]:.2f} / {ref1[1]:.2f} s)"
    )
    print(
        f"  exit 0 {sum(r['rc'] == 0 for r in rs)}, exit 1 {sum(r['rc'] == 1 for r in rs)}, exit 2 "
        f"{len(errs)}, crashes {len(crashes)}, timeouts {sum(r['rc'] is None for r in rs)}"
    )
    for key, ref in (("wall", 0.5 * (ref0[0] + ref1[0])), ("cpu", 0.5 * (ref0[1] + ref1[1]))):
        print(f"{key} time [s] (and as multiples of the reference's {ref:.2f} s):")
        print(line("all (0, 1)", [r[key] for r in rs if r["rc"] in (0, 1)], ref))
        print(line("feasible", [r[key] for r in rs if r["rc"] == 0], ref))
        print(line("infeasible", [r[key] for r in rs if r["rc"] == 1], ref))
        print(line("input err", [r[key] for r in errs], ref))
    print("slowest ten (CPU time):")
    for r in sorted(rs, key=lambda r: -r["cpu"])[:10]:
        print(
            f"  CPU {r['cpu']:6.2f} s  wall {r['wall']:6.2f} s  exit {r['rc']}  "
            f"{r['status'] or '-':<12} {r['name']}"
        )
    tally: dict = {}
    for r in rs:
        for m in r.get("misses") or ():
            tally[m] = tally.get(m, 0) + 1
    if tally:
        n_inf = sum(r["rc"] == 1 for r in rs)
        print(f"what the closest design misses (of {n_inf} infeasible answers):")
        for m, k in sorted(tally.items(), key=lambda t: -t[1]):
            print(f"  {k:4d}  {m}")
    if errs:
        print("input errors (first 8):")
        for r in errs[:8]:
            print(f"  {r['name']}: {r['stderr'].strip()[:150]}")
    for r in rs:
        if r["rc"] is None:
            print(f"  HANG (no exit within {a.timeout:g} s): {r['name']}")
    if crashes:
        print("CRASHES:")
        for r in crashes:
            print(f"  {r['name']} exit {r['rc']}: {r['stderr'].strip()[-600:]}")
    if a.keep:
        a.keep.mkdir(parents=True, exist_ok=True)
        for r in rs:
            (a.keep / f"{r['name']}.yaml").write_text(r["text"])
        (a.keep / "results.json").write_text(
            json.dumps(
                [
                    {
                        k: r[k]
                        for k in (
                            "name",
                            "rc",
                            "wall",
                            "cpu",
                            "status",
                            "combinations",
                            "objective",
                            "misses",
                            "stderr",
                        )
                    }
                    for r in rs
                ],
                indent=1,
            )
        )
    if a.compare:
        sample = [
            r
            for r in rs
            if r["rc"] in (0, 1)
            and r["combinations"]
            and r["combinations"] <= 1e6
            and not r["pareto"]
            and r["status"] in ("optimal", "infeasible")
        ][: a.compare]
        with mp.Pool(a.workers) as pool:
            cs = pool.map(
                compare_case, [(r["name"], r["text"], r["objective"], r["status"]) for r in sample]
            )
        bad = [c for c in cs if not c["same"]]
        print(
            f"default == exhaustive on {len(cs) - len(bad)} of {len(cs)} cases with <= 1e6 "
            "combinations"
        )
        for c in bad:
            print(f"  DIFFERS {c}")
    return 1 if crashes else 0


if __name__ == "__main__":
    sys.exit(main())
