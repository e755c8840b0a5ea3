"""The kinetostatic construction protocol: inertia loads, the force polygons group by group, and
every value of the check table read off as the table reads it."""
from __future__ import annotations

from graphmech.problems.forces.check import analyse_forces
from graphmech.problems.forces.steps import forces_steps
from graphmech.problems.protocol import num
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, run_cli

SIXBAR = SCENES / "force.sixbar_kinetostatic.toml"
PARTIAL = SCENES / "force.slider_crank_inertia_partial.toml"


def test_every_value_of_the_check_table_is_in_the_protocol():
    for path in (SIXBAR, PARTIAL, SCENES / "force.sixbar_kinetostatic-friction.toml"):
        scene = load_scene(path)
        text = "\n".join(forces_steps(scene))
        for row in analyse_forces(scene).rows:
            assert f"{row.name} = " in text and num(row.graphical) in text, (path.name, row.name)
            if row.drawn_mm is not None:
                assert f"{row.name} = {num(row.drawn_mm)} mm × {num(row.scale)} = {num(row.graphical)}" in text


def test_the_sixbar_is_taken_group_by_group_from_the_farthest_with_closed_polygons():
    lines = forces_steps(load_scene(SIXBAR))
    groups = [k for k, line in enumerate(lines) if line.startswith(("group", "driver"))]
    assert [lines[k].split(" (")[0] for k in groups] == ["group 4–5", "group 2–3", "driver 1"]
    assert lines[groups[2]].startswith("driver 1 (link 1):")
    assert "on link 2: F_i2 = m2·a_S2 = 4 kg × 8.178 m/s² = 32.71 N, at S2, opposite a_S2" in lines
    assert "lay off P_r = 1000/μF = 40 mm at 0°" in lines
    assert "close the polygon with the known directions of R_05: measure 6.991 mm at 90°: R_05 = 6.991 × μF = 174.8 N" in lines
    assert lines.index("choose μF = 25 N/mm (as the scene gives it) for the force polygons") < groups[0]
    # the reaction a later group lays off is the one the earlier closed: R_43 = R^n_34 + R^t_34
    assert "lay off R_43 = 861.7/μF = 34.47 mm at 2.22°" in lines


def test_the_protocol_speaks_the_scenes_notation(tmp_path):
    text = SIXBAR.read_text(encoding="utf-8")
    import tomllib

    for notation, words in (("zh", "惯性力F_i2"), ("ru", "сила инерции F_i2")):
        data = tomllib.loads(text)
        data.setdefault("page", {})["notation"] = notation
        lines = forces_steps(parse_scene(data, "x.toml"))
        assert any(words in line for line in lines), notation


def test_the_command_prints_it_numbered():
    code, out, err = run_cli("steps", str(PARTIAL))
    lines = out.splitlines()
    assert code == 0 and err == "" and lines[0].startswith("1. the accelerations from the acceleration polygon")
    assert lines == [f"{k}. {line}" for k, line in enumerate(forces_steps(load_scene(PARTIAL)), 1)]
