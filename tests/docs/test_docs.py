"""The documentation against what its commands and examples print.

Every Markdown page (README.md and docs/**/*.md) is read:

1. Every fenced block that starts with ``$ axisopt ...`` is run; each quoted line must appear in the
   output, in order (a line ``...`` skips output; a line ending in ``...`` matches a line it
   starts).
2. A block after ``<!-- file: PATH -->`` is written to PATH (the page asks the reader to write it).
3. Every ``axisopt`` command in a ``bash``/``sh`` block is run and must exit 0 (or the ``exit N``
   its comment states).
4. Every ``pycon`` block (``>>>`` prompts) is run by doctest (ELLIPSIS, NORMALIZE_WHITESPACE), the
   blocks of one page in one namespace, so the output shown is the output compared.
5. Figures quoted in the prose (deterministic ones: optima, sensitivities, diagnosis results) are
   compared with the command's output to the precision the page quotes them.
6. Every ``yaml`` block that is not a file to write (the annotated examples of the file formats)
   uses only keys the readers accept (checked against the JSON Schema written from their key
   tables).
7. What a command prints fits 100 columns, except the commands listed in ``WIDE`` (the exceptions
   docs/evaluate.md names).
8. Every ``axisopt ...`` command quoted inline in the prose uses options and values the parser
   accepts.

A block preceded by ``<!-- not-run: reason -->`` is not run;
``test_not_run_blocks_are_the_listed_ones`` keeps the list of such blocks explicit, so nothing is
skipped silently. Timings are not deterministic and are not compared; each sits beside the bench
command that prints it (docs/benchmarks.md).
"""

from __future__ import annotations

import contextlib
import doctest
import io
import os
import re
import shlex
from pathlib import Path

import pytest

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md"] + sorted((ROOT / "docs").rglob("*.md"))
TEXT = {p.relative_to(ROOT).as_posix(): p.read_text(encoding="utf-8") for p in PAGES}
FENCE = re.compile(
    r"^(<!-- (?:not-run: (?P<why>[^>]*)|file: (?P<file>[^ >]+)) -->\n)?"
    r"```(?P<lang>[a-z]*)\n(?P<body>.*?)^```",
    re.M | re.S,
)

# Blocks shown but not run, with the reason (page, first words of the block).
NOT_RUN = {
    ("README.md", "python3 -m venv .venv && .venv/bin/pip install -q -e . &&"),
    ("README.md", 'python3 -m venv .venv && .venv/bin/pip install -q -e ".[test,all]"'),
    ("docs/install.md", "python3 -m venv .venv && .venv/bin/pip install -q -e . &&"),
    ("docs/install.md", 'python3 -m venv .venv && .venv/bin/pip install -q -e ".[test,all]"'),
    ("docs/howto-dask.md", "dask scheduler --port 8786"),
    ("docs/solve.md", "axisopt solve problems/teaching_problem.yaml --method bonmin"),
}

# Commands whose output may exceed 100 columns (none now: compare prints designs in blocks that fit,
# diagnose wraps the calibration lines); kept so an exception is explicit and named here if one is
# ever needed.
WIDE: dict = {}


def _fences():
    """(page, line, lang, body, not-run reason) of every fenced block."""
    out = []
    for page, text in TEXT.items():
        for m in FENCE.finditer(text):
            line = text[: m.start("lang")].count("\n") + 1
            body = m.group("body")
            # a file the reader is asked to write: the test writes it in the page's dir
            if m.group("file"):
                out.append((page, line, "file", (m.group("file"), body), None))
            else:
                out.append((page, line, m.group("lang"), body, m.group("why")))
    return out


FENCES = _fences()


def _steps():
    """Every runnable block in page order: (page:line, kind, payload). Kinds: ``quoted`` (a
    ``$ axisopt``
    block: command and quoted lines), ``shell`` (an axisopt command of a bash/sh block and its
    expected exit code), ``pycon`` (a doctest block), ``file`` (a block after
    ``<!-- file: PATH -->``: written to
    PATH in the page's directory, as the reader is asked to)."""
    out = []
    for page, line, lang, body, why in FENCES:
        if why is not None:
            continue
        where = f"{page}:{line}"
        if lang == "file":
            out.append((where, "file", body))
        elif body.startswith("$ axisopt"):
            out.append((where, "quoted", (body.splitlines()[0][2:], body.splitlines()[1:])))
        elif lang == "pycon":
            out.append((where, "pycon", body))
        elif lang in ("bash", "sh"):
            for i, raw in enumerate(body.replace("\\\n", " ").splitlines()):
                cmd, _, comment = raw.partition("#")
                want = re.search(r"\bexit (\d)", comment)
                for part in cmd.split("&&"):
                    part = part.split("|")[0].strip()
                    if part:
                        assert part.startswith("axisopt "), (
                            f"{page}:{line + i}: not an axisopt command: {part!r}"
                        )
                        out.append(
                            (
                                f"{page}:{line + i}",
                                "shell",
                                (part, int(want.group(1)) if want else 0),
                            )
                        )
    return out


STEPS = _steps()


@contextlib.contextmanager
def _in_scratch(tmp_path):
    """Run in an empty directory with ``problems`` linked in, so outputs the docs name land in
    tmp."""
    if not (tmp_path / "problems").exists():
        (tmp_path / "problems").symlink_to(ROOT / "problems")
    old = os.getcwd()
    os.chdir(tmp_path)
    try:
        yield
    finally:
        os.chdir(old)


def _run(cmd: str, tmp_path) -> tuple[int, str]:
    argv = shlex.split(cmd)
    assert argv[0] == "axisopt"
    buf = io.StringIO()
    with _in_scratch(tmp_path), contextlib.redirect_stdout(buf):
        rc = main(argv[1:])
    return rc, buf.getvalue()


class _Page:
    """One scratch directory and one Python namespace per page: the blocks of a page run in order,
    so a tutorial's later command reads what an earlier one wrote."""

    def __init__(self, tmp):
        self.dir = tmp
        self.globs: dict = {"__name__": "__docs__"}


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    made: dict[str, _Page] = {}

    def get(page: str) -> _Page:
        if page not in made:
            made[page] = _Page(tmp_path_factory.mktemp(page.replace("/", "_").replace(".", "_")))
        return made[page]

    return get


def test_docs_have_runnable_blocks():
    kinds = {k for _, k, _ in STEPS}
    assert kinds == {"quoted", "shell", "pycon", "file"}
    assert any(w.startswith("README.md") for w, _, _ in STEPS)


def test_not_run_blocks_are_the_listed_ones():
    found = {(page, body.strip()) for page, _, _, body, why in FENCES if why is not None}
    assert all(isinstance(b, str) for _, b in found)
    assert all(why.strip() for *_, why in FENCES if why is not None), (
        "a not-run block without a reason"
    )
    matched = {
        (page, start)
        for page, start in NOT_RUN
        if any(p == page and b.startswith(start) for p, b in found)
    }
    assert matched == NOT_RUN, f"listed but not found: {NOT_RUN - matched}"
    assert len(found) == len(NOT_RUN), f"not-run blocks not listed here: {sorted(found)}"


def _check_quoted(where, cmd, quoted, out):
    got = [ln.rstrip() for ln in out.splitlines()]
    i = 0
    for q in quoted:
        q = q.rstrip()
        if q.strip() in ("", "..."):
            continue
        prefix = q.endswith("...")
        want = q[:-3] if prefix else q
        while i < len(got) and not (got[i].startswith(want) if prefix else got[i] == want):
            i += 1
        assert i < len(got), (
            f"{where}: line quoted under '{cmd}' not in its output (in order): {q!r}"
        )
        i += 1


@pytest.mark.parametrize("where, kind, payload", STEPS, ids=[f"{w}-{k}" for w, k, _ in STEPS])
def test_block_runs_as_shown(where, kind, payload, pages):
    page = pages(where.rsplit(":", 1)[0])
    if kind == "file":
        name, body = payload
        target = page.dir / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(body, encoding="utf-8")
    elif kind == "quoted":
        cmd, quoted = payload
        _, out = _run(cmd, page.dir)
        _check_quoted(where, cmd, quoted, out)
        wide = [ln for ln in out.splitlines() if len(ln) > 100]
        assert not wide, f"{where}: '{cmd}' prints lines wider than 100 columns: {wide[0]!r}"
    elif kind == "shell":
        cmd, rc = payload
        got, out = _run(cmd, page.dir)
        assert got == rc, f"{where}: '{cmd}' exited {got}, the page says {rc}"
        wide = [ln for ln in out.splitlines() if len(ln) > 100]
        assert not wide or any(" ".join(cmd.split()).startswith(w) for w in WIDE), (
            f"{where}: '{cmd}' prints lines wider than 100 columns: {wide[0]!r}"
        )
    else:
        test = doctest.DocTestParser().get_doctest(payload, page.globs, where, where, 0)
        runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
        buf = io.StringIO()
        with _in_scratch(page.dir):
            runner.run(test, out=buf.write, clear_globs=False)
        # DocTest copies its namespace: carry it to the page's next block
        page.globs.update(test.globs)
        assert runner.failures == 0, buf.getvalue()


def _close(readme_value: str, printed: str) -> bool:
    """``printed`` rounded to the decimals ``readme_value`` shows."""
    decimals = len(readme_value.split(".")[1]) if "." in readme_value else 0
    return round(float(printed), decimals) == float(readme_value)


XJTU_UP = (
    "axisopt diagnose problems/data/xjtu/xjtu_up_friction.csv --design "
    "problems/data/xjtu/xjtu_rig.yaml"
)
# (page, command, regex on the page's prose, regex on the output): each group pair is one figure
FIGURES = [
    (
        "docs/solve.md",
        "axisopt solve problems/vertical_problem.yaml",
        r"raising max drag torque to ([\d.]+) N\.m buys \+([\d.]+) N/um\" on the vertical problem",
        r"raising max drag torque to ([\d.]+) N\.m buys \+([\d.]+) N/um",
    ),
    (
        "docs/diagnose.md",
        "axisopt diagnose problems/data/table_x_stiffness.csv --design problems/data/table_x.yaml",
        r"`support_condition` wins \(dBIC (-[\d.]+), held-out gain (\d+) %\)",
        r"support_condition\s+(-[\d.]+)\s+held-out gain (\d+) %",
    ),
    (
        "docs/diagnose.md",
        "axisopt diagnose problems/data/table_x_stiffness.csv --design problems/data/table_x.yaml",
        r"carrying ([\d.]+) ± ([\d.]+) N/um",
        r"far_end_stiffness = ([\d.]+) ± ([\d.]+) N/um",
    ),
    (
        "docs/diagnose.md",
        "axisopt diagnose problems/data/table_x_stiffness.csv --design problems/data/table_x.yaml "
        "--save-calibration cal.yaml",
        r"modulus comes back to ([\d.]+) ±",
        r"screw modulus ([\d.]+) GPa applied",
    ),
    (
        "docs/diagnose.md",
        "axisopt diagnose problems/data/table_x_stiffness.csv --design problems/data/table_x.yaml",
        r"Held-out RMSE falls from ([\d.]+) um to\s+([\d.]+) um",
        r"held-out RMSE \S+: ([\d.]+) -> ([\d.]+) um(?s:.*)",
    ),
    (
        "docs/diagnose.md",
        XJTU_UP,
        r"friction falls ([\d.]+) ± ([\d.]+) % of its initial value per 35 h",
        r"preload_loss_rate = ([\d.]+) ± ([\d.]+) percent",
    ),
    (
        "docs/diagnose.md",
        XJTU_UP,
        r"held-out RMSE ([\d.]+) -> ([\d.]+) N.m over held-out cycles \(gain (\d+) %\)",
        r"(?s:.*)held-out RMSE \S+: [\d.]+ -> [\d.]+ N \(gain \d+ %\); ([\d.]+) -> ([\d.]+) N.m at "
        r"the screw",
    ),
    (
        "docs/diagnose.md",
        "axisopt diagnose problems/data/table_x_run_est.csv problems/data/table_x_run_val.csv "
        "--design problems/data/table_x.yaml",
        r"The IV fit gives Fs - Fc = ([\d.]+) ± ([\d.]+) N and vs = ([\d.]+) mm/s",
        r"final fit(?s:.*)Fs\s+([\d.]+) ± ([\d.]+) N(?s:.*)vs\s+([\d.]+) mm/s",
    ),
    (
        "docs/diagnose.md",
        "axisopt diagnose problems/data/table_x_run_est.csv problems/data/table_x_run_val.csv "
        "--design problems/data/table_x.yaml",
        r"`stribeck` wins: dBIC (-[\d.]+), validation gain (\d+) %",
        r"stribeck\s+dBIC\s+(-[\d.]+)\s+gain\s+([\d.]+) %",
    ),
    (
        "docs/diagnose.md",
        XJTU_UP.replace("_up_", "_down_"),
        r"The 'down' screw gives ([\d.]+) % per cycle \(gain (\d+) %\)",
        r"preload_loss_rate = ([\d.]+) ±(?s:.*)held-out RMSE \S+: [\d.]+ -> [\d.]+ N \(gain (\d+) "
        r"%\)",
    ),
]


@pytest.fixture(scope="module")
def figure_output(tmp_path_factory):
    """What a figure's command prints, run once a module in a scratch directory of its own: several
    figures (and the noise floor) quote the same diagnosis, a deterministic command of shipped
    inputs."""
    made: dict[str, str] = {}

    def get(cmd: str) -> str:
        if cmd not in made:
            made[cmd] = _run(cmd, tmp_path_factory.mktemp("figure"))[1]
        return made[cmd]

    return get


@pytest.mark.parametrize(
    "page, cmd, in_readme, in_output", FIGURES, ids=[f"figure{i}" for i in range(len(FIGURES))]
)
def test_quoted_figures_match(page, cmd, in_readme, in_output, figure_output):
    text = TEXT[page]
    r = re.search(in_readme, " ".join(text.split()) if "\\s" not in in_readme else text)
    assert r, f"{page} no longer quotes /{in_readme}/"
    out = figure_output(cmd)
    o = re.search(in_output, out)
    assert o, f"'{cmd}' no longer prints /{in_output}/"
    for a, b in zip(r.groups(), o.groups()):
        assert _close(a, b), f"{page} says {a}, '{cmd}' prints {b}"


def test_noise_floor_quoted(figure_output):
    r = re.search(r"at the ([\d.]+) um noise floor", " ".join(TEXT["docs/diagnose.md"].split()))
    out = figure_output(
        "axisopt diagnose problems/data/table_x_stiffness.csv --design problems/data/table_x.yaml"
    )
    o = re.search(r"noise floor ([\d.]+) um", out)
    assert r and o and _close(r.group(1), o.group(1))


def test_test_files_have_unique_basenames():
    """pytest's default import mode keys test modules by basename: two tests/*/test_x.py break
    collection (it did once, in CI only, where no __pycache__ hid it)."""
    root = Path(__file__).resolve().parents[1]
    # pytest keys conftest modules by path: one per folder is fine
    names = [p.name for p in root.rglob("*.py") if p.name not in ("__init__.py", "conftest.py")]
    assert len(names) == len(set(names)), sorted({n for n in names if names.count(n) > 1})


def _yaml_examples():
    """(page:line, kind, parsed) of every ``yaml`` block that is not a file the page has the
    reader write: the annotated examples of the file formats. ``...`` stands for a part left out."""
    import yaml

    out = []
    for page, line, lang, body, why in FENCES:
        if lang != "yaml" or why is not None:
            continue
        doc = yaml.safe_load(body.replace("{...}", "...")) or {}
        kind = (
            "study"
            if "sweep" in doc
            else "problem"
            if {"objective", "limits", "catalog"} & set(doc)
            else "design"
        )
        out.append((f"{page}:{line}", kind, doc))
    return out


def _unknown_keys(value, schema, defs, path="") -> list[str]:
    """Keys of ``value`` the JSON Schema (written from the readers' key tables) does not know,
    recursively."""
    while "$ref" in schema:
        schema = {**defs[schema.pop("$ref").rsplit("/", 1)[1]], **schema}
    options = schema.get("anyOf") or schema.get("oneOf")
    if options:  # the first form under which the value has no unknown key
        found = [_unknown_keys(value, dict(o), defs, path) for o in options]
        return min(found, key=len)
    if isinstance(value, dict):
        if schema.get("type") not in ("object", None) or "properties" not in schema:
            return (
                []
                if schema.get("additionalProperties", True) is not False
                else [f"{path}: {sorted(value)}"]
            )
        props, patterns = schema["properties"], schema.get("patternProperties", {})
        bad = []
        for k, v in value.items():
            matching = [pat for pat in patterns if re.search(pat, str(k))]
            if k in props:
                bad += _unknown_keys(v, dict(props[k]), defs, f"{path}.{k}".lstrip("."))
            elif matching:
                bad += _unknown_keys(
                    v, dict(patterns[matching[0]]), defs, f"{path}.{k}".lstrip(".")
                )
            elif schema.get("additionalProperties", True) is False:
                bad.append(f"{path}.{k}".lstrip("."))
            elif isinstance(schema.get("additionalProperties"), dict):
                bad += _unknown_keys(
                    v, dict(schema["additionalProperties"]), defs, f"{path}.{k}".lstrip(".")
                )
        return bad
    if isinstance(value, list) and isinstance(schema.get("items"), dict):
        return [
            b for v in value for b in _unknown_keys(v, dict(schema["items"]), defs, f"{path}[]")
        ]
    return []


YAML_EXAMPLES = _yaml_examples()


@pytest.mark.parametrize("where, kind, doc", YAML_EXAMPLES, ids=[w for w, _, _ in YAML_EXAMPLES])
def test_yaml_examples_use_known_keys(where, kind, doc):
    """Every key in the pages' annotated YAML examples is one the reader accepts (the schema is
    written from the readers' key tables), so an example cannot keep a renamed or removed key."""
    from axisopt.schema import json_schema

    schema = json_schema(kind)
    bad = _unknown_keys(doc, dict(schema), schema.get("$defs", {}))
    # a swept key is a dotted path into the problem file: it must name a problem key
    if kind == "study":
        problem = json_schema("problem")
        for dotted in doc.get("sweep", {}):
            node = {k: "..." for k in [dotted.split(".")[-1]]}
            for part in reversed(dotted.split(".")[:-1]):
                node = {part: node}
            bad += [f"sweep: {b}" for b in _unknown_keys(node, dict(problem), problem["$defs"])]
    assert not bad, f"{where}: keys a {kind} file does not accept: {bad}"


def test_yaml_key_check_finds_a_misspelt_key():
    from axisopt.schema import json_schema

    schema = json_schema("design")
    doc = {
        "axis": {
            "stroke": "800 mm",
            "duty_cycle": [{"move": "300 mm", "sped": "2 m/min"}, {"dwell": "1 s"}],
        },
        "parts": {"screw": "x", "nutt": "y"},
        "catalgs": [],
    }
    assert sorted(_unknown_keys(doc, dict(schema), schema["$defs"])) == [
        "axis.duty_cycle[].sped",
        "catalgs",
        "parts.nutt",
    ]
    study = {"name": "s", "base": "p.yaml", "sweep": {"axis.strok": [1], "limits.max_cost": [2]}}
    with pytest.raises(AssertionError, match=r"sweep: axis\.strok'"):
        test_yaml_examples_use_known_keys("x", "study", study)


INLINE = re.compile(r"(?<!`)`(axisopt [a-z][^`]*)`(?!`)")


def _inline_commands():
    """(page, command) of every ``axisopt ...`` command quoted inline in the prose (not in a fenced
    block), and of the not-run blocks' axisopt commands (shown, not run: they must at least
    parse)."""
    inline = [
        (page, m.group(1))
        for page, text in TEXT.items()
        for m in INLINE.finditer(FENCE.sub("", text))
    ]
    shown = [
        (page, ln.partition("#")[0].strip())
        for page, _, _, body, why in FENCES
        if why is not None
        for ln in body.replace("\\\n", " ").splitlines()
        if ln.startswith("axisopt ")
    ]
    return inline + shown


def _inline_problems(cmd: str) -> list[str]:
    """What is wrong with an inline command: an option its subcommand does not have, or a value the
    parser refuses. Placeholders (``FILE``, ``KIND``, ``...``) and omitted required arguments are
    the prose's shorthand; ``a|b`` stands for each alternative."""
    import argparse
    import itertools

    from axisopt.cli import build_parser

    parser = build_parser()
    subs = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction)).choices
    argv = shlex.split(cmd)[1:]
    if not argv or argv[0] not in subs:
        return [f"no command {argv[:1]}"]
    sub, rest = subs[argv[0]], argv[1:]
    while True:  # a command's own subcommands (axisopt machine solve ...)
        inner = next((a for a in sub._actions if isinstance(a, argparse._SubParsersAction)), None)
        if inner is None or not rest or rest[0] not in inner.choices:
            break
        sub, rest = inner.choices[rest[0]], rest[1:]
    options = {s for a in sub._actions for s in a.option_strings}
    bad = [
        f"unknown option {t.split('=')[0]}"
        for t in rest
        if t.startswith("--") and t.split("=")[0] not in options
    ]
    alternatives = [t.split("|") if "|" in t and not t.startswith("-") else [t] for t in argv]
    for variant in itertools.product(*alternatives):
        err = io.StringIO()
        try:
            with contextlib.redirect_stderr(err):
                parser.parse_args(list(variant))
        # the CLI's parser raises InputError, argparse SystemExit
        except (SystemExit, Exception) as e:
            msg = f"{e} {err.getvalue()}"
            placeholder = any(
                (t.isupper() or "..." in t or t.split(".")[0].isupper()) and t in msg
                for t in variant
            )
            if "arguments are required" not in msg and not placeholder:
                bad.append(msg.strip())
    return bad


@pytest.mark.parametrize(
    "page, cmd", _inline_commands(), ids=[f"{p}-{c[:40]}" for p, c in _inline_commands()]
)
def test_inline_commands_parse(page, cmd):
    """A command quoted in the prose uses options and values the parser accepts (so a renamed flag
    or a removed choice cannot stay in the text)."""
    assert not _inline_problems(cmd), f"{page}: `{cmd}`: {_inline_problems(cmd)}"


def test_inline_check_finds_a_stale_flag():
    # problem omitted
    assert _inline_problems("axisopt solve --methd exhaustive")[0] == "unknown option --methd"
    assert (
        "invalid choice: 'exhaustiv'"
        in _inline_problems("axisopt solve p.yaml --method exhaustiv")[0]
    )
    assert "invalid choice: 'gears'" in _inline_problems("axisopt parts motors|gears")[0]
    assert not _inline_problems("axisopt parts motors|couplings")
    assert not _inline_problems("axisopt schema KIND")
