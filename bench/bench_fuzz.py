"""Long fuzz run of the command line (prints a table; not a test).

    python bench/bench_fuzz.py [--cases 3000] [--seed 0] [--workers 2] [--timeout 60] [--details bad.txt]
    python bench/bench_fuzz.py --replay 123 --keep /tmp/case123      # write case 123's files, print its command

Every case is one shipped input (design, problem, study with a tiny sweep, saved calibration,
diagnose data CSV, user catalog directory, compare pair, or command-line flags) with a mutation, or
one of the hardening cases of issue 24 (FIFO and device paths, '-', oversized or degenerate data,
...), from ``tests/core/fuzz_inputs.py``, or a realistic axis of ``bench/axis_generator.py`` (kind
``generated``), run as a subprocess ``python -m axisopt ...`` in its own empty directory with a time
limit.  Each outcome is classified against the CLI contract:

  ok                exit 0, --json output finite and without negative masses, stiffnesses, lengths
  negative          exit 1 (proven) or 3 (unproven: Bonmin, a time limit) with an explanation
  clean error       exit 2 with exactly one stderr line starting 'error: '
  multi-line error  exit 2 with anything else on stderr
  traceback         a Python traceback on stderr (any exit code)
  hang              no exit within --timeout seconds (the process group is killed)
  bad output        exit 0 but the JSON holds NaN/Infinity or a negative mass/stiffness/length/frequency
  warning           exit 0 with a Python warning on stderr
  silent negative   exit 1 or 3 with no output at all
  crash             any other exit code (a signal, an abort)

Case ``i`` of seed ``s`` is drawn from ``random.Random(s * 1_000_003 + i)``, so a bad case is
reproduced with ``--seed s --replay i``.  The cases of a run are split evenly over the input kinds
(``--kinds`` to choose).
"""  # noqa: E501

from __future__ import annotations

import argparse
import collections
import multiprocessing as mp
import random
import re
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "core"))

import fuzz_inputs as F  # noqa: E402

sys.path.insert(0, str(ROOT / "bench"))
import axis_generator  # noqa: E402

# besides the shipped inputs' mutations: a realistic axis of bench/axis_generator.py (its own seed
# and index), solved as a user solves it (sensitivities and advice on), sometimes with one of the
# flags a user adds
GENERATED = "generated"
KINDS = F.KINDS + (GENERATED,)


def generated_case(rnd: random.Random, index: int) -> F.Case:
    gen = axis_generator.make(rnd.randrange(1_000_000), index)
    extra = rnd.choice(
        (
            [],
            [],
            ["--top", "3"],
            ["--time-limit", "1"],
            ["--no-sensitivity"],
            ["--method", "exhaustive", "--time-limit", "20"],
        )
    )
    return F.Case(
        GENERATED,
        f"{gen.name}{' slip ' + gen.slip if gen.slip else ''}",
        ["solve", "axis.yaml", "--json", "out.json", *extra],
        files={"axis.yaml": gen.text.encode()},
    )


def make(seed: int, index: int, kinds) -> F.Case:
    rnd = random.Random(seed * 1_000_003 + index)
    ch = F.RandomChooser(rnd)
    kind = kinds[index % len(kinds)]
    if kind == GENERATED:
        return generated_case(rnd, index)
    if kind == "flags" and rnd.random() < 0.02:
        return F.fifo_case()
    case = F.make_case(ch, kind, fast=False)
    if "bonmin" in case.argv and "--time-limit" not in case.argv:
        # Bonmin's default limit is 100 s per mounting: not a hang
        case.argv += ["--time-limit", "10"]
    return case


def _init(cal: bytes, data: dict) -> None:
    F._CAL_CACHE["cal"] = cal
    F._DATA_CACHE.update(data)


def run_one(job):
    seed, index, kinds, timeout = job
    case = make(seed, index, kinds)
    with tempfile.TemporaryDirectory(prefix="fuzz-") as d:
        out = F.run_subprocess(case, Path(d), timeout=timeout)
    cls, detail = F.classify(case, out)
    err_head = "\n".join(out.stderr.strip().splitlines()[:12])
    if cls == "traceback":  # the frames nearest the error are the useful ones
        err_head = "\n".join(out.stderr.strip().splitlines()[-14:])
    return {
        "index": index,
        "kind": case.kind,
        "mutation": case.mutation,
        "command": case.command(),
        "class": cls,
        "detail": detail,
        "seconds": out.seconds,
        "rc": out.rc,
        "stderr": err_head,
    }


def signature(r) -> str:
    """Group bad cases by what went wrong, not by the numbers in the message."""
    d = r["detail"]
    d = re.sub(r"np\.float64\(([^)]*)\)", r"\1", d)
    d = re.sub(r"'[^']*'", "'…'", d)
    d = re.sub(r"\d+(\.\d+)?(e[-+]?\d+)?", "N", d)
    words = r["command"].split()
    cmd = words[1] if len(words) > 1 else "-"
    return f"{r['class']} | {cmd} | {d[:140]}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", type=int, default=3000, help="number of cases (default 3000)")
    ap.add_argument("--seed", type=int, default=0, help="seed of the run (default 0)")
    ap.add_argument("--workers", type=int, default=2, help="parallel subprocesses (default 2)")
    ap.add_argument(
        "--timeout", type=float, default=60.0, help="seconds per case before it counts as a hang"
    )
    ap.add_argument(
        "--kinds", default=",".join(KINDS), help=f"input kinds to fuzz (default {','.join(KINDS)})"
    )
    ap.add_argument(
        "--details", metavar="FILE", help="write every bad case (command, mutation, stderr) to FILE"
    )
    ap.add_argument(
        "--replay", type=int, metavar="INDEX", help="only write case INDEX's files and print it"
    )
    ap.add_argument("--keep", metavar="DIR", help="with --replay: directory for the case's files")
    ap.add_argument(
        "--run", action="store_true", help="with --replay: also run the case and show its outcome"
    )
    args = ap.parse_args(argv)
    kinds = tuple(k.strip() for k in args.kinds.split(",") if k.strip())
    bad_kind = [k for k in kinds if k not in KINDS]
    if bad_kind or not kinds:
        ap.error(
            f"unknown kind {bad_kind[0] if bad_kind else '(none)'}; kinds are {', '.join(KINDS)}"
        )
    if args.cases < 1 or args.workers < 1 or args.timeout <= 0:
        ap.error("--cases and --workers must be at least 1, --timeout positive")

    t0 = time.perf_counter()
    cal = F.calibration_bytes()
    data = F.synthetic_datasets()
    if args.replay is not None:
        _init(cal, data)
        case = make(args.seed, args.replay, kinds)
        d = Path(args.keep or tempfile.mkdtemp(prefix=f"fuzz-{args.replay}-"))
        d.mkdir(parents=True, exist_ok=True)
        case.materialize(d)
        print(
            f"kind {case.kind}\nmutation {case.mutation}\nin {d}:\n  cd {d} && python -m "
            f"{case.command()}"
        )
        if args.run:
            out = F.run_subprocess(case, d, timeout=args.timeout)
            print(
                f"exit {out.rc} in {out.seconds:.1f} s: {F.classify(case, out)}\n--- stderr\n"
                f"{out.stderr[-3000:]}"
            )
        return 0

    jobs = [(args.seed, i, kinds, args.timeout) for i in range(args.cases)]
    results = []
    ctx = mp.get_context("spawn")
    with ctx.Pool(args.workers, initializer=_init, initargs=(cal, data)) as pool:
        for n, r in enumerate(pool.imap_unordered(run_one, jobs), start=1):
            results.append(r)
            if r["class"] in F.BAD:
                print(
                    f"  [{r['class']}] #{r['index']} {r['command'][:150]}\n      "
                    f"{r['mutation'][:160]}\n"
                    f"      -> {r['detail'][:200]}",
                    flush=True,
                )
            if n % 100 == 0:
                print(
                    f"{n}/{args.cases} cases, {time.perf_counter() - t0:.0f} s",
                    file=sys.stderr,
                    flush=True,
                )
    wall = time.perf_counter() - t0

    by = collections.Counter((r["kind"], r["class"]) for r in results)
    classes = [c for c in F.OUTCOMES if any(k[1] == c for k in by)]
    w = max(len(c) for c in classes) + 2
    print(
        f"\n{len(results)} cases in {wall:.0f} s ({args.workers} workers, seed {args.seed}, "
        f"timeout {args.timeout:g} s)\n"
    )
    print(f"{'kind':<12}" + "".join(f"{c:>{w}}" for c in classes) + f"{'total':>8}{'mean s':>8}")
    for k in kinds:
        rs = [r for r in results if r["kind"] == k]
        if not rs:
            continue
        print(
            f"{k:<12}" + "".join(f"{by[(k, c)]:>{w}}" for c in classes) + f"{len(rs):>8}"
            f"{sum(r['seconds'] for r in rs) / len(rs):>8.1f}"
        )
    tot = collections.Counter(r["class"] for r in results)
    print(f"{'all':<12}" + "".join(f"{tot[c]:>{w}}" for c in classes) + f"{len(results):>8}")

    bad = sorted(
        (r for r in results if r["class"] in F.BAD), key=lambda r: (signature(r), r["index"])
    )
    groups = collections.OrderedDict()
    for r in bad:
        groups.setdefault(signature(r), []).append(r)
    if groups:
        print(
            f"\n{len(bad)} bad cases in {len(groups)} groups (first case of each; replay with "
            f"--seed {args.seed} --replay INDEX --run):"
        )
        for sig, rs in groups.items():
            r = rs[0]
            print(
                f"  {len(rs):>4} x {sig}\n         #{r['index']} {r['command'][:140]}\n"
                f"         {r['mutation'][:160]}"
            )
    if args.details:
        with open(args.details, "w", encoding="utf-8") as fh:
            for r in bad:
                fh.write(
                    f"=== #{r['index']} [{r['class']}] {r['kind']} exit {r['rc']} "
                    f"{r['seconds']:.1f} s\n"
                    f"command:  {r['command']}\nmutation: {r['mutation']}\ndetail:   "
                    f"{r['detail']}\n"
                    f"replay:   python bench/bench_fuzz.py --seed {args.seed} --kinds "
                    f"{','.join(kinds)} --replay {r['index']} --run\nstderr:\n{r['stderr']}\n\n"
                )
        print(f"\ndetails of {len(bad)} bad cases written to {args.details}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
