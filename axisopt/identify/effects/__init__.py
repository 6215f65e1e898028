"""The effect library of both diagnosis pipelines: the registry and the declaration (:mod:`.base`)
and the built-in effects by what they act on (:mod:`.stiffness`, :mod:`.dynamics`, :mod:`.friction`,
:mod:`.disturbance`, :mod:`.load`; imported here in the order they are registered, which is the
order tables try them)."""

# isort: off
# the order of registration, which is the order tables try the effects in
from . import stiffness  # noqa: F401
from . import dynamics  # noqa: F401
from . import friction  # noqa: F401
from . import disturbance  # noqa: F401
from . import load  # noqa: F401
from . import orders  # noqa: F401

# isort: on
from .base import (
    TIME_ORDER,
    Effect,
    Shape,
    Term,
    TimeModel,
    all_effects,
    library,
    register_effect,
    replace_part,
    time_effects,
    unregister_effect,
)

BUILTIN = tuple(library())

__all__ = [
    "BUILTIN",
    "TIME_ORDER",
    "Effect",
    "Shape",
    "Term",
    "TimeModel",
    "all_effects",
    "library",
    "register_effect",
    "replace_part",
    "time_effects",
    "unregister_effect",
]
