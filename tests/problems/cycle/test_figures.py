"""The figures of a full cycle and of the characteristics (graphmech/problems/cycle/figures.py):
which positions are drawn, the curves thinned, the numbered pin, the diagrams' axes, the extreme
positions, the Grashof ranges, the sheet's panels, and drawings too large refused."""
from __future__ import annotations

import math
import re
import subprocess
import sys

import pytest

from graphmech.drawing.primitives import Label, Polyline, Segment, Slider
from graphmech.problems import sheet
from graphmech.problems.cycle.check import analyse_cycle
from graphmech.problems.cycle.figures import (MOST_DRAWN, characteristics_items, cycle_items, diagram_items,
                                              drawn_positions, ranges_items, thinned)
from graphmech.render.recording import RecordingBackend
from graphmech.render.sheet import draw_sheet
from graphmech.scene import load_scene, render_scene
from tests.conftest import ROOT, SCENES, assert_refused, run_cli
from tests.scenes import scene_path, scene_text


@pytest.fixture(scope="module")
def slider_crank():
    """The centred slider-crank's cycle analysed: AB = 50 mm at μl = 5 mm/mm, 12 positions."""
    return analyse_cycle(load_scene(scene_path("cycle/slider_crank")))


def labels(items):
    return [(it.text, it.anchor) for it in items if isinstance(it, Label)]


def test_every_position_is_drawn_up_to_the_most_then_every_kth():
    assert drawn_positions(12) == list(range(12))
    assert drawn_positions(MOST_DRAWN) == list(range(MOST_DRAWN))
    assert drawn_positions(MOST_DRAWN + 1) == list(range(0, MOST_DRAWN + 1, 2))  # 13 of 25, never more than 24 + 1
    assert drawn_positions(3600) == list(range(0, 3600, 200))


def test_a_curve_keeps_a_vertex_every_half_millimetre_and_both_ends():
    dense = [(0.01 * k, 0.0) for k in range(1001)]  # 10 mm in 1000 steps
    kept = thinned(dense)
    assert kept[0] == (0.0, 0.0) and kept[-1] == (10.0, 0.0)
    assert len(kept) == 21
    assert all(b[0] - a[0] == pytest.approx(0.5) for a, b in zip(kept, kept[1:]))
    circle = [(5 * math.cos(t / 100), 5 * math.sin(t / 100)) for t in range(629)]
    assert all(math.hypot(*p) == pytest.approx(5.0) for p in thinned(circle))  # vertices only dropped, never moved
    assert thinned([(0, 0), (0.001, 0)]) == ((0.0, 0.0), (0.001, 0.0))  # two points stay two


def test_the_crank_pins_positions_are_numbered_in_its_sense(slider_crank):
    """AB = 50 mm at μl = 5 mm/mm: the pin's circle has a radius of 10 mm; every second of 12 numbered."""
    items = cycle_items(slider_crank.cycle, ("C",))
    numbers = [(t, at) for t, at in labels(items) if t.isdigit()]
    assert [t for t, _ in numbers] == ["1", "3", "5", "7", "9", "11"]
    for t, at in numbers:
        angle = math.radians(30 * (int(t) - 1))
        assert at == pytest.approx((10 * math.cos(angle), 10 * math.sin(angle)), abs=1e-12)
    assert {"A", "B", "C"} <= {t for t, _ in labels(items)}  # position 1 lettered
    assert sum(isinstance(it, Polyline) and it.closed for it in items) == 1  # C's path


def test_a_sliders_diagrams_are_s_v_a_and_a_links_psi_omega_epsilon(slider_crank):
    cyc = slider_crank.cycle
    period = 2 * math.pi / cyc.mu_phi
    names = {dg.subject: [t for t, _ in labels(diagram_items(dg, cyc.n, period)) if not t.isdigit()]
             for dg in cyc.diagrams}
    assert names["C"][:3] == ["s_{C}", "φ", "O"]
    assert {"v_{C}", "a_{C}", "P_{1}", "H_{1}", "P_{2}", "H_{2}"} <= set(names["C"])
    assert names["2"][:3] == ["ψ_{2}", "φ", "O"] and {"ω_{2}", "ε_{2}"} <= set(names["2"])


def test_a_slider_cranks_extreme_positions_and_its_stroke(slider_crank):
    """Centred: C₁ 250 mm, C₂ 150 mm from A on the guide, 50 and 30 mm at μl = 5; H = 20 mm between."""
    items = characteristics_items(slider_crank.drawn, slider_crank.scene.linkage)
    sliders = [it for it in items if isinstance(it, Slider)]
    assert sorted(s.center for s in sliders) == [(30.0, 0.0), (50.0, 0.0)]
    assert {"θ", "H", "γ_{min}", "A", "B₁", "C₁", "B₂", "C₂", "B′", "C′"} <= {t for t, _ in labels(items)}
    stroke = next(at for t, at in labels(items) if t == "H")
    assert stroke[0] == pytest.approx(40.0)  # marked in the middle of C₁C₂


def test_the_grashof_ranges_on_one_axis():
    ranges = [("crank_rocker_AB", 0.0, 0.015), ("double_rocker", 0.015, 0.045), ("double_crank", 0.045, 0.055),
              ("double_rocker", 0.055, 0.115)]
    items, mu = ranges_items(ranges, "AB", 0.01)
    assert mu == 0.001  # 115 mm on 150 mm of axis: 1 mm per mm
    bold = [(it.p0[0], it.p1[0], it.dashed) for it in items if isinstance(it, Segment) and it.role == "result"]
    assert bold == [(0.0, 15.0, False), (15.0, 45.0, True), (45.0, 55.0, False), (55.0, 115.0, True)]
    texts = [t for t, _ in labels(items)]
    assert texts[2:] == ["crank-rocker", "15", "double rocker", "45", "double crank", "55", "double rocker", "115",
                         "AB = 10"]


def test_the_sheet_has_a_panel_per_shown_entry_in_order():
    scene = load_scene(SCENES / "linkage.slider_crank_offset-cycle.toml")
    assert scene.show == ("cycle", "paths", "velocity", "diagrams")
    drawing, warnings = sheet(scene)
    assert [p.name for p in drawing.panels] == ["cycle", "velocity", "diagrams-C"]  # the paths in the cycle panel
    rec = RecordingBackend()
    draw_sheet(drawing, rec)
    assert [c[1] for c in rec.calls if c[0] == "begin_group" and not c[1].startswith(("label", "caption"))] == [
        "title", "panel1-cycle", "panel2-velocity", "panel3-diagrams-C"]
    cycle = drawing.panels[0]
    assert cycle.title == "Kinematic diagram at all positions, paths of E"  # the coupler point
    assert any("(an extreme position)" in n for n in cycle.notes)


def test_the_characteristics_sheet_adds_the_ranges_panel():
    drawing, _ = sheet(load_scene(SCENES / "linkage.grashof_ranges.toml"))
    assert [p.name for p in drawing.panels] == ["characteristics", "ranges"]
    assert drawing.panels[0].title == "Extreme positions, θ, ψ and γ_{min}"
    assert "θ = 33.38°, ψ = 59.1°, K = (180° + θ)/(180° − θ) = 1.455" in drawing.panels[0].notes
    assert drawing.panels[1].notes[0] == "1 mm of l_{AB} per mm"


def test_same_scene_same_svg():
    a, _ = render_scene(SCENES / "linkage.slider_crank_offset-cycle.toml")
    b, _ = render_scene(SCENES / "linkage.slider_crank_offset-cycle.toml")
    assert a == b  # (the committed figure is compared, parsed, in tests/test_cli.py)


def test_a_cycle_sheet_never_imports_matplotlib():
    code = ("import sys; from graphmech.cli import main; "
            f"main(['check', {str(SCENES / 'linkage.slider_crank_offset-cycle.toml')!r}]); "
            "assert not any(m.split('.')[0] == 'matplotlib' for m in sys.modules), 'matplotlib imported'")
    r = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0 and "matplotlib imported" not in r.stderr, r.stderr


def test_the_cycle_panel_numbers_positions_not_links():
    from graphmech.problems.cycle.check import analyse_cycle
    from graphmech.problems.cycle.figures import cycle_items
    from graphmech.drawing.primitives import Label
    from graphmech.scene import load_scene

    an = analyse_cycle(load_scene(SCENES / "linkage.fourbar_28_52_50_72-cycle.toml"))
    numbers = sorted(int(it.text) for it in cycle_items(an.cycle, ("E",)) if isinstance(it, Label) and it.text.isdigit())
    assert numbers == list(range(1, 13))


def test_a_slider_s_v_a_axes_are_named_with_subscripts():
    """The diagrams of slider C are s_C, v_C, a_C: C set as a subscript in the SVG, as books write them."""
    import xml.etree.ElementTree as ET

    svg, _ = render_scene(SCENES / "linkage.slider_crank_offset-cycle.toml")
    ns = "{http://www.w3.org/2000/svg}"
    subscripted = {(t.text, t[0].text) for t in ET.fromstring(svg).iter(ns + "text") if len(t)}
    assert {("s", "C"), ("v", "C"), ("a", "C")} <= subscripted


def test_characteristics_of_a_hundred_metre_drawing_stay_small(tmp_path):
    """Lengths ×50 at the stated μl = 0.5 mm/mm: the arcs of radius BC ∓ AB are metres long and
    drawn with a bounded number of chords (×1e12 took 2e13 points and exhausted memory; such a
    drawing, 1.4e14 mm across, is refused by the bound on the drawn size, as ×1e3 is: 10 m of paper)."""
    from graphmech.drawing.primitives import ARC_MOST, Polyline

    text = (SCENES / "linkage.fourbar_28_52_50_72.toml").read_text(encoding="utf-8").split("[measured]")[0]
    big = text
    for a, b in (("length = 28", "length = 28e3"), ("lengths = [52, 50]", "lengths = [52e3, 50e3]"),
                 ("D = [72, 0]", "D = [72e3, 0]")):
        text, big = text.replace(a, b.replace("e3", "*50")), big.replace(a, b)
    text = re.sub(r"(\d+)\*50", lambda m: str(int(m.group(1)) * 50), text)
    p = tmp_path / "huge.toml"
    p.write_text(big, encoding="utf-8")
    assert_refused(run_cli("render", str(p), "-o", str(tmp_path / "huge.svg")), "huge.toml",
                   "draws the mechanism 1.44e+05 mm across")
    p.write_text(text, encoding="utf-8")
    from graphmech.methods.characteristics import draw_characteristics
    from graphmech.problems.cycle.figures import characteristics_items
    from graphmech.scene import load_scene

    sc = load_scene(p)
    items = characteristics_items(draw_characteristics(sc.linkage, sc.scales["l"]), sc.linkage)
    arcs = [it for it in items if isinstance(it, Polyline)]
    assert arcs and max(len(a.points) for a in arcs) == ARC_MOST + 1
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "huge.svg"))
    assert code == 0 and (tmp_path / "huge.svg").stat().st_size < 200_000, err


@pytest.mark.parametrize("scale, across", [("1e-9", "2e+08"), ("1e9", "2e-10")])
def test_a_stated_scale_that_cannot_be_drawn_is_refused(tmp_path, scale, across):
    """μl = 1e-300 m/mm (render: exit 3) or 1e300 (check: ZeroDivisionError, exit 3) are refused
    where every scale is read (below); within that range the cycle sheet bounds the mechanism."""
    text = scene_text("cycle/slider_crank").replace("[units]", f"[scales]\nl_m_per_mm = {scale}\n\n[units]")
    p = tmp_path / "s.toml"
    p.write_text(re.sub(r'(?m)^find = .*$', "find = []", re.sub(r'(?m)^show = .*$', 'show = ["cycle"]', text)))
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and err.startswith(f"s.toml: scales: μl = {scale.replace('1e9', '1e+09').replace('1e-9', '1e-09')} m/mm draws the "
                                        f"mechanism {across} mm across"), err


def test_the_other_positions_are_thin_dashed_and_no_letter_stands_twice():
    """Position 1 bold with its letters and the coupler BCE a plate; the eleven others thin dashed."""
    from graphmech.drawing.primitives import Plate

    an = analyse_cycle(load_scene(SCENES / "linkage.fourbar_28_52_50_72-cycle.toml"))
    items = cycle_items(an.cycle, ("E",))
    segs = [it for it in items if isinstance(it, Segment)]
    assert sum(1 for s in segs if s.dashed and s.role == "construction") >= 11 * 3
    assert all(s.dashed for s in segs if s.role == "construction")
    assert sum(isinstance(it, Plate) for it in items) == 1  # position 1's coupler BCE
    letters = [t for t, _ in labels(items) if not t.isdigit()]
    assert len(letters) == len(set(letters)) and {"A", "B", "C", "D", "E"} <= set(letters)


def test_the_extreme_positions_panel_letters_each_position_once():
    """B₁C₁ bold, B₂C₂ and the γ_min position B′C′ thin dashed; AD a dash-dot line of centres; γ_min
    lettered off the line AD."""
    an = analyse_cycle(load_scene(SCENES / "linkage.fourbar_28_52_50_72-cycle.toml"))
    items = characteristics_items(an.drawn, an.scene.linkage)
    texts = [t for t, _ in labels(items)]
    assert len(texts) == len(set(texts)) and {"B₁", "C₁", "B₂", "C₂", "B′", "C′", "γ_{min}"} <= set(texts)
    A, D = an.drawn.points["A"], an.drawn.points["D"]
    assert any(s.dashdot and {s.p0, s.p1} == {A, D} for s in items if isinstance(s, Segment))
    assert not any(s.role == "given" for s in items if isinstance(s, Segment))  # the frame is its pivots
    gx, gy = next(at for t, at in labels(items) if t == "γ_{min}")
    off = abs((D[0] - A[0]) * (gy - A[1]) - (D[1] - A[1]) * (gx - A[0])) / math.dist(A, D)
    assert off > 1.5  # the letter's anchor stands off the frame line


def test_common_pole_images_are_merged_where_they_coincide_and_numbered_along_a_line(slider_crank):
    """The slider's images c₁ … c₁₂ lie on the guide's line through p: numbers there, the letter at
    the farthest; no text twice."""
    from graphmech.problems.cycle.figures import polygons_items

    texts = [t for t, _ in labels(polygons_items(slider_crank.cycle, "velocity"))]
    assert len(texts) == len(set(texts))
    assert sum(t.startswith("c") for t in texts) <= 2 and sum(t[:1].isdigit() for t in texts) >= 8
    assert {f"b_{{{k}}}" for k in (2, 3, 5, 6)} <= set(texts)


@pytest.mark.parametrize(("notation", "begins", "timing"), [
    ("en", "position 1 (bold): the working stroke begins", "working stroke 210° in 7 s"),
    ("zh", "位置1（粗线）：工作行程开始", "工作行程210°用时7 s"),
    ("ru", "положение 1 (жирно): начало рабочего хода", "рабочий ход 210° за 7 с"),
])
def test_the_characteristics_notes_are_lettered_in_the_notation(notation: str, begins: str, timing: str) -> None:
    import pathlib
    import tomllib

    from graphmech.problems import KINDS
    from graphmech.scene import parse_scene
    from tests.conftest import SCENES

    data = tomllib.loads(pathlib.Path(SCENES / "linkage.quick_return_timing.toml").read_text(encoding="utf-8"))
    data.setdefault("page", {})["notation"] = notation
    scene = parse_scene(data, "quick_return")
    sheet, _ = KINDS[scene.kind].sheet(scene, ())
    [notes] = [p.notes for p in sheet.panels if p.name == "characteristics"]
    assert any(begins in n for n in notes) and any(n.startswith(timing) for n in notes)
    assert notes[0] == "μ_{l} = 0.001 m/mm"  # symbols and numbers the same in every notation


def test_a_swings_positions_are_numbered_together_out_and_back_and_its_path_is_open():
    an = analyse_cycle(load_scene(SCENES / "linkage.rocker_swing.toml"))
    items = cycle_items(an.cycle, ["E"])
    numbers = [it.text for it in items if isinstance(it, Label) and re.fullmatch(r"[0-9, ]+", it.text)]
    assert numbers == ["1", "2, 12", "3, 11", "4, 10", "5, 9", "6, 8", "7"]
    paths = [it for it in items if isinstance(it, Polyline) and it.role == "result"]
    assert len(paths) == 1 and not paths[0].closed  # out and back over one arc
    notes = [p for p in sheet(load_scene(SCENES / "linkage.rocker_swing.toml"))[0].panels if p.name == "cycle"][0].notes
    assert "12 positions: 1 … 7 out, φ = −97.9° → 97.9° (its limits), 8 … 12 back" in notes
