"""The exact (vector-loop) linkage solution: reference problems, finite differences, failures."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from graphmech.errors import SceneError
from graphmech.exact import Kinematics, solve
from graphmech.mechanisms.linkage import (
    PRP,
    RPP,
    RPR,
    RRP,
    RRR,
    Crank,
    Guide,
    Linkage,
    LinkGuide,
    LinkPoint,
    SliderInput,
)

from tests.conftest import reference_problem as problem


def speed(v: np.ndarray) -> float:
    return float(np.hypot(*v[0]))


# --------------------------------------------------------------------------------------------
# Linkages used below

FOUR_FRAME = {"A": (0.0, 0.0), "D": (0.12, 0.0)}
FOUR_DRIVER = Crank("1", "A", "B", 0.06, 10.0, 3.0)
FOUR_DYAD = RRR("B", "C", "D", ("2", "3"), (0.12, 0.09), "left")
FOURBAR = Linkage(FOUR_FRAME, FOUR_DRIVER, (FOUR_DYAD,),
                  (LinkPoint("S3", "3", ("D", "C"), 0.04, -0.01),))
COUPLER_E = LinkPoint("E", "2", ("B", "C"), 0.06, 0.03)

SIXBAR_RRR = Linkage(
    {**FOUR_FRAME, "G": (0.2, 0.2)}, FOUR_DRIVER,
    (FOUR_DYAD, RRR("E", "F", "G", ("5", "6"), (0.15, 0.15), "right")),
    (LinkPoint("H", "5", ("E", "F"), 0.1, 0.02), COUPLER_E),  # H waits for the dyad E-F-G
)
SIXBAR_RRP = Linkage(
    FOUR_FRAME, FOUR_DRIVER,
    (FOUR_DYAD, RRP("E", "F", ("5", "6"), 0.3, Guide((0.0, 0.25), math.radians(10.0)))),
    (COUPLER_E, LinkPoint("K", "6", ("F",), 0.02, -0.03)),  # x/y offsets on the slider
)
# Slider-driven slider-crank: C driven along the x axis, crank AB (0.1) and coupler CB (0.3).
SLIDER_DRIVEN = Linkage(
    {"A": (0.0, 0.0)}, SliderInput("3", "C", Guide((0.0, 0.0), 0.0), -1.5, 4.0),
    (RRR("C", "B", "A", ("2", "1"), (0.3, 0.1), "left"),),
)
# Guide bar: crank AB, block 2 pivoted at B slides on bar 3 pivoted at the frame point C.
GUIDE_BAR = Linkage(
    {"A": (0.0, 0.0), "C": (0.0, -0.1)}, Crank("1", "A", "B", 0.05, 10.0, -4.0),
    (RPR("B", "C", ("2", "3"), bar="second"),),
    (LinkPoint("F", "3", ("C", "B3"), 0.2, 0.01),),
)
RPP_LINKAGE = Linkage(
    {"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.04, 100.0, 50.0),
    (RPP("B", "C", ("2", "3"), math.radians(120.0), Guide((0.0, -0.02), math.radians(5.0))),),
    (LinkPoint("M", "3", ("C",), 0.03, 0.01),),
)

# The tangent mechanism (PRP): bar 1 turns about A, block 2 slides on it, pinned at C to the
# slider 3 on the vertical frame guide x = 0.1 m: s = h·tan φ.
TANGENT = Linkage(
    {"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.15, 10.0, 3.0),
    (PRP("C", ("2", "3"), (LinkGuide("1", "A", "B"), Guide((0.1, 0.0), math.pi / 2))),),
    (LinkPoint("K", "3", ("C",), 0.0, -0.05),),
)
# A PRP on two moving guides: block 5 on the crank's line AB, block 6 on the rocker's line DC.
PRP_MOVING = Linkage(
    FOUR_FRAME, FOUR_DRIVER, (FOUR_DYAD, PRP("E", ("5", "6"), (LinkGuide("1", "A", "B"), LinkGuide("3", "D", "C")))),
)

# A slotted link drives a pin (RRP on a moving guide): the crank 1 is a slotted bar along A→B, the
# crank 2 about D (|AD| < l_DC: it turns all round) carries the pin C, which rides in block 3 in the slot.
SLOTTED = Linkage(
    {"A": (0.0, 0.0), "D": (0.02, 0.01)}, Crank("1", "A", "B", 0.15, 10.0, 20.0),
    (RRP("D", "C", ("2", "3"), 0.05, LinkGuide("1", "A", "B"), "forward"),),
)


# --------------------------------------------------------------------------------------------
# 1–3. Reference problems


def test_offset_slider_crank_matches_reference() -> None:
    p = problem("linkage.slider_crank_offset")
    inp, ex = p["inputs"], p["exact"]
    mm = 1e-3
    sc = Linkage(
        {"A": (0.0, 0.0)}, Crank("1", "A", "B", inp["lAB_mm"] * mm, inp["omega1_rad_s"]),
        (RRP("B", "C", ("2", "3"), inp["lBC_mm"] * mm, Guide((0.0, inp["e_mm"] * mm), 0.0),
             branch="forward"),),
    )
    kin = solve(sc, np.radians(inp["theta1_deg"]))
    assert kin.valid.tolist() == [True, True]
    rel = 1e-9
    assert np.degrees(kin.angle["2"]) == pytest.approx(ex["theta2_deg"], rel=rel)
    assert kin.omega["2"] == pytest.approx(ex["omega2_rad_s"], rel=rel)
    assert kin.alpha["2"] == pytest.approx(ex["alpha2_rad_s2"], rel=rel)
    assert kin.vel["C"][:, 0] == pytest.approx(ex["v3_m_s"], rel=rel)
    assert kin.acc["C"][:, 0] == pytest.approx(ex["a3_m_s2"], rel=rel)
    assert np.all(kin.vel["C"][:, 1] == 0.0) and np.all(kin.point["C"][:, 1] == 0.03)
    assert kin.omega["3"].tolist() == [0.0, 0.0] and kin.angle["3"].tolist() == [0.0, 0.0]


def oscillating_block(left: float) -> Linkage:
    # angle BAC = 135°: C on the -x axis, the crank at 45° from +x (the extension of CA)
    return Linkage(
        {"A": (0.0, 0.0), "C": (-0.1, 0.0)}, Crank("1", "A", "B", 0.03, 10.0),
        (RPR("B", "C", ("2", "3"), bar="first"),),
        (LinkPoint("D", "2", ("B", "C2"), 0.05, 0.0), LinkPoint("E", "2", ("B", "C2"), 0.05, left)),
    )


# The rates of kin.oscillating_block recomputed by 40-digit numerical differentiation of the
# positions (mpmath), a route independent of both the solver and the bank (whose rates were
# corrected to these on 2026-11-26; they used to be 0.7–2e-7 off).
OSC_40_DIGITS = {
    "omega2": 1.995240068087763688, "alpha2": 8.418687998719072799,
    "vD": 0.2257527358346506934, "aD": 2.605398135765218351,
    "vE": 0.1726775466718565284, "aE": 2.833979214216825844,
}


def test_oscillating_block_matches_reference() -> None:
    ex = problem("kin.oscillating_block")["exact"]
    kin = solve(oscillating_block(+0.04), [math.radians(45.0)])  # E to the left of B→C
    other = solve(oscillating_block(-0.04), [math.radians(45.0)])
    assert kin.valid[0] and kin.reason == ("",)
    lbc = float(np.hypot(*(kin.point["C"][0] - kin.point["B"][0])))
    got = {
        "omega2": abs(kin.omega["2"][0]), "alpha2": abs(kin.alpha["2"][0]),
        "vD": speed(kin.vel["D"]), "aD": speed(kin.acc["D"]),
        "vE": speed(kin.vel["E"]), "aE": speed(kin.acc["E"]),
    }
    assert lbc == pytest.approx(ex["lBC_m"], rel=1e-9)
    for key, value in OSC_40_DIGITS.items():
        assert got[key] == pytest.approx(value, rel=1e-9), key
    toml_key = {"omega2": "omega2_rad_s", "alpha2": "alpha2_rad_s2", "vD": "vD_m_s",
                "aD": "aD_m_s2", "vE": "vE_m_s", "aE": "aE_m_s2"}
    for key, name in toml_key.items():
        assert got[key] == pytest.approx(ex[name], rel=1e-9), key
    assert speed(other.vel["E"]) == pytest.approx(ex["vE_other_side_m_s"], rel=1e-9)
    assert speed(other.acc["E"]) == pytest.approx(ex["aE_other_side_m_s2"], rel=1e-9)
    # the link turns CW, decelerating; block 3 turns with the bar; C3 is the frame pivot C
    assert kin.omega["2"][0] > 0 > kin.alpha["2"][0]
    assert kin.omega["3"][0] == kin.omega["2"][0] and kin.angle["3"][0] == kin.angle["2"][0]
    assert np.all(kin.vel["C3"] == 0.0) and np.all(kin.point["C2"] == kin.point["C"])
    # C2, the bar's point at C, slides along BC: v_C2 ∥ BC
    bc = kin.point["C"][0] - kin.point["B"][0]
    v_c2 = kin.vel["C2"][0]
    assert abs(bc[0] * v_c2[1] - bc[1] * v_c2[0]) <= 1e-12 * np.hypot(*bc) * np.hypot(*v_c2)


def test_slider_fixed_angle_guide_matches_reference() -> None:
    p = problem("linkage.slider_fixed_angle_guide")
    inp, ex = p["inputs"], p["exact"]
    linkage = Linkage(
        {"A": (0.0, 0.0)},
        Crank("1", "A", "B", inp["lAB_mm"] * 1e-3, inp["omega1_rad_s"]),
        (RPP("B", "C", ("2", "3"), math.radians(120.0), Guide((0.0, 0.0), 0.0)),),
    )
    kin = solve(linkage, [math.radians(inp["phi1_deg"])])
    assert kin.vel["C"][0, 0] == pytest.approx(-1.195433962877246, rel=1e-9)
    assert kin.vel["C"][0, 0] == pytest.approx(ex["vC_mm_s"] * 1e-3, rel=1e-9)
    assert kin.vel["C"][0, 1] == 0.0
    assert kin.omega["2"][0] == ex["omega2_rad_s"] == 0.0 and kin.alpha["2"][0] == 0.0
    assert np.degrees(kin.angle["2"][0]) == pytest.approx(120.0, rel=1e-12)
    assert kin.angle["3"][0] == 0.0
    # B2 moves with the crank pin, B3 with the slotted link, and B2 − B3 slides along the slot
    np.testing.assert_array_equal(kin.vel["B2"], kin.vel["B"])
    np.testing.assert_array_equal(kin.vel["B3"], kin.vel["C"])
    rel_v = kin.vel["B2"][0] - kin.vel["B3"][0]
    assert math.atan2(rel_v[1], rel_v[0]) == pytest.approx(math.radians(120.0), rel=1e-12)


# --------------------------------------------------------------------------------------------
# 4. Finite differences in time reproduce vel and acc

H = 1e-4  # s; with a five-point stencil the error is ~1e-12 (v) and ~1e-8 (a), relative


def driver_rates(linkage: Linkage) -> tuple[float, float]:
    d = linkage.driver
    return (d.omega, d.epsilon) if isinstance(d, Crank) else (d.velocity, d.acceleration)


def material(linkage: Linkage, kin: Kinematics, q0: np.ndarray) -> dict[str, np.ndarray]:
    """Positions (5, N, 2) at t = -2H..2H of the material points named in ``kin``."""
    rate, accel = driver_rates(linkage)
    t = np.arange(-2, 3)[:, None] * H
    q = (q0[None, :] + rate * t + 0.5 * accel * t * t).ravel()
    k = solve(linkage, q)
    assert k.valid.all()
    n = q0.size
    out = {name: z.reshape(5, n, 2) for name, z in k.point.items()}
    out["__angles"] = {lid: a.reshape(5, n) for lid, a in k.angle.items()}
    for y in linkage.dyads:  # coincident points that are not the named point's path
        if isinstance(y, RPR):  # the bar's material point at X: fixed distance r0 from the pivot
            on_bar = y.coincident[0]
            pivot = out[y.bar_pivot]
            r0 = np.hypot(*(kin.point[y.block_pivot] - kin.point[y.bar_pivot]).T)
            th = out["__angles"][y.bar_link]
            out[on_bar] = pivot + r0[None, :, None] * np.stack((np.cos(th), np.sin(th)), -1)
        elif isinstance(y, RPP):  # the slotted link translates with C
            out[y.coincident[1]] = kin.point[y.p][None] + out[y.c] - kin.point[y.c][None]
        elif isinstance(y, (PRP, RRP)):  # a guide link's material point at C turns with that link
            for m, g in enumerate(y.guides if isinstance(y, PRP) else (y.guide,)):
                if not isinstance(g, LinkGuide):
                    continue
                on = y.c + g.link
                d0 = kin.point[y.c] - kin.point[g.through]
                turn = out["__angles"][g.link] - out["__angles"][g.link][2]
                c, s = np.cos(turn)[..., None], np.sin(turn)[..., None]
                out[on] = out[g.through] + np.concatenate((c * d0[None, :, :1] - s * d0[None, :, 1:],
                                                           s * d0[None, :, :1] + c * d0[None, :, 1:]), -1)
    return out


def d1(x: np.ndarray) -> np.ndarray:
    return (x[0] - 8 * x[1] + 8 * x[3] - x[4]) / (12 * H)


def d2(x: np.ndarray) -> np.ndarray:
    return (-x[0] + 16 * x[1] - 30 * x[2] + 16 * x[3] - x[4]) / (12 * H * H)


def assert_close(got: np.ndarray, want: np.ndarray, what: str, floor: float) -> None:
    """Agreement to 1e-6 of the largest |want| (at least ``floor``: a frame point's 0 is fine)."""
    scale = max(float(np.max(np.abs(want))), floor)
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-6 * scale, err_msg=what)


FD_CASES = {
    "four-bar": (FOURBAR, np.radians(np.arange(0.0, 360.0, 5.0))),
    "six-bar RRR": (SIXBAR_RRR, np.radians(np.arange(0.0, 360.0, 5.0))),
    "six-bar RRP": (SIXBAR_RRP, np.radians(np.arange(0.0, 360.0, 5.0))),
    "slider-driven slider-crank": (SLIDER_DRIVEN, np.linspace(0.22, 0.38, 33)),
    "guide bar (bar second)": (GUIDE_BAR, np.radians(np.arange(0.0, 360.0, 5.0))),
    "RPP": (RPP_LINKAGE, np.radians(np.arange(0.0, 360.0, 5.0))),
    "PRP tangent": (TANGENT, np.radians([a for a in np.arange(0.0, 360.0, 5.0) if a % 180.0 != 90.0])),
    # away from the guides' parallel positions (near 97° and 310° E runs off to metres)
    "RRP on a slotted crank": (SLOTTED, np.radians(np.arange(0.0, 360.0, 5.0))),
    "PRP on two moving guides": (PRP_MOVING, np.radians(np.r_[0.0:80.0:5.0, 115.0:300.0:5.0, 320.0:360.0:5.0])),
}


@pytest.mark.parametrize("case", list(FD_CASES))
def test_rates_match_finite_differences(case: str) -> None:
    linkage, q0 = FD_CASES[case]
    kin = solve(linkage, q0)
    assert kin.valid.all() and set(kin.reason) == {""}
    path = material(linkage, kin, q0)
    angles = path.pop("__angles")
    assert set(path) == set(kin.point)
    v_floor = 1e-3 * max(float(np.max(np.abs(v))) for v in kin.vel.values())
    a_floor = 1e-3 * max(float(np.max(np.abs(a))) for a in kin.acc.values())
    for name, z in path.items():
        np.testing.assert_allclose(z[2], kin.point[name], rtol=0, atol=1e-15, err_msg=name)
        assert_close(kin.vel[name], d1(z), f"v_{name}", v_floor)
        assert_close(kin.acc[name], d2(z), f"a_{name}", a_floor)
    assert set(angles) == {k for k in linkage.links() if k != linkage.frame_link}
    for lid, th in angles.items():
        th = np.unwrap(th, axis=0)
        assert np.all((kin.angle[lid] >= 0) & (kin.angle[lid] < 2 * np.pi))
        scale = max(float(np.max(np.abs(kin.omega[lid]))), 1.0)
        np.testing.assert_allclose(kin.omega[lid], d1(th), rtol=0, atol=1e-6 * scale)
        scale = max(float(np.max(np.abs(kin.alpha[lid]))), 1.0)
        np.testing.assert_allclose(kin.alpha[lid], d2(th), rtol=0, atol=1e-6 * scale)


def test_tangent_mechanism_in_closed_form() -> None:
    # s = h·tan φ; v = h·ω/cos²φ; a = h·(ε + 2ω²·tan φ)/cos²φ, h = 0.1 m (seed 001 1-14)
    phi = np.radians([-60.0, 10.0, 30.0, 75.0, 200.0])
    kin = solve(TANGENT, phi)
    h, w, e = 0.1, 10.0, 3.0
    np.testing.assert_allclose(kin.point["C"][:, 1], h * np.tan(phi), rtol=1e-12)
    np.testing.assert_allclose(kin.vel["C"][:, 1], h * w / np.cos(phi) ** 2, rtol=1e-12)
    np.testing.assert_allclose(kin.acc["C"][:, 1], h * (e + 2 * w * w * np.tan(phi)) / np.cos(phi) ** 2, rtol=1e-12)
    np.testing.assert_allclose(kin.vel["C"][:, 0], 0.0, atol=1e-14)
    # the block turns with the bar, the slider translates; C1 is the bar's point at C
    np.testing.assert_array_equal(kin.omega["2"], 10.0)
    np.testing.assert_array_equal(kin.omega["3"], 0.0)
    r = np.hypot(*kin.point["C"].T)
    np.testing.assert_allclose(np.hypot(*kin.vel["C1"].T), w * r, rtol=1e-12)
    # the sliding velocity runs along the bar: v_C2C1 × e_bar = 0
    rel = kin.vel["C2"] - kin.vel["C1"]
    np.testing.assert_allclose(rel[:, 0] * np.sin(phi) - rel[:, 1] * np.cos(phi), 0.0, atol=1e-13)


def test_prp_with_parallel_guides_is_not_assembled() -> None:
    kin = solve(TANGENT, np.radians([90.0, 45.0, 270.0]))
    assert kin.valid.tolist() == [False, True, False]
    assert "parallel" in kin.reason[0] and kin.reason[1] == ""
    assert float(kin.point["C"][0, 1]) == 0.0  # not assembled: 0, never inf


def test_prp_structure_errors() -> None:
    both_fixed = dataclasses.replace(TANGENT, dyads=(PRP("C", ("2", "3"), (Guide((0.0, 0.0), 0.0), Guide((0.1, 0.0), 1.0))),),
                                     points=())
    with pytest.raises(SceneError, match="both guides on the frame"):
        solve(both_fixed, np.array([0.3]))
    wrong_link = dataclasses.replace(TANGENT, dyads=(PRP("C", ("2", "3"), (LinkGuide("7", "A", "B"), Guide((0.1, 0.0), 1.0))),),
                                     points=())
    with pytest.raises(SceneError, match="not a moving link"):
        solve(wrong_link, np.array([0.3]))


def test_slotted_link_drives_the_pin_with_the_coriolis_term() -> None:
    # the pin C on the rocker DC (l = 0.05 m) rides in the slot A→B of the crank: C stays on the
    # line AB, |DC| = l, and a_C = a_C1 + 2ω1×v_C3C1 + a_r with a_r ∥ AB
    phi = np.radians(np.arange(0.0, 360.0, 15.0))
    kin = solve(SLOTTED, phi)
    assert kin.valid.all()
    c = kin.point["C"]
    np.testing.assert_allclose(c[:, 0] * np.sin(phi) - c[:, 1] * np.cos(phi), 0.0, atol=1e-15)
    np.testing.assert_allclose(np.hypot(*(c - kin.point["D"]).T), 0.05, rtol=1e-13)
    np.testing.assert_array_equal(kin.omega["3"], 10.0)  # the block turns with the slotted crank
    v_rel = kin.vel["C3"] - kin.vel["C1"]
    k = 2.0 * 10.0 * np.stack((-v_rel[:, 1], v_rel[:, 0]), -1)
    a_r = kin.acc["C3"] - kin.acc["C1"] - k
    np.testing.assert_allclose(a_r[:, 0] * np.sin(phi) - a_r[:, 1] * np.cos(phi), 0.0, atol=1e-12)
    np.testing.assert_allclose(v_rel[:, 0] * np.sin(phi) - v_rel[:, 1] * np.cos(phi), 0.0, atol=1e-14)


def test_link_angles_follow_the_links_first_two_points() -> None:
    kin = solve(SIXBAR_RRR, np.radians([30.0, 200.0]))
    for lid, names in SIXBAR_RRR.links().items():
        if lid == SIXBAR_RRR.frame_link:
            continue
        u, v = kin.point[names[0]], kin.point[names[1]]
        want = np.mod(np.arctan2(v[:, 1] - u[:, 1], v[:, 0] - u[:, 0]), 2 * np.pi)
        np.testing.assert_allclose(kin.angle[lid], want, rtol=0, atol=1e-12, err_msg=lid)


def test_branches_put_the_joint_on_the_asked_side() -> None:
    phi = np.radians(np.arange(0.0, 360.0, 15.0))
    for branch, sign in (("left", 1.0), ("right", -1.0)):
        four = dataclasses.replace(FOURBAR, dyads=(dataclasses.replace(FOUR_DYAD, branch=branch),))
        kin = solve(four, phi)
        b, c, d = kin.point["B"], kin.point["C"], kin.point["D"]
        side = (d[:, 0] - b[:, 0]) * (c[:, 1] - b[:, 1]) - (d[:, 1] - b[:, 1]) * (c[:, 0] - b[:, 0])
        assert np.all(sign * side > 0)
    for branch, sign in (("forward", 1.0), ("backward", -1.0)):
        sc = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.1, 1.0),
                     (RRP("B", "C", ("2", "3"), 0.3, Guide((0.0, 0.03), math.radians(30.0)),
                          branch=branch),))
        kin = solve(sc, phi)
        u = np.array([math.cos(math.radians(30.0)), math.sin(math.radians(30.0))])
        assert np.all(sign * ((kin.point["C"] - kin.point["B"]) @ u) > 0)


# --------------------------------------------------------------------------------------------
# 5. Positions that cannot be assembled, dead centres, tangent assembly


def all_finite(kin: Kinematics) -> bool:
    arrays = [*kin.point.values(), *kin.vel.values(), *kin.acc.values(),
              *kin.angle.values(), *kin.omega.values(), *kin.alpha.values()]
    return all(np.isfinite(a).all() for a in arrays)


def test_unreachable_positions_are_invalid_and_zero() -> None:
    # non-Grashof: at φ = 180° |BD| = 0.22 m > l_BC + l_CD = 0.1 m
    four = Linkage(FOUR_FRAME, Crank("1", "A", "B", 0.1, 10.0),
                   (RRR("B", "C", "D", ("2", "3"), (0.05, 0.05)),),
                   (LinkPoint("E", "2", ("B", "C"), 0.02, 0.01),))
    kin = solve(four, np.radians([180.0, 0.0]))
    assert kin.valid.tolist() == [False, True]
    assert "cannot be assembled" in kin.reason[0] and kin.reason[1] == ""
    assert all_finite(kin)
    for d in (kin.vel, kin.acc):
        assert all(np.all(v[0] == 0.0) for v in d.values())
    assert np.all(kin.point["C"][0] == 0.0) and np.all(kin.point["E"][0] == 0.0)
    assert kin.angle["2"][0] == 0.0 and kin.omega["3"][0] == 0.0
    np.testing.assert_allclose(kin.point["B"][1], [0.1, 0.0])  # the valid position is intact
    assert np.hypot(*(kin.point["C"][1] - kin.point["B"][1])) == pytest.approx(0.05, rel=1e-12)


def test_slider_driven_dead_centre_and_tangent_assembly() -> None:
    # |AC| = l_AB + l_BC = 0.4 m: crank and coupler in line. 0.4(1 + 1e-11) is past the tangent
    # by rounding-size amounts (discriminant ≈ -7e-12, relative): still assembled (clamped).
    s = np.array([0.4, 0.4 * (1 + 1e-11), 0.4 * (1 - 1e-6), 0.4 * (1 + 1e-6), 0.3])
    kin = solve(SLIDER_DRIVEN, s)
    assert kin.valid.tolist() == [False, False, True, False, True]
    assert kin.assembled.tolist() == [True, True, True, False, True]  # a dead centre is assembled
    assert all_finite(kin)
    for i in (0, 1):  # tangent: the configuration exists, the crank's rate does not
        assert "dead centre" in kin.reason[i]
        np.testing.assert_allclose(kin.point["B"][i], [0.1, 0.0], rtol=0, atol=1e-10)
        assert math.cos(kin.angle["1"][i]) == pytest.approx(1.0, abs=1e-12)
        assert kin.omega["1"][i] == 0.0 and np.all(kin.vel["B"][i] == 0.0)
    assert "cannot be assembled" in kin.reason[3] and np.all(kin.point["B"][3] == 0.0)
    # just inside the tangent the rates are large but finite: ω1 = v·sin(θ2)/(l_AB·sin(θ1 − θ2))
    assert 1e3 < abs(kin.omega["1"][2]) < 1e5
    # a regular position: C's given motion, and the loop closes
    assert kin.vel["C"][4].tolist() == [-1.5, 0.0] and kin.acc["C"][4].tolist() == [4.0, 0.0]
    assert np.hypot(*kin.point["B"][4]) == pytest.approx(0.1, rel=1e-12)


def test_structure_errors_are_collected() -> None:
    bad = Linkage(
        {"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.1, 1.0),
        (RRR("B", "C", "Z", ("2", "3"), (0.1, 0.1)),
         RPP("C", "P", ("4", "5"), 0.3, Guide((0.0, 0.0), 0.3))),
        (LinkPoint("Q", "2", ("C",), 0.0, 0.0),),
    )
    with pytest.raises(SceneError) as err:
        solve(bad, [0.0])
    keys = [k for k, _ in err.value.problems]
    assert keys == ["dyads[0]", "dyads[1].slot_angle", "dyads[1].links", "points[0].base"]
    assert isinstance(err.value, ValueError)


def test_result_is_frozen() -> None:
    kin = solve(FOURBAR, [0.3])
    with pytest.raises(dataclasses.FrozenInstanceError):
        kin.valid = np.array([False])  # type: ignore[misc]
    with pytest.raises(ValueError):
        kin.point["C"][0, 0] = 1.0
    with pytest.raises(ValueError):
        kin.omega["2"][0] = 1.0


# --------------------------------------------------------------------------------------------
# An offset guide bar (RPR with ``offset``): the line at e from its own pivot


def offset_guide_bar(e: float, epsilon: float = 0.0) -> Linkage:
    """Crank 0.03 about A at ω = 10, the bar pivoted at C = (0, −0.04), its slot e to the left of C."""
    return Linkage({"A": (0.0, 0.0), "C": (0.0, -0.04)}, Crank("1", "A", "B", 0.03, 10.0, epsilon),
                   (RPR("B", "C", ("2", "3"), bar="second", offset=e),))


def test_an_offset_guide_bar_by_hand_in_the_bars_frame() -> None:
    """φ = 0: CB = (0.03, 0.04), e = 0.03, t = 0.04, û = CB/(t + ie) = (0.96, 0.28); the loop divided
    by û gives ω3·t = 0.288, ṫ − ω3·e = 0.084 and, once more, α3 = −48.12, ẗ = −2.25."""
    kin = solve(offset_guide_bar(0.03), np.array([0.0]))
    assert kin.valid.all()
    assert kin.angle["3"][0] == pytest.approx(math.atan2(0.28, 0.96), rel=1e-14)
    assert kin.omega["3"][0] == pytest.approx(7.2, rel=1e-13)
    assert kin.omega["2"][0] == kin.omega["3"][0] and kin.alpha["2"][0] == kin.alpha["3"][0]
    assert kin.alpha["3"][0] == pytest.approx(-48.12, rel=1e-13)
    u = np.array([0.96, 0.28])
    v_rel = kin.vel["B2"][0] - kin.vel["B3"][0]  # the block slides along û, away from F
    assert v_rel == pytest.approx(0.3 * u, rel=1e-13)
    assert kin.vel["B3"][0] == pytest.approx(7.2 * np.array([-0.04, 0.03]), rel=1e-13)  # ω3 × CB
    a_k = 2.0 * 7.2 * 0.3 * np.array([-0.28, 0.96])  # 2ω3 × v_rel
    a_r = kin.acc["B2"][0] - kin.acc["B3"][0] - a_k
    assert a_r == pytest.approx(-2.25 * u, rel=1e-12)


@pytest.mark.parametrize("e", [0.03, -0.02, 1e-6])
def test_an_offset_guide_bars_rates_match_finite_differences(e: float) -> None:
    """θ3(t) solved at φ(t) = φ0 + ωt + εt²/2: central differences of the exact positions."""
    linkage = offset_guide_bar(e, epsilon=-40.0)
    phi0 = np.radians([10.0, 100.0, 190.0, 280.0])
    h = 1e-5

    def at(t: float) -> Kinematics:
        return solve(linkage, phi0 + 10.0 * t - 20.0 * t * t)

    kp, k0, km = at(h), at(0.0), at(-h)
    th = [np.unwrap(np.stack([km.angle["3"], k0.angle["3"], kp.angle["3"]]), axis=0)[i] for i in range(3)]
    assert k0.omega["3"] == pytest.approx((th[2] - th[0]) / (2 * h), rel=1e-7, abs=1e-7)
    assert k0.alpha["3"] == pytest.approx((th[2] - 2 * th[1] + th[0]) / h ** 2, rel=1e-4, abs=1e-3)
    assert np.array_equal(k0.vel["B2"], k0.vel["B"])  # the block's point at B is the crank pin
    # B3, the bar's point at B now: C + (CB at t = 0) turned with the bar, differenced as a rigid point
    cb = k0.point["B"] - np.array([0.0, -0.04])
    turn = [np.stack([np.cos(t - th[1]), np.sin(t - th[1])], axis=1) for t in th]
    rigid = [np.stack([r[:, 0] * cb[:, 0] - r[:, 1] * cb[:, 1], r[:, 1] * cb[:, 0] + r[:, 0] * cb[:, 1]], axis=1)
             for r in turn]
    assert k0.vel["B3"] == pytest.approx((rigid[2] - rigid[0]) / (2 * h), rel=1e-7, abs=1e-9)
    assert k0.acc["B3"] == pytest.approx((rigid[2] - 2 * rigid[1] + rigid[0]) / h ** 2, rel=1e-4, abs=1e-4)


@pytest.mark.parametrize("e", [0.03, -0.03])
def test_an_offset_guide_bars_line_is_at_e_to_the_left_of_its_pivot(e: float) -> None:
    kin = solve(offset_guide_bar(e), np.radians(np.arange(0.0, 360.0, 15.0)))
    ok = kin.valid  # |CB| > |e| = 0.03: φ outside 214°…326°
    assert ok.sum() == 17
    u = np.stack([np.cos(kin.angle["3"][ok]), np.sin(kin.angle["3"][ok])], axis=1)
    cb = kin.point["B"][ok] - np.array([0.0, -0.04])
    assert u[:, 0] * cb[:, 1] - u[:, 1] * cb[:, 0] == pytest.approx(np.full(17, e), rel=1e-12)  # û × CB = e
    assert ((u * cb).sum(axis=1) > 0.0).all()  # û points from the foot F towards B: t > 0


def test_a_zero_offset_is_the_centred_guide_bar_bit_for_bit() -> None:
    phi = np.radians(np.arange(0.0, 360.0, 7.0))
    a, b = solve(GUIDE_BAR_CENTRED, phi), solve(offset_guide_bar(0.0), phi)
    for field in ("point", "vel", "acc", "angle", "omega", "alpha"):
        got, want = getattr(b, field), getattr(a, field)
        assert got.keys() == want.keys() and all(np.array_equal(got[k], want[k]) for k in want)


GUIDE_BAR_CENTRED = Linkage({"A": (0.0, 0.0), "C": (0.0, -0.04)}, Crank("1", "A", "B", 0.03, 10.0),
                            (RPR("B", "C", ("2", "3"), bar="second"),))


def test_an_offset_guide_bar_fails_inside_its_circle_and_is_dead_on_it() -> None:
    # |CB| runs from 0.01 (φ = 270°) to 0.07 (φ = 90°): with e = 0.04 the pin leaves the bar's reach
    kin = solve(offset_guide_bar(0.04), np.radians([90.0, 270.0]))
    assert kin.valid.tolist() == [True, False] and kin.assembled.tolist() == [True, False]
    assert "within the offset |e| of the bar's pivot C" in kin.reason[1]
    # e = |CB| at φ = 90°: the pin on the circle, t = 0, the rates unbounded: a dead centre
    dead = solve(offset_guide_bar(0.07), np.radians([90.0]))
    assert not dead.valid[0] and dead.assembled[0] and "dead centre" in dead.reason[0]
    assert dead.omega["3"][0] == 0.0 and np.isfinite(dead.angle["3"]).all()


@pytest.mark.parametrize("e", [0.012, -0.012])
def test_an_offset_bar_on_a_moving_pivot_matches_finite_differences(e: float) -> None:
    """The oscillating block turned offset: bar 2 pivoted on the crank pin B, its line e left of B,
    sliding through block 3 pivoted at C = (−0.1, 0); θ2 differenced, and C2 (the bar's point at C)
    against the rigid motion of the bar about B."""
    lk = Linkage({"A": (0.0, 0.0), "C": (-0.1, 0.0)}, Crank("1", "A", "B", 0.03, 10.0, 20.0),
                 (RPR("B", "C", ("2", "3"), bar="first", offset=e),))
    phi0 = np.radians([45.0, 160.0, 300.0])
    h = 1e-5
    kp, k0, km = (solve(lk, phi0 + 10.0 * t + 10.0 * t * t) for t in (h, 0.0, -h))
    th = np.unwrap(np.stack([km.angle["2"], k0.angle["2"], kp.angle["2"]]), axis=0)
    assert k0.omega["2"] == pytest.approx((th[2] - th[0]) / (2 * h), rel=1e-7)
    assert k0.alpha["2"] == pytest.approx((th[2] - 2 * th[1] + th[0]) / h ** 2, rel=1e-4)
    assert np.array_equal(k0.omega["3"], k0.omega["2"])
    # C2 = B + (BC at t = 0) turned with the bar and carried with B
    bc = k0.point["C"] - k0.point["B"]

    def rigid(k: Kinematics, dth: np.ndarray) -> np.ndarray:
        c, s = np.cos(dth), np.sin(dth)
        return k.point["B"] + np.stack([c * bc[:, 0] - s * bc[:, 1], s * bc[:, 0] + c * bc[:, 1]], axis=1)
    r = [rigid(k, t - th[1]) for k, t in zip((km, k0, kp), th)]
    assert k0.vel["C2"] == pytest.approx((r[2] - r[0]) / (2 * h), rel=1e-6, abs=1e-8)
    assert k0.acc["C2"] == pytest.approx((r[2] - 2 * r[1] + r[0]) / h ** 2, rel=1e-3, abs=1e-4)
    assert np.array_equal(k0.vel["C3"], np.zeros((3, 2)))  # the block's point at C is the frame pivot's
