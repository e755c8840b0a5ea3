"""Instant centres by Kennedy's theorem: every centre, ω and v against the exact kinematics,
centres at infinity, a parallelogram's change point, dead centres, the book's four-bar."""
from __future__ import annotations

import json
import math
import tomllib
from itertools import combinations

import numpy as np
import pytest

from graphmech.problems.linkage.check import analyse
from graphmech.problems.instant_centres.check import exact_centre, positions_mm
from graphmech.mechanisms.linkage import Crank, Linkage, RRR
from graphmech.methods.instant_centres import centre_name, instant_centres
from graphmech.scene import parse_scene
from tests.conftest import SCENES, check_json, run_cli, values
from tests.scenes import scene_text

HEAD = """
[units]
length = "mm"
angle = "deg"
omega = "rad/s"
velocity = "m/s"
[scales]
l_m_per_mm = 0.002
"""

FOURBAR = HEAD + """
[frame]
link = "1"
A = [0, 0]
D = [{d}, 0]
[driver]
type = "crank"
link = "2"
pivot = "A"
tip = "B"
length = {a}
angle = {phi}
omega = 10
[[dyad]]
type = "RRR"
joints = ["B", "C", "D"]
links = ["3", "4"]
lengths = [{b}, {c}]
branch = "{branch}"
"""

#: An offset slider-crank at three crank angles; a six-bar (a four-bar driving a slider from its coupler).
SLIDER_CRANK = scene_text("linkage/ic_slider_crank")
SIXBAR = scene_text("linkage/ic_sixbar")

OSCILLATING_BLOCK = scene_text("linkage/ic_oscillating_block")

def scene_of(text: str, show=("instant_centres",), find=()):
    data = tomllib.loads(text)
    data["show"] = list(show)
    data["find"] = list(find)
    return parse_scene(data, "test.toml")


def all_centres_agree(an, tol=1e-9):
    """Every centre of every position against the exact one (points relative to the size)."""
    linkage = an.build.linkage
    mu = an.scales["l"]
    ox, oy = an.build.origin
    checked = 0
    for i, ic in enumerate(an.instant_centres.centres):
        assert ic is not None
        n = len(ic.links)
        assert len(ic.centres) == n * (n - 1) // 2
        for a, b in combinations(ic.links, 2):
            c = ic.centre(a, b)
            assert c.known, (centre_name(a, b), c.why)
            if c.kind == "direct" and c.point is not None:  # a joint: the exact joint
                x, y = c.point[0] * mu + ox, c.point[1] * mu + oy
                assert math.dist((x, y), an.exact.point[c.via[0]][i]) <= tol * an.size
                checked += 1
                continue
            kind, ev = exact_centre(linkage, an.exact, a, b, i)
            if kind == "none":  # at relative rest (a slider at its dead centre): velocities define no centre
                checked += 1
                continue
            if c.at_infinity and kind == "point":  # parallel in the construction, ~1e16 away exactly
                kind, ev = "direction", (ev[0] / math.hypot(*ev), ev[1] / math.hypot(*ev))
            if c.at_infinity:
                assert kind == "direction", centre_name(a, b)
                assert abs(c.direction[0] * ev[1] - c.direction[1] * ev[0]) < tol
            else:
                assert kind == "point", centre_name(a, b)
                x, y = c.point[0] * mu + ox, c.point[1] * mu + oy
                assert math.dist((x, y), ev) <= tol * an.size, (centre_name(a, b), (x, y), ev)
            checked += 1
        for lid, mo in ic.motions.items():
            if lid != linkage.frame_link:
                assert mo.omega == pytest.approx(float(an.exact.omega[lid][i]), abs=tol * 10)
    return checked


def test_book_fourbar_by_instant_centres(problems):
    p = problems["kin.fourbar_instant_centres"]
    doc = check_json(SCENES / "kin.fourbar_instant_centres.toml")
    v = values(doc)
    ex, book = p["exact"], p["book"]
    assert v["omega_3_ic"]["graphical"] == pytest.approx(ex["omega3_rad_s"], rel=1e-9)
    assert v["v_C_ic"]["graphical"] == pytest.approx(ex["vC_m_s"], rel=1e-9)
    assert v["v_min_BC_ic"]["graphical"] == pytest.approx(ex["vE_m_s"], rel=1e-9)
    assert v["s_min_BC_ic"]["graphical"] * 1000 == pytest.approx(ex["BE_mm"], rel=1e-9)
    zeros = [v["phi_v0_C_1"]["graphical"], v["phi_v0_C_2"]["graphical"]]
    # A, B, C in line (P24 = P12): |AC| = 180 or 60 mm, the law of cosines in triangle ACD
    closed = [math.degrees(math.acos((180**2 + 120**2 - 90**2) / (2 * 180 * 120))),
              180 + math.degrees(math.acos((60**2 + 120**2 - 90**2) / (2 * 60 * 120)))]
    assert zeros == pytest.approx(closed, abs=1e-11)
    assert zeros == pytest.approx(ex["phi_vC0_deg"], rel=1e-9)
    # the book's graphical answers differ from these by the bank's rel_diff (1.1 % at most)
    for ours, key in (("omega_3_ic", "omega3_rad_s"), ("v_C_ic", "vC_m_s"), ("v_min_BC_ic", "vE_m_s")):
        g = v[ours]["graphical"]
        assert (book[key] - g) / abs(g) == pytest.approx(p["rel_diff"][key], abs=1e-8)
    assert zeros == pytest.approx(book["phi_vC0_deg"], abs=0.05)
    for q in doc["quantities"]:
        assert q["rel_error"] <= 1e-12, q
    # P24 is on AD (the frame line) and E beyond C: BE > BC
    assert v["y_P24"]["graphical"] == pytest.approx(0.0, abs=1e-15)
    assert v["s_min_BC_ic"]["graphical"] > 0.12


@pytest.mark.parametrize("text,n_links", [(SLIDER_CRANK, 4), (OSCILLATING_BLOCK, 4), (SIXBAR, 6)],
                         ids=["RRP", "RPR", "sixbar"])
def test_every_centre_and_omega_agree_with_the_exact_kinematics(text, n_links):
    an = analyse(scene_of(text))
    assert all_centres_agree(an) == len(an.labels) * n_links * (n_links - 1) // 2


def test_slider_centre_is_at_infinity_perpendicular_to_the_guide():
    an = analyse(scene_of(SLIDER_CRANK, find=["P14", "v_C_ic", "omega_3_ic", "phi_v0_C"]))
    ic = an.instant_centres.centres[0]
    assert ic.centre("1", "4").direction == pytest.approx((0.0, 1.0), abs=1e-15)
    v = {r.name: r for r in an.rows}
    assert v["dir_P14@30"].graphical == pytest.approx(90.0, abs=1e-12)
    for r in an.rows:
        assert r.rel_error <= 1e-9, r
    # a slider's velocity vanishes at its dead centres: where B is on line AC, sin(φ) = e/(l ± r)
    e, r, l = 0.03, 0.1, 0.3
    expect = sorted([math.degrees(math.asin(e / (l + r))), 180 + math.degrees(math.asin(e / (l - r)))])
    assert sorted([v["phi_v0_C_1"].graphical, v["phi_v0_C_2"].graphical]) == pytest.approx(expect, abs=1e-9)


def test_rpr_sliding_pair_centre_is_perpendicular_to_the_bar():
    an = analyse(scene_of(OSCILLATING_BLOCK))
    ic = an.instant_centres.centres[0]
    pos = positions_mm(an.build, an.solutions[0])
    d = ic.centre("3", "4").direction
    bc = np.subtract(pos["C"], pos["B"])
    assert abs(d[0] * bc[0] + d[1] * bc[1]) < 1e-12 * np.hypot(*bc)
    assert ic.centre("1", "4").point == pos["C"]  # the block's pivot on the frame


def test_parallel_kennedy_lines_put_the_centre_at_infinity():
    # a parallelogram: AB ∥ DC, so P13 (on AB and on DC) is at infinity and the coupler translates
    an = analyse(scene_of(FOURBAR.format(d=120, a=60, b=120, c=60, phi=70, branch="left"),
                          find=["P13", "P24", "omega_3_ic", "omega_4_ic", "v_C_ic"]))
    v = {r.name: r for r in an.rows}
    assert v["dir_P13"].graphical == pytest.approx(70.0, abs=1e-9)
    assert v["dir_P13"].exact == pytest.approx(70.0, abs=1e-9)
    assert v["omega_3_ic"].graphical == 0.0
    assert v["omega_4_ic"].graphical == pytest.approx(10.0, rel=1e-9)
    assert v["v_C_ic"].graphical == pytest.approx(0.6, rel=1e-12)  # = v_B: a translating coupler
    assert "x_P13" not in v
    ic = an.instant_centres.centres[0]
    assert ic.centre("2", "4").at_infinity  # AD ∥ BC as well
    assert not any("nan" in json.dumps(r.as_dict()).lower() for r in an.rows)


def test_parallelogram_change_point_says_what_cannot_be_determined(tmp_path):
    text = FOURBAR.format(d=120, a=60, b=120, c=60, phi=0, branch="left")
    an = analyse(scene_of(text, find=["P13", "omega_3_ic", "omega_4_ic", "P23"]))
    ic = an.instant_centres.centres[0]
    for pair in (("1", "3"), ("2", "4")):
        c = ic.centre(*pair)
        assert c.kind == "undetermined" and "coincide" in c.why
    assert set(ic.undetermined) == {"3", "4"}
    text_w = " ".join(an.warnings)
    assert "P13 cannot be determined" in text_w and "P24 cannot be determined" in text_w
    assert "the motion of link 3 cannot be found" in text_w
    assert an.rows == []  # the exact solution is undefined there too (B, C, D in line)
    assert "exact solution is undefined" in text_w
    assert ic.centre("2", "3").point is not None  # the direct centres are still drawn
    path = tmp_path / "change.toml"
    path.write_text('title = "change point"\nshow = ["instant_centres"]\nfind = ["P13"]\n' + text)
    code, out, err = run_cli("render", str(path), "-o", str(tmp_path / "c.svg"))
    assert code == 0, err
    svg = (tmp_path / "c.svg").read_text()
    assert "undetermined" in svg and "nan" not in svg.lower()


def test_dead_centre_of_the_rocker_is_where_p24_meets_p12():
    # the book's four-bar at its first v_C = 0 angle: A, B, C in line, P24 = P12 = A, ω4 = 0
    phi = 26.38432975096472
    an = analyse(scene_of(FOURBAR.format(d=120, a=60, b=120, c=90, phi=phi, branch="left"),
                          find=["P24", "omega_4_ic", "v_C_ic"]))
    v = {r.name: r for r in an.rows}
    assert math.hypot(v["x_P24"].graphical, v["y_P24"].graphical) < 1e-9 * an.size
    assert abs(v["omega_4_ic"].graphical) < 1e-9 and abs(v["v_C_ic"].graphical) < 1e-9


def test_rocker_driven_dead_centre_leaves_the_crank_undetermined():
    # the rocker DC drives; with A, B, C in line P24 falls on P12 = A, so ω2 = ω4·P14P24/P12P24
    # has a zero denominator: a dead centre, the crank cannot be driven from the rocker
    fb = Linkage({"D": (0.12, 0.0), "A": (0.0, 0.0)}, Crank("4", "D", "C", 0.09, 10.0),
                 (RRR("C", "B", "A", ("3", "2"), (0.12, 0.06), "right"),), frame_link="1")
    # C on the line AB beyond B: |AC| = 0.18 = l_AB + l_BC, |DC| = 0.09
    ang = math.acos((0.18 ** 2 + 0.12 ** 2 - 0.09 ** 2) / (2 * 0.18 * 0.12))
    u = np.array([math.cos(ang), math.sin(ang)])
    pos = {"A": (0.0, 0.0), "D": (120.0, 0.0), "B": tuple(60.0 * u), "C": tuple(180.0 * u)}
    ic = instant_centres(fb, pos, mu_l=0.001)
    assert ic.centre("2", "4").point == pytest.approx((0.0, 0.0), abs=1e-9)
    assert "2" in ic.undetermined and "dead centre" in ic.undetermined["2"]
    # the coupler neither: P13 (on AB and on DC) is C itself, where C moves, so
    # ω3 = ω4·P14P34/P13P34 divides by zero too
    assert ic.centre("1", "3").point == pytest.approx(pos["C"], abs=1e-9)
    assert set(ic.undetermined) == {"2", "3"} and "dead centre" in ic.undetermined["3"]
    assert ic.motions["4"].omega == 10.0


SLIDER_DRIVEN = scene_text("linkage/ic_slider_driven")


def test_rpp_three_centres_at_infinity_and_the_line_at_infinity():
    # block 2 in the slot of the translating slider 3: P23, P34 at infinity, so P24 is found on
    # the line at infinity (through P23 and P34) and the finite line AB: at infinity along AB
    text = (SCENES / "linkage.slider_fixed_angle_guide.toml").read_text()
    data = tomllib.loads(text)
    data["show"], data["find"] = ["instant_centres"], ["P24", "P13", "omega_2_ic", "v_C_ic"]
    an = analyse(parse_scene(data, "rpp.toml"))
    assert all_centres_agree(an) == 6
    ic = an.instant_centres.centres[0]
    assert [ic.centre(*k).at_infinity for k in (("2", "3"), ("3", "4"), ("2", "4"))] == [True] * 3
    v = {r.name: r for r in an.rows}
    assert v["dir_P24"].graphical == pytest.approx(45.0, abs=1e-9)  # along AB at φ1 = 45°
    for r in an.rows:
        assert r.rel_error <= 1e-12, r


def test_a_driven_slider_gives_the_velocities_through_its_centre_at_infinity():
    an = analyse(scene_of(SLIDER_DRIVEN, find=["omega_2_ic", "omega_3_ic", "v_B_ic", "P24"]))
    assert all_centres_agree(an) == 2 * 6
    for r in an.rows:
        assert r.rel_error <= 1e-12, r


def test_centres_and_topologies_are_frozen():
    import dataclasses

    from graphmech.mechanisms.topology import Pair

    an = analyse(scene_of(SLIDER_CRANK))
    c = an.instant_centres.centres[0].centre("1", "3")
    with pytest.raises(dataclasses.FrozenInstanceError):
        c.point = (0.0, 0.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        Pair("R", ("1", "2")).kind = "P"


from hypothesis import HealthCheck, assume, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(a=st.floats(20, 80), b=st.floats(60, 160), c=st.floats(40, 140), d=st.floats(60, 160),
       phi=st.floats(0, 360), branch=st.sampled_from(["left", "right"]))
def test_kennedy_any_three_centres_are_in_line_and_agree_with_the_exact_ones(a, b, c, d, phi, branch):
    """For every three links i, j, k the centres P_ij, P_jk, P_ik are on one line (Kennedy), and
    every centre and ω agrees with the exact kinematics unless the construction says it is
    ill-conditioned."""
    from graphmech.errors import DegenerateConstruction

    try:
        an = analyse(scene_of(FOURBAR.format(d=d, a=a, b=b, c=c, phi=phi, branch=branch),
                              find=["P13", "P24", "omega_3_ic", "omega_4_ic", "v_C_ic"]))
    except DegenerateConstruction:  # cannot be assembled at this angle
        assume(False)
        return
    ic = an.instant_centres.centres[0]
    assume(not ic.undetermined and an.exact.valid[0])
    for i, j, k in combinations(ic.links, 3):
        pts = [ic.centre(x, y) for x, y in ((i, j), (j, k), (i, k))]
        fin = [p.point for p in pts if p.point is not None]
        dirs = [p.direction for p in pts if p.direction is not None]
        if len(fin) == 3:
            (x0, y0), (x1, y1), (x2, y2) = fin
            area = abs((x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0))
            span = max(math.dist(fin[0], fin[1]), math.dist(fin[0], fin[2]), math.dist(fin[1], fin[2]))
            assert area <= 1e-9 * max(span, 1.0) ** 2 * max(p.cond for p in pts)
        elif len(fin) == 2 and dirs:
            (x0, y0), (x1, y1) = fin
            u = dirs[0]
            assert abs((x1 - x0) * u[1] - (y1 - y0) * u[0]) <= 1e-9 * max(math.dist(*fin), 1.0) * max(
                p.cond for p in pts)
    for r in an.rows:
        assert r.rel_error <= 1e-9 or r.ill_conditioned, r


COMPOUND = scene_text("linkage/ic_compound_hinge")


def test_a_compound_hinge_is_the_centre_of_every_two_of_its_links():
    # link 5 hangs on C, where 3 and 4 already meet: P34 = P35 = P45 = C
    an = analyse(scene_of(COMPOUND))
    assert all_centres_agree(an) == 2 * 15
    ic = an.instant_centres.centres[0]
    c = positions_mm(an.build, an.solutions[0])["C"]
    assert ic.centre("3", "4").point == ic.centre("3", "5").point == ic.centre("4", "5").point == c
    assert sum(1 for x in ic.centres.values() if x.kind == "direct") == 8  # A, B, D, G, E and C thrice


def _linkage_examples():
    import re

    from tests.conftest import ROOT

    blocks = re.findall(r"```toml\n(.*?)```", (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8"), re.S)
    out = [(f"doc{i}", b) for i, b in enumerate(blocks)]
    out += [(p.stem, p.read_text(encoding="utf-8")) for p in sorted(SCENES.glob("*.toml"))
            if p.stem != "ic.parallelogram_change_point"]
    no_linkage = ("cam", "flywheel", "structure", "efficiency", "balancing", "gear", "train", "synthesis", "geneva",
                  "differential_screw", "centres")
    # a swing out to its limits has no polygons there (its dyad toggles): tests/problems/cycle/test_check.py
    return [(n, t) for n, t in out if not any(k in tomllib.loads(t) for k in no_linkage)
            and tomllib.loads(t).get("cycle", {}).get("between") != "limits"]


@pytest.mark.parametrize("name,text", _linkage_examples(), ids=[n for n, _ in _linkage_examples()])
def test_every_documented_and_reference_linkage_has_all_its_centres_right(name, text):
    data = tomllib.loads(text)
    if "cycle" in data or "characteristics" in data:  # not drawn on a cycle's sheet: found at its positions
        data["find"] = ["P12"]
    else:
        data["show"], data["find"] = ["instant_centres"], []
    for key in ("measured", "forces"):  # a force scene's linkage is a linkage like any other
        data.pop(key, None)
    an = analyse(parse_scene(data, f"{name}.toml"))
    n = len(an.instant_centres.centres[0].links)
    assert all_centres_agree(an) == len(an.labels) * n * (n - 1) // 2




def test_kennedy_completes_centres_stated_directly_and_motions_follow():
    """The four-bar's four revolutes given as direct centres, with no linkage: P13, P24 by Kennedy."""
    from graphmech.methods.instant_centres import Centre, LinkMotion, kennedy, motions_from

    links = ("1", "2", "3", "4")
    direct = {("1", "2"): (0.0, 0.0), ("2", "3"): (0.0, 60.0), ("3", "4"): (120.0, 90.0), ("1", "4"): (120.0, 0.0)}
    centres = {k: Centre(k, "direct", p, None, ("X",)) for k, p in direct.items()}
    order = list(centres)
    kennedy(links, centres, order, 150.0)
    assert centres[("1", "3")].direction == (0.0, 1.0) and centres[("2", "4")].point == (-240.0, 0.0)
    assert order[4:] == [("1", "3"), ("2", "4")]
    start = {"1": LinkMotion("1", 0.0, (0.0, 0.0), ("frame",)), "2": LinkMotion("2", 10.0, (0.0, 0.0), ("driver",))}
    motions, undetermined = motions_from(links, "1", centres, start, 150.0)
    assert motions["4"].omega == pytest.approx(10.0 * 240.0 / 360.0, abs=1e-12) and undetermined == {}


# ---------------------------------------------------------------------------- over many positions at once


def batch_is_per_position(an, phi):
    """instant_centres_batch at the constructible ones of the crank angles ``phi`` against
    instant_centres one position at a time: every centre, ω and v0 bit for bit."""
    from graphmech.methods.instant_centres import instant_centres_batch

    build, linkage, mu = an.build, an.build.linkage, an.scales["l"]
    batch = an.plan.evaluate_batch({build.param: phi})
    idx = np.flatnonzero(batch.valid)
    pos = {}
    for name, slot in build.mech.items():
        x, y = batch.values[slot]
        pos[name] = tuple(c if np.ndim(c) == 0 else np.asarray(c)[idx] for c in (x, y))
    cb = instant_centres_batch(linkage, pos, len(idx), mu_l=mu)
    for i, at in enumerate(idx):
        ic = instant_centres(linkage, positions_mm(build, batch.at(int(at))), mu_l=mu)
        assert cb.order == ic.order or i in cb.by_position
        for key, c in ic.centres.items():
            assert np.array_equal(cb.centres[key][i], c.homogeneous() if c.known else np.zeros(3)), (at, key)
        for lid in ic.links:
            m = ic.motions.get(lid)
            assert bool(cb.determined[lid][i]) == (m is not None)
            if m is not None:
                assert (cb.omega[lid][i], tuple(cb.v0[lid][i])) == (m.omega, m.v0), (at, lid)
    return cb, idx


def _crank_scenes():
    out = []
    for p in sorted(SCENES.glob("ic.*.toml")) + [SCENES / "kin.fourbar_instant_centres.toml"]:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
        if data.get("driver", {}).get("type") == "crank":
            out.append(p)
    return out


@pytest.mark.parametrize("path", _crank_scenes(), ids=lambda p: p.stem)
def test_centres_over_a_turn_as_arrays_are_the_ones_constructed_position_by_position(path):
    an = analyse(parse_scene(tomllib.loads(path.read_text(encoding="utf-8")), path.name))
    phi = np.radians(np.arange(360) + 0.5)
    cb, idx = batch_is_per_position(an, phi)
    assert len(idx) > 0 and cb.omega[an.build.linkage.driver.link].shape == (len(idx),)


def test_a_parallelogram_is_constructed_position_by_position_and_a_slider_crank_as_arrays():
    # the parallelogram's P13 is at infinity wherever AB ∥ DC (the open branch): Kennedy's order
    # there differs from the one for finite centres, so those positions go to instant_centres, as
    # does the change point φ = 0 (P13, P24 undetermined); the crossed branch's are arrays
    an = analyse(scene_of(FOURBAR.format(d=120, a=60, b=120, c=60, phi=70, branch="left")))
    cb, idx = batch_is_per_position(an, np.radians(np.concatenate([np.arange(360) + 0.5, [0.0]])))
    p13 = cb.centres[("1", "3")]
    at_infinity = tuple(int(i) for i in np.flatnonzero((p13[:, 2] == 0.0) & (p13[:, :2] != 0.0).any(axis=1)))
    change = len(idx) - 1
    assert idx[change] == 360 and not cb.determined["3"][change] and not p13[change].any()
    assert len(at_infinity) >= 100 and cb.by_position == at_infinity + (change,)
    # the slider-crank's P14 is at infinity at every position, but always: the arrays handle it
    an = analyse(scene_of(SLIDER_CRANK))
    cb, idx = batch_is_per_position(an, np.radians(np.arange(360) + 0.5))
    assert cb.by_position == () and len(idx) == 360
    assert all(cb.centres[("1", "4")][:, 2] == 0.0)


def test_the_rockers_dead_centre_in_a_turn_is_decided_by_the_arrays():
    # the book's four-bar: at φ = 26.384…° A, B, C are in line and P24 = P12, so ω4 = ω2·P12P24/P14P24
    # is 0 with a sound denominator: no position to construct alone
    an = analyse(scene_of(FOURBAR.format(d=120, a=60, b=120, c=90, phi=0, branch="left")))
    dead = 26.38432975096472
    phi = np.radians(np.concatenate([np.arange(360) + 0.5, [dead]]))
    cb, idx = batch_is_per_position(an, phi)
    assert len(idx) == 361 and cb.by_position == ()
    assert abs(cb.omega["4"][360]) < 1e-9 and cb.determined["4"].all()


def test_batch_velocity_of_a_point_is_the_links_velocity_field():
    from graphmech.methods.instant_centres import instant_centres_batch

    fb = Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("2", "A", "B", 0.06, 10.0),
                 (RRR("B", "C", "D", ("3", "4"), (math.hypot(0.12, 0.03), 0.09)),), frame_link="1")
    pos = {"A": (0.0, 0.0), "D": (120.0, 0.0), "B": (np.array([0.0, 60.0]), np.array([60.0, 0.0])),
           "C": (np.array([120.0, 150.0]), np.array([90.0, 80.0]))}
    cb = instant_centres_batch(fb, pos, 2, mu_l=0.001)
    assert cb.by_position == (0,)  # P13 at infinity there (AB ∥ DC)
    v = cb.velocity("2", pos["B"])  # v_B = ω2 × AB: 10 rad/s · 60 mm, ⟂ AB
    assert v.tolist() == [[-600.0, 0.0], [0.0, 600.0]]
    for i in range(2):
        ic = instant_centres(fb, {k: (float(np.broadcast_to(x, 2)[i]), float(np.broadcast_to(y, 2)[i]))
                                  for k, (x, y) in pos.items()}, mu_l=0.001)
        c = (float(pos["C"][0][i]), float(pos["C"][1][i]))
        assert tuple(cb.velocity("3", pos["C"])[i]) == ic.motions["3"].velocity(c)
