"""Identification: measured-data formats, fitting, effect library, diagnosis, gain report."""

from .data import Dataset, read_dataset
from .diagnose import Diagnosis, diagnose
from .effects import Effect, library, register_effect
from .fit import Param
from .plant import Plant, plant_from_design

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
]
