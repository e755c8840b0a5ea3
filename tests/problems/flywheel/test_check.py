"""The flywheel check: only what the scene asks for, and the extreme cases of the issue."""
from __future__ import annotations

import re
import subprocess
import sys

import numpy as np
import pytest

from tests.conftest import SCENES, check_json, run_cli, values
from tests.scenes import scene_text

ENGINE = """\
title = "Engine"
show = {show}
find = {find}

[flywheel]
positions = {n}
cycle_deg = 180
speed_rpm = 620
delta = {delta}
balance = "resisting"
method = "{method}"
inertia_kgm2 = {J}

[[flywheel.load]]
type = "crank"
phi_deg = [0, 20, 50, 180]
moment_Nm = [0, 200, 200, 0]
"""


def engine(tmp_path, *, show='["energy"]', find='["J_F"]', n=36, delta=0.01, method="indicator", J=0.0,
           extra=""):
    p = tmp_path / "e.toml"
    p.write_text(ENGINE.format(show=show, find=find, n=n, delta=delta, method=method, J=J) + extra,
                 encoding="utf-8")
    return p


def test_an_indicator_scene_draws_no_wittenbauer_and_integrates_no_motion(tmp_path):
    from graphmech.problems.flywheel.check import analyse_flywheel
    from graphmech.scene import load_scene

    an = analyse_flywheel(load_scene(engine(tmp_path)))
    assert an.design.wittenbauer is None and an.design.indicator is not None
    assert an.motion is None
    an = analyse_flywheel(load_scene(engine(tmp_path, method="wittenbauer", J=0.5)))
    assert an.design.indicator is None and an.design.wittenbauer is not None and an.motion is None


def test_a_flywheel_check_imports_neither_matplotlib_nor_svgwrite():
    code = ("import sys; from graphmech.cli import main; "
            f"rc = main(['check', r'{SCENES / 'fly.compressor_course_project.toml'}', '--json']); "
            "assert rc == 0; print('matplotlib' in sys.modules, 'svgwrite' in sys.modules)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert r.stdout.split()[-2:] == ["False", "False"]


def test_constant_inertia_wittenbauer_equals_the_energy_indicator(tmp_path):
    """With Jп constant the Wittenbauer diagram is a vertical line of points: its tangents give
    exactly ΔW_max/(ω_m²δ) − J_e, the energy-indicator result."""
    find = '["J_F_wittenbauer", "J_F_indicator", "J_F"]'
    q = values(check_json(engine(tmp_path, method="wittenbauer", J=0.4, find=find)))
    assert q["J_F_wittenbauer"]["graphical"] == pytest.approx(q["J_F_indicator"]["graphical"], rel=1e-12)
    assert q["J_F_wittenbauer"]["exact"] == pytest.approx(q["J_F_indicator"]["exact"], rel=1e-10)


def test_tiny_delta_warns_that_the_tangents_cannot_be_drawn_apart(tmp_path):
    doc = check_json(engine(tmp_path, method="wittenbauer", J=0.5, delta=1e-4, find='["k", "l", "J_F"]'))
    q = values(doc)
    assert any("cannot be told apart" in w for w in doc["warnings"])
    assert q["k"]["ill_conditioned"] and q["l"]["ill_conditioned"]
    # found analytically, J_F itself is as accurate as at any δ (36 positions: the discretisation)
    assert q["J_F"]["rel_error"] < 5e-3
    assert not q["J_F"]["ill_conditioned"]


@pytest.mark.parametrize("delta", [0.5, 0.04, 1e-4])
def test_true_motion_reaches_the_designed_delta_with_the_exact_form(tmp_path, delta):
    """The exact tangent form (1 ± δ/2)² designs a flywheel whose true motion has δ as designed
    (up to the positions' discretisation; 360 positions here); the book form (1 ± δ) does not at δ = 0.5."""
    extra = '\n[flywheel.true_motion]\nsolver = "Radau"\nrtol = 1e-10\n'
    q = values(check_json(engine(tmp_path, method="wittenbauer", J=0.01, delta=delta, n=360,
                                 find='["delta_achieved"]', extra=extra)))
    assert q["delta_achieved"]["rel_error"] <= 1e-7  # ODE against the energy equation, same J_F
    assert q["delta_achieved"]["graphical"] == pytest.approx(delta, rel=1e-3)


def test_book_form_misses_a_large_delta(tmp_path):
    """With Jп varying, the book's (1 ± δ) moves the tangents' touching points: at δ = 0.25 the
    compressor's flywheel so designed lets the speed swing 0.9 % more than required; the exact
    form (1 ± δ/2)² meets δ to the discretisation of 720 positions."""
    text = (SCENES / "fly.compressor_course_project.toml").read_text(encoding="utf-8")
    got = {}
    for form in ("exact", "book"):
        t = text.replace('delta = "1/25"', "delta = 0.25").replace("positions = 12", "positions = 720")
        t = t.replace('tangents = "exact"', f'tangents = "{form}"')
        t = re.sub(r"find = \[.*?\]\n", 'find = ["delta_achieved"]\n', t, count=1, flags=re.S)
        p = tmp_path / f"{form}.toml"
        p.write_text(t, encoding="utf-8")
        got[form] = values(check_json(p))["delta_achieved"]["graphical"]
    assert got["exact"] == pytest.approx(0.25, rel=1e-4)
    assert 0.005 < got["book"] / 0.25 - 1 < 0.015


def test_no_flywheel_needed_when_the_design_comes_out_negative(tmp_path):
    extra = '\n[flywheel.true_motion]\nsolver = "Radau"\nrtol = 1e-10\n'
    doc = check_json(engine(tmp_path, method="wittenbauer", J=0.5, delta=0.5, find='["J_F", "delta_achieved"]',
                            extra=extra))
    q = values(doc)
    assert q["J_F"]["graphical"] < 0
    assert any("no flywheel is needed" in w for w in doc["warnings"])
    assert doc["true_motion"]["J_F"] == 0.0
    assert q["delta_achieved"]["graphical"] < 0.5


def test_a_load_with_a_step(tmp_path):
    """A resisting moment that steps from 0 to 300 N·m half-way: ΔT has a kink, the integrator
    restarts at the step, and the ODE agrees with the energy equation."""
    text = ENGINE.format(show='["energy"]', find='["J_F", "delta_achieved", "M_b"]', n=360, delta=0.05,
                         method="wittenbauer", J=0.3)
    text = text.replace('balance = "resisting"', 'balance = "driving"').replace(
        "phi_deg = [0, 20, 50, 180]\nmoment_Nm = [0, 200, 200, 0]",
        "phi_deg = [0, 90, 90, 180]\nmoment_Nm = [0, 0, -300, -300]")
    text += '\n[flywheel.true_motion]\nsolver = "BDF"\nrtol = 1e-10\n'
    p = tmp_path / "step.toml"
    p.write_text(text, encoding="utf-8")
    q = values(check_json(p))
    assert q["M_b"]["exact"] == pytest.approx(150.0, rel=1e-12)
    assert q["M_b"]["graphical"] == pytest.approx(150.0, rel=1e-12)  # the step falls on a position
    assert q["delta_achieved"]["rel_error"] <= 1e-7


def test_a_braking_scene_with_masses_stops_their_mean_reduced_inertia(tmp_path):
    """A slider-crank's piston (4.5 kg) adds its reduced inertia, averaged over a turn, to J."""
    scene = tmp_path / "b.toml"
    scene.write_text(scene_text("flywheel/braking_with_masses"), encoding="utf-8")
    q = values(check_json(scene))["t_stop"]
    # v_C of a centred slider-crank r = 75, l = 300 mm: mean of (v_C/ω)² over a turn, by quadrature
    phi = np.linspace(0.0, 2 * np.pi, 20000, endpoint=False)
    r, l = 0.075, 0.3
    ds = -r * np.sin(phi) - r * r * np.sin(phi) * np.cos(phi) / np.sqrt(l * l - (r * np.sin(phi)) ** 2)
    J = 0.1 + 4.5 * float(np.mean(ds ** 2))
    assert q["exact"] == pytest.approx(J * 100.0 / 20.0, rel=1e-9)
    assert q["graphical"] == pytest.approx(q["exact"], rel=1e-12)


def test_measured_flywheel_values_are_judged_against_the_same_positions(tmp_path):
    p = engine(tmp_path, method="indicator", find='["J_F", "DeltaW_max"]')
    doc = check_json(p, "--measured", "DeltaW_max=88.8", "--measured", "J_F=3.0")
    verdicts = {v["name"]: v for v in doc["measured"]}
    assert verdicts["DeltaW_max"]["ok"] and not verdicts["J_F"]["ok"]


def test_unknown_flywheel_quantity_is_one_line(tmp_path):
    code, out, err = run_cli("check", str(engine(tmp_path, find='["J_FF"]')))
    assert code == 2 and "find[0]" in err and "did you mean" in err and err.count("\n") == 1


def test_a_flywheel_scene_draws_its_mechanism_at_position_1(tmp_path):
    """show = ["mechanism", …] draws the linkage where φ = 0 beside the diagrams (once an internal error)."""
    from graphmech.scene import render_scene

    text = (SCENES / "fly.compressor_course_project.toml").read_text(encoding="utf-8")
    text = re.sub(r"show = \[.*\]", 'show = ["mechanism", "energy"]', text)
    scene = tmp_path / "fly.toml"
    scene.write_text(text, encoding="utf-8")
    svg, _ = render_scene(scene)
    seen = re.sub(r"<[^>]+>", "", svg)  # the text as read: sub- and superscripts are tspans
    assert "position 1 (φ = 0)" in seen and "μl = " in seen and "μT = " in seen
    code, _, err = run_cli("render", str(scene), "-o", str(tmp_path / "f.svg"))
    assert code == 0, err


def test_delta_w_max_is_read_on_the_indicator_as_drawn_at_its_enlarged_scale() -> None:
    """The indicator of fly.ic_engine_flywheel is drawn at μT′ = μT/6 (7 mm would be unreadable):
    the row's drawn length and μ are those of the drawing, so drawn × μ is still the value."""
    from graphmech.problems.flywheel.figures import energy_factor
    from graphmech.scene import load_scene
    from graphmech.problems import KINDS
    from tests.conftest import SCENES, check_json

    scene = load_scene(SCENES / "fly.ic_engine_flywheel.toml")
    design = KINDS[scene.kind].analyse(scene, {}).design
    [row] = [q for q in check_json(SCENES / "fly.ic_engine_flywheel.toml")["quantities"] if q["name"] == "DeltaW_max"]
    assert energy_factor(design) == 6
    assert row["scale"] == pytest.approx(design.scales["T"] / 6, rel=1e-12)
    assert row["drawn_mm"] * row["scale"] == pytest.approx(row["graphical"], rel=1e-12)
    assert row["drawn_mm"] > 40.0


def test_with_a_constant_jp_omega_is_extreme_where_delta_t_is(tmp_path):
    """phi_max, phi_min (the tangents' points of contact) fall on ΔT's extremes when Jп is
    constant — the IC engine: 104.17° and 11.67°, read at 105° and 10° — and tan ψ is a formula."""
    q = values(check_json(engine(tmp_path, find='["phi_max", "phi_min", "phi_DeltaT_max", "phi_DeltaT_min", '
                                              '"tan_psi_max", "tan_psi_min"]', J=0.5)))
    for top in ("max", "min"):
        assert q[f"phi_{top}"]["graphical"] == q[f"phi_DeltaT_{top}"]["graphical"]
        assert q[f"phi_{top}"]["exact"] == pytest.approx(q[f"phi_DeltaT_{top}"]["exact"], abs=1e-9)
    assert q["phi_max"]["graphical"] == pytest.approx(105.0) and q["phi_min"]["graphical"] == pytest.approx(10.0)
    assert q["phi_max"]["exact"] == pytest.approx(104.1666667, abs=1e-6)
    assert q["phi_min"]["exact"] == pytest.approx(11.6666667, abs=1e-6)
    wm = 620 * np.pi / 30
    mu = q["tan_psi_max"]["graphical"] / (wm ** 2 * 1.005 ** 2 / 2)  # μJ/μT of the drawing
    assert q["tan_psi_min"]["graphical"] == pytest.approx(mu * wm ** 2 * 0.995 ** 2 / 2, rel=1e-14)
    assert q["tan_psi_max"]["unit"] == "" and q["tan_psi_max"]["rel_error"] <= 1e-15


def test_a_measured_kl_is_judged_as_drawn(tmp_path):
    """kl (mm) was refused with an internal error when nothing else asked for the diagram."""
    code, out, err = run_cli("check", str(engine(tmp_path, J=0.5, method="wittenbauer")), "--measured", "kl=1")
    assert code == 1 and err == ""
    assert re.search(r"^kl +1 +\S+ +0\.5 +OUT", out, re.MULTILINE), out


def test_a_machine_that_repeats_every_turn_taken_over_two_turns(tmp_path):
    """The compressor over Φ = 720° with 24 positions is the same flywheel as over 360° with 12: the
    slider load acts on every compression stroke, ΔT repeats, k and l are the same points."""
    one = (SCENES / "fly.compressor_course_project.toml").read_text(encoding="utf-8")
    one = re.sub(r"(?ms)^find = \[.*?\]\n", 'find = ["M_b", "k", "l", "J_F", "phi_max", "phi_min"]\n', one, count=1)
    one = one.split("[flywheel.true_motion]")[0]
    two = one.replace("positions = 12", "positions = 24\ncycle_deg = 720")
    (tmp_path / "one.toml").write_text(one, encoding="utf-8")
    (tmp_path / "two.toml").write_text(two, encoding="utf-8")
    a, b = values(check_json(tmp_path / "one.toml")), values(check_json(tmp_path / "two.toml"))
    for name in ("M_b", "k", "l", "J_F"):
        assert b[name]["graphical"] == pytest.approx(a[name]["graphical"], rel=1e-10), name
        assert b[name]["exact"] == pytest.approx(a[name]["exact"], rel=1e-9), name
    for name in ("phi_max", "phi_min"):  # one of two equal extremes, a turn apart
        assert b[name]["exact"] % 360 == pytest.approx(a[name]["exact"], abs=1e-7)
        assert b[name]["graphical"] % 360 == pytest.approx(a[name]["graphical"], abs=1e-9)


# ------------------------------------------------------------------------------------------
# ΔT(φ) given as a table ([flywheel.energy_increment])
# ------------------------------------------------------------------------------------------

DT_JP = [0.6008325, 0.6018516, 0.6019891, 0.6017175, 0.6011137, 0.6005196,
         0.6, 0.6031759, 0.6045547, 0.6025725, 0.6009025, 0.6]


def test_the_table_of_delta_t_gives_the_flywheel_at_its_vertices() -> None:
    """fly.energy_table: ΔT and Jп polygonal, so the tangents touch at the tables' points — here
    ΔT_min at 30° and ΔT_max at 210° (both positions): the exact values by hand from the table."""
    v = values(check_json(SCENES / "fly.energy_table.toml"))
    w2, delta = 28.0 ** 2, 0.2
    k = 6401.1 - w2 * (1 + delta) / 2 * DT_JP[7]       # ψmax touches at 210°
    l_ = -459.6 - w2 * (1 - delta) / 2 * DT_JP[1]      # ψmin at 30°
    assert v["k"]["exact"] == pytest.approx(k, rel=1e-14)
    assert v["l"]["exact"] == pytest.approx(l_, rel=1e-14)
    assert v["J_F"]["exact"] == pytest.approx((k - l_) / (w2 * delta), rel=1e-14)
    assert v["J_F"]["graphical"] == pytest.approx(43.14864, rel=1e-6)  # read at the same vertices
    for name, deg in (("phi_max", 210.0), ("phi_min", 30.0), ("phi_DeltaT_max", 210.0), ("phi_DeltaT_min", 30.0)):
        assert v[name]["exact"] == pytest.approx(deg, rel=1e-14)
        assert v[name]["graphical"] == pytest.approx(deg, rel=1e-14)
    assert (v["DeltaT_max"]["exact"], v["DeltaT_min"]["exact"]) == (6401.1, -459.6)
    assert v["DeltaW_max"]["exact"] == pytest.approx(6860.7, rel=1e-14)
    j_mean = sum(DT_JP) / 12  # a closed polygon over equal steps: the mean of its points
    assert v["J_F_indicator"]["exact"] == pytest.approx(6860.7 / (w2 * delta) - j_mean, rel=1e-12)
    assert v["DeltaT@2"]["exact"] == -459.6  # read off the table; drawn at μT and read back
    assert v["DeltaT@2"]["graphical"] == pytest.approx(-459.6, rel=1e-14)


def test_the_table_of_delta_t_and_the_moments_it_came_from_agree_on_j_f() -> None:
    """The ΔT of fly.energy_table is what fly.wittenbauer_course_project's Mп gives every 15°: the
    polygon through it misses the parabolas between by little, and the two J_F agree to 1e-5."""
    dt = values(check_json(SCENES / "fly.energy_table.toml"))["J_F"]["exact"]
    mp = values(check_json(SCENES / "fly.wittenbauer_course_project.toml"))["J_F"]["exact"]
    assert dt == pytest.approx(43.14864, rel=1e-6) and mp == pytest.approx(43.14874, rel=1e-6)
    assert abs(dt - mp) / mp < 1e-5


def test_an_extreme_of_delta_t_between_positions_is_exact_at_its_vertex(tmp_path) -> None:
    """A vertex that is no position: the exact side takes it (45°), the drawing reads the nearest
    position (60°, the higher of its neighbours) and estimates its own error from 2N and 4N positions."""
    path = tmp_path / "dt.toml"
    path.write_text("""\
find = ["DeltaT_max", "phi_DeltaT_max", "phi_max", "J_F"]
[flywheel]
speed_rad_s = 100
delta = 0.05
inertia_kgm2 = 0.2
[flywheel.energy_increment]
phi_deg = [0, 45, 90, 270]
increment_J = [0, 300, 100, -100]
""", encoding="utf-8")
    v = values(check_json(path))
    # at 60°: 300 − 200·15/45
    assert v["DeltaT_max"]["exact"] == 300.0 and v["DeltaT_max"]["graphical"] == pytest.approx(700 / 3, rel=1e-12)
    assert v["phi_DeltaT_max"]["exact"] == pytest.approx(45.0, rel=1e-14)
    assert v["phi_DeltaT_max"]["graphical"] == pytest.approx(60.0, rel=1e-14)
    assert v["phi_max"]["exact"] == pytest.approx(45.0, rel=1e-14)   # Jп constant: the extreme of ΔT
    # Jп constant: the Wittenbauer J_F is the energy method's, ΔW_max/(ω_m²δ) − Jп
    assert v["J_F"]["exact"] == pytest.approx((300.0 + 100.0) / (100.0 ** 2 * 0.05) - 0.2, rel=1e-12)
    # 2N positions (every 15°) reach the vertex that N missed: each estimate is its own row's error
    for name in ("DeltaT_max", "phi_DeltaT_max", "J_F"):
        assert v[name]["error_estimate"] == pytest.approx(v[name]["rel_error"], rel=1e-9)
    assert v["DeltaT_max"]["rel_error"] == pytest.approx(1 / 6, rel=1e-12)


def test_the_true_motions_integration_time_is_in_the_text_table_alone(tmp_path):
    """``check`` says how long the equation of motion took to integrate (the one check that may
    exceed the cold-start budget); ``check --json`` stays the same bytes run to run without it."""
    scene = engine(tmp_path, extra='\n[flywheel.true_motion]\nsolver = "Radau"\nrtol = 1e-10\n')
    code, out, _ = run_cli("check", str(scene))
    assert code == 0
    [line] = [ln for ln in out.splitlines() if ln.startswith("true motion integrated in ")]
    assert re.fullmatch(r"true motion integrated in \d+\.\d\d s \(Radau(, \d runs)?\)", line)
    assert out.rstrip("\n").endswith(line)  # under the table and its notes
    code, doc, _ = run_cli("check", str(scene), "--json")
    assert code == 0 and "integrated" not in doc and "seconds" not in doc
    assert run_cli("check", str(scene), "--json")[1] == doc


def test_a_flywheel_without_true_motion_says_no_integration_time(tmp_path):
    code, out, _ = run_cli("check", str(engine(tmp_path)))
    assert code == 0 and "integrated" not in out
