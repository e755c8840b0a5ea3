"""The instant-centre figures (graphmech/problems/instant_centres/figures.py): centres lettered as
the book prints them, the panel's scale, the polygon of links, and the sheet's panels and notes."""
from __future__ import annotations

import tomllib

import pytest

from graphmech.drawing.primitives import Circle, Label, Segment
from graphmech.methods.instant_centres import positions_mm
from graphmech.problems.instant_centres.figures import circle_panel, label, panel_scale
from graphmech.problems.linkage.check import analyse
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES
from tests.scenes import scene_text

#: A six-bar at φ = 40° and 165° showing its instant centres: 15 centres, 6 links.
SIXBAR = scene_text("linkage/ic_sixbar")


@pytest.fixture(scope="module")
def parallelogram():
    """AB = CD = 60 mm at 70°, AD = BC = 120 mm: four direct centres, P13 and P24 at infinity."""
    an = analyse(load_scene(SCENES / "ic.parallelogram.toml"))
    return an, an.instant_centres.centres[0]


def test_centres_are_lettered_with_subscripts():
    assert label("1", "3") == "P₁₃"
    assert label("2", "10") == "P₂,₁₀"  # a two-digit link: the numbers parted by a comma


def test_the_panel_keeps_the_diagrams_scale_when_it_fits_else_a_rounder_coarser_one(parallelogram):
    an, ic = parallelogram
    pos = positions_mm(an.build, an.solutions[0])  # A (0, 0) … C (70.3, 28.2) mm at μl = 0.002
    assert panel_scale(0.002, pos, ic, (200.0, 100.0)) == 0.002
    assert panel_scale(0.002, pos, ic, (20.0, 10.0)) == 0.01  # 70.3 mm into 20: ×3.5 → the round 0.01


def test_the_polygon_of_links_a_solid_chord_per_joint_a_dashed_one_per_kennedy_centre(parallelogram):
    _, ic = parallelogram
    panel = circle_panel("ic-circle", ic, row=3)
    chords = [it for it in panel.items if isinstance(it, Segment)]
    assert [c.dashed for c in chords] == [False] * 4 + [True] * 2
    assert [it.text for it in panel.items if isinstance(it, Label)] == ["1", "2", "3", "4"]
    assert sum(isinstance(it, Circle) for it in panel.items) == 5  # the circle and a dot per link
    assert (panel.title, panel.notes, panel.row) == ("Polygon of links", ("solid: direct, dashed: by Kennedy",), 3)


def test_an_undetermined_centre_gets_no_chord_and_a_note():
    an = analyse(load_scene(SCENES / "ic.parallelogram_change_point.toml"))
    panel = circle_panel("c", an.instant_centres.centres[0])
    assert len([it for it in panel.items if isinstance(it, Segment)]) < 6
    assert panel.notes[1].startswith("undetermined: ") and "P13" in panel.notes[1]


def test_the_sheet_draws_every_centre_and_the_polygon_of_links():
    from graphmech.scene import render_scene
    from graphmech.problems.instant_centres.figures import ic_panels
    from graphmech.drawing.primitives import Sheet
    from graphmech.render.recording import RecordingBackend
    from graphmech.render.sheet import draw_sheet

    svg, warnings = render_scene(SCENES / "kin.fourbar_instant_centres.toml")
    assert "Polygon of links" in svg and "226.6°" in svg  # the zeros of v_C to 4 figures
    book = analyse(parse_scene(tomllib.loads((SCENES / "kin.fourbar_instant_centres.toml").read_text()), "b"))
    drawn = ic_panels(book, (420.0, 297.0))
    texts = {it.text for p in drawn for it in p.items if type(it).__name__ == "Label"}
    assert {"P₁₃", "P₂₄", "P₁₂", "P₃₄", "φ_{2} = 26.38°", "φ_{2} = 226.6°"} <= texts
    zero = drawn[-1]
    assert zero.name == "ic-zero-C"  # the mechanism where v_C = 0: P24 on P12 = A, twice
    marks = [it.anchor for it in zero.items if type(it).__name__ == "Label" and it.text == "P₂₄"]
    assert marks == [pytest.approx((0.0, 0.0), abs=1e-9)]
    an = analyse(parse_scene(tomllib.loads(SIXBAR), "test.toml"))
    panels = ic_panels(an, (420.0, 297.0))
    assert [p.name for p in panels] == ["ic-40", "ic-circle-40", "ic-165", "ic-circle-165"]
    circle = panels[1]
    segs = [it for it in circle.items if type(it).__name__ == "Segment"]
    ic = an.instant_centres.centres[0]
    kennedy = sum(1 for c in ic.centres.values() if c.kind == "kennedy")
    assert sum(s.dashed for s in segs) == kennedy and len(segs) == 15
    rec = draw_sheet(Sheet("t", tuple(panels), (420.0, 297.0)), RecordingBackend())
    texts = [c[1] for c in rec if c[0] == "text"]
    for name in ("P₁₅", "P₂₆", "P₃₆", "P₄₅"):
        assert name in texts


def test_a_negative_omega_on_the_sheet_has_a_minus_sign():
    """The coupler at the rocker's extreme turns at ω3 = −ω2·AB/BC = −5 rad/s; the note printed
    '-5' with a hyphen."""
    from graphmech.scene import render_scene

    svg, _ = render_scene(SCENES / "ic.fourbar_dead_centre.toml")
    assert "= −5 rad/s" in svg and "= -5 rad/s" not in svg


def test_a_velocity_that_never_vanishes_is_said_so_on_the_sheet(tmp_path):
    """The parallelogram's v_C = ω·CD never vanishes: the note read "vC = 0 at φ₂ = " and nothing."""
    from graphmech.scene import render_scene

    text = (SCENES / "ic.parallelogram.toml").read_text(encoding="utf-8")
    p = tmp_path / "par.toml"
    p.write_text("\n".join('find = ["phi_v0_C"]' if line.startswith("find") else line
                           for line in text.splitlines()) + "\n", encoding="utf-8")
    svg, warnings = render_scene(p)
    assert "v_C does not vanish over the crank's turn" in " ".join(warnings)
    assert "= 0 at φ₂ = <" not in svg and "≠ 0 over the whole turn" in svg


def test_the_zero_velocity_panel_primes_the_other_position():
    """v_C = 0 twice: the first position bold with B, C; the second thin dashed with B′, C′ — no letter twice."""
    from graphmech.problems.instant_centres.figures import ic_panels

    book = analyse(parse_scene(tomllib.loads((SCENES / "kin.fourbar_instant_centres.toml").read_text()), "b"))
    zero = ic_panels(book, (420.0, 297.0))[-1]
    texts = [it.text for it in zero.items if type(it).__name__ == "Label"]
    assert len(texts) == len(set(texts)) and {"A", "D", "B", "C", "B′", "C′"} <= set(texts)
    dashed = [it for it in zero.items if type(it).__name__ == "Segment" and it.dashed]
    assert len(dashed) == 3 and all(s.role == "construction" for s in dashed)  # AB′, B′C′, C′D
    assert zero.title == "v_{C} = 0" and zero.scales == (("l", book.build.mu_l),)
