"""The values a result reports of each design, declared once (:data:`REPORTED`): the
:class:`.result.Candidate` fields after ``objective``, the candidate tables' columns
(:data:`.result.CANDIDATE_COLUMNS`), the Candidate's repr, the study table
(``study.table.RESULT_COLUMNS``), the compare and HTML tables' column names and the API reference
read it; :mod:`.candidates` fills the values."""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType


@dataclass(frozen=True)
class Reported:
    """One value a result reports of each design, declared once: the :class:`Candidate` field (and
    JSON key) of that name, its column in the candidate tables (:data:`CANDIDATE_COLUMNS`,
    ``Candidate.row``) and the study table (``study.table.RESULT_COLUMNS``), its label in
    ``Candidate.__repr__``, its meaning in the API reference, and where its value comes from (a goal
    of ``model.goals.OBJECTIVE_TABLE`` whose ``field`` it is, or a model output's minimum over the
    stroke).  Adding a reported value is one entry of :data:`REPORTED`."""

    field: str  # the Candidate attribute and JSON key
    name: str  # the tables' column name (without its unit)
    unit: str  # display unit (the column's and the repr's)
    doc: str  # meaning, unit in brackets (docs/api.md)
    label: str = ""  # Candidate.__repr__'s label ('' : not in the repr)
    # the model output it is read from, its minimum over the stroke ('' : a goal's field)
    output: str = ""
    per: float = 1.0  # the output's SI units per display unit
    profile: tuple = ()  # the study table's columns right after it: (column, (record section, key))

    @property
    def column(self) -> str:
        return f"{self.name} [{self.unit}]"


REPORTED = (
    Reported(
        "min_stiffness",
        "min_stiffness",
        "N/um",
        "[N/um], minimum over the model position grid",
        "min stiffness",
        profile=(("min_stiffness_at [mm]", ("profile", "min_stiffness_position_mm")),),
    ),
    Reported(
        "min_frequency",
        "min_frequency",
        "Hz",
        "[Hz]",
        "1st frequency",
        profile=(
            ("min_frequency_at [mm]", ("profile", "min_frequency_position_mm")),
            ("weakest_link", ("profile", "weakest_link")),
        ),
    ),
    Reported("cost", "cost", "EUR", "[EUR]", "cost"),
    Reported("moving_mass", "moving_mass", "kg", "[kg]", "moving mass"),
    Reported("total_mass", "total_mass", "kg", "[kg]"),
    Reported("drag_torque", "drag_torque", "N.m", "[N*m]", "drag", output="drag_torque"),
    Reported("life_h", "life", "h", "nut L10 life [h]", "nut life", output="life", per=3600.0),
)
REPORTED_BY_FIELD = MappingProxyType({r.field: r for r in REPORTED})
