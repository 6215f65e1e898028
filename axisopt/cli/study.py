"""``axisopt study STUDY.yaml``: a batch trade study, locally or on a Dask cluster."""

from __future__ import annotations

import sys
import time

from ..errors import InputError
from .common import (
    EXIT_INPUT,
    EXIT_NEGATIVE,
    EXIT_OK,
    add_html_report,
    check_html_report,
    one_line,
    write_html_report,
)


def register(sub) -> None:
    s = sub.add_parser("study", help="run a batch trade study (sweeps over a base problem)")
    s.add_argument("study", help="study YAML file")
    add_run_options(s)
    s.add_argument(
        "--time-limit",
        type=float,
        default=100.0,
        metavar="S",
        help="time limit [s] of each case's solve (default 100, as solve's)",
    )
    s.add_argument("--quiet", action="store_true", help="no progress bar")
    add_html_report(s, "the study (figures, cases table, summary)")
    s.set_defaults(func=cmd_study)


def add_run_options(s) -> None:
    """A study run's options (axis and machine studies): --out, --workers, --scheduler, --resume,
    --overwrite."""
    s.add_argument(
        "--out", metavar="DIR", help="output directory (default: <study file stem>-results)"
    )
    s.add_argument(
        "--workers",
        type=int,
        metavar="N",
        help="local worker processes (default: all cores; 0 solves in this process)",
    )
    s.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="run on an existing Dask cluster, e.g. tcp://127.0.0.1:8786 (needs axisopt[dask])",
    )
    s.add_argument(
        "--resume",
        action="store_true",
        help="continue an interrupted study in --out, solving only the missing cases",
    )
    s.add_argument(
        "--overwrite",
        action="store_true",
        help="solve every case again: the case results already in --out are deleted first",
    )


def check_run_options(args) -> None:
    """The run options that exclude each other or are out of range: InputError."""
    if args.resume and args.overwrite:
        raise InputError("--resume continues a run, --overwrite starts it again: give one of them")
    if args.workers is not None and args.workers < 0:
        raise InputError(f"--workers must be 0 or more, got {args.workers}")
    if args.scheduler is not None and not args.scheduler.strip():
        raise InputError("empty scheduler address (e.g. tcp://127.0.0.1:8786)", where="--scheduler")
    if args.scheduler is not None and args.workers is not None:
        raise InputError(
            "--workers and --scheduler exclude each other (the cluster has its own workers)"
        )


def run_with_progress(args, command: str, run, study) -> tuple:
    """A study's run loop (axis and machine studies): the output folder (--out, else beside the
    study file's stem), its cases cleared first on --overwrite, ``run(study, out, ...)`` with the
    run options and the progress bar; (its summary, out), the summary None when interrupted (the way
    to resume printed on one line)."""
    from pathlib import Path

    from ..study.result import clear_cases

    out = args.out or f"{Path(args.study).stem}-results"
    if args.overwrite and Path(out).is_dir():
        clear_cases(out)
    bar = ProgressBar(not args.quiet and is_terminal(sys.stderr))
    try:
        summary = run(
            study,
            out,
            workers=args.workers,
            scheduler=args.scheduler,
            resume=args.resume,
            progress=bar,
        )
        return summary, out
    except KeyboardInterrupt:
        bar.close()
        print(
            one_line(
                f"interrupted: finished cases are saved in {out}/cases; continue with "
                f"'{command} {args.study} --out {out} --resume'"
            ),
            file=sys.stderr,
        )
        return None, out
    finally:  # the bar's line ends before anything else is printed (an error included)
        bar.close()


class ProgressBar:
    """Progress on stderr: tqdm when installed, else one rewritten line."""

    def __init__(self, enabled: bool):
        self.enabled = enabled
        self.tqdm = None
        self.last = 0.0

    def __call__(self, p) -> None:
        if not self.enabled:
            return
        if self.tqdm is None:
            try:
                from tqdm import tqdm
            except ImportError:
                self.tqdm = False
            else:
                self.tqdm = tqdm(total=p.total, initial=p.done, unit="case", file=sys.stderr)
                self.seen = p.done
        if self.tqdm:
            self.tqdm.update(p.done - self.seen)
            self.seen = p.done
            self.tqdm.set_postfix(failed=p.failed)
            return
        now = time.perf_counter()
        if now - self.last < 0.25 and p.done < p.total:
            return
        self.last = now
        eta = p.eta
        left = "--" if eta is None else _hms(eta)
        print(
            f"\r  {p.done}/{p.total} cases done, {p.failed} failed, {_hms(p.elapsed)} elapsed, "
            f"{left} left   ",
            end="",
            file=sys.stderr,
            flush=True,
        )

    def close(self) -> None:
        if not self.enabled:
            return
        self.enabled = False  # closed once
        if self.tqdm:
            self.tqdm.close()
        elif self.last:
            print(file=sys.stderr, flush=True)


def is_terminal(stream) -> bool:
    """The bar is drawn only on a terminal: a log file or pipe gets no carriage-return lines."""
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


def _hms(s: float) -> str:
    s = int(round(s))
    return (
        f"{s // 3600}:{s // 60 % 60:02d}:{s % 60:02d}" if s >= 3600 else f"{s // 60}:{s % 60:02d}"
    )


def cmd_study(args) -> int:
    import math
    from dataclasses import replace
    from pathlib import Path

    from ..study import load_study, run_study

    if not (math.isfinite(args.time_limit) and args.time_limit > 0):
        raise InputError(f"--time-limit must be positive, got {args.time_limit}")
    check_run_options(args)
    check_html_report(args.report, args.plotly)
    study = replace(load_study(args.study), time_limit=args.time_limit)
    summary, out = run_with_progress(args, "axisopt study", run_study, study)
    if summary is None:
        return 130
    s = summary
    if s.redone:
        print(
            f"resume: {s.redone} case{'s' if s.redone != 1 else ''} recorded as worker_died (an "
            f"infrastructure failure) by an earlier run solved again"
        )
    print(
        f"study {study.name}: {s.total} cases; {s.solved} solved now in {s.time:.1f} s on "
        f"{s.backend}"
        + (f" ({s.workers} workers)" if s.workers else "")
        + (f", {s.resumed} kept from an earlier run" if s.resumed else "")
        + f"; {s.failed} failed"
    )
    if args.report:
        from ..report.htmlpages import study_page
        from ..study.table import results_table

        md = Path(s.files["report"]).read_text(encoding="utf-8") if "report" in s.files else ""
        write_html_report(args, True, study_page, study, results_table(study, out), md)
        s.files["html report"] = args.report
    for name, path in s.files.items():
        print(f"  {name}: {path}")
    notes = []
    if s.died:
        notes.append(
            f"{s.died} case{'s' if s.died != 1 else ''} not solved because the worker process died "
            f"twice while solving {'them' if s.died != 1 else 'it'} (status worker_died)"
        )
    if s.lost:
        notes.append(f"{s.lost} cases not run ({s.lost_reason})")
    if notes:
        note = "; ".join(notes) + f"; rerun with 'axisopt study {args.study} --out {out} --resume'"
        print("note: " + one_line(note), file=sys.stderr)  # one line
    # 1 when any case has no design (infeasible, invalid combination, solver failure, worker died)
    # or was not run; 0 only when every case found its design
    return EXIT_NEGATIVE if s.lost or s.died or s.failed else EXIT_OK


__all__ = ["register", "EXIT_INPUT"]
