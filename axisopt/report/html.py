"""Self-contained HTML reports: one file with the summary first, then sections, readable on a phone.
The figures are static SVG by default (matplotlib, :mod:`axisopt.report.static`: the file opens
offline, needs no plotly and stays well under 1.5 MB); with ``interactive=True`` they are plotly
figures (zoom, hover), its JavaScript inlined once (offline, about 5 MB) or loaded from the plotly
CDN.

:class:`Page` collects blocks (key figures, text, tables, figures) under headings; the ``*_page``
builders turn an evaluation, a solve result, a comparison, a study table or a diagnosis into a Page.
plotly is an optional dependency (``pip install 'axisopt[html]'``), needed only for interactive
figures; without it :func:`require_plotly` is a one-line error.  Tables wrap their text and part ids
to fit a 1280 px window; on a phone a table wider than the screen scrolls inside its own box (no
column is ever hidden).  Nothing here prints; :func:`write_page` writes atomically."""

from __future__ import annotations

import html
import math
import re
from dataclasses import dataclass, field

from ..errors import InputError
from ..units import N_PER_UM
from . import interactive as ifig  # plotly itself is imported only when a figure is drawn

_CSS = """
:root { color-scheme: light; --ink:#1d2330; --muted:#5b6475; --line:#d9dee7; --ok:#1a7f37; --bad:#c62828; }
* { box-sizing: border-box; }
body { font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; color: var(--ink);
       margin: 0 auto; padding: 12px; max-width: 1240px; }
h1 { font-size: 1.35em; margin: .3em 0; } h2 { font-size: 1.1em; margin: 1.4em 0 .4em;
     border-bottom: 1px solid var(--line); padding-bottom: .2em; }
p.sub { color: var(--muted); margin: 0 0 .8em; }
nav { font-size: .9em; margin: .4em 0 1em; } nav a { display: inline-block; margin: 0 .9em .2em 0; }
.cards { display: grid; grid-template-columns: repeat(auto-fill, minmax(150px, 1fr)); gap: 8px; }
.card { border: 1px solid var(--line); border-radius: 6px; padding: 6px 9px; }
.card .k { color: var(--muted); font-size: .8em; }
.card .v { font-size: 1.15em; font-weight: 600; overflow-wrap: anywhere; }
.card.bad { border-color: var(--bad); } .card.bad .v { color: var(--bad); }
.card.ok .v { color: var(--ok); }
pre { overflow-x: auto; font-size: 12px; line-height: 1.3; background: #f6f8fa; padding: 8px; border-radius: 6px; }
.scroll { overflow-x: auto; max-width: 100%; }
table { border-collapse: collapse; font-size: 13px; } th, td { padding: 3px 6px; border-bottom: 1px solid var(--line);
        text-align: right; white-space: normal; overflow-wrap: break-word; vertical-align: top; }
th { vertical-align: bottom; } td.n { white-space: nowrap; } td.t { text-align: left; }
span.id { white-space: nowrap; } th:first-child, td:first-child { text-align: left; }
td.bad { color: var(--bad); font-weight: 600; } td.ok { color: var(--ok); }
td.m-fail { background: #fde2e1; color: var(--bad); font-weight: 600; } td.m-tight { background: #fff1cc; }
td.m-fair { background: #eef7e4; } td.m-ample { color: var(--ok); }
p.key { font-size: .8em; color: var(--muted); }
td.wrap, th.wrap { white-space: normal; text-align: left; min-width: 12em; }
.fig { width: 100%; min-height: 320px; } .fig.static { min-height: 0; margin: .4em 0; }
.fig.static svg { display: block; max-width: 100%; height: auto; }
footer { color: var(--muted); font-size: .8em; margin-top: 2em; }
@media (max-width: 600px) { body { padding: 8px; } table { font-size: 12px; } th, td { padding: 3px 4px; }
  td.wrap, th.wrap { min-width: 7em; } td.n { white-space: normal; } }
"""  # noqa: E501


def require_plotly():
    try:
        import plotly  # noqa: F401
    except ImportError:
        raise InputError(
            "the HTML report needs plotly: pip install 'axisopt[html]'", where="--report"
        ) from None


@dataclass
class Page:
    """An HTML report under construction: ``cards`` (label, value, state) first, then the
    sections."""

    title: str
    subtitle: str = ""
    cards: list = field(default_factory=list)
    sections: list = field(default_factory=list)  # (heading, [html fragments])
    interactive: bool = False  # plotly figures (else static SVG)

    def card(self, label: str, value: str, state: str = "") -> None:
        self.cards.append((label, value, state))

    def section(self, heading: str) -> list:
        body: list = []
        self.sections.append((heading, body))
        return body

    def figure(self, heading: str, interactive, static, height: int = 420) -> None:
        """A section ``heading`` holding one figure: ``interactive()`` (a plotly figure) on an
        interactive page, else ``static()`` (a matplotlib Figure) as SVG; each is only built when
        used."""
        body = self.section(heading)
        body.append(figure(interactive(), height) if self.interactive else _svg(static(), heading))

    def render(self, plotly_js: str = "inline") -> str:
        """The page; on an interactive page ``plotly_js`` 'inline' (plotly.js in the file: offline)
        or 'cdn' (a script tag loading the installed plotly's version from the plotly CDN: a small
        file that needs the network).  A static page has no script at all."""
        if not self.interactive:
            script, credit = (
                "",
                "static SVG figures (matplotlib); --plotly inline for interactive ones",
            )
        else:
            script, credit = _plotly_script(plotly_js)
        cards = "".join(
            f'<div class="card {s}"><div class="k">{_e(k)}</div><div class="v">{_e(v)}</div></div>'
            for k, v, s in self.cards
        )
        nav = "".join(f'<a href="#s{i}">{_e(h)}</a>' for i, (h, _) in enumerate(self.sections))
        body = "".join(
            f'<h2 id="s{i}">{_e(h)}</h2>' + "".join(parts)
            for i, (h, parts) in enumerate(self.sections)
        )
        return (
            '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
            '<meta name="viewport" content="width=device-width, initial-scale=1">'
            f"<title>{_e(self.title)}</title><style>{_CSS}</style>"
            f"{script}</head><body>"
            f"<h1>{_e(self.title)}</h1>"
            + (f'<p class="sub">{_e(self.subtitle)}</p>' if self.subtitle else "")
            + f'<div class="cards">{cards}</div><nav>{nav}</nav>{body}'
            f"<footer>axisopt report; {_e(credit)}</footer></body></html>\n"
        )


def _plotly_script(plotly_js: str) -> tuple[str, str]:
    """The plotly.js script tag and the footer's credit."""
    import plotly
    from plotly.offline import get_plotlyjs

    if plotly_js == "inline":
        script, note = f"<script>{get_plotlyjs()}</script>", "inlined, works offline"
    elif plotly_js == "cdn":
        from plotly.offline.offline import get_plotlyjs_version

        src = f"https://cdn.plot.ly/plotly-{get_plotlyjs_version()}.min.js"
        script, note = f'<script src="{src}" charset="utf-8"></script>', f"loaded from {src}"
    else:
        raise ValueError(f"plotly_js must be 'inline' or 'cdn', not {plotly_js!r}")
    return script, f"figures by plotly {plotly.__version__} ({note})"


def _svg(fig, alt: str) -> str:
    from .static import svg

    return svg(fig, alt)


def _e(text) -> str:
    return html.escape(str(text))


def pre(text: str) -> str:
    return f"<pre>{_e(text)}</pre>"


def para(text: str) -> str:
    return f"<p>{_e(text)}</p>"


def table(head, rows, states=None, classes=None) -> str:
    """A table in its own horizontal scroller (the page never scrolls sideways); ``states``
    (optional) gives per row the class of its last cell ('ok' / 'bad'), ``classes`` (optional) per
    row a list of cell classes ('' for none).  Text and part ids wrap (a 1280 px window shows every
    column); a number with its unit stays on one line."""
    # a heading may break after a dot or underscore (axis.<wbr>moving_<wbr>mass [kg]): long key
    # names fit
    th = "".join(f"<th>{_breakable(h)}</th>" for h in head)
    trs = []
    for i, r in enumerate(rows):
        cls = classes[i] if classes is not None else [""] * len(r)
        cls = [
            (c + " n").strip()
            if _NUMBER.match(str(v))
            else (c + " t").strip()
            if isinstance(v, (list, tuple)) or not _NUMBER.match(str(v)) and str(v) != "-"
            else c
            for v, c in zip(r, cls)
        ]
        cells = [
            f'<td class="{c}">{_html(v)}</td>' if c else f"<td>{_html(v)}</td>"
            for v, c in zip(r, cls)
        ]
        if states is not None and states[i]:
            cells[-1] = f'<td class="{states[i]}">{_html(r[-1])}</td>'
        trs.append("<tr>" + "".join(cells) + "</tr>")
    return (
        "<div "
        f'class="scroll"><table><thead><tr>{th}</tr></thead><tbody>{"".join(trs)}'
        "</tbody></table></div>"
    )


def _html(v) -> str:
    """A cell's text, escaped; a list (a design's part ids) one unbroken id after the other,
    wrapping only between ids."""
    if isinstance(v, (list, tuple)):
        return " / ".join(f'<span class="id">{_e(x)}</span>' for x in v)
    return _e(v)


_BREAK = re.compile(r"([._])(?=\w)")


def _breakable(heading: str) -> str:
    """A heading escaped, with a break opportunity after each dot and underscore of its name (not of
    its unit: ``axis.<wbr>moving_<wbr>mass [kg]``, ``drag [N.m]`` whole)."""
    name, sep, unit = str(heading).partition(" [")
    return _BREAK.sub(r"\1<wbr>", _e(name)) + _e(sep + unit)


# 1,234.5 / 0.97 / 12 N/um / 5 %
_NUMBER = re.compile(r"^[-+]?[\d.,]+(e[-+]?\d+)?( ?[^\s\d]{1,6})?$")


def figure(fig, height: int = 420) -> str:
    """A plotly figure as a div (the page inlines plotly.js once)."""
    fig.update_layout(
        height=height,
        margin=dict(l=55, r=15, t=40, b=45),
        template="plotly_white",
        legend=dict(orientation="h", y=-0.18),
    )
    return (
        '<div class="fig">'
        + fig.to_html(
            full_html=False,
            include_plotlyjs=False,
            config={"responsive": True, "displaylogo": False},
        )
        + "</div>"
    )


def check_report_path(path, interactive: bool = False) -> None:
    """A --report target must end in .html, and plotly must be installed for interactive figures
    (one-line InputError otherwise)."""
    if not str(path).lower().endswith((".html", ".htm")):
        raise InputError(
            f"the report is HTML: give a file ending in .html, not '{path}'", where="--report"
        )
    from ..fileio import check_output_path

    check_output_path(path, what="HTML report", where="--report")
    if interactive:
        require_plotly()


# --plotly: static SVG figures (default), plotly.js inlined or linked
PLOTLY_CHOICES = ("no", "inline", "cdn")


def write_page(page: Page, path, plotly: str = "no") -> None:
    """Write ``page`` to ``path``; ``plotly`` as :meth:`Page.render` takes it ('no' on a static
    page)."""
    from ..fileio import write_text_atomic

    check_report_path(path, page.interactive)
    write_text_atomic(str(path), page.render(plotly), what="HTML report")


# -------------------------------------------------------------------------------------------
# figures
# ------------------------------------------------------------------------------------------- pages
def evaluation_cards(page: Page, ev) -> None:
    from .evaluation import check_rows

    k, _ = ev.minimum("k_total")
    f, _ = ev.minimum("f1")
    rows = check_rows(ev)
    failed = [r["check"] for r in rows if not r["pass"]]
    page.card("min axial stiffness", f"{k / N_PER_UM:,.1f} N/um")
    page.card("min 1st frequency", f"{f:,.1f} Hz")
    page.card("weakest link", ev.weakest)
    page.card("total mass", f"{ev['total_mass']:,.1f} kg")
    page.card("cost (illustrative)", f"{ev['cost']:,.0f} EUR")
    page.card(
        "checks", "all pass" if not failed else f"{len(failed)} fail", "ok" if not failed else "bad"
    )


# below each bound its class; above: ample
MARGIN_CLASSES = ((1.0, "m-fail"), (1.1, "m-tight"), (1.5, "m-fair"))


def margin_class(m, passed: bool | None = None) -> str:
    """How close a margin (available / needed) is to failing: m-fail < 1 <= m-tight < 1.1 <= m-fair
    < 1.5 <= m-ample.  A check that passes (``passed``: a margin the solver put on its limit,
    0.9999999 printed as 1.00) is tight, never coloured as failing."""
    if m is None or not math.isfinite(m):
        return ""
    for bound, cls in MARGIN_CLASSES:
        if m < bound:
            return "m-tight" if cls == "m-fail" and passed else cls
    return "m-ample"


MARGIN_KEY = (
    '<p class="key">margin = available / needed: <span class="m">below 1 fails (red), 1-1.1 tight '
    "(amber), 1.1-1.5 fair (pale green), from 1.5 ample (green)</span></p>"
)


def parts_table(design, problem=None) -> str:
    """The parts list to order (:func:`axisopt.report.partslist.parts_list`; the preload kept within
    ``problem``'s limits)."""
    from .partslist import parts_list

    rows = parts_list(design, problem)
    return table(
        ["part", "id", "vendor", "quantity", "order"],
        [[r["part"], r["id"], r["vendor"], str(r["quantity"]), r["order"] or "-"] for r in rows],
        classes=[["", "", "", "", "wrap"]] * len(rows),
    )


def checks_table(ev, margins: dict | None = None) -> str:
    """The checks with their values and margins; ``margins``: a problem's least margins (pass or
    FAIL against them, :func:`axisopt.report.evaluation.judged_rows`)."""
    from .checktext import judged_rows
    from .text import fmt_value

    head = ["check", "available", "needed", "margin", "result"]
    body, classes = [], []
    for r in judged_rows(ev, margins):
        u = f" {r['unit']}" if r["unit"] else ""
        have = (
            f"{fmt_value(r['available_min'])}-{fmt_value(r['available'])}{u}"
            if r["check"] == "bearing_fit"
            else ("n/a" if r["available"] is None else fmt_value(r["available"]) + u)
        )
        body.append(
            [
                r["label"],
                have,
                (fmt_value(r["needed"]) + u) if r["needed"] else "none",
                "n/a" if r["margin"] is None else f"{r['margin']:.2f}",
                ("pass" if r["pass"] else "FAIL")
                + (
                    ""
                    if "allowed" not in r
                    else " (check off)"
                    if r["allowed"] == 0
                    else f" (margin {r['allowed']:g} allowed)"
                ),
            ]
        )
        classes.append(
            ["wrap", "", "", margin_class(r["margin"], r["pass"]), "ok" if r["pass"] else "bad"]
        )
    return table(head, body, classes=classes) + MARGIN_KEY


def evaluation_page(ev, title: str | None = None, interactive: bool = False) -> Page:
    from . import static
    from .evaluation import evaluation_table
    from .plots import plot_profiles

    d = ev.design
    page = Page(
        title or f"Axis evaluation: {d.name}",
        f"{d.axis.mounting}, stroke {d.axis.stroke * 1e3:.0f} mm; parts "
        + ", ".join(f"{k} {v}" for k, v in d.part_ids().items()),
        interactive=interactive,
    )
    evaluation_cards(page, ev)
    drive = d.motor is not None
    # the static profile figure carries the duty cycle against the motor limits in its right-hand
    # panel
    page.figure(
        "Stiffness and frequency over the stroke"
        + ("; drive against the motor" if drive and not interactive else ""),
        lambda: ifig.profiles_figure([ev], [d.name]),
        lambda: plot_profiles([ev]),
    )
    page.figure(
        "Stiffness chain", lambda: ifig.chain_figure(ev), lambda: static.chain_figure(ev), 300
    )
    if drive and interactive:
        page.figure("Drive: duty cycle against the motor", lambda: ifig.drive_figure(ev), None, 460)
    page.figure(
        "Dynamic compliance of the table (FRF)",
        lambda: ifig.frf_figure(ev),
        lambda: static.frf_figure(ev),
        560,
    )
    page.section("Checks").append(checks_table(ev))
    page.section("Parts to order").append(parts_table(d))
    page.section("Full evaluation (as printed)").append(pre(evaluation_table(ev)))
    return page
