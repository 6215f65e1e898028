"""Identification: measured-data formats, fitting, the effect library, diagnosis of reduced tables
(:mod:`.diagnose`) and of time records (:mod:`.idim`), judged by one selection rule
(:mod:`.selection`)."""

from .effects import Effect, library, register_effect, time_effects, unregister_effect
from .fit import Param
from .plant import Plant, plant_from_design
from .tables.data import Dataset, read_dataset
from .tables.diagnose import Diagnosis, diagnose

__all__ = [
    "Dataset",
    "Diagnosis",
    "Effect",
    "Param",
    "Plant",
    "diagnose",
    "library",
    "plant_from_design",
    "read_dataset",
    "register_effect",
    "time_effects",
    "unregister_effect",
]
