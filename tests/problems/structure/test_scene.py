"""Reading the [structure] table: bad pairs, drivers off the frame, links listed twice."""
from __future__ import annotations


import pytest

from graphmech.errors import SceneError
from graphmech.scene import parse_scene
from tests.conftest import run_cli


@pytest.mark.parametrize("pair,reason", [
    ({"kind": "P", "links": ["1", "2", "3"]}, "joins exactly two links"),
    ({"kind": "Q", "links": ["1", "2"]}, "unknown value"),
    ({"kind": "R", "links": ["2", "2"]}, "listed twice"),
    ({"kind": "R", "links": ["1", "2"], "at_mm": [0, 0]}, "coordinates or none"),
    ({"kind": "R", "links": ["1", "2"], "angle_deg": 10}, "a revolute (R) has no direction: drop angle"),  # was ignored
])
def test_bad_pairs_are_one_line_errors(pair, reason):
    data = {"structure": {"frame": "1", "drivers": ["2"], "pair": [
        pair, {"kind": "R", "links": ["2", "3"]}, {"kind": "R", "links": ["3", "1"]}]}}
    with pytest.raises(SceneError) as e:
        parse_scene(data, "bad.toml")
    assert reason in str(e.value)


def test_cli_exit_2_for_a_driver_off_the_frame(tmp_path):
    p = tmp_path / "s.toml"
    p.write_text('[structure]\nframe = "1"\ndrivers = ["3"]\npair = [{kind = "R", links = ["1", "2"]}, '
                 '{kind = "R", links = ["2", "3"]}, {kind = "R", links = ["3", "4"]}, {kind = "R", links = ["4", "1"]}]\n')
    code, out, err = run_cli("check", str(p))
    assert code == 2 and err.count("\n") == 1 and "structure.drivers[0]" in err and "joined to the frame" in err
    code, out, err = run_cli("render", str(p), "-o", str(tmp_path / "s.svg"))
    assert code == 2 and not (tmp_path / "s.svg").exists()


@pytest.mark.parametrize("key", ["drivers", "links"])
def test_a_link_listed_twice_among_the_drivers_or_links_is_refused(key):
    """drivers = ["2", "2"] was taken as two drivers ("F = 1 but 2 driver(s): over-constrained")."""
    data = {"structure": {"frame": "1", "drivers": ["2"], "pair": [
        {"kind": "R", "links": ["1", "2"]}, {"kind": "R", "links": ["2", "3"]}, {"kind": "R", "links": ["3", "4"]},
        {"kind": "R", "links": ["4", "1"]}]}}
    data["structure"][key] = ["2", "2"] if key == "drivers" else ["2", "3", "4", "2"]
    with pytest.raises(SceneError) as e:
        parse_scene(data, "twice.toml")
    where = f"structure.{key}[1]" if key == "drivers" else f"structure.{key}[3]"
    assert e.value.one_line() == f"twice.toml: {where}: link '2' is listed twice"
