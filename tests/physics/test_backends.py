"""Every public physics function agrees on floats, numpy arrays and CasADi SX.

dynamic_compliance is excluded: it returns a complex FRF and is numpy-only by design.
"""

from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest

from axisopt.physics import (
    MODULES,
    bearings,
    carriage,
    checks,
    damping,
    dynamics,
    friction,
    gantry,
    guides,
    nut,
    screw,
    thermal,
)

# complex numpy-only FRFs; selector helper (no numbers) carriage.mean_load takes sequences:
# tests/physics/test_carriage_published.py checks its backends load_factor_default picks a table row
# by a float speed (a choice, not a formula)
EXCLUDED = {
    "dynamic_compliance",
    "drive_train_compliance",
    "choose",
    "mean_load",
    "load_factor_default",
}
SCALE = (0.9, 1.0, 1.1)
RAD15 = math.radians(15.0)


def case(func, pos=(), kw=None, fixed=None, label=""):
    """pos/kw values: a float (scaled by SCALE) or a 3-tuple used as is."""
    return pytest.param(
        func, tuple(pos), dict(kw or {}), dict(fixed or {}), id=f"{func.__name__}{label}"
    )


BALL = dict(
    n_balls=40.0,
    ball_diameter=6.35e-3,
    pitch_diameter=0.04,
    contact_angle=math.radians(45),
    lead_angle=0.0794,
)
CASES = [
    case(screw.series_stiffness, pos=(2e8, 5e8, 1e9)),
    case(screw.parallel_stiffness, pos=(2e8, 5e8)),
    case(
        screw.screw_stiffness,
        kw=dict(root_diameter=0.02, x=0.3, span=1.0),
        fixed=dict(mounting="fixed-fixed"),
        label="-ff",
    ),
    case(
        screw.screw_stiffness,
        kw=dict(root_diameter=0.02, x=0.3, span=1.0),
        fixed=dict(mounting="fixed-free"),
        label="-f",
    ),
    case(
        screw.screw_stiffness_catalog,
        kw=dict(root_diameter=0.02, length=1.0),
        fixed=dict(mounting="fixed-fixed"),
    ),
    case(screw.screw_torsional_stiffness, kw=dict(root_diameter=0.02, length=1.0)),
    case(screw.screw_axial_rigidity, kw=dict(root_diameter=0.02)),
    case(
        screw.two_path_stiffness,
        kw=dict(k_near=8e8, k_far=(0.0, 8e8, 1e9), axial_rigidity=6e7, x=0.3, span=1.0),
    ),
    case(
        screw.screw_bearing_stiffness,
        kw=dict(root_diameter=0.02, x=0.3, span=1.0, k_bearing_set=8e8),
        fixed=dict(mounting="fixed-fixed"),
        label="-ff",
    ),
    case(
        screw.screw_bearing_stiffness,
        kw=dict(root_diameter=0.02, x=0.3, span=1.0, k_bearing_set=8e8),
        fixed=dict(mounting="fixed-supported"),
        label="-fs",
    ),
    case(screw.torsion_axial_stiffness, kw=dict(torsional_stiffness=1e4, lead=0.01)),
    case(thermal.thermal_growth, kw=dict(length=1.0, temperature_rise=3.0)),
    case(thermal.rotating_shaft_heat_transfer, kw=dict(speed=(10.0, 100.0, 300.0), radius=0.02)),
    case(
        thermal.free_convection_temperature_rise,
        kw=dict(friction_power=(10.0, 50.0, 100.0), diameter=0.04, area=0.1),
    ),
    case(
        thermal.friction_temperature_rise,
        kw=dict(friction_power=(10.0, 50.0, 100.0), heat_transfer=20.0, area=0.1),
    ),
    case(thermal.restrained_thermal_force, kw=dict(root_diameter=0.03, temperature_rise=3.0)),
    case(
        thermal.thermal_force_elastic_ends,
        kw=dict(root_diameter=0.03, span=1.0, temperature_rise=3.0, k_bearing_set=8e8),
    ),
    case(
        thermal.thermal_displacement,
        kw=dict(
            x=0.4,
            span=1.0,
            root_diameter=0.03,
            temperature_rise=3.0,
            k_bearing_set=8e8,
            both_ends_fixed=(0.0, 1.0, 1.0),
        ),
    ),
    case(
        thermal.horizontal_cylinder_free_film,
        kw=dict(temperature_rise=(2.0, 5.0, 10.0), diameter=0.04),
    ),
    case(thermal.mixed_convection_film, kw=dict(forced=(1.0, 10.0, 30.0), free=4.0)),
    case(
        thermal.shaft_end_fraction,
        kw=dict(
            film=(5.0, 10.0, 20.0),
            nominal_diameter=0.04,
            root_diameter=0.034,
            half_length=0.5,
            end_conductance=2.0,
        ),
    ),
    case(
        thermal.screw_heat_network,
        kw=dict(
            nut_power=(10.0, 20.0, 40.0),
            bearing_power=10.0,
            film=8.0,
            nominal_diameter=0.04,
            root_diameter=0.034,
            span=1.0,
            ends=2.0,
            nut_conductance=1.9,
            end_conductance=2.0,
            housing_conductance=5.0,
        ),
    ),
    case(screw.screw_rotary_inertia, kw=dict(diameter=0.025, length=1.0)),
    *(
        case(
            screw.screw_sag,
            kw=dict(mass_per_length=8.2, root_diameter=0.0347, span=2.2),
            fixed=dict(mounting=m),
            label=f"-{m}",
        )
        for m in ("fixed-free", "fixed-supported", "fixed-fixed", "supported-supported")
    ),
    case(screw.screw_mass, kw=dict(diameter=0.025, length=1.0)),
    case(screw.lead_angle, kw=dict(lead=0.01, nominal_diameter=0.032)),
    case(
        nut.nut_stiffness_catalog, kw=dict(k_catalog=8e8, preload=1500.0, dynamic_load_rating=30e3)
    ),
    case(nut.hertz_point_deflection, kw=dict(load=200.0, radius_x=3e-3, radius_y=0.03)),
    case(nut.nut_axial_deflection_hertz, kw=dict(axial_load=2000.0, **BALL)),
    case(nut.nut_stiffness_hertz, kw=dict(axial_load=2000.0, **BALL)),
    case(nut.lift_off_force, kw=dict(preload=1500.0)),
    case(nut.preload_ceiling, kw=dict(dynamic_load_rating=45e3)),
    case(nut.double_nut_shift, kw=dict(force_ratio=(0.5, 2.0, 4.0))),
    case(
        nut.nut_length_estimate,
        kw=dict(lead=0.01, nominal_diameter=0.04, double=(0.0, 1.0, 1.0)),
    ),
    case(nut.preloaded_pair_load, kw=dict(preload=1500.0, axial_load=(1000.0, 5000.0, 3000.0))),
    case(
        nut.double_nut_stiffness_under_load,
        kw=dict(k0=8e8, preload=1000.0, axial_load=(-1000.0, 2500.0, 5000.0)),
    ),
    case(nut.nut_preload_drag_torque, kw=dict(preload=1500.0, lead=0.008, nominal_diameter=0.025)),
    case(bearings.radial_from_axial_eq27, kw=dict(axial_stiffness=5e8, contact_angle=0.3)),
    case(
        bearings.radial_from_axial_catalog,
        kw=dict(axial_stiffness=5e8),
        fixed=dict(contact_angle=RAD15),
    ),
    case(
        bearings.radial_from_axial,
        kw=dict(axial_stiffness=5e8),
        fixed=dict(contact_angle=RAD15),
        label="-catalog",
    ),
    case(
        bearings.radial_from_axial,
        kw=dict(axial_stiffness=5e8, contact_angle=0.3),
        fixed=dict(method="eq27"),
        label="-eq27",
    ),
    case(
        bearings.radial_stiffness_eq20,
        kw=dict(bore=0.06, outer_diameter=0.095, radial_load=1000.0, c_type=5.43),
    ),
    case(
        bearings.radial_stiffness_palmgren,
        kw=dict(radial_load=1000.0, ball_diameter=0.01, n_balls=15.0, contact_angle=RAD15),
    ),
    case(
        bearings.radial_stiffness_kramer,
        kw=dict(radial_load=1000.0, ball_diameter=0.01, n_balls=15.0),
    ),
    case(
        bearings.bearing_radial_stiffness,
        kw=dict(radial_load=1000.0, ball_diameter=0.01, n_balls=15.0),
        fixed=dict(method="kramer"),
    ),
    case(
        bearings.bearing_friction_torque,
        kw=dict(
            f0=4.0,
            f1=3e-4,
            viscosity=(1e-6, 30e-6, 100e-6),
            speed=20.0,
            mean_diameter=0.05,
            load=2000.0,
        ),
    ),
    case(
        bearings.support_starting_torque_envelope,
        kw=dict(preload=(500.0, 2000.0, 3900.0), mean_diameter=0.056),
    ),
    case(
        bearings.row_static_rating,
        kw=dict(set_rating=81.5e3, rows_loaded=(1.0, 2.0, 1.0), rows_rated=2.0),
    ),
    case(
        bearings.support_static_margin,
        kw=dict(
            rating_strong=81.5e3,
            rating_weak=40.75e3,
            push=(30e3, 10e3, 50e3),
            back=(10e3, 20e3, 5e3),
            safety=1.4285714,
        ),
    ),
    case(bearings.housing_stiffness_default, kw=dict(set_stiffness=1e9)),
    case(nut.bracket_stiffness_default, kw=dict(nut_stiffness=5e8)),
    case(guides.guide_tangential_stiffness, kw=dict(normal_stiffness=4e8)),
    case(guides.guide_ball_stiffness, kw=dict(preload_per_ball=50.0, deflection_constant=1e-7)),
    case(
        guides.guide_normal_stiffness_hertz,
        kw=dict(preload_per_ball=50.0, deflection_constant=1e-7, n_balls=40.0, contact_angle=0.785),
    ),
    case(
        guides.guide_tangential_stiffness_hertz,
        kw=dict(preload_per_ball=50.0, deflection_constant=1e-7, n_balls=40.0, contact_angle=0.785),
    ),
    case(
        guides.guide_friction_force,
        kw=dict(
            friction_force=15.0,
            friction_coefficient=0.002,
            friction_viscous=30.0,
            normal_load=(-5e3, 1e4, 2e4),
            speed=(-0.5, 0.1, 0.6),
        ),
    ),
    case(
        dynamics.axial_natural_frequency,
        kw=dict(stiffness=2e8, moving_mass=300.0, screw_mass=8.0, x=0.4, span=1.0),
    ),
    case(
        dynamics.axial_angular_frequency_eq11, kw=dict(root_diameter=0.04, length=0.5, mass=450.0)
    ),
    case(
        dynamics.effective_axial_mass,
        kw=dict(moving_mass=300.0, screw_mass=8.0, x=0.4, span=1.0),
        fixed=dict(mounting="fixed-supported"),
        label="-fixed-supported",
    ),
    case(
        dynamics.effective_axial_mass,
        kw=dict(moving_mass=300.0, screw_mass=8.0, x=0.4, span=1.0),
        fixed=dict(mounting="fixed-fixed"),
        label="-fixed-fixed",
    ),
    case(
        dynamics.table_mode_frequency,
        kw=dict(normal_stiffness_per_block=5e8, n_blocks=4.0, mass=300.0),
    ),
    case(
        dynamics.axial_torsional_eigenvalues,
        kw=dict(
            rotary_inertia=2e-3, torsional_stiffness=3e3, axial_stiffness=2e8, mass=300.0, lead=0.01
        ),
    ),
    case(
        dynamics.axial_torsional_frequencies,
        kw=dict(
            rotary_inertia=2e-3, torsional_stiffness=3e3, axial_stiffness=2e8, mass=300.0, lead=0.01
        ),
    ),
    case(
        dynamics.drive_train_eigenvalues,
        kw=dict(
            motor_inertia=1e-3,
            screw_inertia=2e-3,
            coupling_stiffness=3e4,
            axial_stiffness=2e8,
            mass=300.0,
            lead=0.01,
        ),
    ),
    case(
        dynamics.drive_train_frequencies,
        kw=dict(
            motor_inertia=1e-3,
            screw_inertia=2e-3,
            coupling_stiffness=3e4,
            axial_stiffness=2e8,
            mass=300.0,
            lead=0.01,
        ),
    ),
    case(damping.rolling_joint_damping, kw=dict(bore=(0.03, 0.1, 0.2))),
    case(
        damping.chain_damper_share,
        kw=dict(damping=5e3, chain_stiffness=2e8, component_stiffness=8e8),
    ),
    case(damping.critical_damping, kw=dict(mass=300.0, stiffness=2e8)),
    case(damping.damping_ratio, kw=dict(damping=8e3, mass=300.0, stiffness=2e8)),
    case(damping.damping_coefficient, kw=dict(ratio=0.05, mass=300.0, stiffness=2e8)),
    case(damping.damping_ratio_from_log_decrement_eq39, kw=dict(log_decrement=0.3)),
    case(damping.damping_ratio_from_log_decrement_exact, kw=dict(log_decrement=0.3)),
    case(
        damping.damping_ratio_from_log_decrement,
        kw=dict(log_decrement=0.3),
        fixed=dict(method="exact"),
    ),
    case(damping.damping_ratio_from_loss_factor, kw=dict(loss_factor=0.04)),
    case(damping.damping_ratio_from_decay_rate, kw=dict(decay_rate=40.0, angular_frequency=800.0)),
    case(damping.modal_damping_ratio, pos=(300.0, 2e8, 6e3, 9e3), kw=dict(structural_ratio=0.002)),
    case(friction.screw_efficiency, kw=dict(lead_angle=0.08, friction_coefficient=0.005)),
    case(friction.axial_force_torque, kw=dict(axial_force=500.0, lead=0.01, efficiency=0.9)),
    case(
        friction.motor_drag_torque,
        kw=dict(
            preload_torque=0.3,
            bearing_torque=0.1,
            guide_force=80.0,
            lead=0.01,
            efficiency=0.9,
            seal_torque=0.05,
        ),
    ),
    case(
        checks.critical_speed,
        kw=dict(root_diameter=0.02, span=1.0),
        fixed=dict(mounting="fixed-supported"),
    ),
    case(
        checks.critical_speed_hiwin,
        kw=dict(root_diameter=0.02, span=1.0),
        fixed=dict(mounting="fixed-free"),
    ),
    case(
        checks.buckling_load,
        kw=dict(root_diameter=0.02, length=1.0),
        fixed=dict(mounting="fixed-fixed"),
    ),
    case(checks.life_revolutions, kw=dict(dynamic_load_rating=30e3, load=3e3, load_factor=1.2)),
    case(
        checks.life_time, kw=dict(dynamic_load_rating=30e3, load=3e3, speed=200.0, load_factor=1.2)
    ),
    case(
        checks.guide_life_distance,
        kw=dict(dynamic_load_rating=30e3, load=3e3, load_factor=1.2, roller=0.0),
    ),
    case(
        checks.guide_life_distance,
        kw=dict(dynamic_load_rating=30e3, load=3e3, load_factor=1.2, roller=1.0),
    ),
    case(checks.dn_value, kw=dict(diameter=0.032, speed=300.0)),
    case(
        carriage.carriage_moments,
        kw=dict(
            feed_force=(-4e3, 2e3, 5e3),
            cross_force=1e3,
            normal_force=3e3,
            x=(-0.1, 0.0, 0.2),
            y=0.05,
            height=0.3,
        ),
    ),
    case(
        carriage.moment_share,
        kw=dict(count=(1.0, 2.0, 3.0), spacing=0.4, moment_factor=120.0, per_other=2.0),
    ),
    case(
        carriage.block_radial_load,
        kw=dict(
            normal_force=3e3,
            pitch_moment=(-900.0, 400.0, 800.0),
            roll_moment=200.0,
            n_blocks=4.0,
            c_pitch=2.0,
            c_roll=1.5,
            sx=(1.0, -1.0, 1.0),
            sy=(-1.0, 1.0, 1.0),
        ),
    ),
    case(
        carriage.block_lateral_load,
        kw=dict(
            cross_force=1e3,
            yaw_moment=(-300.0, 200.0, 500.0),
            n_blocks=4.0,
            c_yaw=2.0,
            sx=(1.0, -1.0, 1.0),
        ),
    ),
    case(
        carriage.equivalent_block_load,
        kw=dict(radial=(-2e3, 1e3, 3e3), lateral=(500.0, -400.0, 0.0)),
    ),
    case(
        carriage.corner_block_loads,
        kw=dict(
            normal_force=3e3,
            cross_force=(-1e3, 0.0, 2e3),
            pitch_moment=(-900.0, 400.0, 800.0),
            roll_moment=200.0,
            yaw_moment=-300.0,
            n_blocks=4.0,
            c_pitch=2.0,
            c_roll=1.5,
            c_yaw=2.0,
        ),
    ),
    case(
        carriage.max_block_load,
        kw=dict(
            normal_force=3e3,
            cross_force=(-1e3, 0.0, 2e3),
            pitch_moment=(-900.0, 400.0, 800.0),
            roll_moment=200.0,
            yaw_moment=-300.0,
            n_blocks=4.0,
            c_pitch=2.0,
            c_roll=1.5,
            c_yaw=2.0,
        ),
    ),
    case(carriage.static_safety, kw=dict(static_load_rating=50e3, load=8e3)),
    case(
        carriage.pattern_rocking_stiffness,
        kw=dict(
            block_stiffness=5e8,
            count=(1.0, 2.0, 3.0),
            spacing=0.4,
            per_other=2.0,
            moment_factor=150.0,
        ),
    ),
    case(carriage.rocking_frequency, kw=dict(rocking_stiffness=2e7, inertia=30.0)),
    case(carriage.box_inertia, kw=dict(mass=500.0, length=0.8, depth=0.3, offset=0.15)),
    case(gantry.side_force_share, kw=dict(force=6e3, y=(-0.9, 0.0, 0.4), span=2.2)),
    case(
        gantry.side_mass_share,
        kw=dict(bridge_mass=900.0, cross_mass=400.0, y=(-0.9, 0.0, 0.4), span=2.2),
    ),
    case(gantry.side_shares, kw=dict(cross_stroke=1.8, span=2.2)),
    case(gantry.yaw_stiffness, kw=dict(k1=2e8, k2=(1.5e8, 2e8, 2.5e8), span=2.2, k_guides=1e7)),
    case(gantry.bridge_yaw_inertia_estimate, kw=dict(bridge_mass=900.0, span=2.2)),
    case(
        gantry.gantry_matrices,
        kw=dict(
            bridge_mass=900.0,
            bridge_inertia=363.0,
            cross_mass=400.0,
            y=(-0.9, 0.0, 0.4),
            k1=2e8,
            k2=(1.5e8, 2e8, 2.5e8),
            span=2.2,
            k_guides=1e7,
        ),
    ),
    case(
        gantry.gantry_eigenvalues,
        kw=dict(
            bridge_mass=900.0,
            bridge_inertia=363.0,
            cross_mass=400.0,
            y=(-0.9, 0.0, 0.4),
            k1=2e8,
            k2=(1.5e8, 2e8, 2.5e8),
            span=2.2,
            k_guides=1e7,
        ),
    ),
    case(
        gantry.gantry_frequencies,
        kw=dict(
            bridge_mass=900.0,
            bridge_inertia=363.0,
            cross_mass=400.0,
            y=(-0.9, 0.0, 0.4),
            k1=2e8,
            k2=(1.5e8, 2e8, 2.5e8),
            span=2.2,
            k_guides=1e7,
        ),
    ),
]


def _values(v):
    return tuple(v) if isinstance(v, tuple) else tuple(v * s for s in SCALE)


def _flat(out):
    return list(out) if isinstance(out, tuple) else [out]


def _reference(func, pos, kw, fixed, i):
    args = [_values(v)[i] for v in pos]
    kwargs = {k: _values(v)[i] for k, v in kw.items()}
    return [float(o) for o in _flat(func(*args, **kwargs, **fixed))]


@pytest.mark.parametrize(("func", "pos", "kw", "fixed"), CASES)
def test_float_numpy_casadi_agree(func, pos, kw, fixed):
    refs = [_reference(func, pos, kw, fixed, i) for i in range(3)]
    assert all(np.isfinite(r).all() for r in refs)

    arr_out = _flat(
        func(
            *[np.array(_values(v)) for v in pos],
            **{k: np.array(_values(v)) for k, v in kw.items()},
            **fixed,
        )
    )
    for j, out in enumerate(arr_out):
        np.testing.assert_allclose(np.asarray(out, dtype=float), [r[j] for r in refs], rtol=1e-12)

    psyms = [ca.SX.sym(f"p{i}") for i in range(len(pos))]
    ksyms = {k: ca.SX.sym(k) for k in kw}
    sym_out = _flat(func(*psyms, **ksyms, **fixed))
    f = ca.Function("f", psyms + list(ksyms.values()), [ca.SX(o) for o in sym_out])
    for i in range(3):
        got = f(*[_values(v)[i] for v in pos], *[_values(v)[i] for v in kw.values()])
        got = [float(g) for g in (got if isinstance(got, tuple) else (got,))]
        np.testing.assert_allclose(got, refs[i], rtol=1e-9)


def test_every_public_function_is_covered():
    covered = {p.values[0].__name__ for p in CASES}
    public = {
        name
        for m in MODULES
        for name in m.__all__
        if callable(getattr(m, name))
        and not isinstance(getattr(m, name), type)
        and not name.isupper()
    }
    assert public - EXCLUDED - covered == set()
