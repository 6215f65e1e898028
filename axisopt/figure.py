"""The matplotlib Figure every plot of axisopt draws on: outside pyplot, and shown as an image by
Jupyter.

A plain ``matplotlib.figure.Figure()`` that pyplot does not manage shows in a fresh Jupyter kernel
as ``<Figure size 1300x800 with 3 Axes>``: IPython's inline backend registers its image formatter
only once pyplot has been imported (or ``%matplotlib inline`` run).  :class:`Figure` adds the
rich-display method IPython looks for (``_repr_png_``), so ``axisopt.plot_profiles(ev)`` as the last
line of a cell shows the plot in any kernel, while the command line never imports pyplot, picks no
backend and needs no display (the figure is drawn by matplotlib's Agg renderer when it is saved or
shown).  Imported only where a plot is drawn, so ``import axisopt`` does not import matplotlib.
"""

from __future__ import annotations

import io

from matplotlib.figure import Figure as _MplFigure

NOTEBOOK_DPI = 80  # dots per inch of the image a notebook shows (a 13 x 8 in figure: 1040 x 640 px)


class Figure(_MplFigure):
    """A matplotlib Figure (not registered with pyplot) that Jupyter and IPython display as a PNG
    image."""

    def _repr_png_(self) -> bytes:
        """The figure as PNG bytes, as IPython's display machinery asks for it."""
        buf = io.BytesIO()
        self.savefig(buf, format="png", dpi=NOTEBOOK_DPI)
        return buf.getvalue()


def new_figure(**kw) -> Figure:
    """A new :class:`Figure` (keyword arguments as ``matplotlib.figure.Figure``, e.g.
    ``figsize``)."""
    return Figure(**kw)


__all__ = ["Figure", "new_figure", "NOTEBOOK_DPI"]
