"""Friction where the seeds put it (issue 22, item 6): the wedge clamp with two declared faces
(000 效率 2), the wedge buffer's two self-locking limits (000 效率 3), a wrench's torque through
the thread and the collar (001 10-3), a screw lift's drive power (001 10-4).

Each scene's rows come from the drawn polygons (graphical) and the closed forms of
graphmech.exact.efficiency (exact); here both are set against the textbook formulas written out
by hand, and against the seeds' printed answers.
"""
from __future__ import annotations

import math

import pytest

from tests.conftest import SCENES, assert_refused, check_json, run_cli, values

PHI_15 = math.atan(0.15)  # 8.5308°
PHI_10 = math.atan(0.1)  # 5.7106°


def both(q: dict, name: str) -> tuple[float, float]:
    return q[name]["graphical"], q[name]["exact"]


# ---------------------------------------------------------------------------- 000 效率 2: the clamp


def test_wedge_clamp_two_faces_matches_the_book():
    q = values(check_json(SCENES / "eff.wedge_clamp_two_faces.toml"))
    a, Q = math.radians(12), 1000.0
    # the book: R23 = P·cos φ/sin(α − 2φ) with P the force along face 1 → P = Q·sin(α − 2φ)/cos φ
    # (reverse, holding); forward P = Q·sin(α + 2φ)/cos φ; P0 = Q·sin α
    assert both(q, "F@reverse") == pytest.approx((Q * math.sin(a - 2 * PHI_15) / math.cos(PHI_15),) * 2, rel=1e-12)
    assert q["F@reverse"]["graphical"] == pytest.approx(-89.2125442, rel=1e-8)  # negative: it holds by itself
    assert both(q, "F@forward") == pytest.approx((Q * math.sin(a + 2 * PHI_15) / math.cos(PHI_15),) * 2, rel=1e-12)
    assert both(q, "F0") == pytest.approx((Q * math.sin(a),) * 2, rel=1e-12)
    # η′ = sin(α − 2φ)/(sin α·cos φ), the book's reverse efficiency; ≤ 0: self-locking
    eta_r = math.sin(a - 2 * PHI_15) / (math.sin(a) * math.cos(PHI_15))
    assert both(q, "eta@reverse") == pytest.approx((eta_r, eta_r), rel=1e-12) and eta_r < 0
    assert q["eta@forward"]["graphical"] == pytest.approx(math.sin(a) * math.cos(PHI_15) / math.sin(a + 2 * PHI_15),
                                                          rel=1e-12)
    # R1's normal part balances R2's: R1·cos φ1 = Q·cos(α ± φ2)
    assert q["R_face1@forward"]["graphical"] == pytest.approx(Q * math.cos(a + PHI_15) / math.cos(PHI_15), rel=1e-12)
    # the book's condition α − 2φ ≤ 0, found by redrawing
    assert both(q, "alpha_lock_reverse") == pytest.approx((math.degrees(2 * PHI_15),) * 2, rel=1e-12)
    assert q["alpha_lock_reverse"]["graphical"] == pytest.approx(17.0615312, rel=1e-8)
    assert q["phi_face1"]["graphical"] == q["phi_face2"]["graphical"] == pytest.approx(math.degrees(PHI_15))


def test_a_frictionless_face_turns_no_reaction():
    q = values(check_json(SCENES / "eff.wedge_clamp_two_faces-one_frictionless.toml"))
    a, Q = math.radians(12), 1000.0
    assert q["phi_face2"]["graphical"] == 0.0
    # only φ1: F = Q·sin(α ∓ φ1)/cos φ1, and the limit α ≤ φ1 — the 12° wedge no longer holds
    assert both(q, "F@reverse") == pytest.approx((Q * math.sin(a - PHI_15) / math.cos(PHI_15),) * 2, rel=1e-12)
    assert q["F@reverse"]["graphical"] > 0
    assert both(q, "F@forward") == pytest.approx((Q * math.sin(a + PHI_15) / math.cos(PHI_15),) * 2, rel=1e-12)
    assert both(q, "alpha_lock_reverse") == pytest.approx((math.degrees(PHI_15),) * 2, rel=1e-12)
    # face 2 frictionless: R2 = Q on its normal, so R1's normal part is Q·cos α both ways
    assert q["R_face1@forward"]["graphical"] == pytest.approx(q["R_face1@reverse"]["graphical"], rel=1e-12)
    assert q["R_face1@forward"]["graphical"] == pytest.approx(Q * math.cos(a) / math.cos(PHI_15), rel=1e-12)


def test_faces_of_different_friction_add_their_angles(tmp_path):
    p = tmp_path / "c.toml"
    p.write_text('find = ["F", "alpha_lock_reverse"]\n[efficiency]\ntype = "wedge_clamp"\n'
                 'wedge_angle_deg = 20\nload_N = 1000\n[[efficiency.face]]\nf = 0.1\n[[efficiency.face]]\nf = 0.15\n',
                 encoding="utf-8")
    q = values(check_json(p))
    a = math.radians(20)
    # face 1's φ divides (F ∥ face 1 makes 90° ± φ1 with R1); both φ turn the triangle
    assert q["F@forward"]["graphical"] == pytest.approx(1000 * math.sin(a + PHI_10 + PHI_15) / math.cos(PHI_10),
                                                        rel=1e-12)
    assert q["F@reverse"]["graphical"] == pytest.approx(1000 * math.sin(a - PHI_10 - PHI_15) / math.cos(PHI_10),
                                                        rel=1e-12)
    assert q["alpha_lock_reverse"]["graphical"] == pytest.approx(math.degrees(PHI_10 + PHI_15), rel=1e-12)


# ---------------------------------------------------------------------------- 000 效率 3: the buffer


def test_buffer_reports_both_self_locking_limits():
    q = values(check_json(SCENES / "eff.self_locking_limits.toml"))
    a, Q = math.radians(40), 1000.0
    # the book: P = Q·cot(α − φ), P0 = Q·cot α, η = tan(α − φ)/tan α; reverse P′ = Q·cot(α + φ),
    # η′ = tan α/tan(α + φ)
    assert both(q, "F@forward") == pytest.approx((Q / math.tan(a - PHI_15),) * 2, rel=1e-12)
    assert both(q, "F@reverse") == pytest.approx((Q / math.tan(a + PHI_15),) * 2, rel=1e-12)
    assert both(q, "F0") == pytest.approx((Q / math.tan(a),) * 2, rel=1e-12)
    assert q["eta@forward"]["graphical"] == pytest.approx(math.tan(a - PHI_15) / math.tan(a), rel=1e-12)
    assert q["eta@reverse"]["graphical"] == pytest.approx(math.tan(a) / math.tan(a + PHI_15), rel=1e-12)
    assert q["R12@forward"]["graphical"] == pytest.approx(Q / math.sin(a - PHI_15), rel=1e-12)
    # forward locks for α ≤ φ, reverse for α ≥ 90° − φ: works both ways for 8.53° < α < 81.47°
    assert q["alpha_lock_forward"]["graphical"] == pytest.approx(math.degrees(PHI_15), rel=1e-9)
    assert q["alpha_lock_reverse"]["graphical"] == pytest.approx(90 - math.degrees(PHI_15), rel=1e-12)
    # as coefficients for α = 40°: forward f ≥ tan 40° = 0.8391, reverse f ≥ cot 40° = 1.1918
    assert q["f_lock_forward"]["graphical"] == pytest.approx(0.839099631, rel=1e-9)
    assert q["f_lock_reverse"]["graphical"] == pytest.approx(1.191753593, rel=1e-9)
    for name in ("alpha_lock_forward", "alpha_lock_reverse", "f_lock_forward", "f_lock_reverse"):
        assert q[name]["rel_error"] <= 1e-9, name


def test_buffer_locks_forward_below_its_friction_angle(tmp_path):
    p = tmp_path / "b.toml"
    p.write_text('find = ["eta"]\n[efficiency]\ntype = "buffer"\nwedge_angle_deg = 8\nf = 0.15\nload_N = 100\n',
                 encoding="utf-8")
    q = values(check_json(p))
    # α = 8° < φ = 8.53°: tan(α − φ) < 0, the forward stroke cannot move
    assert q["eta@forward"]["graphical"] == pytest.approx(math.tan(math.radians(8) - PHI_15) / math.tan(
        math.radians(8)), rel=1e-12)
    assert q["eta@forward"]["graphical"] < 0


# ---------------------------------------------------------------------------- 001 10-3: wrench and collar


D2, P, D1 = 7.188e-3, 1.25e-3, 6.647e-3
PSI = math.atan(P / (math.pi * D2))  # 3.1683°


def test_wrench_gives_the_books_bolt_force_with_the_mean_radius():
    q = values(check_json(SCENES / "thread.collar_friction_wrench.toml"))
    r_m = (9e-3 + 11.5e-3) / 4  # 5.125 mm, the book's r_f
    Fa = 30.0 / (D2 / 2 * math.tan(PSI + PHI_10) + 0.12 * r_m)
    assert both(q, "r_c") == pytest.approx((r_m, r_m), rel=1e-15)
    assert both(q, "F_a") == pytest.approx((Fa, Fa), rel=1e-12)
    assert q["F_a"]["graphical"] == pytest.approx(25500, abs=0.5)  # the seed prints 25 500 N
    assert q["sigma_a"]["graphical"] == pytest.approx(4 * Fa / (math.pi * D1 ** 2), rel=1e-12)
    assert q["sigma_a"]["graphical"] / 1e6 == pytest.approx(734.85, abs=0.02)  # > σs = 315 MPa: it fails
    # the torque splits into the thread's and the collar's: T = M + M_c
    assert q["M_c"]["graphical"] == pytest.approx(0.12 * Fa * r_m, rel=1e-12)
    assert q["T_tighten"]["graphical"] == pytest.approx(30.0, rel=1e-12)


def test_annulus_radius_is_the_exact_one_and_lowers_the_force():
    q = values(check_json(SCENES / "thread.collar_friction_wrench-annulus.toml"))
    R, r = 11.5e-3 / 2, 9e-3 / 2
    r_a = 2 / 3 * (R ** 3 - r ** 3) / (R ** 2 - r ** 2)  # 5.1504 mm > 5.125 mm
    assert both(q, "r_c") == pytest.approx((r_a, r_a), rel=1e-14)
    assert r_a * 1e3 == pytest.approx(5.150406504, rel=1e-9)
    Fa = 30.0 / (D2 / 2 * math.tan(PSI + PHI_10) + 0.12 * r_a)
    assert both(q, "F_a") == pytest.approx((Fa, Fa), rel=1e-12)
    assert q["F_a"]["graphical"] == pytest.approx(25434.4988, rel=1e-9)


def test_a_given_load_asks_the_torque_that_tightens_it(tmp_path):
    p = tmp_path / "t.toml"
    p.write_text('find = ["T_tighten", "M_c", "r_c"]\n[efficiency]\ntype = "screw"\nf_v = 0.1\nd2_mm = 7.188\n'
                 'pitch_mm = 1.25\ncollar_mm = [9, 11.5]\nf_c = 0.12\nload_N = 25500\n', encoding="utf-8")
    q = values(check_json(p))
    T = 25500 * (D2 / 2 * math.tan(PSI + PHI_10) + 0.12 * 5.125e-3)
    assert both(q, "T_tighten") == pytest.approx((T, T), rel=1e-12)
    assert T == pytest.approx(30.0, rel=2e-5)  # the book's wrench, back again
    assert q["M_c"]["graphical"] == pytest.approx(0.12 * 25500 * 5.125e-3, rel=1e-12)


# ---------------------------------------------------------------------------- 001 10-4: the drive


def test_screw_drive_power_from_its_lift_speed():
    q = values(check_json(SCENES / "thread.screw_drive_power.toml"))
    Q, d2, L, v = 1e5, 65e-3, 40e-3, 0.8 / 60
    psi = math.atan(L / (math.pi * d2))  # 11.083°
    eta = math.tan(psi) / math.tan(psi + PHI_10)
    assert q["psi"]["graphical"] == pytest.approx(11.083, abs=5e-4)
    assert both(q, "eta@forward") == pytest.approx((eta, eta), rel=1e-12)
    assert eta == pytest.approx(0.648, abs=1.1e-3)  # the book prints 0.648
    T = Q * d2 / 2 * math.tan(psi + PHI_10)
    assert q["M@forward"]["graphical"] == pytest.approx(T, rel=1e-12)
    assert q["n_screw"]["graphical"] == pytest.approx(20.0, rel=1e-12)  # v/L = 800/40 r/min
    # P = Q·v/η, and the same as T·ω with ω = 2π·n/60 (the book: 2054.30 W)
    assert both(q, "P_drive") == pytest.approx((Q * v / eta,) * 2, rel=1e-12)
    assert q["P_drive"]["graphical"] == pytest.approx(T * 2 * math.pi * 20 / 60, rel=1e-12)
    assert q["P_drive"]["graphical"] == pytest.approx(2054.3, abs=0.1)
    # lowering: T′ = Q·d2/2·tan(ψ − φv) > 0, a braking torque is needed
    assert q["M@reverse"]["graphical"] == pytest.approx(Q * d2 / 2 * math.tan(psi - PHI_10), rel=1e-12)


# ---------------------------------------------------------------------------- refused in one line


CLAMP = 'find = ["F"]\n[efficiency]\ntype = "wedge_clamp"\nwedge_angle_deg = 12\nload_N = 1000\n'


@pytest.mark.parametrize("text, words", [
    (CLAMP + '[[efficiency.face]]\nf = 0.1\n', ("efficiency.face: 1 [[efficiency.face]] tables",)),
    (CLAMP + 'f = 0.1\n[[efficiency.face]]\nf = 0.1\n[[efficiency.face]]\nf = 0\n',
     ("efficiency.f: a wedge clamp's faces each declare their own f",)),
    (CLAMP + '[[efficiency.face]]\nf = -0.1\n[[efficiency.face]]\nf = 0\n',
     ("efficiency.face[0].f: must lie in [0, 10)",)),
    (CLAMP + '[[efficiency.face]]\nname = "a"\n[[efficiency.face]]\nf = 0\n', ("efficiency.face[0].f", "missing")),
    (CLAMP.replace("12", "95") + '[[efficiency.face]]\nf = 0.1\n[[efficiency.face]]\nf = 0\n',
     ("efficiency.wedge_angle_deg: must lie between 0° and 90°",)),
    ('show = ["diagram"]\nfind = ["F_a"]\n[efficiency]\ntype = "screw"\nf_v = 0.1\nd2_mm = 7.188\npitch_mm = 1.25\n'
     'collar_mm = [9, 11.5]\nf_c = 0.12\n', ("find[0]: F_a needs torque_Nm (the wrench's torque) in [efficiency]",)),
    ('find = ["r_c"]\n[efficiency]\ntype = "screw"\nd2_mm = 7\npitch_mm = 1\ncollar_mm = [9, 11.5]\n'
     'collar_radius = "exact"\n', ("efficiency.collar_radius", "unknown value")),
    ('find = ["P_drive"]\n[efficiency]\ntype = "screw"\nf_v = 0.1\nd2_mm = 65\npitch_mm = 10\nload_kN = 100\n',
     ("find[0]: P_drive needs speed_m_s (the load's lift speed) in [efficiency]",)),
    ('show = ["diagram"]\nfind = ["n_screw"]\n[efficiency]\ntype = "screw"\nlead_angle_deg = 5\nspeed_m_s = 0.01\n',
     ("find[0]: n_screw needs pitch_mm (the lead L = n·P) in [efficiency]",)),
    ('find = ["F"]\n[efficiency]\ntype = "incline"\nangle_deg = 30\nf = 0.1\nload_N = 1\nwedge_angle_deg = 3\n',
     ("efficiency.wedge_angle_deg: not a key of type 'incline' (it belongs to 'wedge_clamp')",)),
    ('find = ["F_a"]\n[efficiency]\ntype = "screw"\nf_v = 0.1\nd2_mm = 7.188\npitch_mm = 1.25\n'
     'collar_mm = [9, 11.5]\nf_c = 0.12\ntorque_Nm = -3\n', ("efficiency.torque_Nm",)),
])
def test_bad_input_is_refused_in_one_line(tmp_path, text, words):
    p = tmp_path / "s.toml"
    p.write_text(text, encoding="utf-8")
    err = assert_refused(run_cli("check", str(p)), "s.toml", *words)
    assert err.count("efficiency.wedge_angle_deg") <= 1  # a key of two other types is said once
