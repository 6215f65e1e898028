"""The forward-selection rule both diagnosis pipelines judge candidate effects by.

Each round every candidate is fitted jointly with the model so far; a candidate is accepted when

* it lowers the Bayesian information criterion, :math:`\\Delta\\mathrm{BIC} = n
  \\ln(\\mathrm{RSS}_1/\\mathrm{RSS}_0) + \\Delta p \\ln n`, below ``accept_dbic`` (-10: "very
  strong" evidence on Kass and Raftery's scale, J. Am. Stat. Assoc. 90 (1995) 773-795),
* it predicts held-out data better: the RMSE on data the fit did not see falls by at least
  ``min_gain`` percent, :math:`100\\,(1 - \\mathrm{RMSE}_1/\\mathrm{RMSE}_0) \\ge` ``min_gain``,
* its fitted values are physical (each effect declares its range).

The criteria are judged in ``order``; a candidate not accepted keeps the first one it failed as its
reason.  When no single candidate passes, pairs from the round's ``pair_pool`` best candidates are
fitted jointly and judged alike, and a pair must also beat the better of its members alone by
``min_gain`` (each is needed).

The two pipelines keep the rules they were validated with: :data:`TABLE_RULE` (reduced tables,
held-out data from grouped cross-validation) and :data:`TIME_RULE` (time records, held-out
validation runs or blocks).
"""

from __future__ import annotations

from dataclasses import dataclass

DBIC, PLAUSIBLE, GAIN = "dbic", "plausible", "gain"


@dataclass(frozen=True)
class SelectionRule:
    accept_dbic: float = -10.0  # a candidate must lower BIC below this
    min_gain: float = 5.0  # [%] held-out RMSE must fall by at least this much
    # criteria in the order judged: the first failed is the reason
    order: tuple = (DBIC, PLAUSIBLE, GAIN)
    # pairs are tried among at most this many single candidates (the best by dBIC)
    pair_pool: int = 5
    pair_needs_signal: bool = False  # True: a pair's members must each lower BIC alone (dBIC < 0)
    # [%] two accepted explanations whose held-out RMSE differ by less are equivalent
    resolution: float = 1.0

    def equivalent(self, rmse_a: float, rmse_b: float) -> float | None:
        """How far apart [%] two explanations that both pass predict the held-out data, when that is
        within ``resolution`` (the data do not tell them apart: say so and name the separating
        measurement), else None."""
        if not rmse_a > 0:
            return None
        d = 100.0 * abs(rmse_b - rmse_a) / rmse_a
        return d if d < self.resolution else None

    def gain(self, before: float, after: float) -> float:
        """Held-out gain [%]: how much the held-out RMSE falls from ``before`` to ``after``."""
        return 100.0 * (1.0 - after / before) if before > 0 else 0.0

    def _first_failed(self, dbic: float, gain, why: str) -> tuple:
        """(criterion, reason, gain [%]) of the first criterion failed ((None, '', gain) when all
        pass)."""
        for crit in self.order:
            if crit == DBIC and dbic >= self.accept_dbic:
                return crit, f"dBIC {dbic:.1f} not below {self.accept_dbic:g}", gain
            if crit == PLAUSIBLE and why:
                return crit, f"would need {why}", gain
            if crit == GAIN:
                gain = gain() if callable(gain) else gain
                if gain < self.min_gain:
                    return crit, f"held-out gain {gain:.1f} % below {self.min_gain:g} %", gain
        return None, "", gain

    def reason(self, dbic: float, gain, why: str) -> str:
        """Why a single candidate is not accepted ('' when it is): the first criterion it fails, and
        its implausible values when those are not the reason already.  ``gain`` [%] may be a
        callable, called only when the gain is judged (a cross-validation costs fits); ``why``: its
        implausible values."""
        crit, text, _ = self._first_failed(dbic, gain, why)
        if why and crit not in (None, PLAUSIBLE):
            text += f"; and it would need {why}"
        return text

    def pair_reason(self, dbic: float, gain, why: str, alone) -> str:
        """Why a pair is not accepted ('' when it is): the first criterion failed, then whether it
        beats the better member alone (``alone`` [%], may be a callable) by ``min_gain``."""
        _, text, g = self._first_failed(dbic, gain, why)
        if text:
            return text
        a = alone() if callable(alone) else alone
        if g - a < self.min_gain:
            return (
                f"held-out gain {g:.1f} % is not {self.min_gain:g} % above the better member alone "
                f"({a:.1f} %)"
            )
        return ""

    def pair_pool_of(self, scored: list) -> list:
        """The round's candidates (sorted by dBIC) that pairs are formed from."""
        pool = [c for c in scored if c.dbic < 0.0] if self.pair_needs_signal else list(scored)
        return pool[: self.pair_pool]


# reduced tables: plausibility before the (costly) cross-validation; 5 candidates give 10 pair fits
TABLE_RULE = SelectionRule(
    order=(DBIC, PLAUSIBLE, GAIN), pair_pool=5, pair_needs_signal=False, resolution=2.0
)
# time records: the held-out gain of every candidate is known; 6 candidates that lower BIC alone
# give 15 pair fits
TIME_RULE = SelectionRule(order=(DBIC, GAIN, PLAUSIBLE), pair_pool=6, pair_needs_signal=True)
