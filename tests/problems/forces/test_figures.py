"""The force sheet: panels, scales that fit the page, free bodies, couples and Zhukovsky's lever."""
from __future__ import annotations

import math
import re
import tomllib
import xml.etree.ElementTree as ET
from functools import partial

import pytest

from graphmech.drawing.lettering import plain
from graphmech.problems.forces.check import analyse_forces
from graphmech.scene import load_scene, parse_scene
from tests.conftest import ROOT, SCENES, run_cli
from tests.scenes import scene_text, write_scene


def _scene(text: str):
    return parse_scene(tomllib.loads(text), "t.toml")


_write = partial(write_scene, name="s.toml")


def _drawn(svg: str) -> list[str]:
    """Every text of an SVG as the reader sees it (sub- and superscripts are tspans)."""
    return ["".join(t.itertext()) for t in ET.fromstring(svg).iter() if t.tag.endswith("}text")]


def _has(svg: str, *texts: str) -> bool:
    """Each of ``texts`` (lettered, with marks) is drawn in ``svg``, within some line."""
    drawn = " | ".join(_drawn(svg))
    return all(plain(t) in drawn for t in texts)


def test_force_sheet_panels_and_one_position_only(tmp_path):
    from graphmech.scene import render_scene

    svg, warnings = render_scene(SCENES / "force.sixbar_kinetostatic.toml")
    assert _has(svg, "Free body, group 4–5", "Force polygon, group 2–3", "Zhukovsky", "μ_{F} = 25 N/mm",
                "Detail I of the force polygon, group 4–5", "μ_{F} = 2.5 N/mm")
    text = scene_text("forces/fourbar_loaded").replace('show = ["mechanism"]', 'show = ["force_polygons"]').replace('angle = 180', 'angle = [170, 180]')
    code, _, err = run_cli("render", str(_write(tmp_path, text)), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and "draw one position" in err and not (tmp_path / "x.svg").exists()


DOC_BLOCKS = re.findall(r"```toml\n(.*?)```", (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8"), re.S)


def _doc_scene(title: str) -> str:
    return next(b for b in DOC_BLOCKS if b.startswith(f'title = "{title}"'))


@pytest.mark.parametrize("title", ["Oscillating block: reactions with friction", "Slider-driven rocker: balancing force"])
def test_chosen_scales_fit_the_force_sheet_on_its_page(tmp_path, title):
    # μl was chosen for the mechanism alone, filling the page: the free bodies and the lever ran
    # off it ("the panels need 410.9 mm of height … run off the page", RPR at μl = 0.0005 m/mm)
    p = _write(tmp_path, _doc_scene(title))
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "s.svg"))
    assert code == 0 and "run off the page" not in err
    code, out, _ = run_cli("check", str(p))
    mu_l = re.search(r"μl = (\S+) m/mm \(chosen\)", out)
    assert code == 0 and mu_l is not None  # the table reads the figure's lengths at the μl drawn
    assert _has((tmp_path / "s.svg").read_text(encoding="utf-8"), f"μ_{{l}} = {mu_l[1]} m/mm")


def test_the_lever_with_friction_names_the_frictionless_balancing_moment(tmp_path):
    # the caption said "M_b = μv·ΣM_p/ω1 = …" though the lever knows no friction: it is M_b0
    code, _, err = run_cli("render", str(_write(tmp_path, _doc_scene("Oscillating block: reactions with friction")
                                               .replace('show = ["forces", "force_polygons"]',
                                                        'show = ["forces", "lever"]'))), "-o", str(tmp_path / "s.svg"))
    svg = (tmp_path / "s.svg").read_text(encoding="utf-8")
    assert code == 0 and _has(svg, "M_{b0} = μ_{v}·ΣM_{p}/ω_{1} = ", "N·m (without friction)")


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
    drawn = _drawn(svg)
    assert "F′i2" not in drawn and "Fi2" in drawn and "F′i3" in drawn


def test_a_scene_couple_is_drawn_on_the_loads_and_on_its_free_body(tmp_path):
    # M_r = 4 N·m on rocker 3 acted in every polygon but was drawn only on Zhukovsky's lever (at c
    # and p): the loads panel and the free body of group 2–3 left it out
    p = _write(tmp_path, _doc_scene("Slider-driven rocker: balancing force"))
    code, _, _ = run_cli("render", str(p), "-o", str(tmp_path / "s.svg"))
    svg = (tmp_path / "s.svg").read_text(encoding="utf-8")
    assert code == 0 and _drawn(svg).count("Mr") == 4
    no_lever = _doc_scene("Slider-driven rocker: balancing force").replace(
        'show = ["forces", "force_polygons", "lever"]', 'show = ["force_polygons"]')
    code, _, _ = run_cli("render", str(_write(tmp_path, no_lever, name="t.toml")), "-o", str(tmp_path / "t.svg"))
    assert code == 0 and _drawn((tmp_path / "t.svg").read_text(encoding="utf-8")).count("Mr") == 1


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
    assert any(isinstance(x, Label) and x.text == "M_{03}" for x in items)
    xs = [p for x in items if isinstance(x, Arrow) for p in (x.p0[0], x.p1[0])]
    assert max(xs) - min(xs) < 100.0  # mm: the free body stays compact


def test_a_sheet_that_fits_no_round_scale_keeps_readable_drawings_and_says_so(tmp_path):
    # the first fit made everything coarser until the spill was least: μF = 20 N/mm drew 3 mm
    # polygons on an A4 sheet that captions alone overfill; now μl, μv first, a coarser scale only
    # for a real gain, and a hint
    # on an A5 sheet (on A4 the double slider fits since captions wrap and the footer stands in
    # the margin: μl = 0.005, μF = 2 N/mm)
    a5 = scene_text("forces/double_slider").replace("[units]", '[page]\nsize = [210, 148]\n[units]')
    code, _, err = run_cli("render", str(_write(tmp_path, a5)), "-o", str(tmp_path / "s.svg"))
    assert code == 0 and 'give [page] size = "A3"' in err
    fa = analyse_forces(_scene(a5))
    assert (fa.scales["l"], fa.scales["F"]) == (0.025, 5.0) and fa.spill_mm > 0
    assert analyse_forces(_scene(scene_text("forces/double_slider"))).spill_mm == 0.0
    rows = {r.name: r for r in fa.rows}
    # the loads drive the slider here (F_b0 < 0 along +v): η = F_b/F_b0
    assert rows["F_b0"].exact == pytest.approx(-46.921582, rel=1e-7)
    assert rows["eta"].exact == pytest.approx(rows["F_b"].exact / rows["F_b0"].exact, rel=1e-14)
    a3 = scene_text("forces/double_slider").replace("[units]", '[page]\nsize = "A3"\n[units]')
    code, _, err = run_cli("render", str(_write(tmp_path, a3, name="a3.toml")), "-o", str(tmp_path / "a3.svg"))
    assert code == 0 and "run off the page" not in err and "A3" not in err


# ----------------------------------------------------------------------------- the module's own pieces


@pytest.mark.parametrize("name, printed", [
    ("R^t_12", "R^{t}_{12}"), ("R^n_43", "R^{n}_{43}"), ("F_i2", "F_{i2}"), ("P_r", "P_{r}"), ("G_5", "G_{5}"),
    ("M_b", "M_{b}"), ("Q", "Q"), ("R^x_12", "R^{x}_{12}"), ("F'_i2", "F′_{i2}"), ("F_load_1", "F_{load,1}"),
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
    drawn = [(n, complex(v[0]) / 25.0) for n, v in group.chain if abs(complex(v[0])) / 25.0 >= 0.1]
    assert [n for n, _ in drawn][0] == "G_2"  # R^t_12 is 0.07 mm: a head with no vector, left out
    assert len(arrows) == len(drawn)
    starts, vertex = {}, 0j
    for n, v in group.chain:  # head to tail from o, the vertex moved on by R^t_12 too
        starts[n], vertex = vertex, vertex + complex(v[0]) / 25.0
    assert abs(vertex) < 1e-9  # and back to o
    for (name, v), a in zip(drawn, arrows):
        assert math.dist(a.p0, a.p1) == pytest.approx(abs(v), rel=1e-12)  # |F| / μF, mm
        assert a.p0 == pytest.approx((starts[name].real, starts[name].imag), abs=1e-9)
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
    assert [p.name for p in sheet.panels] == ["forces", "free-4-5", "polygon-4-5", "detail-4-5", "free-2-3",
                                              "polygon-2-3", "detail-2-3", "free-1", "polygon-1", "detail-1", "lever"]
    texts = [c[1] for c in draw_sheet(sheet, RecordingBackend()) if c[0] == "text"]
    assert texts.count("μ_{F} = 25 N/mm") == 3  # one per force polygon
    assert {"μ_{F} = 2.5 N/mm", "μ_{F} = 1 N/mm"} <= set(texts)  # the details' own scales
    lever = analyse_forces(scene).lever
    assert f"M_{{b}} = μ_{{v}}·ΣM_{{p}}/ω_{{1}} = {float(lever.balancing_moment[0]):.4g} N·m" in texts
    assert {"R^{t}_{34}", "R^{n}_{12}", "P_{r}", "F_{i2}", "M_{b}", "S_{2}", "h_{2}", "o", "p"} <= set(texts)


# ----------------------------------------------------------------------------- issue 15: figures to hand out


def _sheet_of(path, notation: str = "en"):
    from graphmech.problems.forces.check import render_forces

    text = path.read_text(encoding="utf-8")
    if notation != "en":
        text = text.replace("[page]\n", f'[page]\nnotation = "{notation}"\n')
        assert f'notation = "{notation}"' in text
    return render_forces(_scene(text))


@pytest.mark.parametrize("name", ["force.sixbar_kinetostatic", "force.sixbar_kinetostatic-friction",
                                  "force.slider_crank_inertia_partial"])
def test_every_force_panel_states_its_scales_and_letters_at_3_5_mm_without_an_underscore(name):
    from graphmech.drawing.primitives import Label

    sheet, _ = _sheet_of(SCENES / f"{name}.toml")
    kinds = {"forces": "l", "free": "l", "polygon": "F", "detail": "F", "lever": "v"}
    for panel in sheet.panels:
        kind = kinds.get(panel.name.split("-")[0])
        if kind is None:  # the kinematic panels before them are the linkage's
            continue
        assert [k for k, _ in panel.scales] == [kind], panel.name
        for text in [panel.title, *panel.notes] + [x.text for x in panel.items if isinstance(x, Label)]:
            assert "_" not in plain(text), (panel.name, text)  # "M_b", "F_i2", "f_v" were drawn so
        assert all(x.size >= 3.5 for x in panel.items if isinstance(x, Label)), panel.name


def test_a_stated_muF_that_draws_short_vectors_is_warned_about_and_the_table_stays():
    # μF = 25 N/mm draws the inertia forces of the six-bar 1.3 mm long: ±0.5 mm is ±38 %
    code, out, err = run_cli("check", str(SCENES / "force.sixbar_kinetostatic.toml"))
    assert code == 0
    assert re.search(r"^F_i4 +1\.286 +25 ", out, re.M)  # the row itself as before
    # the other line: ω2 = v_CB/l_BC, whose v_CB is 8.9 mm of the velocity polygon at μv = 0.02
    short_v, warning = err.splitlines()
    assert short_v.startswith("force.sixbar_kinetostatic.toml: warning: omega_2 is drawn 8.91 mm long")
    assert warning.startswith("force.sixbar_kinetostatic.toml: warning: μF = 25 N/mm (stated) draws 6 of the "
                              "forces asked for shorter than 10 mm, where reading to ±0.5 mm errs by more than 5 %: "
                              "F_i4 1.286 mm (±39 %), F_i2 1.309 mm (±38 %), F_i3 1.356 mm (±37 %), "
                              "F_i5 4.344 mm (±12 %), R_05 6.991 mm (±7.2 %), R_05_y 6.991 mm (±7.2 %)")
    assert warning.endswith("; μF = 2.5 N/mm draws them all at least 10 mm long")
    assert "R_05_x" not in warning  # 0 N: no vector
    code, _, err = run_cli("check", str(SCENES / "force.slider_crank_inertia_partial.toml"))
    assert code == 0 and err == ""  # F_i3 39 mm, F_i2 54 mm at μF = 100 N/mm


def test_a_chosen_muF_draws_the_forces_asked_for_10_mm_long_where_the_page_allows(tmp_path):
    text = (SCENES / "force.sixbar_kinetostatic.toml").read_text(encoding="utf-8").replace("mu_F_N_per_mm = 25\n", "")
    reactions = text.replace(text[text.index("find = ["):text.index("]\n", text.index("find = [")) + 2],
                             'find = ["R_01", "R_12", "R_23", "R_03", "R_34", "R_45", "R_05"]\n')
    fa = analyse_forces(_scene(reactions))
    # 70 mm for the largest polygon gave 25 N/mm and R_05 (174.8 N) 7 mm: now the round μF that
    # draws it 10 mm or more, as the A2 page has room for the polygons then
    assert fa.scales["F"] == 10.0 and fa.spill_mm == 0.0 and fa.warnings == []
    rows = {r.name: r for r in fa.rows}
    assert min(abs(r.drawn_mm) for r in rows.values()) == pytest.approx(174.786222 / 10.0, rel=1e-8)
    # the inertia forces too (32 N) would need 2.5 N/mm: R_23 644 mm long, more than the page allows
    fa = analyse_forces(_scene(text))
    assert fa.scales["F"] == 10.0 and len(fa.warnings) == 2
    assert fa.warnings[0].startswith("omega_2 is drawn 8.91 mm long")  # v_CB on the velocity polygon
    assert fa.warnings[1].startswith("μF = 10 N/mm (chosen: a finer round scale does not fit the page) draws 3 of "
                                     "the forces asked for shorter than 10 mm")
    assert "F_i4 3.214 mm (±16 %)" in fa.warnings[1]


def test_a_force_polygon_with_short_vectors_gets_a_detail_at_a_round_muF():
    from graphmech.drawing.primitives import Arrow, Circle, Label
    from graphmech.problems.forces.figures import READ_MIN_MM, detail_items, polygon_detail, polygon_items

    fa = analyse_forces(load_scene(SCENES / "force.sixbar_kinetostatic.toml"))
    group = next(g for g in fa.solution.groups if g.name == "group 4–5")
    detail = polygon_detail(group, 25.0, 0)
    # G_4 1.37 mm, F_i4 1.29 mm … at 25 N/mm: ten times larger, 2.5 N/mm, a round scale
    assert (detail.factor, detail.mu_F) == (10.0, 2.5)
    assert set(detail.shown) == {"R^t_34", "G_4", "F_i4", "G_5", "F_i5"}
    items = detail_items(group, 25.0, 0, detail)
    chain = {n: complex(v[0]) / 2.5 for n, v in group.chain}
    arrows = [x for x in items if isinstance(x, Arrow)]
    for name in ("G_4", "F_i4", "G_5", "F_i5"):
        assert abs(chain[name]) >= READ_MIN_MM  # readable there
        assert any(math.dist(a.p0, a.p1) == pytest.approx(abs(chain[name]), rel=1e-12) for a in arrows), name
    texts = {x.text for x in items if isinstance(x, Label)}
    assert {"G_{4}", "F_{i4}", "G_{5}", "F_{i5}", "P_{r}", "o"} <= texts  # P_r cut at the window's edge
    x0, y0, x1, y1 = (v * 10.0 for v in detail.box)
    assert max(x1 - x0, y1 - y0) <= 100.0
    main = polygon_items(group, 25.0, 0, detail, "I")
    main_texts = [x.text for x in main if isinstance(x, Label)]
    assert "G_{4}" not in main_texts and "P_{r}" in main_texts and "I" in main_texts  # no clump at o: a ring
    assert sum(isinstance(x, Circle) for x in main) == 1
    readable = next(g for g in fa.solution.groups if g.name == "group 4–5")
    assert polygon_detail(readable, 0.25, 0) is None  # every vector over 10 mm: no detail


def test_friction_circles_under_1_mm_are_enlarged_and_the_reactions_touch_them():
    # ρ = 0.15 × 12 mm = 1.8 mm is 0.36 mm at μl = 0.005 m/mm: hidden under the 1.2 mm pin, while
    # the note said the reactions were tangent to them
    from graphmech.drawing.primitives import Arrow, Circle

    sheet, _ = _sheet_of(SCENES / "force.sixbar_kinetostatic-friction.toml")
    free = next(p for p in sheet.panels if p.name == "free-2-3")
    assert free.notes[-1] == "friction circles ρ = f_{v}·r ×10 (not to scale), reactions tangent to them"
    circles = [x for x in free.items if isinstance(x, Circle)]
    assert sorted(round(c.r, 9) for c in circles) == [3.6, 4.5, 4.5, 6.0]  # E, B, C, D: 10 × ρ/μl
    arrows = [x for x in free.items if isinstance(x, Arrow)]
    touching = [a for a in arrows for c in circles if math.dist(a.p0, c.center) == pytest.approx(c.r, rel=1e-9)]
    assert len(touching) == 3  # R_12 at B, R_43 at E, R_03 at D (C joins the group's own links)
    for c in circles:  # the reaction at each journal starts where its line touches the circle drawn
        for a in [a for a in touching if math.dist(a.p0, c.center) == pytest.approx(c.r, rel=1e-9)]:
            u = (a.p1[0] - a.p0[0], a.p1[1] - a.p0[1])
            radial = ((a.p0[0] - c.center[0]) * u[0] + (a.p0[1] - c.center[1]) * u[1]) / math.hypot(*u)
            assert radial == pytest.approx(0.0, abs=1e-9)  # ⟂ to the radius: tangent
    loads = next(p for p in sheet.panels if p.name == "forces")
    assert "friction circles ρ = f_{v}·r ×10 (not to scale)" in loads.notes
    assert min(x.r for x in loads.items if isinstance(x, Circle)) == pytest.approx(3.6)


def test_friction_circles_large_enough_are_drawn_at_mu_l():
    from graphmech.problems.forces.figures import friction_factor, friction_notes

    assert friction_factor({"A": 0.006}, 0.005) == 1.0  # 1.2 mm: visible
    assert friction_factor({"A": 0.006, "B": 0.001}, 0.005) == 20.0  # 0.2 mm → 4 mm, A with it 24 mm
    assert friction_notes(1.0, "en", True) == ("friction circles ρ = f_{v}·r at μ_{l}, reactions tangent to them",)
    assert "не в масштабе" in friction_notes(10.0, "ru", False)[0]


@pytest.mark.parametrize("notation, words", [
    ("zh", ("力多边形", "分离体", "儒可夫斯基杠杆", "局部放大", "杆组 4–5")),
    ("ru", ("план сил", "расчётная схема", "рычаг Жуковского", "выносной элемент", "группа 4–5")),
])
def test_the_force_sheet_in_chinese_and_russian_notation_changes_captions_not_check(tmp_path, notation, words):
    en, _ = _sheet_of(SCENES / "force.sixbar_kinetostatic.toml")
    other, _ = _sheet_of(SCENES / "force.sixbar_kinetostatic.toml", notation)
    assert [p.name for p in other.panels] == [p.name for p in en.panels]
    captions = " ".join(p.title for p in other.panels)
    assert all(w in captions for w in words) and "Force polygon" not in captions
    assert all(a.title != b.title for a, b in zip(en.panels, other.panels))
    text = (SCENES / "force.sixbar_kinetostatic.toml").read_text(encoding="utf-8")
    p = _write(tmp_path, text.replace("[page]\n", f'[page]\nnotation = "{notation}"\n'))
    ref = SCENES / "force.sixbar_kinetostatic.toml"
    for args in ((), ("--json",)):  # the same table, JSON and warnings: notation is drawn text only
        code, out, err = run_cli("check", str(p), *args)
        assert (code, out, err.replace(p.name, ref.name)) == run_cli("check", str(ref), *args)
        assert "μF = 25 N/mm (stated) draws 6" in (err + out)


def test_an_offset_guide_bars_free_body_draws_its_arm_and_its_line():
    """The oscillating block with its bar's line e = 12 mm left of B: the free body of group 2–3 draws
    the arm BF (|BF| = e, ⟂ FC) and the line FC, not the segment BC; the block lies along FC."""
    from graphmech.drawing.primitives import Segment, Slider
    from graphmech.problems.forces.figures import free_body_items
    from tests.problems.forces.test_check import RPR_LOADS

    text = (SCENES / "kin.oscillating_block.toml").read_text(encoding="utf-8")
    text = text.replace('bar = "first"\n', 'bar = "first"\noffset = 12\n')
    text = text.replace('show = ["mechanism", "velocity", "acceleration"]', 'show = ["force_polygons"]')
    fa = analyse_forces(_scene(text + RPR_LOADS))
    group = next(gr for gr in fa.solution.groups if "2" in gr.links)
    items = free_body_items(fa.build, fa.kin, group, {}, {j.point for j in fa.solution.joints}, 0)
    mu = fa.build.mu_l
    B, C = (fa.build.to_drawing((complex(fa.kin.point[n][0]).real, complex(fa.kin.point[n][0]).imag)) for n in "BC")
    segs = [(x.p0, x.p1) for x in items if isinstance(x, Segment)]
    arm = next(s for s in segs if math.dist(s[0], B) < 1e-9 and math.dist(s[1], C) > 1.0)
    F = arm[1]
    assert math.dist(B, F) == pytest.approx(12.0 / 1000 / mu, rel=1e-12)
    assert (F, C) in segs and not any({s[0], s[1]} == {B, C} for s in segs)
    u = ((C[0] - F[0]) / math.dist(F, C), (C[1] - F[1]) / math.dist(F, C))
    assert (F[0] - B[0]) * u[0] + (F[1] - B[1]) * u[1] == pytest.approx(0.0, abs=1e-9)  # BF ⟂ FC
    block = next(x for x in items if isinstance(x, Slider))
    assert math.cos(block.angle) * u[1] - math.sin(block.angle) * u[0] == pytest.approx(0.0, abs=1e-12)
