"""Issue 12 on forces, efficiency and balancing: extreme but valid input is drawn, solved to 1e-9
or warned of in one line; a page that cannot hold a drawing refuses it in one line."""
from __future__ import annotations

import cmath
import json
import math
from fractions import Fraction

import pytest

from graphmech.exact import balancing as ex_bal
from tests.conftest import SCENES, assert_refused, check_json, run_cli, values


def write(tmp_path, text, name="r.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


# ---------------------------------------------------------------------------- balancing


def dynamic_rotor(planes_mm: str) -> str:
    """The reference rotor (bal.rotor_dynamic) with its correction planes moved."""
    text = (SCENES / "bal.rotor_dynamic.toml").read_text(encoding="utf-8")
    text = text.replace("planes_cm = [0, 90]", f"planes_mm = {planes_mm}")
    return text.replace("[scales]\nW_kgcm_per_mm = 10\n", "")


ONE_PLANE = """
title = "every mass in plane I"
show = ["rotor", "polygon"]
[balancing]
type = "dynamic"
planes_cm = [0, 90]
correction_radius_cm = 50
[[balancing.mass]]
m_kg = 10
r_cm = 40
angle_deg = 155
z_cm = 0
"""


def test_a_dynamic_balance_with_every_mass_in_one_plane_draws_the_other_as_a_point(tmp_path):
    p = write(tmp_path, ONE_PLANE)
    code, out, err = run_cli("render", str(p), "-o", str(tmp_path / "b.svg"))
    assert code == 0, err
    assert err.count("\n") == 1 and "plane II: every mass lies in the other correction plane" in err
    svg = (tmp_path / "b.svg").read_text(encoding="utf-8")
    assert "no mass acts in plane II: no correction mass needed" in svg
    q = values(check_json(p))
    assert q["W_I"]["graphical"] == pytest.approx(4.0, rel=1e-15)  # 10 kg · 0.4 m, all of it in plane I
    assert q["W_II"]["graphical"] == 0.0 and "theta_II" not in q


def float_corrections(text_path) -> tuple[complex, complex]:
    """W_I, W_II solved in rational arithmetic from the very floats the scene gives (no round-off)."""
    from graphmech.scene import load_scene

    p = load_scene(text_path).balancing
    zI, zII = Fraction(p.planes[0]), Fraction(p.planes[1])
    out = []
    for other, sign in ((zII, -1), (zI, 1)):
        re = im = Fraction(0)
        for u in p.masses:
            v = u.m * u.r * cmath.exp(1j * u.theta)  # the same float vector the code starts from
            lever = (other - Fraction(u.z)) if sign < 0 else (Fraction(u.z) - other)
            re += Fraction(v.real) * lever
            im += Fraction(v.imag) * lever
        out.append(complex(float(-re / (zII - zI)), float(-im / (zII - zI))))
    return out[0], out[1]


@pytest.mark.parametrize("planes", ["[0, 0.001]", "[900, 900.001]", "[450, 450.001]"])
def test_correction_planes_a_micrometre_apart_are_solved_to_1e9(planes, tmp_path):
    p = write(tmp_path, dynamic_rotor(planes))
    doc = check_json(p)
    q = values(doc)
    WI, WII = float_corrections(p)
    assert q["W_I"]["graphical"] == pytest.approx(abs(WI), rel=1e-12)
    assert q["W_II"]["graphical"] == pytest.approx(abs(WII), rel=1e-12)
    # about 10⁵ × the unbalance, opposite: the residuals are still round-off, well below 1e-9
    # (about z = 0 with planes 900 mm out they were 1e-4 of the moments)
    assert q["residual_force"]["rel_error"] < 1e-9 and q["residual_moment"]["rel_error"] < 1e-9
    assert not doc["warnings"] and not any(r["ill_conditioned"] for r in doc["quantities"])


def test_planes_too_close_for_their_distance_from_z0_are_warned_of_and_flagged(tmp_path):
    p = write(tmp_path, dynamic_rotor("[9000, 9000.001]"))
    doc = check_json(p)
    (w,) = doc["warnings"]
    assert "0.001 mm apart" in w and "z/Δ = 9e+06" in w and "ill-conditioned" in w
    assert all(r["ill_conditioned"] for r in doc["quantities"])
    q = values(doc)
    WI, _ = float_corrections(p)
    assert q["W_I"]["graphical"] == pytest.approx(abs(WI), rel=1e-12)  # still right for the floats given


def test_the_exact_split_takes_its_moments_about_the_planes():
    # a mass in plane I, 9 m out: all of it goes to plane I, none to plane II (about z = 0 the
    # exact solution itself lost 2e-10 to cancellation)
    u = [ex_bal.Unbalance(1.0, 0.1, 0.0, 9.0)]
    WI, WII = ex_bal.dynamic_correction(u, 9.0, 9.000001)
    assert WI == -0.1 and WII == 0.0
