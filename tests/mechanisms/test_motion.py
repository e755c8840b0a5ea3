"""The follower's motion laws (graphmech.mechanisms.motion): the textbook's reference problem, impacts,
validation, a finite-difference property, the table law and vectorised evaluation."""
from __future__ import annotations

import dataclasses
import math
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import SceneError
from graphmech.mechanisms import motion
from graphmech.mechanisms.cam import MotionProgram, Segment
from graphmech.mechanisms.motion import (
    Extremum,
    Impact,
    breakpoints,
    displacement,
    impacts,
    maxima,
    validate,
)
from tests.conftest import ROOT

PI = math.pi


def cycle(h: float, law: str, d0: float, table: tuple = ()) -> MotionProgram:
    """Rise over d0, far dwell, return over d0 by the same law, near dwell: each dwell (π − d0)."""
    return MotionProgram(h, (Segment("rise", d0, law, table), Segment("dwell", PI - d0),
                             Segment("return", d0, law, table), Segment("dwell", PI - d0)))


def rel(a: float, b: float) -> float:
    return abs(a - b) / abs(b)


# ------------------------------------------------------------------------------------------------
# 1. the reference problem cam.law_maxima
# ------------------------------------------------------------------------------------------------

BOOK_LAW = {"uniform": "uniform", "const_acc": "parabolic", "cosine": "cosine", "sine": "sine"}


@pytest.mark.parametrize("name", list(BOOK_LAW))
def test_law_maxima_reference_problem(problems, name):
    p = problems["cam.law_maxima"]
    h = p["inputs"]["h_mm"] / 1000.0
    d0 = p["inputs"]["delta0_rad"]
    omega = p["inputs"]["omega_rad_s"]
    prog = cycle(h, BOOK_LAW[name], d0)
    assert validate(prog) == []
    m = maxima(prog, omega)
    ex, book = p["exact"], p["book"]

    for q in ("v", "a"):
        key = f"{name}_{q}max_m_s" + ("2" if q == "a" else "")
        # exact values to 1e-9
        assert m[q].value == pytest.approx(ex[key], rel=1e-9, abs=1e-15)
        assert m[q].signed == pytest.approx(ex[key], rel=1e-9, abs=1e-15)  # on the rise: positive
        # the book's printed value within 0.1 % (its amax 0 for the uniform law: exactly)
        if book[key] == 0.0:
            assert m[q].value == 0.0
        else:
            assert rel(m[q].value, book[key]) <= 1e-3
        at = ex.get(f"{name}_{q}max_at_rad")
        if isinstance(at, float):
            assert m[q].at == pytest.approx(at, rel=1e-9, abs=1e-12)
            if f"{name}_{q}max_at_rad" in book:
                assert m[q].at == pytest.approx(book[f"{name}_{q}max_at_rad"], abs=1e-9)
        else:  # a range of angles ("whole stroke", "0..pi/4", "0 (…)"): the first is 0
            assert at is not None and m[q].at == 0.0

    # what the ranges in `exact` say, checked along the rise
    inside = np.linspace(0.0, d0, 1001)[1:-1]
    if name == "uniform":
        v = omega * displacement(prog, inside, 1)
        np.testing.assert_allclose(v, ex["uniform_vmax_m_s"], rtol=1e-12)  # the whole stroke
        assert np.all(displacement(prog, inside, 2) == 0.0)  # a = 0 inside the stroke …
        rigid = [(i.angle, i.kind) for i in impacts(prog)]  # … infinite at its ends: rigid impacts
        assert (0.0, "rigid") in rigid and (pytest.approx(d0), "rigid") in rigid
    if name == "const_acc":
        a = omega**2 * displacement(prog, inside, 2)
        amax = ex["const_acc_amax_m_s2"]
        np.testing.assert_allclose(a[inside < d0 / 2], amax, rtol=1e-12)
        np.testing.assert_allclose(a[inside >= d0 / 2], -amax, rtol=1e-12)
    if name == "cosine":  # amax also at π/2 (decelerating, a left-hand limit)
        assert omega**2 * displacement(prog, d0 * (1 - 1e-9), 2) == pytest.approx(-ex["cosine_amax_m_s2"], rel=1e-9)
    if name == "sine":  # amax also at 3π/8, negative
        assert omega**2 * displacement(prog, 3 * PI / 8, 2) == pytest.approx(-ex["sine_amax_m_s2"], rel=1e-12)


def test_poly345_maxima_analytic():
    h, d0, w = 0.03, 1.2, 7.0
    m = maxima(cycle(h, "poly345", d0), w)
    assert m["v"].value == pytest.approx(1.875 * h * w / d0, rel=1e-13)
    assert m["v"].at == pytest.approx(d0 / 2, rel=1e-13)
    assert m["a"].value == pytest.approx(10 * math.sqrt(3) / 3 * h * w**2 / d0**2, rel=1e-13)
    assert m["a"].at == pytest.approx((3 - math.sqrt(3)) / 6 * d0, rel=1e-13)
    assert m["j"].value == pytest.approx(60 * h * w**3 / d0**3, rel=1e-13)
    assert m["j"].at == 0.0 and m["j"].signed > 0


def test_jerk_maxima_of_the_trigonometric_laws():
    h, d0, w = 0.05, PI / 2, 10.0
    cos_j = maxima(cycle(h, "cosine", d0), w)["j"]
    assert cos_j.value == pytest.approx(PI**3 / 2 * h * w**3 / d0**3, rel=1e-13)
    assert cos_j.at == pytest.approx(d0 / 2) and cos_j.signed < 0
    sin_j = maxima(cycle(h, "sine", d0), w)["j"]
    assert sin_j.value == pytest.approx(4 * PI**2 * h * w**3 / d0**3, rel=1e-13)
    assert sin_j.at == 0.0 and sin_j.signed > 0
    assert maxima(cycle(h, "parabolic", d0), w)["j"] == Extremum(0.0, 0.0, 0.0)


@pytest.mark.parametrize("law", ["uniform", "parabolic", "cosine", "sine", "poly345"])
def test_maxima_bound_a_dense_evaluation(law):
    """Exact maxima are never below what a dense evaluation sees, and a dense one comes close."""
    prog = MotionProgram(0.04, (Segment("rise", 1.0, law), Segment("dwell", 0.5),
                                Segment("return", 2.0, law), Segment("dwell", 2 * PI - 3.5)))
    m = maxima(prog, 3.0)
    grid = np.linspace(0, 2 * PI, 200_001)
    for k, key in ((1, "v"), (2, "a"), (3, "j")):
        sampled = np.max(np.abs(3.0**k * displacement(prog, grid, k)))
        assert sampled <= m[key].value * (1 + 1e-12)
        assert sampled >= m[key].value * (1 - 1e-4)  # the parabolic law's v peak is a kink


# ------------------------------------------------------------------------------------------------
# 2. impacts, and validation
# ------------------------------------------------------------------------------------------------


def kinds_at(prog: MotionProgram) -> list[tuple[float, str]]:
    return [(round(i.angle, 12), i.kind) for i in impacts(prog)]


def test_uniform_rigid_impacts_at_both_ends_of_rise_and_return():
    h, d0, dr = 0.05, PI / 2, 2 * PI / 3
    prog = MotionProgram(h, (Segment("rise", d0, "uniform"), Segment("dwell", 0.5),
                             Segment("return", dr, "uniform"), Segment("dwell", 2 * PI - d0 - 0.5 - dr)))
    got = impacts(prog)
    assert [i.kind for i in got] == ["rigid"] * 4
    np.testing.assert_allclose([i.angle for i in got], [0.0, d0, d0 + 0.5, d0 + 0.5 + dr], rtol=1e-15)
    np.testing.assert_allclose([i.jump for i in got], [h / d0, -h / d0, -h / dr, h / dr], rtol=1e-13)


def test_uniform_rise_straight_into_return_jumps_by_twice_the_speed():
    h, d0 = 0.02, PI
    prog = MotionProgram(h, (Segment("rise", d0, "uniform"), Segment("return", d0, "uniform")))
    got = impacts(prog)
    assert [(i.angle, i.kind) for i in got] == [(0.0, "rigid"), (PI, "rigid")]
    assert got[0].jump == pytest.approx(2 * h / d0, rel=1e-13)
    assert got[1].jump == pytest.approx(-2 * h / d0, rel=1e-13)


def test_parabolic_soft_impacts_at_start_middle_and_end():
    h, d0 = 0.05, PI / 2
    prog = cycle(h, "parabolic", d0)
    got = impacts(prog)
    assert all(i.kind == "soft" for i in got)
    a = 4 * h / d0**2  # d²s/dδ² on the first half of the rise
    expected = [(0.0, a), (d0 / 2, -2 * a), (d0, a),  # rise: +a, jumps to −a at x = ½, then 0
                (PI, -a), (PI + d0 / 2, 2 * a), (PI + d0, -a)]  # return: mirrored
    np.testing.assert_allclose([i.angle for i in got], [e[0] for e in expected], rtol=1e-15, atol=0)
    np.testing.assert_allclose([i.jump for i in got], [e[1] for e in expected], rtol=1e-13)
    # and displacement takes the right-hand value at the middle, the left-hand one just before
    assert displacement(prog, d0 / 2, 2) == pytest.approx(-a, rel=1e-15)
    assert displacement(prog, d0 / 2 - 1e-9, 2) == pytest.approx(a, rel=1e-15)
    # an angle a rounding away from the middle counts as the middle
    assert displacement(prog, np.nextafter(d0 / 2, 0.0), 2) == pytest.approx(-a, rel=1e-15)


def test_cosine_soft_impacts_at_both_ends_with_dwells():
    h, d0 = 0.05, PI / 2
    got = impacts(cycle(h, "cosine", d0))
    a0 = PI**2 / 2 * h / d0**2
    assert [i.kind for i in got] == ["soft"] * 4
    np.testing.assert_allclose([i.angle for i in got], [0.0, d0, PI, PI + d0], rtol=1e-15)
    np.testing.assert_allclose([i.jump for i in got], [a0, a0, -a0, -a0], rtol=1e-13)


def test_cosine_rise_into_return_of_same_angle_has_no_impact_at_the_top():
    # at the top the rise decelerates at −π²h/(2δ0²) and the return starts with the same value
    prog = MotionProgram(0.05, (Segment("rise", PI / 2, "cosine"), Segment("return", PI / 2, "cosine"),
                                Segment("dwell", PI)))
    assert kinds_at(prog) == [(0.0, "soft"), (round(PI, 12), "soft")]


@pytest.mark.parametrize("law", ["sine", "poly345"])
def test_sine_and_poly345_have_no_impacts(law):
    assert impacts(cycle(0.05, law, PI / 2)) == ()
    prog = MotionProgram(0.05, (Segment("rise", 1.0, law), Segment("return", 2 * PI - 1.0, law)))
    assert impacts(prog) == ()


def test_impact_and_extremum_are_frozen():
    imp = impacts(cycle(0.05, "uniform", PI / 2))[0]
    assert isinstance(imp, Impact)
    with pytest.raises(dataclasses.FrozenInstanceError):
        imp.jump = 0.0  # type: ignore[misc]
    ext = maxima(cycle(0.05, "sine", PI / 2), 1.0)["v"]
    with pytest.raises(dataclasses.FrozenInstanceError):
        ext.value = 0.0  # type: ignore[misc]


def test_breakpoints_are_the_joints():
    prog = MotionProgram(0.01, (Segment("dwell", 0.3), Segment("rise", 1.0, "parabolic"),
                                Segment("dwell", 0.7), Segment("return", 2 * PI - 2.0, "sine")))
    np.testing.assert_array_equal(breakpoints(prog), [0.0, 0.3, 1.3, 2.0])


@pytest.mark.parametrize("bad_angle", [0.0, -0.1, math.nan, math.inf])
def test_validate_rejects_a_dwell_of_angle_not_above_zero(bad_angle):
    prog = MotionProgram(0.05, (Segment("rise", PI, "sine"), Segment("dwell", bad_angle),
                                Segment("return", PI, "sine")))
    problems = validate(prog)
    assert len(problems) == 1
    key, reason = problems[0]
    assert key == "program.segments[1].angle"
    assert ("> 0" in reason) if math.isfinite(bad_angle) else ("finite" in reason)
    with pytest.raises(SceneError) as err:  # every function refuses it, naming the key path
        displacement(prog, 0.0)
    assert err.value.problems == problems
    assert "program.segments[1].angle" in str(err.value)
    # the zero dwell simply left out: valid
    assert validate(MotionProgram(0.05, (Segment("rise", PI, "sine"), Segment("return", PI, "sine")))) == []


def test_validate_collects_every_problem():
    prog = MotionProgram(-1.0, (Segment("return", 1.0, "sine"), Segment("rise", 1.0, "magic"),
                                Segment("rise", 1.0, "cosine"), Segment("bounce", 1.0)))  # type: ignore[arg-type]
    keys = dict(validate(prog))
    assert "program.stroke" in keys
    assert "return with the follower down" in keys["program.segments[0].kind"]
    assert "unknown law 'magic'" in keys["program.segments[1].law"]
    assert "rise after a rise" in keys["program.segments[2].kind"]
    assert "program.segments[3].kind" in keys
    problems = validate(prog)
    assert any(k == "program.segments" and "return after its last rise" in r for k, r in problems)
    assert any(k == "program.segments" and "add up to 4 rad" in r for k, r in problems)


def test_validate_angle_sum_tolerance():
    ok = MotionProgram(0.05, (Segment("rise", PI + 4e-10, "sine"), Segment("return", PI, "sine")))
    assert validate(ok) == []
    off = MotionProgram(0.05, (Segment("rise", PI + 2e-9, "sine"), Segment("return", PI, "sine")))
    assert [k for k, _ in validate(off)] == ["program.segments"]


@pytest.mark.parametrize(("table", "key", "words"), [
    (((0.0, 0.1), (1.0, 1.0)), "program.segments[0].table[0]", "first point must be (0, 0)"),
    (((0.0, 0.0), (0.5, 0.5), (1.0, 0.9)), "program.segments[0].table[2]", "last point must be (1, 1)"),
    (((0.0, 0.0), (0.5, 0.5), (0.5, 0.6), (1.0, 1.0)), "program.segments[0].table[2]", "increase strictly"),
    (((0.0, 0.0), (0.4, 0.6), (0.6, 0.5), (1.0, 1.0)), "program.segments[0].table[2]", "must not decrease"),
    (((0.0, 0.0), (0.5, math.nan), (1.0, 1.0)), "program.segments[0].table[1]", "finite"),
    (((0.0, 0.0),), "program.segments[0].table", "at least"),
])
def test_validate_table_points(table, key, words):
    prog = MotionProgram(0.05, (Segment("rise", PI, "table", table), Segment("return", PI, "sine")))
    problems = dict(validate(prog))
    assert words in problems[key]


def test_one_degree_rise_evaluates_accurately():
    h, d0 = 0.01, math.radians(1.0)
    prog = MotionProgram(h, (Segment("rise", d0, "sine"), Segment("return", 2 * PI - d0, "cosine")))
    assert validate(prog) == []
    assert displacement(prog, d0 / 2) == pytest.approx(h / 2, rel=1e-13)
    assert displacement(prog, d0 / 2, 1) == pytest.approx(2 * h / d0, rel=1e-13)  # sine f'(½) = 2
    assert displacement(prog, d0 / 4, 2) == pytest.approx(2 * PI * h / d0**2, rel=1e-12)
    assert displacement(prog, 0.0, 3) == pytest.approx(4 * PI**2 * h / d0**3, rel=1e-13)
    x = np.linspace(0, 1, 11)[:-1]  # the whole rise against the closed form
    np.testing.assert_allclose(displacement(prog, x * d0), h * (x - np.sin(2 * PI * x) / (2 * PI)),
                               rtol=1e-13, atol=1e-17)
    # at the joint the return's values (right-hand limits): s = h, s' = 0, s'' = −π²h/(2·δr²)
    dr = 2 * PI - d0
    assert displacement(prog, d0) == h
    assert displacement(prog, d0, 1) == 0.0
    assert displacement(prog, d0, 2) == pytest.approx(-PI**2 / 2 * h / dr**2, rel=1e-13)
    m = maxima(prog, 1.0)
    assert m["a"].value == pytest.approx(2 * PI * h / d0**2, rel=1e-13)
    assert m["a"].at == pytest.approx(d0 / 4, rel=1e-13)


def test_argument_errors():
    prog = cycle(0.05, "sine", PI / 2)
    with pytest.raises(ValueError, match="order"):
        displacement(prog, 0.0, 4)
    with pytest.raises(ValueError, match="finite"):
        displacement(prog, [0.0, math.nan])
    with pytest.raises(ValueError, match="omega"):
        maxima(prog, math.inf)


# ------------------------------------------------------------------------------------------------
# 3. finite differences reproduce the next derivative (Hypothesis)
# ------------------------------------------------------------------------------------------------


@st.composite
def tables(draw: st.DrawFn) -> tuple[tuple[float, float], ...]:
    n = draw(st.integers(1, 6))  # interior points
    dx = np.array(draw(st.lists(st.floats(0.2, 1.0), min_size=n + 1, max_size=n + 1)))
    dy = np.array(draw(st.lists(st.floats(0.05, 1.0), min_size=n + 1, max_size=n + 1)))
    xs, ys = np.cumsum(dx) / dx.sum(), np.cumsum(dy) / dy.sum()
    return ((0.0, 0.0),) + tuple(zip(xs[:-1].tolist(), ys[:-1].tolist())) + ((1.0, 1.0),)


@st.composite
def programs(draw: st.DrawFn) -> MotionProgram:
    kinds: list[str] = []
    for _ in range(draw(st.integers(1, 2))):
        kinds.append("rise")
        if draw(st.booleans()):
            kinds.append("dwell")
        kinds.append("return")
        if draw(st.booleans()):
            kinds.append("dwell")
    weights = np.array(draw(st.lists(st.floats(0.3, 3.0), min_size=len(kinds), max_size=len(kinds))))
    angles = weights / weights.sum() * 2 * PI
    segments = []
    for kind, angle in zip(kinds, angles.tolist()):
        if kind == "dwell":
            segments.append(Segment("dwell", angle))
        else:
            law = draw(st.sampled_from(["parabolic", "cosine", "sine", "poly345", "table"]))
            segments.append(Segment(kind, angle, law, draw(tables()) if law == "table" else ()))  # type: ignore[arg-type]
    return MotionProgram(draw(st.floats(1e-3, 1.0)), tuple(segments))


@settings(max_examples=80, deadline=None)
@given(programs())
def test_central_differences_reproduce_the_next_derivative(prog):
    assert validate(prog) == []
    starts = breakpoints(prog)
    for seg, start in zip(prog.segments, starts):
        d0 = seg.angle
        x = np.linspace(0.02, 0.98, 25)
        knots = [0.5] if seg.law == "parabolic" else [p[0] for p in seg.table[1:-1]] if seg.law == "table" else []
        for k in knots:  # away from the law's own joints too
            x = x[np.abs(x - k) > 0.01]
        delta, e = start + x * d0, 2e-5 * d0
        dense = start + np.linspace(0.0, 1.0, 2001)[:-1] * d0
        for k in range(3):
            fd = (displacement(prog, delta + e, k) - displacement(prog, delta - e, k)) / (2 * e)
            exact = displacement(prog, delta, k + 1)
            # the segment's size of it (at least h/δ0^(k+1): a straight table's s'' is rounding)
            scale = max(np.max(np.abs(displacement(prog, dense, k + 1))), prog.stroke / d0 ** (k + 1))
            assert np.all(np.abs(fd - exact) <= 1e-6 * scale), (seg, k)
            assert np.all(np.isfinite(exact))


# ------------------------------------------------------------------------------------------------
# 4. the table law
# ------------------------------------------------------------------------------------------------


def test_table_of_37_points_reproduces_the_cosine_law():
    h, d0 = 0.05, PI / 2
    xs = np.linspace(0.0, 1.0, 37)
    table = tuple(zip(xs.tolist(), ((1 - np.cos(PI * xs)) / 2).tolist()))
    table = ((0.0, 0.0),) + table[1:-1] + ((1.0, 1.0),)
    tab, cos = cycle(h, "table", d0, table), cycle(h, "cosine", d0)
    grid = np.linspace(0.0, 2 * PI, 20_001)
    s_tab = displacement(tab, grid)
    assert np.max(np.abs(s_tab - displacement(cos, grid))) <= 1e-3 * h
    # it passes through the points
    np.testing.assert_allclose(displacement(tab, xs[:-1] * d0), h * np.array(table)[:-1, 1], rtol=1e-14, atol=1e-18)
    # monotone: non-decreasing on the rise, non-increasing on the return, and never overshoots
    rise, ret = (grid >= 0) & (grid < d0), (grid >= PI) & (grid < PI + d0)
    assert np.all(np.diff(s_tab[rise]) >= 0) and np.all(displacement(tab, grid[rise], 1) >= 0)
    assert np.all(np.diff(s_tab[ret]) <= 0) and np.all(displacement(tab, grid[ret], 1) <= 0)
    assert np.all(s_tab >= 0.0) and np.all(s_tab <= h)
    # its maxima are exact for the interpolant (never below a dense evaluation) and near the cosine law's
    m_tab, m_cos = maxima(tab, 10.0), maxima(cos, 10.0)
    fine = np.linspace(0.0, 2 * PI, 400_001)
    for k, key in ((1, "v"), (2, "a")):
        sampled = np.max(np.abs(10.0**k * displacement(tab, fine, k)))
        assert sampled <= m_tab[key].value * (1 + 1e-12)
        assert sampled >= m_tab[key].value * (1 - 1e-4)
    assert rel(m_tab["v"].value, m_cos["v"].value) <= 1e-2


def test_table_law_impacts_are_those_of_the_interpolant():
    # a straight-line table is the uniform law: rigid impacts at the ends, nothing inside
    line = ((0.0, 0.0), (0.25, 0.25), (0.5, 0.5), (1.0, 1.0))
    got = impacts(cycle(0.05, "table", PI / 2, line))
    assert [i.kind for i in got] == ["rigid"] * 4
    np.testing.assert_allclose(displacement(cycle(0.05, "table", PI / 2, line), [0.3, 1.0], 1), 0.05 / (PI / 2),
                               rtol=1e-13)


def test_scipy_is_imported_only_for_a_table_law():
    code = (
        "import sys, math\n"
        "from graphmech.mechanisms.cam import MotionProgram, Segment\n"
        "from graphmech.mechanisms import motion\n"
        "p = MotionProgram(0.05, (Segment('rise', math.pi, 'sine'), Segment('return', math.pi, 'parabolic')))\n"
        "motion.displacement(p, [0.1, 2.0], 2); motion.impacts(p); motion.maxima(p, 1.0)\n"
        "assert 'scipy' not in sys.modules\n"
        "t = MotionProgram(0.05, (Segment('rise', math.pi, 'table', ((0, 0), (0.5, 0.4), (1, 1))),"
        " Segment('return', math.pi, 'sine')))\n"
        "motion.displacement(t, 1.0)\n"
        "assert 'scipy' in sys.modules\n"
    )
    run = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stderr


# ------------------------------------------------------------------------------------------------
# 5. vectorised evaluation
# ------------------------------------------------------------------------------------------------


def test_3600_angles_at_once(monkeypatch):
    h, d0 = 0.05, PI / 2
    prog = cycle(h, "sine", d0)
    delta = np.arange(3600) * (2 * PI / 3600)

    calls = []
    law = motion._f

    def counting(*args, **kwargs):
        calls.append(np.shape(args[1]))
        return law(*args, **kwargs)

    monkeypatch.setattr(motion, "_f", counting)
    s = displacement(prog, delta)
    assert s.shape == (3600,)
    assert len(calls) <= 2  # one call per moving segment, each with all its angles at once
    assert sum(np.prod(c) for c in calls) == np.count_nonzero((delta < d0) | ((delta >= PI) & (delta < PI + d0)))
    monkeypatch.undo()

    # the closed form, piece by piece
    x_r = delta / d0
    x_t = (delta - PI) / d0
    f = lambda x: x - np.sin(2 * PI * x) / (2 * PI)
    expected = np.select([delta < d0, delta < PI, delta < PI + d0], [h * f(x_r), h, h * (1 - f(x_t))], 0.0)
    np.testing.assert_allclose(s, expected, rtol=1e-13, atol=1e-17)
    # any shape, and angles outside [0, 2π) taken modulo 2π
    np.testing.assert_array_equal(displacement(prog, delta.reshape(60, 60)), s.reshape(60, 60))
    np.testing.assert_allclose(displacement(prog, delta - 4 * PI), s, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(displacement(prog, delta + 2 * PI, 1), displacement(prog, delta, 1), rtol=1e-11, atol=1e-14)
    # the same as one angle at a time
    for i in range(0, 3600, 97):
        assert displacement(prog, float(delta[i]), 2) == displacement(prog, delta, 2)[i]
    assert displacement(prog, 0.3).shape == ()
    for k in range(4):
        assert np.all(np.isfinite(displacement(cycle(h, "uniform", d0), delta, k)))
