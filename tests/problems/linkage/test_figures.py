"""The kinematics figures in textbook conventions, asserted on the stream of draw calls."""
from __future__ import annotations

import math

import pytest

from graphmech.problems.linkage.check import analyse
from graphmech.problems.reader import page_size
from graphmech.problems.linkage.sizes import position_text
from graphmech.problems.linkage.figures import display, linkage_sheet
from graphmech.drawing.primitives import ArcArrow, Arrow, FixedPivot, GuideLine, Hinge, Label, Segment, Slider
from graphmech.render.recording import RecordingBackend
from graphmech.render.sheet import draw_sheet
from graphmech.scene import load_scene
from tests.conftest import SCENES


def sheet_of(name: str):
    an = analyse(load_scene(SCENES / f"{name}.toml"))
    b = an.build
    texts = [position_text(b, lab) for lab in an.labels]
    return an, linkage_sheet(an.scene.title, b.linkage, b, an.plan, an.solutions, an.labels, texts, an.scales,
                             list(an.scene.show), page_size(an.scene))


def panel(sheet, prefix):
    return next(p for p in sheet.panels if p.name.startswith(prefix))


def test_display_letters_as_the_book_prints_them():
    assert display("c2'") == "c₂′" and display("p'") == "p′" and display("n3'") == "n₃′"


def test_slider_crank_diagram_symbols():
    an, sheet = sheet_of("linkage.slider_crank_offset")
    mech = panel(sheet, "mechanism-50")
    kinds = [type(i) for i in mech.items]
    assert kinds.count(FixedPivot) == 1  # A, hatched
    assert kinds.count(Slider) == 1 and kinds.count(GuideLine) == 1  # block 3 on its guide
    assert kinds.count(Hinge) == 2  # B and C
    assert {i.text for i in mech.items if isinstance(i, Label)} >= {"A", "B", "C", "1", "2", "3", "ω_{1}"}
    arc = next(i for i in mech.items if isinstance(i, ArcArrow))
    assert arc.sweep > 0  # ω1 counter-clockwise
    # links are drawn at μl: |AB| on paper is l_AB/μl = 100 mm / 5 = 20 mm
    seg = next(i for i in mech.items if isinstance(i, Segment))
    assert math.dist(seg.p0, seg.p1) == pytest.approx(0.1 / an.scales["l"])


def test_velocity_polygon_draws_vectors_from_the_pole_and_thin_construction_lines():
    an, sheet = sheet_of("linkage.slider_crank_offset")
    vel = panel(sheet, "velocity-50")
    arrows = [i for i in vel.items if isinstance(i, Arrow)]
    lines = [i for i in vel.items if isinstance(i, Segment)]
    assert {a.role for a in arrows} == {"result"} and len(arrows) == 3  # pb, pc, bc
    assert lines and {s.role for s in lines} == {"construction"}
    # pc is v_C/μv long and lies along the guide (x)
    pc = next(a for a in arrows if a.p0 == (0.0, 0.0) and abs(a.p1[1]) < 1e-9)
    assert abs(pc.p1[0]) * an.scales["v"] == pytest.approx(0.8671274775157003, rel=1e-12)
    assert {i.text for i in vel.items if isinstance(i, Label)} == {"p", "b", "c"}


def test_acceleration_polygon_lays_off_the_normal_component_with_its_point_n():
    an, sheet = sheet_of("kin.oscillating_block")
    acc = panel(sheet, "acceleration")
    texts = {i.text for i in acc.items if isinstance(i, Label)}
    assert {"p′", "b′", "n₂′", "k′", "c₂′", "d′", "e′"} <= texts
    rec = draw_sheet(sheet, RecordingBackend())
    heads = [c for c in rec if c[0] == "polyline" and c[3] is True and c[4] is True]
    assert len(heads) >= 8  # every vector has an arrowhead drawn as a filled polygon


def test_scale_notes_are_written_under_each_panel():
    an, sheet = sheet_of("kin.oscillating_block")
    notes = [n for p in sheet.panels for n in p.notes]
    assert notes == ["μ_{l} = 0.002 m/mm", "μ_{v} = 0.005 (m/s)/mm", "μ_{a} = 0.05 (m/s²)/mm"]
    assert [p.scales for p in sheet.panels] == [(("l", 0.002),), (("v", 0.005),), (("a", 0.05),)]


def test_a_ternary_link_is_a_plate_with_its_hinges_on_top():
    """Link 3 of the six-bar carries B, C and E: one filled triangle, not three bars."""
    from graphmech.drawing.primitives import Plate
    from graphmech.methods.instant_centres import positions_mm
    from graphmech.problems.linkage.figures import mechanism_items

    an = analyse(load_scene(SCENES / "ic.sixbar.toml"))
    pos = positions_mm(an.build, an.solutions[0])
    items = mechanism_items(an.build, pos)
    plates = [it for it in items if isinstance(it, Plate)]
    assert len(plates) == 1 and sorted(plates[0].points) == sorted([pos["B"], pos["C"], pos["E"]])
    bars = {frozenset((it.p0, it.p1)) for it in items if isinstance(it, Segment)}
    assert frozenset((pos["B"], pos["C"])) not in bars  # BC is an edge of the plate
    hinges = {it.center for it in items if isinstance(it, Hinge)}
    assert {pos["B"], pos["C"], pos["E"]} <= hinges
    assert items.index(plates[0]) < min(i for i, it in enumerate(items) if isinstance(it, Hinge))


def test_the_found_senses_of_omega_and_epsilon_are_drawn_on_the_link():
    """Oscillating block at 45°: ω₂ = +1.995 rad/s (counter-clockwise), ε₂ = −8.419 rad/s² (clockwise)."""
    from graphmech.problems.linkage.sheet import scene_sheet

    sheet, _ = scene_sheet(load_scene(SCENES / "kin.oscillating_block.toml"), ())
    mech = panel(sheet, "mechanism")
    found = [it for it in mech.items if isinstance(it, ArcArrow) and it.role == "result"]
    texts = [it.text for it in mech.items if isinstance(it, Label)]
    assert "ω_{2}" in texts and "ε_{2}" in texts and "ω_{1}" in texts
    assert [math.copysign(1.0, a.sweep) for a in found] == [1.0, -1.0]


def test_a_guide_is_hatched_away_from_the_crank_pivot():
    """The offset guide runs 6 mm above A: its hatching is above it (GuideLine hatches its right)."""
    an, sheet = sheet_of("linkage.slider_crank_offset")
    for name in ("mechanism-50", "mechanism-220"):
        g = next(it for it in panel(sheet, name).items if isinstance(it, GuideLine))
        ax, ay = next(it for it in panel(sheet, name).items if isinstance(it, FixedPivot)).center
        (x0, y0), (x1, y1) = g.p0, g.p1
        assert y0 == y1 == pytest.approx(ay + 6.0)  # e = 30 mm at μl = 0.005
        right = (y1 - y0) * (ax - x0) - (x1 - x0) * (ay - y0)  # > 0: A on the hatched side
        assert right < 0


def test_a_guide_through_the_crank_pivot_stops_short_of_it():
    """A centred slider-crank's guide passes through A: it is drawn from 7 mm past A, never through it."""
    import tomllib

    from graphmech.problems.linkage.figures import PIVOT_CLEAR, mechanism_items
    from graphmech.scene import parse_scene
    from tests.problems.linkage.test_check import SLIDER_AT_DEAD_CENTRE

    text = SLIDER_AT_DEAD_CENTRE.replace("length = 100\nangle = 0", "length = 100\nangle = 150")
    an = analyse(parse_scene(tomllib.loads(text), "s.toml"))
    pos = {n: (float(an.solutions[0].values[s][0]), float(an.solutions[0].values[s][1]))
           for n, s in an.build.mech.items()}
    g = next(it for it in mechanism_items(an.build, pos) if isinstance(it, GuideLine))
    ax = pos["A"][0]
    assert min(g.p0[0], g.p1[0]) == pytest.approx(ax + PIVOT_CLEAR) and max(g.p0[0], g.p1[0]) > pos["C"][0]


def test_tangent_mechanism_draws_the_sliding_and_coriolis_sides():
    # seed 001 1-14 (PRP): v_C = v_C1 + v_C2C1 (∥ AB); a_C = a_C1 + a^k + a^r, the Coriolis side its own
    an, sheet = sheet_of("kin.tangent_mechanism")
    vel, acc = panel(sheet, "velocity"), panel(sheet, "acceleration")
    assert {i.text for i in vel.items if isinstance(i, Label)} == {"p", "b", "c₁", "c"}
    assert {"p′", "b′", "c₁′", "k′", "c′", "a^{k}"} <= {i.text for i in acc.items if isinstance(i, Label)}
    mv, ma = an.scales["v"], an.scales["a"]
    # pc runs up the guide, v3 = ω1·h/cos²φ; c1c runs along the bar (30°), v_C2C1 = ω1·h·tan φ/cos φ
    h, w, phi = 0.1, 10.0, math.radians(30.0)
    arrows = [(a.p0, a.p1) for a in vel.items if isinstance(a, Arrow)]
    pc = next(p1 for p0, p1 in arrows if p0 == (0.0, 0.0) and abs(p1[0]) < 1e-9)
    assert pc[1] * mv == pytest.approx(h * w / math.cos(phi) ** 2, rel=1e-12)
    c1c = [(p0, p1) for p0, p1 in arrows if p0 != (0.0, 0.0)]
    assert len(c1c) == 1
    (x0, y0), (x1, y1) = c1c[0]
    assert math.degrees(math.atan2(y1 - y0, x1 - x0)) == pytest.approx(30.0, abs=1e-9)
    assert math.hypot(x1 - x0, y1 - y0) * mv == pytest.approx(h * w * math.tan(phi) / math.cos(phi), rel=1e-12)
    # the Coriolis side c1′k′ is 2ω1·v_C2C1/μa long, ⟂ the bar (v_rel turned 90° with ω1, CCW)
    k = next(a for a in acc.items if isinstance(a, Arrow) and a.role == "construction"
             and math.dist(a.p0, a.p1) * ma == pytest.approx(2 * w * h * w * math.tan(phi) / math.cos(phi), rel=1e-12))
    assert math.degrees(math.atan2(k.p1[1] - k.p0[1], k.p1[0] - k.p0[0])) == pytest.approx(120.0, abs=1e-9)
    mech = panel(sheet, "mechanism")
    sliders = [i for i in mech.items if isinstance(i, Slider)]
    assert sorted(round(math.degrees(s.angle)) for s in sliders) == [30, 90]  # block 2 on the bar, rod 3's slider
    assert any(isinstance(i, GuideLine) for i in mech.items)
    assert not {"C1", "C2", "C3"} & {i.text for i in mech.items if isinstance(i, Label)}


def test_slotted_link_draws_the_pin_block_in_the_moving_slot(tmp_path):
    from tests.scenes import scene_path

    an = analyse(load_scene(scene_path("linkage/slotted_link_pin")))
    b = an.build
    sheet = linkage_sheet(an.scene.title, b.linkage, b, an.plan, an.solutions, an.labels,
                          [position_text(b, lab) for lab in an.labels], an.scales, list(an.scene.show),
                          page_size(an.scene))
    mech, vel, acc = panel(sheet, "mechanism"), panel(sheet, "velocity"), panel(sheet, "acceleration")
    assert [round(math.degrees(s.angle)) for s in mech.items if isinstance(s, Slider)] == [40]  # along the slot
    assert not any(isinstance(i, GuideLine) for i in mech.items)  # no frame guide: the slot moves
    assert {"p", "b", "c₂", "c"} == {i.text for i in vel.items if isinstance(i, Label)}
    assert {"c₂′", "k′", "c′", "a^{k}", "n₃′"} <= {i.text for i in acc.items if isinstance(i, Label)}


def test_a_class_iii_group_is_drawn_with_its_plate_and_assurs_point():
    """kin.class_iii_sixbar: the ternary link 3 a plate, B–C, F–D, G–E bars, S where BC and FD extended meet."""
    from graphmech.drawing.primitives import Plate

    _, sheet = sheet_of("kin.class_iii_sixbar")
    mech = panel(sheet, "mechanism")
    labels = {i.text: i.anchor for i in mech.items if isinstance(i, Label)}
    assert {"A", "B", "C", "D", "E", "F", "G", "S", "1", "2", "3", "4", "5"} <= set(labels)
    plates = [i for i in mech.items if isinstance(i, Plate)]
    assert len(plates) == 1 and {labels[n] for n in "CDE"} == set(plates[0].points)
    s = labels["S"]
    for p, x in (("B", "C"), ("F", "D")):  # S on the lines BC and FD
        (px, py), (xx, xy) = labels[p], labels[x]
        assert abs((xx - px) * (s[1] - py) - (xy - py) * (s[0] - px)) < 1e-9 * math.dist(labels[p], labels[x]) ** 2
    assert sum(isinstance(i, FixedPivot) for i in mech.items) == 3  # A, F, G
    vel, acc = panel(sheet, "velocity"), panel(sheet, "acceleration")
    assert {i.text for i in vel.items if isinstance(i, Label)} == {"p", "b", "c", "d", "e", "s"}
    assert {"p′", "b′", "c′", "d′", "e′", "s′", "σ₁′", "σ₂′", "n₂′", "n₄′", "n₅′"} <= {
        i.text for i in acc.items if isinstance(i, Label)}
