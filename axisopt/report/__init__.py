"""Reports: tables, JSON dicts and plots in vendor units.  Nothing here prints (the ``cli`` package
does).

- :mod:`.evaluation`: one design's evaluation as a text table and a JSON dict
- :mod:`.plots`: stiffness and frequency over the stroke, duty cycle on the torque-speed plane
- :mod:`.methods`: ``evaluate --methods`` and ``--frf`` tables, dicts and plot
- :mod:`.solve`: a SolveResult as ``solve`` prints it, and the Pareto front's scatter matrix
- :mod:`.compare`: designs side by side (``compare``'s table, JSON and CSV; the notebook's
  ``Comparison``)
"""

from ..fileio import PLOT_FORMATS, atomic_file, make_output_dir, save_figure, write_text_atomic
from ..units import N_PER_UM
from .drivetext import drive_lines
from .evaluation import drive_dict, evaluation_dict, evaluation_table
from .plots import duty_points, plot_profiles
from .text import RPM

__all__ = [
    "evaluation_dict",
    "evaluation_table",
    "drive_dict",
    "drive_lines",
    "plot_profiles",
    "duty_points",
    "atomic_file",
    "make_output_dir",
    "save_figure",
    "write_text_atomic",
    "PLOT_FORMATS",
    "N_PER_UM",
    "RPM",
]
