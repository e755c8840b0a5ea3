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
