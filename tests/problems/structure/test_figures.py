"""The structure sheet: groups outlined, every reference sheet on its page, no matplotlib, scales refused."""
from __future__ import annotations


import pytest

from tests.conftest import SCENES, run_cli


def test_structure_sheet_outlines_the_groups():
    from graphmech.scene import render_scene

    svg, warnings = render_scene(SCENES / "dof.hfut_cases-ic_engine_EG.toml")
    assert "III (2,3,4,5)" in svg and "II (7,8)" in svg and "special construction" in svg
    assert "I: 1 + 6" in svg and "rank J = 20 of 20" in svg


def test_rendering_instant_centres_and_structure_never_imports_matplotlib(tmp_path):
    import subprocess
    import sys

    from tests.conftest import ROOT

    scenes = [SCENES / "kin.fourbar_instant_centres.toml", SCENES / "dof.hfut_cases-3-2.toml"]
    code = ("import sys; from graphmech.cli import main; "
            f"rc = main(['render', *{[str(s) for s in scenes]!r}, '-d', r'{tmp_path}']); "
            "assert not any(m.split('.')[0] == 'matplotlib' for m in sys.modules), 'matplotlib imported'; "
            "sys.exit(rc)")
    r = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "dof.hfut_cases-3-2.svg").read_text().startswith("<svg")


@pytest.mark.parametrize("name", sorted(p.stem for p in SCENES.glob("*.toml")
                                        if p.stem.startswith(("dof.", "structure."))))
def test_every_structure_sheet_fits_its_page(name):
    """The class III message (IC engine from EG) made the block diagram's panel 403 mm wide on an
    A4 page; HFUT 3-2's diagram was drawn at μl = 0.005 (38 mm tall, labels on top of each other)."""
    from graphmech.scene import render_scene

    svg, warnings = render_scene(SCENES / f"{name}.toml")
    assert not [w for w in warnings if "runs off the page" in w], warnings
    if name == "dof.hfut_cases-3-2":
        assert "μl = 0.0025 m/mm" in svg


def test_a_stated_scale_that_cannot_draw_the_pairs_is_refused(tmp_path):
    """μl = 1e-300 m/mm drew the parallelogram 1e299 mm across: render exit 3. Now refused where
    every scale is read; within that range the structure sheet bounds the drawing itself."""
    text = (SCENES / "structure.parallelogram_redundant.toml").read_text(encoding="utf-8")
    p = tmp_path / "tiny.toml"
    p.write_text(text.replace('[units]', '[scales]\nl_m_per_mm = 1e-300\n\n[units]'), encoding="utf-8")
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and err.startswith("tiny.toml: scales.l_m_per_mm: 1e-300: under 1e-15 SI units per mm"), err
    p.write_text(text.replace('[units]', '[scales]\nl_m_per_mm = 1e-12\n\n[units]'), encoding="utf-8")
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and err.startswith("tiny.toml: scales: μl = 1e-12 m/mm draws the mechanism 1.3e+11 mm"), err
    assert not (tmp_path / "x.svg").exists()


# ----------------------------------------------------------------------------- the module's own pieces


def _five_bar(drivers=("2", "5")):
    from graphmech.mechanisms.topology import Pair, Topology

    pairs = (Pair("R", ("1", "2"), "A", (0.0, 0.0)), Pair("R", ("2", "3"), "B", (0.02, 0.05)),
             Pair("R", ("3", "4"), "C", (0.08, 0.09)), Pair("R", ("4", "5"), "D", (0.13, 0.04)),
             Pair("R", ("5", "1"), "E", (0.15, 0.0)))
    return Topology("1", ("2", "3", "4", "5"), pairs, drivers)


def test_the_scale_is_the_round_one_that_fits_the_pairs_in_the_room():
    from graphmech.problems.structure.figures import choose_scale

    # 0.15 m × 0.09 m in 100 × 100 mm: at least 0.0015 m/mm, the round 0.002
    assert choose_scale(_five_bar(), (100.0, 100.0)) == 0.002
    assert choose_scale(_five_bar(), (30.0, 100.0)) == 0.005  # 0.15 m in 30 mm


def test_the_block_diagram_holds_class_I_then_each_group():
    from graphmech.drawing.primitives import Arrow, Label
    from graphmech.mechanisms.topology import structure
    from graphmech.problems.structure.figures import block_panel

    topo = _five_bar()
    panel = block_panel(structure(topo), topo)
    assert [i.text for i in panel.items if isinstance(i, Label)] == ["I: 1 + 2, 5", "II: 3, 4"]
    assert sum(isinstance(i, Arrow) for i in panel.items) == 1 and panel.notes == ("a class II mechanism",)


def test_the_cases_panel_writes_each_count_out():
    from graphmech.problems.structure.figures import cases_panel

    panel = cases_panel([{"label": "3-1", "n": 7, "pl": 10, "ph": 0, "p_redundant": 0, "F_local": 0, "F": 1}])
    assert [i.text for i in panel.items] == ["3-1:  F = 3·7 − (2·10 + 0 − 0) − 0 = 1"]


def test_a_links_outline_is_the_hull_of_its_pairs():
    from graphmech.problems.structure.figures import _hull

    square = _hull([(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.5, 0.5), (0.0, 1.0)])
    assert sorted(square) == [(0.0, 0.0), (0.0, 1.0), (1.0, 0.0), (1.0, 1.0)]  # the inner pair is no corner
    assert _hull([(0.0, 0.0), (2.0, 0.0), (1.0, 0.0)]) == [(0.0, 0.0), (2.0, 0.0)]  # a binary link: its line


def test_recorded_draw_calls_of_the_ic_engine_sheet():
    from graphmech.drawing.primitives import Polyline
    from graphmech.problems.structure.check import analyse_structure
    from graphmech.problems.structure.figures import structure_sheet
    from graphmech.render.recording import RecordingBackend
    from graphmech.render.sheet import draw_sheet
    from graphmech.scene import load_scene

    an = analyse_structure(load_scene(SCENES / "dof.hfut_cases-ic_engine_EG.toml"))
    calls = draw_sheet(structure_sheet("IC engine", an, (297.0, 210.0)), RecordingBackend())
    texts = [c[1] for c in calls if c[0] == "text"]
    assert "III: 2, 3, 4, 5" in texts and "II: 7, 8" in texts and "a class III mechanism" in texts
    # each group outlined by a dashed contour on the mechanism
    mechanism = next(p for p in structure_sheet("IC engine", an, (297.0, 210.0)).panels if p.name == "structure")
    outlines = [i for i in mechanism.items if isinstance(i, Polyline) and i.dashed]
    assert len(outlines) == len(an.structure.groups) == 2
