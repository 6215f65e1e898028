"""The reference MINLP solvers' own status words, declared once: what each SCIP status
(``Model.getStatus()``) and each Bonmin return status (CasADi's ``stats()["return_status"]``) means
for an axisopt solve.  The solve's own status (``SolveResult.status``) is one of
:data:`axisopt.search.result.STATUS_TABLE`; these tables say how a solver's word maps onto it
(SCIP's status list: the SCIP Optimization Suite documentation, ``SCIP_STATUS``; Bonmin's: the
Bonmin user's manual, ``TMINLP::SolverReturn``)."""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType

# what a solver's word says of one mounting's MINLP
PROVED = "proved"  # solved to optimality (or infeasibility) within the solver's tolerances
STOPPED = "stopped"  # a limit stopped it: the point it has (if any) is not proven
UNEXPECTED = "unexpected"  # anything else: reported as a note, the solve is not proven


@dataclass(frozen=True)
class SolverStatus:
    word: str  # the solver's own status
    outcome: str  # PROVED | STOPPED | UNEXPECTED
    meaning: str


SCIP_STATUS_TABLE = (
    SolverStatus("optimal", PROVED, "optimal within SCIP's feasibility and gap tolerances"),
    SolverStatus("gaplimit", PROVED, "stopped at the relative gap asked (search.minlp.scip.GAP)"),
    SolverStatus("infeasible", PROVED, "no integer point meets the constraints"),
    SolverStatus("timelimit", STOPPED, "the time limit"),
    SolverStatus("userinterrupt", STOPPED, "interrupted"),
    SolverStatus("memlimit", STOPPED, "the memory limit"),
    SolverStatus("nodelimit", STOPPED, "the node limit"),
    SolverStatus("stallnodelimit", STOPPED, "the stall node limit"),
    SolverStatus("totalnodelimit", STOPPED, "the total node limit"),
    SolverStatus("sollimit", STOPPED, "the solution-count limit"),
    SolverStatus("bestsollimit", STOPPED, "the improving-solution limit"),
    SolverStatus("restartlimit", STOPPED, "the restart limit"),
)
SCIP_STATUSES = MappingProxyType({s.word: s for s in SCIP_STATUS_TABLE})

BONMIN_SUCCESS, BONMIN_INFEASIBLE = "SUCCESS", "INFEASIBLE"
BONMIN_STATUS_TABLE = (
    # Bonmin's branch-and-bound is exact only on convex problems: on this nonconvex one neither word
    # proves
    SolverStatus(
        BONMIN_SUCCESS, STOPPED, "a local optimum of the branch-and-bound (not a global proof)"
    ),
    SolverStatus(BONMIN_INFEASIBLE, STOPPED, "no point found (not a proof on a nonconvex problem)"),
)
BONMIN_STATUSES = MappingProxyType({s.word: s for s in BONMIN_STATUS_TABLE})


def scip_outcome(word: str) -> str:
    """PROVED, STOPPED or UNEXPECTED for a SCIP status word."""
    s = SCIP_STATUSES.get(word)
    return UNEXPECTED if s is None else s.outcome
