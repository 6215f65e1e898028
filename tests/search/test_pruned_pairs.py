"""The certificate counts the combinations never formed because of a (motor, coupling) pair: a
coupling another beats on every count, or one that cannot carry the motor's peak torque.  Reference:
the pairs counted by hand for a catalog built so that the answer is known."""

from dataclasses import replace

import numpy as np
from search_synthetic import add_drives, make_catalog, make_double, make_problem

from axisopt.search import solve
from axisopt.search.parts import build_space


def test_left_out_pairs_are_counted():
    rng = np.random.default_rng(11)
    cat = make_catalog(rng, n_screws=2, nuts_per_screw=2, n_bearings=3, n_guides=2)
    make_double(cat)
    cat = add_drives(cat, rng, n_motors=3, n_couplings=3)
    m, cp = cat.motors.copy(), cat.couplings.copy()
    m["peak_torque"] = [10.0, 20.0, 40.0]
    # C0 carries every motor; C1 only the first two (30 N.m); C2 is C0 with more inertia: dominated
    cp["rated_torque"] = [100.0, 30.0, 100.0]
    cp["torsional_stiffness"] = [2e5, 3e5, 2e5]
    cp["inertia"] = [2e-4, 1e-4, 5e-4]
    cp["max_speed"] = cp["max_speed"].iloc[0]
    cp["price"] = [100.0, 100.0, 120.0]
    cat = cat.replace(motors=m, couplings=cp)
    p = make_problem(cat, limits={"max_cost": 1e5})
    p = replace(p, restrictions=replace(p.restrictions, drive=True))
    sp = build_space(p)
    assert sp.n_drives == 3 + 2  # C0 with every motor, C1 with M0 and M1
    left_out = 3 * 3 - 5  # M2-C1 (40 N.m > 30 N.m) and the three pairs with the dominated C2
    mech = sp.size // sp.n_drives
    r = solve(p, "default", top=1, sensitivities=False)
    assert r.certificate.pruned_by_dominance == mech * left_out
    assert r.certificate.combinations == mech * 5
