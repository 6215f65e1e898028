"""Small presentation helpers the result classes share for notebooks: a number in engineering form,
a list of row dicts as a pandas DataFrame, the same rows as a small HTML table, a one-line repr.

Sits low (beside ``units``) so that the computing packages' result classes (model, search, identify,
study) give ``to_frame()``, a short ``__repr__`` and ``_repr_html_`` without importing ``report``
(the layers run one way).  pandas is imported only when a frame is asked for, so ``import axisopt``
stays fast.  Nothing here prints.
"""

from __future__ import annotations

import html
import math

REPR_WIDTH = 400  # characters a one-line repr may take before it is cut


def fmt(x, unit: str = "") -> str:
    """A physical value as an engineer writes it: thousands separators from 100 up, three
    significant digits below; ``unit`` appended after a space; '-' for a missing or non-finite
    value.

    >>> fmt(1234.4, "N/um"), fmt(0.785, "N.m"), fmt(None)
    ('1,234 N/um', '0.785 N.m', '-')
    """
    if x is None:
        return "-"
    v = _number(x)
    if isinstance(v, str):
        return v
    text = f"{v:,.0f}" if abs(v) >= 100 else f"{v:.3g}"
    return f"{text} {unit}" if unit else text


def _number(x) -> float | str:
    """``x`` as a finite float, or the text that stands for it: ``str(x)`` where it is no number,
    '-' where it is not finite."""
    try:
        v = float(x)
    except (TypeError, ValueError):
        return str(x)
    return v if math.isfinite(v) else "-"


def fmt_objective(x, unit: str = "") -> str:
    """An objective in a repr with the digits the solve text shows (``best: 186.085 N/um``): designs
    a few thousandths apart read apart, not all as '186'; '-' for a missing or non-finite value."""
    v = _number(x)
    if isinstance(v, str):
        return v
    return f"{v:,.3f}" + (f" {unit}" if unit else "")


def fmt_column(values) -> list[str]:
    """A table column as an engineer writes it: the numbers with one number of decimals (three
    significant digits for the smallest, none from 100 up, thousands separators), more decimals
    where that would write different numbers alike (five designs of 161.24, 161.38 ... N/um read as
    161.2, 161.4, not five times '161'), up to six more; text, whole numbers and missing values as
    in a repr.

    >>> fmt_column([161.24, 161.38, 0.5])
    ['161.240', '161.380', '0.500']
    >>> fmt_column([161.24, 161.38, 162.0])
    ['161.2', '161.4', '162.0']
    """
    out = [_cell(v) for v in values]
    nums = {
        i: float(v)
        for i, v in enumerate(values)
        if isinstance(v, (int, float, np_number()))
        and not isinstance(v, bool)
        and math.isfinite(float(v))
    }
    if not any(isinstance(values[i], float) for i in nums):
        return out  # counts and ids: as they are
    tiny = any(0 < abs(v) < 1e-3 for v in nums.values())
    first = 0 if tiny else min(max(_decimals(v) for v in nums.values()), 6)
    distinct = len({float(f"{v:.9g}") for v in nums.values()})
    for extra in range(7):
        d = first + extra
        texts = {i: (f"{v:.{3 + extra}g}" if tiny else f"{v:,.{d}f}") for i, v in nums.items()}
        if len(set(texts.values())) >= distinct or extra == 6:
            break
    for i, t in texts.items():
        out[i] = t
    return out


def np_number():
    """numpy's scalar base class when numpy is loaded (a table of numpy floats), else float."""
    import sys

    np = sys.modules.get("numpy")
    return np.number if np is not None else float


def _decimals(v: float) -> int:
    """The decimals :func:`fmt` gives ``v``: none from 100 up, three significant digits below."""
    return 0 if v == 0 or abs(v) >= 100 else max(0, 2 - math.floor(math.log10(abs(v))))


def frame(rows, columns=None):
    """pandas DataFrame of ``rows`` (a list of dicts; ``columns`` fixes the order and keeps the
    columns of an empty table)."""
    import pandas as pd

    return pd.DataFrame(list(rows), columns=list(columns) if columns is not None else None)


def html_table(rows, caption: str = "", columns=None, max_rows: int = 30) -> str:
    """A small HTML table of ``rows`` (list of dicts): numbers as :func:`fmt_column` writes them
    (enough digits to tell the rows apart), text escaped; ``max_rows`` rows at most (a last row says
    how many were left off)."""
    rows = list(rows)
    cols = list(columns) if columns is not None else list(dict.fromkeys(k for r in rows for k in r))
    out = ["<table>"]
    if caption:
        out.append(f"<caption style='text-align:left'>{html.escape(caption)}</caption>")
    out.append(
        "<thead><tr>"
        + "".join(f"<th>{html.escape(str(c))}</th>" for c in cols)
        + "</tr></thead><tbody>"
    )
    shown = rows[:max_rows]
    # digits enough to tell rows apart
    texts = {c: fmt_column([r.get(c) for r in shown]) for c in cols}
    for i in range(len(shown)):
        out.append("<tr>" + "".join(f"<td>{html.escape(texts[c][i])}</td>" for c in cols) + "</tr>")
    if len(rows) > max_rows:
        out.append(
            f"<tr><td colspan='{len(cols)}'>... {len(rows) - max_rows} more rows (to_frame() has "
            "them all)</td></tr>"
        )
    out.append("</tbody></table>")
    return "".join(out)


def html_fields(fields: dict, caption: str = "") -> str:
    """A two-column HTML table (name, value) of a result's headline values."""
    return html_table(
        [{"": k, "value": v} for k, v in fields.items()], caption, columns=("", "value")
    )


def one_line(name: str, head: str, fields: dict) -> str:
    """``Name(head; key value; key value ...)`` (an empty key: the value alone) cut at
    :data:`REPR_WIDTH` characters."""
    body = "; ".join(
        f"{k} {_cell(v)}" if k else _cell(v) for k, v in fields.items() if v not in (None, "")
    )
    text = f"{name}({head}{'; ' if head and body else ''}{body})"
    return text if len(text) <= REPR_WIDTH else text[: REPR_WIDTH - 4] + " ...)"


def _cell(v) -> str:
    if v is None:
        return "-"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return fmt(v) if isinstance(v, float) else f"{v:,}"
    return str(v)


__all__ = [
    "fmt",
    "fmt_column",
    "frame",
    "html_table",
    "html_fields",
    "one_line",
    "REPR_WIDTH",
    "json_value",
]


def json_value(v):
    """``v`` ready for JSON: a non-finite float (and one inside a list, tuple or dict) becomes
    None."""
    if isinstance(v, float) and not math.isfinite(v):
        return None
    if isinstance(v, (list, tuple)):
        return [json_value(x) for x in v]
    if isinstance(v, dict):
        return {k: json_value(x) for k, x in v.items()}
    return v
