"""axisopt: size machine-tool feed axes from real catalogs and diagnose measured axes.

In a notebook (:mod:`axisopt.api`)::

    import axisopt
    ev = axisopt.evaluate("problems/teaching_design.yaml")     # Evaluation: ev.to_frame(), ev.check_table()
    res = axisopt.solve("problems/teaching_problem.yaml")      # SolveResult: res.to_frame(), res.best.design

``load_design``, ``load_problem``, ``evaluate``, ``solve``, ``compare``, ``study``, ``diagnose``,
``plot_profiles`` and ``plot_pareto`` are imported on first use (PEP 562), so ``import axisopt``
(and the command line's start-up) pays for none of them.
"""  # noqa: E501

__version__ = "0.1.0"

# name -> module that defines it, imported on first access
_LAZY = {
    "load_design": "axisopt.design",
    "load_problem": "axisopt.problem",
    **{
        name: "axisopt.api"
        for name in (
            "evaluate",
            "solve",
            "compare",
            "study",
            "diagnose",
            "plot_profiles",
            "plot_pareto",
        )
    },
}

__all__ = ["__version__", *_LAZY]


def __getattr__(name: str):
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'axisopt' has no attribute {name!r}")
    import importlib

    value = getattr(importlib.import_module(module), name)
    globals()[name] = value  # later look-ups skip this function
    return value


def __dir__():
    return sorted(set(globals()) | set(_LAZY))
