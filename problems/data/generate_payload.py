"""Regenerate the shipped runs with different payloads (synthetic, seeded):
``python problems/data/generate_payload.py``.

table_x_payload_est.csv (8 s, no payload) and table_x_payload_val.csv (5 s, a 350 kg fixture clamped on the
table): the axis of table_x.yaml as in generate_timerecord.py without the Stribeck rise (620 kg moving,
Coulomb 500 N, viscous 1200 N s/m, PD loop, 1 kHz), each run with a ``payload [kg]`` column, one value through
the run.  The validation run's axis carries 620 + 350 kg.  Simulated by axisopt.identify.records.synth.
"""

import csv
from dataclasses import replace
from pathlib import Path

from axisopt.identify.records.synth import AxisTruth, simulate_axis

HERE = Path(__file__).resolve().parent
AXIS = AxisTruth(mass=620.0, viscous=1200.0, coulomb=500.0, stribeck=0.0, stribeck_v=0.003)


def run(path: Path, payload: float, duration: float, seed: int) -> None:
    rec = simulate_axis(replace(AXIS, mass=AXIS.mass + payload), duration=duration, seed=seed)
    tmp = path.with_suffix(".tmp")
    rec.write_csv(tmp)
    rows = list(csv.reader(tmp.read_text().splitlines()))
    tmp.unlink()
    with path.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(rows[0] + ["payload [kg]"])
        for r in rows[1:]:
            w.writerow(r + [f"{payload:g}"])


def main():
    run(HERE / "table_x_payload_est.csv", 0.0, 8.0, 71)
    run(HERE / "table_x_payload_val.csv", 350.0, 5.0, 72)
    print("wrote table_x_payload_est.csv and table_x_payload_val.csv")


if __name__ == "__main__":
    main()
