"""The function task: a four-bar function generator by Freudenstein's equation — the lengths drawn
at μl against the exact rational solve, the precision points reached, the structural error read
off the sampled curve against the located extreme, the figure, the steps, the refusals."""
from __future__ import annotations

import json
import math
from fractions import Fraction

import numpy as np
import pytest

from graphmech.errors import GraphmechError, SceneError
from graphmech.exact.freudenstein import FourBar, output_angle
from graphmech.methods.freudenstein import design, named_function
from graphmech.problems.synthesis.check import (
    analyse_synthesis,
    judge_synthesis,
    text_lines,
)
from graphmech.problems.synthesis.figures import synthesis_sheet
from graphmech.problems.synthesis.function import (
    exact_lengths,
    exact_R,
    gamma_min_range,
    lengths_from_R,
)
from graphmech.problems.synthesis.steps import protocol
from tests.conftest import SCENES, assert_refused, run_cli
from tests.scenes import parse_text, replace_once, write_scene

LOG10 = (SCENES / "synthesis.function_log10.toml").read_text(encoding="utf-8")
D = math.radians


def _rows(text: str) -> dict:
    return {r.name: r for r in analyse_synthesis(parse_text(text)).rows}


def _with(**keys: str) -> str:
    """The classic scene with keys replaced (``phi_start_deg="0"``)."""
    text = LOG10
    for k, v in keys.items():
        line = next(ln for ln in text.splitlines() if ln.startswith(f"{k} = "))
        text = replace_once(text, line, f"{k} = {v}")
    return text


def test_the_log10_classic_is_drawn_measured_and_reanalysed():
    an = analyse_synthesis(parse_text(LOG10))
    rows = {r.name: r for r in an.rows}
    # Freudenstein's lengths for the frame d = 50 mm (the method's, as its own test states them for d = 1)
    assert rows["lAB"].exact == pytest.approx(0.05 * 1.8508606189, abs=1e-11)
    assert rows["lBC"].exact == pytest.approx(0.05 * 2.8680075409, abs=1e-11)
    assert rows["lCD"].exact == pytest.approx(0.05 * 1.9205111315, abs=1e-11)
    assert an.scales["l"] == 0.002 and rows["lAB"].drawn_mm == pytest.approx(46.27151547, rel=1e-9)
    assert rows["lAD"].drawn_mm == 25.0 and max(rows[n].rel_error for n in ("lAB", "lBC", "lCD", "lAD")) < 1e-14
    assert rows["reanalysis_error"].exact < 1e-12 and rows["reanalysis_error"].graphical < 1e-12
    # the structural error: the largest at x = 1 (an end: the sampled curve has it exactly)
    s = rows["structural_error_max"]
    assert s.exact == pytest.approx(0.1686366204, abs=1e-9) and s.graphical == pytest.approx(s.exact, rel=1e-10)
    assert s.error_source == "discretisation" and s.basis == "201 samples of the curve"
    assert (rows["x_error_max"].graphical, rows["x_error_max"].exact) == (1.0, 1.0)
    assert rows["gamma_min_range"].exact == pytest.approx(23.4575785, abs=1e-6)
    assert an.warnings == []
    sol = an.solutions[0]
    assert sol["grashof"] == "double_rocker" and sol["input_reversed"] and not sol["output_reversed"]
    assert sol["condition"] == pytest.approx(17.818093697, rel=1e-8)
    assert np.degrees(sol["structural_error"]["extremes_deg"][1]) != 0.0
    assert sol["structural_error"]["extremes_deg"] == pytest.approx([-0.1686366, 0.1270480, -0.0711612, 0.0521220],
                                                                   abs=1e-6)
    lines = text_lines(an)
    assert lines[0].startswith("design: l_AB = 92.543 mm, l_BC = 143.4 mm, l_CD = 96.0256 mm, l_AD = 50 mm: "
                               "double rocker; AB points at φ + 180° (R₂ < 0); re-analysed at the 3 precision points")
    assert lines[1].startswith("structural error (chebyshev spacing): largest 0.1686° at x = 1 ")


def test_uniform_spacing_gives_a_larger_structural_error_than_chebyshev():
    cheb = _rows(LOG10)
    uni = _rows(_with(spacing='"uniform"'))
    assert uni["structural_error_max"].exact == pytest.approx(0.1962396139, abs=1e-9)
    assert cheb["structural_error_max"].exact < 0.86 * uni["structural_error_max"].exact
    # uniform: the largest error inside the range, read off 201 samples — within the curve's own estimate
    u, x = uni["structural_error_max"], uni["x_error_max"]
    assert 1.0 < x.exact < 2.0 and abs(x.graphical - x.exact) <= 0.5 / 200
    assert u.rel_error <= u.error_estimate + 1e-12 and 0.0 < u.rel_error < 1e-4


def test_the_exact_solve_is_rational_and_agrees_with_the_method():
    f = named_function("log10")
    for n in (2, 3, 4, 5):
        r = design(f, 1.0, 2.0, D(45), D(60), D(135), D(90), d=0.05, n=n)
        R = exact_R(r.phi, r.psi)
        assert all(isinstance(v, Fraction) for v in R)
        assert [float(v) for v in R] == pytest.approx(list(r.R), rel=1e-12, abs=1e-15)
        ex = exact_lengths(r.phi, r.psi, 0.05)
        assert (ex["a"], ex["b"], ex["c"]) == pytest.approx((r.a, r.b, r.c), rel=1e-12)
        assert (ex["sa"] < 0, ex["sc"] < 0) == (r.input_reversed, r.output_reversed)
    # three points: every equation holds exactly in rational arithmetic
    r = design(f, 1.0, 2.0, D(45), D(60), D(135), D(90))
    R1, R2, R3 = exact_R(r.phi, r.psi)
    for a, b in zip(r.phi, r.psi):
        assert R1 * Fraction(math.cos(a)) - R2 * Fraction(math.cos(b)) + R3 == Fraction(math.cos(a - b))


def test_no_real_coupler_and_an_infinite_link_are_said():
    with pytest.raises(GraphmechError, match=r"no real coupler: b² = a² \+ c² \+ d² − 2ac·R₃ = -1 ≤ 0"):
        lengths_from_R(Fraction(1), Fraction(1), Fraction(2), 1.0)  # a = c = d = 1, R₃ = 2
    with pytest.raises(GraphmechError, match="infinitely long"):
        lengths_from_R(Fraction(0), Fraction(1), Fraction(0), 1.0)


@pytest.mark.parametrize(("phi0", "dphi"), [(D(45), D(60)), (D(150), D(80)), (D(-30), D(-100))])
def test_gamma_min_over_the_range_in_closed_form_is_the_sampled_minimum(phi0: float, dphi: float):
    bar = FourBar(0.4, 1.1, 0.9, 1.0)
    phis = phi0 + dphi * np.linspace(0.0, 1.0, 200001)
    psi, ok = output_angle(bar, phis, "left")
    assert ok.all()
    B = bar.a * np.exp(1j * phis)
    C = -bar.d + bar.c * np.exp(1j * psi)
    delta = np.arccos(np.real((B - C) * np.conj(-bar.d - C)) / (bar.b * bar.c))
    gamma = np.minimum(delta, np.pi - delta)
    assert gamma_min_range(bar, phi0, dphi) == pytest.approx(float(gamma.min()), abs=1e-9)


def test_near_dependent_points_are_warned_of_and_flagged():
    an = analyse_synthesis(parse_text(_with(phi_range_deg="5", psi_range_deg="5")))
    assert len(an.warnings) == 1 and an.warnings[0].startswith(
        "the precision points are nearly dependent: Freudenstein's system has the condition number 1.24e+03")
    assert all(r.ill_conditioned for r in an.rows)


def test_two_and_five_points_are_said():
    two = analyse_synthesis(parse_text(_with(points="2")))
    assert two.warnings == ["2 precision points: one of R₁, R₂, R₃ is free; the minimum-norm solution is taken"]
    assert {r.name: r for r in two.rows}["reanalysis_error"].exact < 1e-12
    five = analyse_synthesis(parse_text(_with(points="5")))
    assert five.warnings[0].startswith("5 precision points: Freudenstein's equation is met in least squares")
    rows = {r.name: r for r in five.rows}
    assert rows["reanalysis_error"].exact == pytest.approx(0.00124531633, rel=1e-6)  # near, not through
    assert rows["structural_error_max"].exact == pytest.approx(0.124392921, rel=1e-6)


def test_a_hand_length_is_judged():
    verdicts = judge_synthesis(analyse_synthesis(parse_text(LOG10 + "\n[measured]\nlBC = 0.1434\nlAB = 0.0900\n")))
    assert [(v.name, v.ok) for v in verdicts] == [("lBC", True), ("lAB", False)]


def test_the_figure_draws_the_linkage_and_the_error_curve():
    from graphmech.drawing.primitives import Circle, Polyline, Segment

    an = analyse_synthesis(parse_text(LOG10))
    sheet = synthesis_sheet(an, (297.0, 210.0))
    link, err = sheet.panels
    segs = [i for i in link.items if isinstance(i, Segment)]
    assert len([s for s in segs if s.role == "result"]) == 3  # A B₁, B₁ C₁, C₁ D
    assert len([s for s in segs if s.dashed]) == 6  # AB_k, B_kC_k, DC_k at the two other positions
    assert len([s for s in segs if s.dashdot]) == 1  # the frame line
    assert link.notes[1] == "l_{AB} = 92.54 mm, l_{BC} = 143.4 mm, l_{CD} = 96.03 mm, l_{AD} = 50 mm"
    curve = [i for i in err.items if isinstance(i, Polyline) and i.role == "result"]
    assert len(curve) == 1 and len(curve[0].points) == 201
    ys = [y for _, y in curve[0].points]
    assert min(ys) == pytest.approx(-0.1686366204 / 0.005, rel=1e-9)  # μψ = 0.005 °/mm
    assert curve[0].points[0][0] == 0.0 and curve[0].points[-1][0] == pytest.approx(100.0)
    marks = [i.center for i in err.items if isinstance(i, Circle) and i.center[1] == 0.0]
    assert [x for x, _ in marks] == pytest.approx([6.698729810778, 50.0, 93.301270189222])  # Chebyshev x_k
    assert err.notes[0] == "μ_{ψ} = 0.005 °/mm, μ_{x} = 0.01 /mm" and err.scales == (("psi", D(0.005)),)


@pytest.mark.parametrize(("notation", "first", "last"), [
    ("en", "the 3 precision points (Chebyshev spacing): x_k = 1.067, 1.5, 1.933",
     "the structural error over the range is largest, 0.1686°, at x = 1 (201 samples)"),
    ("zh", "3个精确点（切比雪夫间隔）：x_k = 1.067, 1.5, 1.933", "全程结构误差最大0.1686°，在x = 1处（201个采样点）"),
    ("ru", "3 точки точного воспроизведения (по Чебышёву): x_k = 1.067, 1.5, 1.933",
     "структурная ошибка на всём диапазоне наибольшая, 0.1686°, при x = 1 (точек: 201)"),
])
def test_the_steps_in_three_languages(notation: str, first: str, last: str):
    text = replace_once(LOG10, '[synthesis]', f'[page]\nnotation = "{notation}"\n\n[synthesis]')
    lines = protocol(analyse_synthesis(parse_text(text)))
    assert len(lines) == 6 and lines[1].startswith(first) and lines[-1].endswith(last)
    assert "46.27 mm" in lines[4] and "71.7 mm" in lines[4]  # AB₁ drawn, B₁C₁ measured


def test_check_json_reports_the_design(tmp_path):
    code, out, err = run_cli("check", str(SCENES / "synthesis.function_log10.toml"), "--json")
    assert code == 0, err
    doc = json.loads(out)
    sol = doc["synthesis"]["solutions"][0]
    assert doc["synthesis"]["task"] == "function" and sol["function"] == "log10"
    assert sol["precision_points"]["x"] == pytest.approx([1.0669872981, 1.5, 1.9330127019])
    assert sol["structural_error"]["max_deg"] == pytest.approx(0.1686366204, abs=1e-9)


@pytest.mark.parametrize(("keys", "where", "words"), [
    ({"function": '"log"'}, "synthesis.function", "unknown value 'log': use log10, ln, exp, sqrt, square, cube, reciprocal, sin, cos, tan or power (did you mean log10?)"),
    ({"x_range": "[-1, 2]"}, "synthesis.x_range", "log10 over [-1, 2]: log10 needs x > 0 over the range"),
    ({"x_range": "[0, 2]"}, "synthesis.x_range", "log10 needs x > 0"),
    ({"x_range": "[1, 1]"}, "synthesis.x_range", "the range of x is empty"),
    ({"points": "6"}, "synthesis.points", "6 precision points: 2 … 5 are offered"),
    ({"points": "1"}, "synthesis.points", "1 precision points: 2 … 5 are offered"),
    ({"points": "2.5"}, "synthesis.points", "must be a whole number"),
    ({"phi_range_deg": "0"}, "synthesis.phi_range_deg", "Δφ = 0: the input crank does not turn"),
    ({"psi_range_deg": "0"}, "synthesis.psi_range_deg", "Δψ = 0"),
    ({"spacing": '"random"'}, "synthesis.spacing", "unknown value"),
    ({"function": '"power"'}, "synthesis.exponent", 'missing: function = "power" needs exponent'),
    ({"phi_start_deg": "0", "psi_start_deg": "45", "psi_range_deg": "-90"}, "synthesis.psi_range_deg",
     "cannot be assembled on the right branch from φ = 57.8700° on (no continuous motion over the range)"),
    ({"phi_start_deg": "0", "psi_start_deg": "0", "psi_range_deg": "45"}, "synthesis.psi_range_deg",
     "the precision points lie on both assembly branches"),
    ({"phi_start_deg": "210", "phi_range_deg": "90", "psi_start_deg": "225", "psi_range_deg": "-90", "points": "4"},
     "synthesis.psi_range_deg", "cannot be assembled at the first precision point φ = 213.4254° on either branch"),
])
def test_what_no_generator_answers_is_refused_in_one_line(tmp_path, keys: dict, where: str, words: str):
    scene = write_scene(tmp_path, _with(**keys), "fn.toml")
    for argv in (("check", str(scene)), ("render", str(scene), "-o", str(tmp_path / "x.svg"))):
        line = assert_refused(run_cli(*argv), "fn.toml", words)
        assert line.startswith(f"fn.toml: {where}: ")
    assert not (tmp_path / "x.svg").exists()


def test_a_power_takes_its_exponent_and_only_it_does():
    rows = _rows(_with(function='"power"').replace('x_range', 'exponent = 0.5\nx_range'))
    assert rows["reanalysis_error"].exact < 1e-12
    with pytest.raises(SceneError) as e:
        parse_text(LOG10.replace("x_range", "exponent = 2\nx_range"))
    assert e.value.problems == [("synthesis.exponent", 'log10 takes no exponent (only function = "power" does)')]


@pytest.mark.parametrize(("keys", "words"), [
    ({"x_range": "[1e308, 1]"}, "|x| up to 1e+308: beyond 1e+06 (scale x first)"),
    ({"x_range": "[1, 1.000000000000001]"}, "is too narrow for double precision"),
    ({"x_range": "[-1, 1]", "function": '"cos"'}, "f(x₀) = f(x₁) = 0.540302: the output's swing cannot be laid on y"),
    ({"x_range": "[1, 2]", "function": '"tan"'}, "tan has a pole at x = 1.5708 rad, inside the range"),
])
def test_ranges_double_precision_cannot_carry_are_refused_at_x_range(keys: dict, words: str):
    with pytest.raises(SceneError) as e:
        parse_text(_with(**keys))
    assert len(e.value.problems) == 1 and e.value.problems[0][0] == "synthesis.x_range"
    assert words in e.value.problems[0][1]


def test_a_range_ending_on_the_domains_edge_is_sampled_inside_it():
    # sqrt over [0.5, 0]: x from φ rounds a hair below 0 at the end (sqrt(−1e-17) is NaN): clipped
    text = _with(function='"sqrt"', x_range="[0.5, 0]", phi_start_deg="179.9", phi_range_deg="2",
                 psi_start_deg="179.9", psi_range_deg="10", points="4", spacing='"uniform"', frame_mm="1e9")
    an = analyse_synthesis(parse_text(text))
    sheet = synthesis_sheet(an, (297.0, 210.0))
    assert all(math.isfinite(r.graphical) and math.isfinite(r.exact) for r in an.rows) and len(sheet.panels) == 2
    assert {r.name: r for r in an.rows}["structural_error_max"].exact == pytest.approx(2.45712, rel=1e-4)


def test_a_measured_length_is_judged_in_the_json(tmp_path):
    """A measured l_AB in a function scene: the drawn lengths were numpy scalars, the verdict's ok
    a numpy bool, and ``check --json`` stopped on an internal error (exit 3)."""
    scene = write_scene(tmp_path, LOG10 + "\n[measured]\nlAB = 0.0925\nreanalysis_error = 0.5\n", "fn.toml")
    code, out, err = run_cli("check", "--json", str(scene))
    assert code == 1, err  # reanalysis_error = 0.5 is far off: a failed verdict, not a crash
    verdicts = {v["name"]: v for v in json.loads(out)["measured"]}
    assert verdicts["lAB"]["ok"] is True and verdicts["lAB"]["tolerance"] == pytest.approx(0.001)
    assert verdicts["reanalysis_error"]["ok"] is False
    assert all(type(r.graphical) is float for r in analyse_synthesis(parse_text(LOG10)).rows)


@pytest.mark.parametrize(("frame", "words"), [
    ("1e-300", "synthesis.frame_mm: 1e-303 m is below 1e-09 m: too short for a link to be designed in double precision"),
    ("1e300", "synthesis.frame_mm: 1e+297 m is beyond 1e+06 m: too large for a linkage to be designed in double precision"),
])
def test_a_frame_out_of_double_precision_is_refused_at_its_key(tmp_path, frame: str, words: str):
    """frame_mm = 1e-300 was refused at synthesis.psi_range_deg ('no real coupler: b² … = 0'): b²
    underflowed, and the key named was not the one at fault."""
    scene = write_scene(tmp_path, _with(frame_mm=frame), "fn.toml")
    assert_refused(run_cli("check", str(scene)), "fn.toml", words)


def test_a_nanometre_frame_is_still_designed():
    rows = _rows(_with(frame_mm="1e-6"))
    assert rows["lAD"].exact == pytest.approx(1e-9) and rows["lAB"].exact == pytest.approx(0.09254303094497704 / 5e7)
