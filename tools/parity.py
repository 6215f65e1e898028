"""Compare the shipped problems' and designs' JSON outputs of two commits (a refactor must not
change them).

    python tools/parity.py REF [--against WORKTREE_OR_HEAD] [--keep DIR]

Checks REF out in a temporary git worktree, runs ``axisopt solve --json`` for every
``problems/*problem*.yaml`` ``axisopt evaluate --json`` for every ``problems/*design*.yaml`` (and
the paper designs) and ``axisopt diagnose --json`` for every shipped data set (``problems/data``:
the static table, the XJTU friction series, the time records as estimation and validation pairs)
with each tree on ``PYTHONPATH``, drops the timing fields (``time_s``, ``*_time``, ``seconds``), and
prints the keys that differ.  Exit 0 when every output is identical, 1 otherwise.  ``--allow KEY``
ignores a top-level path prefix (e.g. a report section that the change is meant to add).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TIMING = ("time", "time_s", "screening_time", "screening_rate", "seconds")


# The shipped measured data sets, each with the design it was taken on (docs/diagnose.md runs the
# same).
DIAGNOSE = (
    (("data/table_x_stiffness.csv",), "data/table_x.yaml"),
    (("data/xjtu/xjtu_up_friction.csv",), "data/xjtu/xjtu_rig.yaml"),
    (("data/xjtu/xjtu_down_friction.csv",), "data/xjtu/xjtu_rig.yaml"),
    (("data/table_x_run_est.csv", "data/table_x_run_val.csv"), "data/table_x.yaml"),
    (("data/table_x_ripple_est.csv", "data/table_x_ripple_val.csv"), "data/table_x.yaml"),
    (("data/table_x_backlash_est.csv", "data/table_x_backlash_val.csv"), "data/table_x.yaml"),
)


def _files(tree: Path):
    probs = sorted(p.name for p in (tree / "problems").glob("*.yaml"))
    return (
        [("solve", f) for f in probs if "problem" in f]
        + [("evaluate", f) for f in probs if "problem" not in f]
        + [("diagnose", data) for data in DIAGNOSE]
    )


def _strip(obj):
    if isinstance(obj, dict):
        return {k: _strip(v) for k, v in obj.items() if k not in TIMING and not k.endswith("_time")}
    if isinstance(obj, list):
        return [_strip(v) for v in obj]
    return obj


def _label(name) -> str:
    return name if isinstance(name, str) else "+".join(Path(f).stem for f in name[0])


def _run(tree: Path, cmd: str, name, out: Path) -> object:
    env = dict(os.environ, PYTHONPATH=str(tree), AXISOPT_COLOR="0")
    target = out / f"{cmd}-{_label(name)}.json"
    if cmd == "diagnose":
        files, design = name
        args = [f"problems/{f}" for f in files] + ["--design", f"problems/{design}"]
    else:
        args = [f"problems/{name}"]
    proc = subprocess.run(
        [sys.executable, "-m", "axisopt", cmd, *args, "--json", str(target)],
        cwd=tree,
        env=env,
        capture_output=True,
        text=True,
    )
    if not target.exists():
        return {"exit": proc.returncode, "stderr": proc.stderr.strip()[-300:]}
    return _strip(json.loads(target.read_text()))


def _diff(a, b, path=""):
    if type(a) is not type(b):
        yield path or "/", a, b
    elif isinstance(a, dict):
        for k in sorted(set(a) | set(b), key=str):
            if k not in a or k not in b:
                yield f"{path}/{k}", a.get(k, "<missing>"), b.get(k, "<missing>")
            else:
                yield from _diff(a[k], b[k], f"{path}/{k}")
    elif isinstance(a, list):
        if len(a) != len(b):
            yield f"{path}[len]", len(a), len(b)
        for i, (x, y) in enumerate(zip(a, b)):
            yield from _diff(x, y, f"{path}[{i}]")
    elif a != b:
        yield path, a, b


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ref", help="commit to compare against (e.g. a commit before the refactor)")
    ap.add_argument(
        "--allow", action="append", default=[], help="ignore differences under this path prefix"
    )
    ap.add_argument("--only", action="append", default=[], help="compare only these problem files")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        ref_tree = tmp / "ref"
        subprocess.run(
            ["git", "worktree", "add", "--detach", "-q", str(ref_tree), args.ref],
            cwd=ROOT,
            check=True,
        )
        try:
            (tmp / "a").mkdir()
            (tmp / "b").mkdir()
            bad = 0
            for cmd, name in _files(ROOT):
                if args.only and _label(name) not in args.only:
                    continue
                a = _run(ref_tree, cmd, name, tmp / "a")
                b = _run(ROOT, cmd, name, tmp / "b")
                diffs = [d for d in _diff(a, b) if not any(d[0].startswith(p) for p in args.allow)]
                print(
                    f"{cmd:8s} {_label(name):34s} "
                    f"{'same' if not diffs else f'{len(diffs)} differences'}"
                )
                for path, x, y in diffs[:8]:
                    print(f"    {path}: {str(x)[:70]} -> {str(y)[:70]}")
                bad += bool(diffs)
        finally:
            subprocess.run(["git", "worktree", "remove", "--force", str(ref_tree)], cwd=ROOT)
    print("identical" if not bad else f"{bad} outputs differ")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
