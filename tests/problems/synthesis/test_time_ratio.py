"""The time-ratio task: the bank's crank-rocker (two designs, the book's values within its flagged
reading), each design re-analysed to 1e-9, and the extremes: K = 1, K near 3, no Grashof crank."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.errors import SceneError
from graphmech.problems import check
from graphmech.problems.synthesis.time_ratio import analyse_time_ratio, names, prefix
from graphmech.scene import load_scene
from tests.conftest import SCENES, reference_problem
from tests.scenes import parse_text, replace_once, scene_text

BANK = "linkage.crank_rocker_synthesis_K1.5"
SWING = scene_text("synthesis/swing")


def _rows(scene):
    an, _verdicts, extras, lines = check(scene)
    return {r.name: r for r in an.rows}, extras, lines


def test_the_banks_two_designs_are_its_exact_values_and_the_books_within_its_flag():
    ref = reference_problem(BANK)
    rows, extras, lines = _rows(load_scene(SCENES / f"{BANK}.toml"))
    assert rows["theta"].graphical == pytest.approx(ref["exact"]["theta_deg"], abs=1e-12)
    for k in (1, 2):
        for n in ("lAB", "lBC", "AC1", "AC2"):
            r = rows[f"sol{k}_{n}"]
            assert r.graphical * 1000 == pytest.approx(ref["exact"][f"sol{k}_{n}_mm"], rel=1e-12)
            assert r.rel_error < 1e-12
            assert abs(ref["book"][f"sol{k}_{n}_mm"] / (r.exact * 1000) - 1) <= ref["max_abs_rel_diff"] + 1e-12
        assert rows[f"sol{k}_K"].exact == pytest.approx(1.5, abs=1e-12)
    sols = extras["synthesis"]["solutions"]
    assert [s["name"] for s in sols] == ["sol1", "sol2"] and all(s["grashof"] == "crank_rocker_AB" for s in sols)
    for s in sols:  # the re-analysis error of each design: K and the 45° limit
        assert s["reanalysis"]["K_error"] < 1e-9 and s["reanalysis"]["limit_angle_error_deg"] < 1e-9
    assert lines[0].startswith("sol1: l_AB = 49.3118 mm, l_BC = 120.152 mm: crank-rocker")


def test_one_design_takes_no_prefix_and_reproduces_its_swing():
    rows, extras, _ = _rows(parse_text(SWING))
    assert set(rows) == set(names(1)) and "K" in rows and prefix(0, 1) == ""
    assert rows["psi"].exact == pytest.approx(40.0, abs=1e-9) and rows["K"].exact == pytest.approx(1.4, abs=1e-9)
    assert extras["synthesis"]["solutions"][0]["reanalysis"]["psi_error_deg"] < 1e-9
    assert all(r.rel_error < 1e-9 for r in rows.values())


def test_K_1_designs_without_quick_return_and_says_so():
    scene = parse_text(replace_once(SWING, "K = 1.4", "K = 1"))
    found = analyse_time_ratio(scene.problem.problem, 0.002)
    assert found.rows[0].exact == 0.0 and any("no quick return" in w for w in found.warnings)
    assert {r.name: r for r in found.rows}["K"].exact == pytest.approx(1.0, abs=1e-9)


def test_K_near_3_designs_with_theta_near_90():
    text = replace_once(replace_once(replace_once(SWING, "K = 1.4", "K = 2.99"), "rocker_mm = 75", "rocker_mm = 150"),
                        "swing_deg = 40", "swing_deg = 90")
    rows, _, _ = _rows(parse_text(text))
    assert rows["theta"].exact == pytest.approx(89.774, abs=1e-3)
    assert rows["K"].exact == pytest.approx(2.99, rel=1e-9) and rows["psi"].exact == pytest.approx(90, abs=1e-9)


def test_a_swing_with_no_grashof_crank_is_said_in_one_line():
    text = replace_once(replace_once(SWING, "rocker_mm = 75", "rocker_mm = 50"), "swing_deg = 40", "swing_deg = 60")
    with pytest.raises(SceneError) as e:
        check(parse_text(text, "s.toml"))
    ((where, why),) = e.value.problems
    assert where == "synthesis.swing_deg" and why.startswith("no Grashof crank: no crank-rocker with l_CD = 0.05 m")


@settings(max_examples=300, deadline=None)
@given(K=st.floats(1.0, 2.999), c=st.floats(1.0, 500.0), ratio=st.floats(0.2, 5.0), angle=st.floats(5.0, 175.0),
       swing=st.booleans())
def test_any_asked_design_is_designed_to_1e_9_or_refused_in_words(K, c, ratio, angle, swing):
    # (a rocker under 1/5 of the frame at a limit within 5° of the frame line is a near dead point:
    # the re-analysis there loses digits to the folded triangle BCD, not to the construction)
    d = c * ratio
    key = "swing_deg" if swing else "limit_angle_deg"
    text = (f'[synthesis]\ntask = "time_ratio"\nmechanism = "crank_rocker"\nK = {K!r}\nrocker_mm = {c!r}\n'
            f"frame_mm = {d!r}\n{key} = {angle!r}\n")
    try:
        an, _, extras, _ = check(parse_text(text))
    except SceneError as e:
        assert len(e.problems) == 1
        return
    for r in an.rows:  # the lengths to round-off; the re-analysis near a dead point (ψ → 180°) a little worse
        assert r.rel_error < (1e-9 if r.unit == "m" else 1e-7), r
    for s in extras["synthesis"]["solutions"]:
        assert s["reanalysis"]["K_error"] < 1e-9 and s["grashof"] == "crank_rocker_AB"
        assert next(v for k, v in s["reanalysis"].items() if k.endswith("_error_deg")) < 1e-7


def test_a_guide_bar_is_designed_and_reanalysed():
    text = '[synthesis]\ntask = "time_ratio"\nmechanism = "guide_bar"\nK = 2\nframe_mm = 300\nstroke_mm = 400\n'
    rows, extras, lines = _rows(parse_text(text))
    assert list(rows) == ["theta", "lAB", "lCD", "K", "psi", "gamma_min"]
    assert rows["lAB"].graphical == pytest.approx(0.15, rel=1e-12) and rows["lCD"].graphical == pytest.approx(0.4, rel=1e-12)
    assert rows["K"].exact == pytest.approx(2.0, rel=1e-12) and rows["gamma_min"].exact == pytest.approx(90.0)
    assert all(r.rel_error < 1e-12 for r in rows.values())
    re = extras["synthesis"]["solutions"][0]["reanalysis"]
    assert re["K_error"] < 1e-9 and re["psi_error_deg"] < 1e-9
    assert lines[0].startswith("design: l_AB = 150 mm, the bar l_CD = 400 mm: a swinging guide bar")
    rows, _, _ = _rows(parse_text(text.replace("stroke_mm = 400\n", "")))
    assert "lCD" not in rows


@settings(max_examples=200, deadline=None)
@given(K=st.floats(1.000001, 34.99), d=st.floats(1.0, 1000.0), H=st.one_of(st.none(), st.floats(1.0, 1000.0)))
def test_any_guide_bar_is_designed_to_1e_9(K, d, H):
    stroke = "" if H is None else f"stroke_mm = {H!r}\n"
    text = f'[synthesis]\ntask = "time_ratio"\nmechanism = "guide_bar"\nK = {K!r}\nframe_mm = {d!r}\n{stroke}'
    an, _, extras, _ = check(parse_text(text))
    assert all(r.rel_error < 1e-9 for r in an.rows), an.rows
    assert extras["synthesis"]["solutions"][0]["reanalysis"]["K_error"] < 1e-9


def test_a_slider_crank_is_designed_and_reanalysed():
    text = '[synthesis]\ntask = "time_ratio"\nmechanism = "slider_crank"\nK = 1.5\nstroke_mm = 50\noffset_mm = 10\n'
    rows, extras, lines = _rows(parse_text(text))
    assert list(rows) == ["theta", "AC1", "AC2", "lAB", "lBC", "K", "stroke", "gamma_min"]
    assert all(r.rel_error < 1e-12 for r in rows.values())
    assert rows["K"].exact == pytest.approx(1.5, rel=1e-12) and rows["stroke"].exact == pytest.approx(0.05, rel=1e-12)
    re = extras["synthesis"]["solutions"][0]["reanalysis"]
    assert re["K_error"] < 1e-9 and re["stroke_error"] < 1e-9
    assert lines[0].startswith("design: l_AB = 23.3189 mm, l_BC = 37.3419 mm: the crank turns fully")


def test_a_slider_crank_with_no_crank_is_said_in_one_line():
    text = '[synthesis]\ntask = "time_ratio"\nmechanism = "slider_crank"\nK = 2.5\nstroke_mm = 50\noffset_mm = 60\n'
    with pytest.raises(SceneError) as e:
        check(parse_text(text))
    ((where, why),) = e.value.problems
    assert where == "synthesis.offset_mm" and why.startswith("no crank: no slider-crank with H = 0.05 m")


@settings(max_examples=200, deadline=None)
@given(K=st.floats(1.01, 2.999), H=st.floats(1.0, 1000.0), ratio=st.floats(0.01, 2.0))
def test_any_slider_crank_is_designed_to_1e_9_or_refused(K, H, ratio):
    # (an offset under 1 % of the stroke puts A all but on C₁, and K within 1 % of 1 a θ-circle
    # hundreds of strokes across: l_AB is then a difference of nearly equal lengths — the
    # problem's conditioning, not the construction's error)
    text = (f'[synthesis]\ntask = "time_ratio"\nmechanism = "slider_crank"\nK = {K!r}\nstroke_mm = {H!r}\n'
            f"offset_mm = {H * ratio!r}\n")
    try:
        an, _, extras, _ = check(parse_text(text))
    except SceneError as e:
        assert len(e.problems) == 1
        return
    assert all(r.rel_error < (1e-9 if r.unit == "m" else 1e-7) for r in an.rows), an.rows
    assert extras["synthesis"]["solutions"][0]["reanalysis"]["K_error"] < 1e-9


def test_K_near_1_flags_its_lengths_ill_conditioned_and_says_which_cut():
    # θ = 0.009°: the θ-circle's centre O is where two lines meet at θ, its radius ~ 1/θ
    found = analyse_time_ratio(parse_text(replace_once(SWING, "K = 1.4", "K = 1.0001")).problem.problem, 0.002)
    rows = {r.name: r for r in found.rows}
    for k in (1, 2):
        assert all(rows[f"sol{k}_{n}"].ill_conditioned for n in ("AC1", "AC2", "lAB", "lBC"))
        assert not rows[f"sol{k}_K"].ill_conditioned
    assert sum("ill-conditioned intersection" in w and "θ-circle" in w for w in found.warnings) == 2
    # a clear K says nothing of the kind
    clear = analyse_time_ratio(parse_text(SWING).problem.problem, 0.002)
    assert not any(r.ill_conditioned for r in clear.rows) and not clear.warnings


def test_K_near_1_in_a_slider_crank_is_flagged_too():
    text = ('[synthesis]\ntask = "time_ratio"\nmechanism = "slider_crank"\nK = 1.0002\nstroke_mm = 50\n'
            "offset_mm = 10\n")
    an, _, _, _ = check(parse_text(text))
    rows = {r.name: r for r in an.rows}
    assert rows["lAB"].ill_conditioned and any("ill-conditioned intersection" in w for w in an.warnings)


def test_rocker_middle_turns_the_drawing_not_the_design():
    level = parse_text(SWING.replace("swing_deg = 40", "swing_deg = 40\nrocker_middle_deg = 0"))
    upright = analyse_time_ratio(parse_text(SWING).problem.problem, 0.002)
    turned = analyse_time_ratio(level.problem.problem, 0.002)
    assert [r.graphical for r in turned.rows] == pytest.approx([r.graphical for r in upright.rows], rel=1e-12)
    g = turned.drawn[0]
    C1, C2, D, A = g.points["C1"], g.points["C2"], g.points["D"], g.points["A"]
    assert (C1[1] + C2[1]) / 2 == pytest.approx(D[1], abs=1e-12) and C1[0] > D[0]  # level, C right of D
    assert A[1] > D[1]  # A on the left of the middle position DC: above it


def test_rocker_middle_with_a_limit_angle_is_refused():
    text = (SCENES / f"{BANK}.toml").read_text()
    with pytest.raises(SceneError) as e:
        check(parse_text(text.replace("limit_angle_deg = 45", "limit_angle_deg = 45\nrocker_middle_deg = 0"), "s.toml"))
    ((where, why),) = e.value.problems
    assert where == "synthesis.rocker_middle_deg" and "goes with swing" in why


def test_the_cotton_gin_treadle_seed_001_2_5_is_its_closed_form():
    # K = 1: A on the line C1C2 (vertical), 1000 mm from D: l_AB = l_CD sin 10°, l_BC = √(l_AD² − (l_CD cos 10°)²)
    rows, extras, _ = _rows(load_scene(SCENES / "synthesis.cotton_gin_pedal.toml"))
    import math

    assert rows["lAB"].graphical == pytest.approx(0.5 * math.sin(math.radians(10)), rel=1e-12)
    assert rows["lBC"].graphical == pytest.approx(math.sqrt(1.0 - (0.5 * math.cos(math.radians(10))) ** 2), rel=1e-12)
    assert rows["K"].exact == pytest.approx(1.0, abs=1e-12) and rows["psi"].exact == pytest.approx(20.0, abs=1e-9)
    assert extras["synthesis"]["solutions"][0]["grashof"] == "crank_rocker_AB"


def test_the_shaper_and_the_offset_slider_crank_scenes_are_their_closed_forms():
    import math

    rows, _, _ = _rows(load_scene(SCENES / "synthesis.shaper_guide_bar.toml"))
    assert rows["lAB"].graphical == pytest.approx(0.3 * math.sin(math.radians(30)), rel=1e-12)
    assert rows["lCD"].graphical == pytest.approx(0.4 / (2 * math.sin(math.radians(30))), rel=1e-12)
    assert rows["K"].exact == pytest.approx(2.0, rel=1e-12) and rows["psi"].exact == pytest.approx(60.0, rel=1e-12)
    rows, _, _ = _rows(load_scene(SCENES / "synthesis.offset_slider_crank_K1.5.toml"))
    a, b = rows["lAB"].exact, rows["lBC"].exact
    assert rows["lAB"].rel_error < 1e-12 and rows["lBC"].rel_error < 1e-12
    # the designed slider-crank's own limits: stroke √((b+a)²−e²) − √((b−a)²−e²) and θ between them
    e = 0.01
    assert math.sqrt((b + a) ** 2 - e * e) - math.sqrt((b - a) ** 2 - e * e) == pytest.approx(0.05, rel=1e-12)
    theta = math.asin(e / (b - a)) - math.asin(e / (b + a))
    assert math.degrees(theta) == pytest.approx(36.0, rel=1e-12)
