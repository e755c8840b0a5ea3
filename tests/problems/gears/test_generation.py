"""Generation by the rack cutter in a gear scene: [gear.generation] read (a blank speed and L give
z and x), refused in one line at its key, its rows against the bank's four cases, the undercut said,
the panel drawn, the SVG byte-identical."""
from __future__ import annotations

import math
import tomllib

import pytest

from graphmech.mechanisms.gear import RackGeneration, SpurGear
from graphmech.scene import parse_scene
from tests.conftest import ROOT, SCENES, assert_refused, check_json, run_cli, values
from tests.scenes import only_problem

PID = "gear.rack_cutter_generation_cases"
CASES = [SCENES / f"{PID}-{i}.toml" for i in (1, 2, 3, 4)]
GEN = "[gear.generation]\ncutter_speed_m_s = 0.002\n"
#: Bank key (case, name) → (check name, factor from SI to the bank's unit).
KEYS = {"r_mm": ("r", 1e3), "L_mm": ("L", 1e3), "n_r_min": ("n_blank", 1.0), "z": ("z", 1.0), "x": ("x", 1.0)}


def read(text: str):
    return parse_scene(tomllib.loads(text), "g.toml").problem


def test_a_cutter_speed_with_z_and_x():
    p = read("[gear]\nm_mm = 4\nz = 15\nx = 0.1\n" + GEN + "positions = 24\n")
    assert p.generation == RackGeneration(0.002, None, None, 24)
    assert p.gears.gears == (SpurGear(15, 0.1),)


def test_a_blank_speed_and_datum_distance_give_z_and_x():
    p = read("[gear]\nm_mm = 4\n" + GEN + "blank_speed_rpm = 0.7958\ndatum_distance_mm = 30\n")
    g = p.generation
    assert g.blank_speed == pytest.approx(0.7958 * math.pi / 30.0) and g.datum_distance == pytest.approx(0.030)
    assert g.positions == 12
    assert p.gears.gears[0].z == 12 and p.gears.gears[0].x == pytest.approx(1.5)  # the whole z drawn on the same L


@pytest.mark.parametrize("body, where, words", [
    ("m_mm = 4\nz = 15\n" + GEN + "blank_speed_rpm = 0.7958\ndatum_distance_mm = 30", "gear.z", "over-determined"),
    ("m_mm = 4\nz = 15\n" + GEN + "blank_speed_rpm = 0.7958", "gear.generation.blank_speed_rpm",
     "needs datum_distance"),
    ("m_mm = 4\nz = 15\n" + GEN + "datum_distance_mm = 30", "gear.generation.datum_distance_mm", "state x"),
    ('m_mm = 4\nz = [15, 30]\nmeshing = "external"\n' + GEN, "gear.generation", "poses one gear"),
    ("m_mm = 4\nz = 15\n" + GEN + "positions = 1", "gear.generation.positions", "2 … 400"),
    ("m_mm = 4\nz = 15\n" + GEN + "positions = 12.5", "gear.generation.positions", "whole number"),
    ("m_mm = 4\n[gear.generation]\nblank_speed_rpm = 1\ndatum_distance_mm = 30",
     "gear.generation.cutter_speed", "missing"),
    ("m_mm = 4\nz = 15\n" + GEN + "cutter = 1", "gear.generation.cutter", "unknown key"),
    ("m_mm = 4\n" + GEN + "blank_speed_rpm = 1e-9\ndatum_distance_mm = 30", "gear.generation.blank_speed_rpm",
     "no gear"),
    # found by a mutation campaign: x = (L − r)/m of 4.6e18 reached the involute function unchecked
    ("m_mm = 4\n" + GEN + "blank_speed_rpm = 0.7958\ndatum_distance_mm = 18446744073709551616",
     "gear.generation.datum_distance_mm", "beyond ±10 is no gear's"),
])
def test_bad_generation_tables_are_refused_in_one_line(body, where, words):
    path, reason = only_problem(f"[gear]\n{body}\n", "g.toml")
    assert path == where and words in reason, (path, reason)


def test_a_refusal_on_the_command_line_is_one_line(tmp_path):
    f = tmp_path / "g.toml"
    f.write_text("[gear]\nm_mm = 4\nz = 15\n" + GEN + "blank_speed_rpm = 0.7958\n")
    assert_refused(run_cli("check", str(f)), "g.toml", "gear.generation.blank_speed_rpm")


def test_generation_names_need_the_table(tmp_path):
    path, reason = only_problem('find = ["n_blank"]\n[gear]\nm_mm = 4\nz = 15\n', "g.toml")
    assert path == "find[0]" and "n_blank" in reason
    f = tmp_path / "g.toml"
    f.write_text('show = ["generation"]\n[gear]\nm_mm = 4\nz = 15\n')
    assert_refused(run_cli("check", str(f)), "g.toml", "show", "[gear.generation]")


@pytest.mark.parametrize("case", [1, 2, 3, 4])
def test_the_books_four_cases_against_the_bank(problems, case):
    p = problems[PID]
    q = values(check_json(CASES[case - 1]))
    checked = 0
    for key, want in p["exact"].items():
        c, _, rest = key.partition("_")
        if c != f"c{case}" or rest not in KEYS:
            continue
        name, factor = KEYS[rest]
        assert q[name]["exact"] * factor == pytest.approx(want, rel=1e-12), key
        assert q[name]["graphical"] * factor == pytest.approx(want, rel=1e-9), key
        book = p["book"].get(key)
        if book is not None:
            assert q[name]["graphical"] * factor == pytest.approx(book, rel=abs(p["rel_diff"].get(key, 0.0)) + 1e-4), key
        checked += 1
    assert checked >= 3


def test_the_generated_tooth_rows_state_their_own_error():
    q = values(check_json(CASES[1]))
    for name in ("s_pitch_generated", "sa_generated"):
        row = q[name]
        assert row["error_source"] == "discretisation" and "12 positions" in row["basis"]
        assert 0.0 < row["rel_error"] < 1e-2
        assert row["rel_error"] < 10.0 * row["error_estimate"]  # the estimate is of the error's size
    one = values(check_json(CASES[0]))
    assert one["s_pitch_generated"]["rel_error"] < 1e-9  # φ = 0 rolls through the pitch point: exact there
    assert one["omega_blank"]["graphical"] == pytest.approx(0.002 / 0.030, rel=1e-14)


def test_the_undercut_and_the_rounded_speed_are_said():
    doc = check_json(CASES[3])
    text = " ".join(doc.get("warnings", []))
    assert "undercut" in text and "z = 2r/m = 18.0006" in text and "z = 18" in text
    q = values(doc)
    sa = q["sa_generated"]
    assert sa["exact"] < 0.00244309 * 1.0001  # the fillet's thickness on the tip circle, not the involute's
    _, _, err = run_cli("check", str(CASES[2]))
    assert "11.9996" in err and "drawn with z = 12" in err


def test_the_figure_has_the_generation_panel_and_is_byte_identical(tmp_path):
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    for f in (a, b):
        code, _, err = run_cli("render", str(CASES[3]), "-o", str(f))
        assert code == 0, err
    svg = a.read_text()
    assert a.read_bytes() == b.read_bytes()
    assert "Generation by the rack cutter" in svg and "undercut" in svg and "L = 30 mm" in svg
    assert "v = 0.002 m/s" in svg and "x_{min}" not in svg


def test_the_committed_figures_are_the_scenes(tmp_path):
    """Each committed figure is what its scene renders today, and draws the generation: its caption,
    the cutter's pitch line, and the undercut where the case is undercut (1, 2 and 4)."""
    for i, f in enumerate(CASES, start=1):
        out = tmp_path / f"{f.stem}.svg"
        assert run_cli("render", str(f), "-o", str(out))[0] == 0
        committed = (ROOT / "figures" / f"{f.stem}.svg").read_bytes()
        assert out.read_bytes() == committed, f.stem
        text = committed.decode("utf-8")
        assert "Generation by the rack cutter" in text and "cutter&#x27;s pitch line" in text.replace("'", "&#x27;")
        assert (">undercut<" in text) == (i != 3), f.stem


def test_the_generation_scale_is_chosen_or_stated_and_said(tmp_path):
    text = (SCENES / "gear.rack_cutter_generation_cases-1.toml").read_text(encoding="utf-8")
    code, out, _ = run_cli("check", str(SCENES / "gear.rack_cutter_generation_cases-1.toml"))
    assert code == 0 and "μl = 0.0005 m/mm (generation, chosen)" in out
    f = tmp_path / "g.toml"
    f.write_text(text + "\n[scales]\ngeneration_mm_per_mm = 0.2\n", encoding="utf-8")
    code, out, _ = run_cli("check", str(f))
    assert code == 0 and "μl = 0.0002 m/mm (generation, stated)" in out
    f.write_text(text + "\n[scales]\ngeneration_mm_per_mm = 1e-12\n", encoding="utf-8")
    code, out, err = run_cli("check", str(f))
    assert code == 2 and "scales.generation" in err


@pytest.mark.parametrize("z, x, n", [(8, 0.5, 8), (12, -0.5, 12), (15, 0.0, 8), (18, 0.5, 12), (25, -1.5, 8),
                                     (40, 1.0, 12), (14, 0.6, 8), (9, 0.6, 20), (20, 0.4, 10), (20, 0.8, 32)])
def test_each_generated_thickness_is_within_the_error_it_states(tmp_path, z, x, n):
    f = tmp_path / "g.toml"
    f.write_text(f'find = ["s_pitch_generated", "sa_generated"]\n[gear]\nm_mm = 4\nz = {z}\nx = {x}\n'
                 f"[gear.generation]\ncutter_speed_m_s = 0.002\npositions = {n}\n", encoding="utf-8")
    rows = check_json(f)["quantities"]
    assert rows
    for row in rows:
        assert row["error_source"] == "discretisation" or row["rel_error"] < 1e-9, row
        if row["error_estimate"] is not None:
            assert row["rel_error"] <= row["error_estimate"], row


def test_the_figure_cuts_the_blank_once(monkeypatch):
    """The rows' error estimates (two more cuttings of the blank) are the check's: the figure
    does without them and is the same drawing."""
    from pathlib import Path

    from graphmech import api
    from graphmech.problems.gears.generation import GenerationAnalysis

    scene = Path(__file__).parents[3] / "figures" / "scenes" / "gear.rack_cutter_generation_cases-4.toml"
    want = api.load(scene).render().svg

    def refuse(self):
        raise AssertionError("the figure cut a reference")

    monkeypatch.setattr(GenerationAnalysis, "reference", refuse)
    monkeypatch.setattr(GenerationAnalysis, "shifted", refuse)
    assert api.load(scene).render().svg == want
