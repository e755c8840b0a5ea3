"""Full-cycle and characteristics scenes: the cycle through both dead centres, N = 3600, a
parallelogram at its change point, what is refused, and that only what is asked is computed."""
from __future__ import annotations

import json
import math
import re

import pytest

from graphmech.scene import render_scene
from tests.conftest import SCENES, check_json, run_cli, values
from tests.scenes import scene_text

#: The centred slider-crank (AB = 50, BC = 200 mm) over 12 positions from its extreme.
SLIDER = scene_text("cycle/slider_crank")


def scene(tmp_path, name="s.toml", *, n=12, show=None, find=None, extra=""):
    """The slider-crank cycle scene with N positions, its own show and find, ``extra`` lines in [cycle]."""
    text = SLIDER.replace("positions = 12", f"positions = {n}").replace('paths = ["C"]\n', f'paths = ["C"]\n{extra}')
    for key, value in (("show", show), ("find", find)):
        if value is not None:
            text = re.sub(rf"(?m)^{key} = .*$", lambda m: f"{key} = {value}", text)
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def test_a_full_cycle_through_both_dead_centres(tmp_path):
    """Centred slider-crank, 12 positions from the extreme: positions 1 and 7 are the dead centres."""
    doc = check_json(scene(tmp_path))
    q = values(doc)
    # θ = 0 (K = 1): both strokes take 180°; position 1 is then the outer dead centre (crank at 0°)
    assert doc["cycle"]["start_deg"] == pytest.approx(0.0, abs=1e-9)
    for k in ("1", "7"):  # a zero velocity at a crank-driven dead centre is a normal result
        assert abs(q[f"v_C@{k}"]["graphical"]) < 1e-12 and not q[f"v_C@{k}"]["ill_conditioned"]
    assert q["a_C@1"]["graphical"] == pytest.approx(-10 ** 2 * 0.05 * (1 + 50 / 200), rel=1e-12)  # −ω²r(1 + λ)
    assert q["s_C@7"]["graphical"] == pytest.approx(-0.1, rel=1e-12)  # the stroke 2·AB
    assert abs(q["v_C_diagram@1.5"]["rel_error"]) < 0.05 and abs(q["a_C_diagram@7"]["rel_error"]) < 0.1
    assert q["omega_2@4"]["graphical"] == pytest.approx(q["omega_2@4"]["exact"], rel=1e-12)
    text = json.dumps(doc)
    assert "NaN" not in text and "Infinity" not in text
    d = doc["diagrams"][0]
    assert d["subject"] == "C" and 0 < d["max_rel_error_v"] < 0.05 and 0 < d["max_rel_error_a"] < 0.1


def test_the_crank_rockers_rocker_is_at_rest_at_position_1():
    q = values(check_json(SCENES / "linkage.fourbar_28_52_50_72-cycle.toml"))
    assert q["omega_3@4"]["graphical"] == pytest.approx(q["omega_3@4"]["exact"], rel=1e-12)
    assert q["psi_3@7"]["graphical"] == pytest.approx(q["psi_3@7"]["exact"], rel=1e-12)
    # graphical differentiation at 12 positions: within a few per cent, not 1e-9
    assert 1e-4 < q["omega_3_diagram@1.5"]["rel_error"] < 0.02
    assert 1e-4 < q["alpha_3_diagram@4"]["rel_error"] < 0.02


def test_n_3600_is_checked_and_drawn_thinned(tmp_path):
    p = scene(tmp_path, n=3600, find='["v_C@1", "v_C@1801", "s_C@1801", "v_C_diagram@900.5", "a_C_diagram@1"]')
    doc = check_json(p)
    q = values(doc)
    assert abs(q["v_C@1801"]["graphical"]) < 1e-12
    assert q["s_C@1801"]["graphical"] == pytest.approx(-0.1, rel=1e-12)
    assert doc["diagrams"][0]["max_rel_error_v"] < 1e-6 and doc["diagrams"][0]["max_rel_error_a"] < 1e-5
    svg, warnings = render_scene(p)
    assert svg.count("<svg") == 1
    # 18 mechanisms drawn, not 3600: the note says so, and the file stays small
    assert "every 200th of the 3600 positions drawn" in svg
    assert len(svg) < 3_000_000


def test_only_what_is_asked_is_computed(tmp_path, monkeypatch):
    import graphmech.problems.cycle.check as cc

    calls = []
    real = cc.evaluate_cycle
    monkeypatch.setattr(cc, "evaluate_cycle", lambda *a, **k: calls.append(k) or real(*a, **k))
    p = scene(tmp_path, show='["characteristics"]', find='["theta", "stroke"]')
    q = values(check_json(p))
    assert calls == []  # a characteristics scene evaluates no cycle
    assert q["theta"]["graphical"] == pytest.approx(0.0, abs=1e-12) and q["stroke"]["exact"] == pytest.approx(0.1)
    calls.clear()
    p = scene(tmp_path, show='["cycle"]', find='["s_C@3"]')
    check_json(p)
    assert calls and all(not k.get("polygons") for k in calls)  # no polygons evaluated when none are shown
    assert all(k.get("diagrams") == ["C"] for k in calls)  # only the diagram a value is found on


def test_a_parallelogram_at_its_change_point(tmp_path):
    p = tmp_path / "para.toml"
    p.write_text(scene_text("cycle/parallelogram"), encoding="utf-8")
    doc = check_json(p)
    assert doc["characteristics"]["grashof"] == "change_point" == doc["characteristics"]["grashof_exact"]
    assert any("Grashof's equality" in w for w in doc["warnings"])
    assert values(doc)["gamma_min"]["graphical"] == pytest.approx(0.0, abs=1e-6)  # all four links on one line
    svg, _ = render_scene(p)
    assert "change point" in svg
    p.write_text(p.read_text().replace('find = ["gamma_min"]', 'find = ["theta"]'))
    code, out, err = run_cli("check", str(p))
    assert code == 2 and err.count("\n") == 1 and "no extreme positions" in err


def test_a_crank_that_cannot_turn_has_no_cycle(tmp_path):
    """A double rocker (AB = 30 in the ranges problem's four-bar): one line naming the position."""
    text = (SCENES / "linkage.grashof_ranges.toml").read_text(encoding="utf-8")
    text = text.replace("length = 10", "length = 30").replace('show = ["characteristics"]', 'show = ["cycle"]')
    text = text.replace("[characteristics]\nranges = true", "[cycle]\npositions = 12")
    head, _, tail = text.partition("find = [")
    text = head + "find = []\n" + tail.split("]\n", 1)[1]
    p = tmp_path / "dr.toml"
    p.write_text(text, encoding="utf-8")
    code, _, err = run_cli("check", str(p))
    assert code == 2 and err.count("\n") == 1 and "cannot make a full turn" in err and "position" in err, err


def test_a_students_hand_diagram_is_judged_against_the_same_chords(tmp_path):
    p = scene(tmp_path, find='["v_C_diagram@3.5"]')
    q = values(check_json(p))["v_C_diagram@3.5"]
    mu = q["scale"]
    good, bad = q["graphical"] + 0.4 * mu, q["graphical"] + 0.6 * mu  # 0.4 mm and 0.6 mm off on the drawing
    code, out, _ = run_cli("check", str(p), "--json", "--measured", f"v_C_diagram@3.5={good}")
    doc = json.loads(out)
    assert code == 0 and doc["measured"][0]["ok"] and doc["measured"][0]["expected"] == q["graphical"]
    code, out, _ = run_cli("check", str(p), "--json", "--measured", f"v_C_diagram@3.5={bad}")
    assert code == 1 and not json.loads(out)["measured"][0]["ok"]
    code, _, err = run_cli("check", str(p), "--measured", "v_C_diagram=1")
    assert code == 2 and "name the position" in err


def test_a_parallelogram_full_cycle_passes_its_change_points(tmp_path):
    """At φ = 0° and 180° all four links lie on one line: the mechanism is drawn there, its velocity
    polygon cannot be (⟂BC and ⟂DC are parallel) and is left out with a warning naming the position;
    the fixed branch runs on as a parallelogram on one side and an antiparallelogram on the other."""
    p = tmp_path / "para.toml"
    text = (scene_text("cycle/parallelogram").replace('"Parallelogram"', '"Parallelogram through its change points"')
            .replace('show = ["characteristics"]', 'show = ["cycle", "velocity", "diagrams"]')
            .replace('find = ["gamma_min"]', 'find = ["omega_3@4", "omega_3@10", "psi_3@4", "omega_3_diagram@3.5"]')
            .replace("angle_deg = 60", "angle_deg = 0"))
    p.write_text(text + '[cycle]\npositions = 12\ndiagrams = ["3"]\n[page]\nsize = "A3"\n', encoding="utf-8")
    doc = check_json(p)
    q = values(doc)
    assert q["omega_3@4"]["graphical"] == pytest.approx(10.0, rel=1e-12)  # parallelogram: ω3 = ω1
    assert q["omega_3@10"]["graphical"] != pytest.approx(10.0, rel=1e-3)  # antiparallelogram
    assert q["omega_3_diagram@3.5"]["graphical"] == pytest.approx(10.0, rel=1e-12)  # ψ linear: chords exact
    gone = [w for w in doc["warnings"] if "no polygon" in w]
    assert [w.split(" (")[0] for w in gone] == ["position 1", "position 7"]
    assert not any("φ₁ = 1°" in w for w in doc["warnings"])  # positions are named by number, not as angles
    assert "NaN" not in json.dumps(doc)
    svg, _ = render_scene(p)
    assert "no polygon at positions 1, 7" in svg


def test_ill_conditioned_positions_are_one_line_however_many(tmp_path):
    """A crank-rocker a hair from its change point (20 + 80 vs 60 + 40.02): near the folded position the
    coupler and rocker almost align; 360 positions give one summary line per kind, not hundreds."""
    p = tmp_path / "near.toml"
    p.write_text(scene_text("cycle/near_change_point"), encoding="utf-8")
    doc = check_json(p)
    summary = [w for w in doc["warnings"] if w.startswith(("ill-conditioned intersections", "shallow intersections"))]
    assert summary and len(summary) <= 2
    assert "positions 1" in summary[0] or "position" in summary[0]
    assert len(doc["warnings"]) == len(summary)  # not one line per position and step


@pytest.mark.parametrize("direction", ["ccw", "cw"])
def test_the_diagrams_follow_the_cranks_sense(tmp_path, direction):
    """Numbered in the crank's sense either way; the chords' values agree with the exact ones to O(1/N²)."""
    p = scene(tmp_path, n=72, find='["v_C_diagram@10.5", "a_C_diagram@30", "omega_2_diagram@50.5", "alpha_2_diagram@5"]',
              extra="")
    p.write_text(p.read_text().replace("omega = 10", f'omega = 10\ndirection = "{direction}"'))
    doc = check_json(p)
    for row in doc["quantities"]:
        assert row["rel_error"] < 5e-3, row
    assert doc["diagrams"][0]["max_rel_error_v"] < 1e-3


def test_a_guide_bar_cycle_starts_at_its_extreme(tmp_path):
    p = tmp_path / "gb.toml"
    text = (SCENES / "linkage.quick_return_timing-guide_bar.toml").read_text(encoding="utf-8")
    text = text.replace('show = ["characteristics"]', 'show = ["cycle", "diagrams"]').replace(
        "[characteristics]\nt_work_s = 7", '[cycle]\npositions = 24\nstart = "extreme"\ndiagrams = ["3"]')
    head, _, tail = text.partition("find = [")
    text = head + 'find = ["phi_start"]\n' + tail.split("]\n", 1)[1]
    p.write_text(text, encoding="utf-8")
    doc = check_json(p)
    ch = values(doc)
    assert doc["cycle"]["start_deg"] == pytest.approx(ch["phi_start"]["exact"], abs=1e-9)
    assert doc["diagrams"][0]["max_rel_error_v"] < 0.02


def test_a_points_way_along_its_path_and_a_link_that_turns_fully(tmp_path):
    """Coupler point E: s is its chords laid end to end (dividers), v its speed, a its tangential
    acceleration, all O(1/N²) from the exact ∫|v|dt, |v|, v·a/|v|; the crank (link 1) gains a full
    turn per cycle, which closes its ψ–φ curve, so its chords are exact."""
    text = (SCENES / "linkage.fourbar_28_52_50_72-cycle.toml").read_text(encoding="utf-8")
    text = text.replace('diagrams = ["3"]', 'diagrams = ["3", "E", "1"]')
    head, _, tail = text.partition("find = [")
    rest = tail.split("]\n", 1)[1]
    errs = {}
    for n in (12, 120):
        p = tmp_path / f"e{n}.toml"
        p.write_text(head + 'find = ["s_E@5", "v_E_diagram@5.5", "a_E_diagram@3", "omega_1_diagram@3.5", '
                     '"psi_1@7"]\n' + rest.replace("positions = 12", f"positions = {n}"), encoding="utf-8")
        doc = check_json(p)
        q = values(doc)
        assert q["omega_1_diagram@3.5"]["graphical"] == pytest.approx(10.0, rel=1e-12)
        assert q["psi_1@7"]["graphical"] == pytest.approx(360.0 * 6 / n, rel=1e-12)
        e = next(d for d in doc["diagrams"] if d["subject"] == "E")
        assert e["kind"] == "path"
        errs[n] = (e["max_rel_error_v"], e["max_rel_error_a"])
    assert errs[12][0] / errs[120][0] == pytest.approx(100, rel=0.2)  # order 2
    assert errs[12][1] / errs[120][1] == pytest.approx(100, rel=0.7)
    assert errs[120][0] < 1e-3 and errs[120][1] < 1e-2


def test_the_compressors_cycle_starts_where_its_flywheel_project_does():
    """start = "extreme" finds the outer dead centre the flywheel scene states by hand, asin(e/(a + b)):
    the twelve positions of the kinematics sheet are those the reduction to the crank uses."""
    from graphmech.scene import load_scene

    cyc = load_scene(SCENES / "fly.compressor_course_project-cycle.toml")
    fly = load_scene(SCENES / "fly.compressor_course_project.toml")
    assert cyc.positions.labels == fly.positions.labels == tuple(str(k) for k in range(1, 13))
    for a, b in zip(cyc.positions.values, fly.positions.values):
        assert abs((a - b + math.pi) % (2 * math.pi) - math.pi) < 1e-12
    q = values(check_json(SCENES / "fly.compressor_course_project-cycle.toml"))
    assert q["phi_start"]["graphical"] == pytest.approx(math.degrees(math.asin(10 / 375)), rel=1e-12)
    assert q["s_C@7"]["graphical"] == pytest.approx(-q["stroke"]["exact"], abs=1e-5)  # position 7: near the inner dead centre


def test_the_text_table_tells_the_class_the_ranges_and_the_diagrams_errors():
    code, out, _ = run_cli("check", str(SCENES / "linkage.grashof_ranges.toml"))
    assert code == 0 and "crank rocker AB by Grashof's rule" in out and "double crank: 45 … 55 mm" in out
    code, out, _ = run_cli("check", str(SCENES / "linkage.slider_crank_offset-cycle.toml"))
    assert code == 0 and "diagrams of C by chords (H1 = 20, H2 = 15 mm): largest error over the cycle 1.6e-02 (v)" in out


def test_a_slider_crank_whose_crank_cannot_turn_names_the_construction_step(tmp_path):
    p = tmp_path / "sc.toml"
    p.write_text(scene_text("cycle/slider_crank_cannot_turn"), encoding="utf-8")
    code, out, err = run_cli("check", str(p))  # a + e = 160 mm > b = 150 mm
    assert code == 2 and err.count("\n") == 1 and "C₁ = arc(A, BC − AB) ∩ guide" in err and "does not turn fully" in err


def test_stated_diagram_scales_fix_the_pole_distances(tmp_path):
    """μv and μa stated: H₁ = μs·ω₁/(μφ·μv), H₂ = μv·ω₁/(μφ·μa); the values do not depend on H."""
    extra = 'scales = { s_mm_per_mm = 2, phi_deg_per_mm = 3, v_m_s_per_mm = 0.02, a_m_s2_per_mm = 0.25 }'
    p = scene(tmp_path, find='["v_C_diagram@3.5", "a_C_diagram@4"]', extra=extra)
    doc = check_json(p)
    d = doc["diagrams"][0]
    assert d["mu_v"] == pytest.approx(0.02, rel=1e-12) and d["mu_a"] == pytest.approx(0.25, rel=1e-12)
    assert d["H1_mm"] == pytest.approx(0.002 * 10 / (math.radians(3) * 0.02), rel=1e-12)
    assert doc["scales"]["v@C"] == pytest.approx(0.02, rel=1e-12)
    q = values(doc)
    other = values(check_json(scene(tmp_path, "o.toml", find='["v_C_diagram@3.5", "a_C_diagram@4"]',
                                    extra='scales = { s_mm_per_mm = 2, phi_deg_per_mm = 3 }\npole_distance_mm = 40')))
    for k in q:
        assert q[k]["graphical"] == pytest.approx(other[k]["graphical"], rel=1e-12)
    code, _, err = run_cli("check", str(scene(tmp_path, "c.toml", extra=extra + "\npole_distance_mm = 40")))
    assert code == 2 and "cycle.pole_distance_mm" in err and "not both" in err


def test_a_deltoid_asked_for_its_characteristics_is_one_line(tmp_path):
    """AB = BC = 30, CD = AD = 72: the folded extreme position has C on A (no crank angle)."""
    text = (SCENES / "linkage.fourbar_28_52_50_72.toml").read_text(encoding="utf-8")
    text = text.replace("length = 28", "length = 30").replace("lengths = [52, 50]", "lengths = [30, 72]")
    text = text.split("[measured]")[0]
    p = tmp_path / "kite.toml"
    p.write_text(text, encoding="utf-8")
    code, _, err = run_cli("check", str(p))
    assert code == 2 and err.count("\n") == 1 and ": characteristics: " in err and "deltoid" in err, err


def test_instant_centres_are_refused_on_a_cycle_sheet_but_found(tmp_path):
    """show = ["instant_centres", "cycle"] drew the cycle and silently no centres."""
    p = scene(tmp_path, show='["instant_centres", "cycle"]', find='["P13@4"]')
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and err.startswith("s.toml: show[0]: the instant centres are drawn one row per position")
    assert not (tmp_path / "x.svg").exists()
    doc = check_json(scene(tmp_path, "t.toml", show='["cycle"]', find='["P13@4", "omega_2_ic@4"]'))
    got = values(doc)
    # centred slider-crank r = 50, l = 200 at position 4 (φ = 90° from the extreme at 0°): the rod's
    # ω = −ω1·r·cos φ/(l·cos β) = 0
    assert got["omega_2_ic@4"]["graphical"] == pytest.approx(0.0, abs=1e-12)
    assert got["x_P13@4"]["graphical"] == pytest.approx(got["x_P13@4"]["exact"], abs=1e-12)


def test_an_absurd_drawing_precision_is_refused_not_an_internal_error(tmp_path):
    """--precision 1e308 made θ's protractor tolerance inf, and check --json died on it (exit 3)."""
    scene_path = SCENES / "linkage.fourbar_28_52_50_72.toml"
    code, _, err = run_cli("check", "--json", str(scene_path), "--precision", "1e308")
    assert code == 2 and err == "graphmech: --precision must be a number of mm above 0 and at most 10\n", err
    p = tmp_path / "coarse.toml"
    p.write_text(scene_path.read_text(encoding="utf-8") + "\n[check]\nprecision_mm = 1e308\n", encoding="utf-8")
    code, _, err = run_cli("check", "--json", str(p))
    assert code == 2 and err == "coarse.toml: check.precision_mm: at most 10 mm, not 1e+308: coarser judges nothing\n"
    doc = check_json(scene_path, "--precision", "10")  # the coarsest accepted: finite tolerances
    assert all(math.isfinite(m["tolerance"]) for m in doc["measured"])


# ---------------------------------------------------------------------------- a driver that swings

def _fourbar_closed_form(phi, a=0.08, b=0.04, c=0.06, d=0.05, w=5.0):
    """C and ω₃ of the rocker-driven four-bar A = (0, 0), D = (d, 0), C left of B→D, by the cosine
    rule and the velocity equation a·ω₁·i·e^{iφ} + ω₂·i·(C − B) = ω₃·i·(C − D) (complex numbers)."""
    B, D = a * complex(math.cos(phi), math.sin(phi)), complex(d, 0.0)
    bd = abs(D - B)
    along = (b * b - c * c + bd * bd) / (2 * bd)
    C = B + (D - B) / bd * complex(along, math.sqrt(b * b - along * along))  # left of B→D
    # real and imaginary parts: ω₂·(C − B) − ω₃·(C − D) = −a·ω₁·e^{iφ}
    u, v, r = C - B, -(C - D), -a * w * complex(math.cos(phi), math.sin(phi))
    det = u.real * v.imag - u.imag * v.real
    return C, (u.real * r.imag - u.imag * r.real) / det


def test_a_rocker_swings_between_its_limits_and_back():
    doc = check_json(SCENES / "linkage.rocker_swing.toml")
    q = values(doc)
    limit = math.degrees(math.acos(-0.1375))  # BD = BC + CD = 100: cos φ = (80² + 50² − 100²)/(2·80·50)
    assert q["driver_from"]["graphical"] == pytest.approx(-limit, abs=1e-9)
    assert q["driver_to"]["graphical"] == pytest.approx(limit, abs=1e-9)
    assert doc["swing"] == {"from": pytest.approx(-limit), "to": pytest.approx(limit), "unit": "deg", "limits": True}
    step = 2 * limit / 6  # 12 positions: 1 … 7 out, 8 … 12 back
    for k, sign in ((2, 1.0), (12, -1.0)):  # position 2 and 12: one place, ω₁ reversed on the way back
        phi = math.radians(-limit + step)
        _, w3 = _fourbar_closed_form(phi)
        assert q[f"omega_3@{k}"]["graphical"] == pytest.approx(sign * w3, rel=1e-9)
        assert q[f"omega_3@{k}"]["exact"] == pytest.approx(sign * w3, rel=1e-9)
    assert q["a_C@4"]["graphical"] == pytest.approx(q["a_C@10"]["graphical"], rel=1e-12)  # a ∝ ω₁² at ε₁ = 0
    # the output CD swings from B, C, D in one line at φ = 97.9° to where A, B, C fold (AC = 40 mm)
    B = 80.0 * complex(math.cos(math.radians(limit)), math.sin(math.radians(limit)))
    fold = math.atan2(-60.0 * math.sqrt(1 - 0.75 ** 2), -60.0 * 0.75)  # cos ∠ADC = (50² + 60² − 40²)/(2·50·60)
    assert q["output_swing"]["graphical"] == pytest.approx(math.degrees(math.atan2(B.imag, B.real - 50.0) - fold), abs=1e-9)
    assert q["output_swing"]["rel_error"] < 1e-9
    ends = [w for w in doc["warnings"] if "no polygon" in w]
    assert len(ends) == 2 and all("an end of the swing" in w for w in ends)  # the toggles: the driver stops there


def test_a_slider_drives_over_its_stroke_and_back():
    q = values(check_json(SCENES / "linkage.slider_stroke.toml"))
    assert (q["driver_from"]["graphical"], q["driver_to"]["graphical"]) == (0.02, 0.12)
    # position 2 (s = 45 mm, out) and 8 (the same place, back): B = (45, 0), C on BC = 80, CD = 50 right of B→D
    B, D = complex(0.045, 0.0), complex(0.1, 0.06)
    bd = abs(D - B)
    along = (0.08 ** 2 - 0.05 ** 2 + bd * bd) / (2 * bd)
    C = B + (D - B) / bd * complex(along, -math.sqrt(0.08 ** 2 - along * along))
    # v_B + ω₂·i·(C − B) = ω₃·i·(C − D), v_B = 0.5 m/s along x (out; −0.5 back)
    # divided by i: ω₂·(C − B) − ω₃·(C − D) = i·v_B, two real equations
    u, v, r = C - B, -(C - D), complex(0.0, 0.5)
    det = u.real * v.imag - u.imag * v.real
    w3 = (u.real * r.imag - u.imag * r.real) / det
    assert q["omega_3@2"]["graphical"] == pytest.approx(w3, rel=1e-9)
    assert q["omega_3@8"]["graphical"] == pytest.approx(-w3, rel=1e-9)
    assert q["a_C@3"]["graphical"] == pytest.approx(q["a_C@7"]["graphical"], rel=1e-12)


def test_a_crank_swings_between_stated_angles_the_way_it_turns(tmp_path):
    # the crank-rocker 28/52/50/72 told to swing from 30° to 90°: clockwise it goes the long way round
    text = (SCENES / "linkage.fourbar_28_52_50_72-cycle.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?ms)^\[cycle\].*?(?=^\[|\Z)", "[cycle]\npositions = 8\nbetween_deg = [30, 90]\n\n", text)
    text = re.sub(r"(?m)^show = .*$", 'show = ["cycle", "velocity"]', text)
    text = re.sub(r"(?m)^find = .*$", 'find = ["driver_from", "driver_to", "omega_3@2", "omega_3@8"]', text)
    text = text.split("[measured]")[0]
    for sense, to in (("", 90.0), ("-", 90.0 - 360.0)):
        p = tmp_path / f"s{sense}.toml"
        p.write_text(re.sub(r"(?m)^omega = ([0-9.]+)$", lambda m: f"omega = {sense}{m.group(1)}", text), encoding="utf-8")
        q = values(check_json(p))
        assert q["driver_to"]["graphical"] == pytest.approx(to, abs=1e-12)
        assert q["omega_3@2"]["graphical"] == pytest.approx(-q["omega_3@8"]["graphical"], rel=1e-12)
        assert q["omega_3@2"]["rel_error"] < 1e-9


def test_a_hand_reading_on_the_return_stroke_is_judged_with_the_driver_reversed():
    doc = check_json(SCENES / "linkage.rocker_swing.toml", "--measured", "omega_3@12=-1.83", "--measured",
                     "omega_3@12=+1.83", "--measured", "omega_3@12=1.83")
    got = [(m["measured"], m["ok"], m["rule"]) for m in doc["measured"] if m["name"] == "omega_3@12"]
    # position 12: ω₃ < 0 on the way back; a sign written is judged, none written is the magnitude
    assert got == [(-1.83, True, "drawing precision, sign checked"), (1.83, False, "drawing precision, sign checked"),
                   (1.83, True, "drawing precision, magnitude only")]


def test_the_offset_guide_bars_characteristics_and_cycle(tmp_path):
    """linkage.offset_guide_bar-characteristics: θ = ψ = |arccos((e + a)/d) − arccos((e − a)/d)| with
    a = 110, d = 350, e = 40 mm; cos γmin = e/(d − a) — every drawn value within 1e-9 of exact/. The
    same linkage through a turn: the bar's ψ3–φ diagram reads the angle of its line (F→B), not of CB."""
    got = values(check_json(SCENES / "linkage.offset_guide_bar-characteristics.toml"))
    assert all(r["rel_error"] <= 1e-9 for r in got.values()), got
    psi = abs(math.acos(0.15 / 0.35) - math.acos(-0.07 / 0.35))
    assert got["theta"]["graphical"] == pytest.approx(math.degrees(psi), rel=1e-12)
    assert got["psi"]["graphical"] == pytest.approx(math.degrees(psi), rel=1e-12)
    assert got["K"]["graphical"] == pytest.approx((math.pi + psi) / (math.pi - psi), rel=1e-12)
    assert got["gamma_min"]["graphical"] == pytest.approx(math.degrees(math.acos(0.04 / 0.24)), rel=1e-12)
    text = (SCENES / "linkage.offset_guide_bar-characteristics.toml").read_text(encoding="utf-8")
    text = text.replace('show = ["characteristics"]', 'show = ["cycle", "diagrams", "velocity"]')
    text = re.sub(r"find = \[.*\]", 'find = ["psi_3@4", "psi_3@7", "omega_3@4", "v_B3B2@7"]', text)
    text = text.replace("[page]", '[cycle]\npositions = 12\nstart = "extreme"\ndiagrams = ["3"]\n'
                                  "pole_distance_mm = [20, 15]\n\n[page]")
    (tmp_path / "c.toml").write_text(text.replace("l_mm_per_mm = 3", "l_mm_per_mm = 3\nv_m_s_per_mm = 0.01"),
                                     encoding="utf-8")
    cyc = values(check_json(tmp_path / "c.toml"))
    assert len(cyc) == 4 and all(r["rel_error"] <= 1e-9 for r in cyc.values()), cyc
    # position 7 is 180° of crank past the extreme where the working stroke starts: ψ3 < ψ, still going
    assert 0.0 < cyc["psi_3@7"]["exact"] < math.degrees(psi) and cyc["psi_3@4"]["exact"] > 0.0


def test_the_figure_leaves_the_diagrams_errors_to_the_check(monkeypatch):
    """Each diagram's largest error over the cycle (the exact rates at every position) is the check
    table's summary: the figure does without it and is the same drawing."""
    from pathlib import Path

    from graphmech import api
    from graphmech.problems.cycle import check as cycle_check

    scene = Path(__file__).parents[3] / "figures" / "scenes" / "linkage.slider_crank_offset-cycle.toml"
    want = api.load(scene).render().svg
    assert api.load(scene).check().extras["diagrams"][0]["max_rel_error_v"] < 0.05

    def refuse(*_):
        raise AssertionError("the figure computed the diagrams' errors")

    monkeypatch.setattr(cycle_check, "_diagram_errors", refuse)
    assert api.load(scene).render().svg == want
