"""The force sheet: panels, scales that fit the page, free bodies, couples and Zhukovsky's lever."""
from __future__ import annotations

import math
import re
import tomllib
from functools import partial

import pytest

from graphmech.problems.forces.check import analyse_forces
from graphmech.scene import load_scene, parse_scene
from tests.conftest import ROOT, SCENES, run_cli
from tests.scenes import scene_text, write_scene


def _scene(text: str):
    return parse_scene(tomllib.loads(text), "t.toml")


_write = partial(write_scene, name="s.toml")


def test_force_sheet_panels_and_one_position_only(tmp_path):
    from graphmech.scene import render_scene

    svg, warnings = render_scene(SCENES / "force.sixbar_kinetostatic.toml")
    for title in ("Free body, group 4–5", "Force polygon, group 2–3", "Zhukovsky", "μF = 25 N/mm"):
        assert title in svg
    text = scene_text("forces/fourbar_loaded").replace('show = ["mechanism"]', 'show = ["force_polygons"]').replace('angle = 180', 'angle = [170, 180]')
    code, _, err = run_cli("render", str(_write(tmp_path, text)), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and "draw one position" in err and not (tmp_path / "x.svg").exists()


DOC_BLOCKS = re.findall(r"```toml\n(.*?)```", (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8"), re.S)


def _doc_scene(title: str) -> str:
    return next(b for b in DOC_BLOCKS if b.startswith(f'title = "{title}"'))


@pytest.mark.parametrize("title, mu_l", [
    ("Oscillating block: reactions with friction", "μl = 0.002 m/mm"),
    ("Slider-driven rocker: balancing force", "μl = 0.005 m/mm"),
])
def test_chosen_scales_fit_the_force_sheet_on_its_page(tmp_path, title, mu_l):
    # μl was chosen for the mechanism alone, filling the page: the free bodies and the lever ran
    # off it ("the panels need 410.9 mm of height … run off the page", RPR at μl = 0.0005 m/mm)
    p = _write(tmp_path, _doc_scene(title))
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "s.svg"))
    assert code == 0 and "run off the page" not in err
    assert mu_l in (tmp_path / "s.svg").read_text(encoding="utf-8")
    code, out, _ = run_cli("check", str(p))
    assert code == 0 and mu_l + " (chosen)" in out  # the table reads the figure's lengths


def test_the_lever_with_friction_names_the_frictionless_balancing_moment(tmp_path):
    # the caption said "M_b = μv·ΣM_p/ω1 = …" though the lever knows no friction: it is M_b0
    code, _, err = run_cli("render", str(_write(tmp_path, _doc_scene("Oscillating block: reactions with friction")
                                               .replace('show = ["forces", "force_polygons"]',
                                                        'show = ["forces", "lever"]'))), "-o", str(tmp_path / "s.svg"))
    svg = (tmp_path / "s.svg").read_text(encoding="utf-8")
    assert code == 0 and "M_b0 = μv·ΣM_p/ω1 = " in svg and "N·m (without friction)" in svg


def test_a_resultant_moved_farther_than_the_mechanism_is_drawn_as_a_couple(tmp_path):
    # link 2 of 1 mg with J = 0.03 kg·m²: h = |M_i/F_i| ≈ 19 km, and F_i2′ was drawn there (the
    # sheet "needs 11289459.9 mm of height")
    text = (SCENES / "force.sixbar_kinetostatic.toml").read_text(encoding="utf-8")
    assert "mass_kg = 4\n" in text
    p = _write(tmp_path, text.replace("mass_kg = 4\n", "mass_kg = 1e-6\n"))
    fa = analyse_forces(load_scene(p))
    assert float(fa.solution.inertia["2"].offset[0]) > 1e4  # metres
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "s.svg"))
    svg = (tmp_path / "s.svg").read_text(encoding="utf-8")
    assert code == 0 and "run off the page" not in err
    assert "Fᵢ₂′" not in svg and "Fᵢ₂" in svg and "Fᵢ₃′" in svg


def test_a_scene_couple_is_drawn_on_the_loads_and_on_its_free_body(tmp_path):
    # M_r = 4 N·m on rocker 3 acted in every polygon but was drawn only on Zhukovsky's lever (at c
    # and p): the loads panel and the free body of group 2–3 left it out
    p = _write(tmp_path, _doc_scene("Slider-driven rocker: balancing force"))
    code, _, _ = run_cli("render", str(p), "-o", str(tmp_path / "s.svg"))
    svg = (tmp_path / "s.svg").read_text(encoding="utf-8")
    assert code == 0 and svg.count(">Mᵣ<") == 4
    no_lever = _doc_scene("Slider-driven rocker: balancing force").replace(
        'show = ["forces", "force_polygons", "lever"]', 'show = ["force_polygons"]')
    code, _, _ = run_cli("render", str(_write(tmp_path, no_lever, name="t.toml")), "-o", str(tmp_path / "t.svg"))
    assert code == 0 and (tmp_path / "t.svg").read_text(encoding="utf-8").count(">Mᵣ<") == 1


def test_the_fit_counts_the_footer_of_the_rendered_sheet(tmp_path):
    # the chosen μv fitted Zhukovsky's lever to a page without the footer line: rendered, it
    # needed 383.2 mm where the A2 page leaves 381.2 mm
    text = (SCENES / "force.sixbar_kinetostatic.toml").read_text(encoding="utf-8")
    text = text.replace('show = ["forces", "force_polygons", "lever"]', 'show = ["lever"]')
    text = re.sub(r"\[scales\]\n(.*\n){3}", "", text).replace("mu_F_N_per_mm = 25\n", "")
    text = text.replace("angle = 120\n", "angle = 41.6009\n").replace("omega = 12\n", "omega = -50\n")
    assert "[scales]" not in text and "omega = -50" in text
    code, _, err = run_cli("render", str(_write(tmp_path, text)), "-o", str(tmp_path / "s.svg"))
    assert code == 0 and "run off the page" not in err


def test_a_guide_reaction_whose_line_crosses_far_off_is_drawn_at_the_slider_with_its_moment():
    # RPP, slot ⟂ guide, friction: the guide's reaction on slot 3 is nearly along the guide and its
    # line of action crossed the guide 0.55 m from C — its arrow floated 270 mm off the free body
    from graphmech.drawing.primitives import Arrow, Label
    from graphmech.problems.forces.figures import free_body_items

    text = scene_text("forces/rpp_loaded").replace("slot_angle_deg = 60", "slot_angle_deg = 90").replace(
        "angle_deg = { start = 0, stop = 360, step = 60 }", "angle_deg = 45")
    scene = _scene(text.replace('show = ["mechanism"]', 'show = ["force_polygons"]'))
    fa = analyse_forces(scene)
    g = fa.solution.guides[0]
    c = complex(fa.kin.point["C"][0])
    e = float(g.moment[0]) / abs(complex(g.force[0]))
    assert abs(e) > 0.2  # metres: the line of action is far off
    group = next(gr for gr in fa.solution.groups if "3" in gr.links)
    items = free_body_items(fa.build, fa.kin, group, {}, {j.point for j in fa.solution.joints}, 0,
                            fa.solution.guides)
    at_c = fa.build.to_drawing((c.real, c.imag))
    assert any(isinstance(x, Arrow) and math.dist(x.p0, at_c) < 1e-9 for x in items)
    assert any(isinstance(x, Label) and x.text == "M₀₃" for x in items)
    xs = [p for x in items if isinstance(x, Arrow) for p in (x.p0[0], x.p1[0])]
    assert max(xs) - min(xs) < 100.0  # mm: the free body stays compact


def test_a_sheet_that_fits_no_round_scale_keeps_readable_drawings_and_says_so(tmp_path):
    # the first fit made everything coarser until the spill was least: μF = 20 N/mm drew 3 mm
    # polygons on an A4 sheet that captions alone overfill; now μl, μv first, a coarser scale only
    # for a real gain, and a hint
    code, _, err = run_cli("render", str(_write(tmp_path, scene_text("forces/double_slider"))), "-o", str(tmp_path / "s.svg"))
    assert code == 0 and 'give [page] size = "A3"' in err
    fa = analyse_forces(_scene(scene_text("forces/double_slider")))
    # (μl 0.02, not 0.01, since labels keep clear of every stroke: at 0.01 they push the crowded
    # free bodies 7 mm wider, and 0.02 spills more than FIT_GAIN_MM less)
    assert (fa.scales["l"], fa.scales["F"]) == (0.02, 5.0) and fa.spill_mm > 0
    rows = {r.name: r for r in fa.rows}
    # the loads drive the slider here (F_b0 < 0 along +v): η = F_b/F_b0
    assert rows["F_b0"].exact == pytest.approx(-46.921582, rel=1e-7)
    assert rows["eta"].exact == pytest.approx(rows["F_b"].exact / rows["F_b0"].exact, rel=1e-14)
    a3 = scene_text("forces/double_slider").replace("[units]", '[page]\nsize = "A3"\n[units]')
    code, _, err = run_cli("render", str(_write(tmp_path, a3, name="a3.toml")), "-o", str(tmp_path / "a3.svg"))
    assert code == 0 and "run off the page" not in err and "A3" not in err


# ----------------------------------------------------------------------------- the module's own pieces


@pytest.mark.parametrize("name, printed", [
    ("R^t_12", "Rᵗ₁₂"), ("R^n_43", "Rⁿ₄₃"), ("F_i2", "Fᵢ₂"), ("P_r", "Pᵣ"), ("G_5", "G₅"),
    ("M_b", "M_b"), ("Q", "Q"), ("R^x_12", "R^x₁₂"),
])
def test_force_names_as_the_book_prints_them(name, printed):
    from graphmech.problems.forces.figures import force_label

    assert force_label(name) == printed


def test_a_group_polygon_is_laid_off_head_to_tail_at_muF_and_closes_at_o():
    from graphmech.drawing.primitives import Arrow, Segment
    from graphmech.problems.forces.figures import CLOSING_OVERRUN, polygon_items

    fa = analyse_forces(load_scene(SCENES / "force.sixbar_kinetostatic.toml"))
    group = next(g for g in fa.solution.groups if g.name == "group 2–3")
    items = polygon_items(group, 25.0, 0)
    arrows = [x for x in items if isinstance(x, Arrow)]
    drawn = [(n, complex(v[0]) / 25.0) for n, v in group.chain if abs(complex(v[0])) / 25.0 > 1e-9]
    assert len(arrows) == len(drawn)
    for (name, v), a, b in zip(drawn, arrows, arrows[1:] + arrows[:1]):
        assert math.dist(a.p0, a.p1) == pytest.approx(abs(v), rel=1e-12)  # |F| / μF, mm
        assert a.p1 == pytest.approx(b.p0, abs=1e-9)  # head to tail, the last back to o
        assert a.role == ("result" if name in group.unknown else "given")
    closing = [x for x in items if isinstance(x, Segment)]
    assert len(closing) == 2  # through the chain's end and its start, along the two unknowns
    assert {round(math.dist(s.p0, s.p1) - 2 * CLOSING_OVERRUN, 9) for s in closing} == {
        round(abs(v), 9) for n, v in drawn if n in group.unknown}


def test_recorded_draw_calls_of_the_six_bar_force_sheet():
    from graphmech.problems.forces.check import render_forces
    from graphmech.render.recording import RecordingBackend
    from graphmech.render.sheet import draw_sheet

    scene = load_scene(SCENES / "force.sixbar_kinetostatic.toml")
    sheet, _ = render_forces(scene)
    assert [p.name for p in sheet.panels] == ["forces", "free-4-5", "polygon-4-5", "free-2-3", "polygon-2-3",
                                              "free-1", "polygon-1", "lever"]
    texts = [c[1] for c in draw_sheet(sheet, RecordingBackend()) if c[0] == "text"]
    assert texts.count("μF = 25 N/mm") == 3  # one per force polygon
    lever = analyse_forces(scene).lever
    assert f"M_b = μv·ΣM_p/ω1 = {float(lever.balancing_moment[0]):.6g} N·m" in texts
    assert {"Rᵗ₃₄", "Rⁿ₁₂", "Pᵣ", "o", "p"} <= set(texts)
