"""Reading the [structure] table: bad pairs, drivers off the frame, links listed twice."""
from __future__ import annotations


import pytest

from graphmech.errors import SceneError
from graphmech.problems.structure.scene import Case
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, run_cli


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


def test_a_topology_with_coordinates_is_read_in_si():
    st = load_scene(SCENES / "structure.parallelogram_redundant.toml").problem
    topo = st.topology
    assert st.geometry and st.cases == () and (topo.frame, topo.links, topo.drivers, topo.redundant) == (
        "1", ("2", "3", "4", "5"), ("2",), 1)
    assert [(p.name, p.kind, p.links) for p in topo.pairs[:2]] == [("A", "R", ("1", "2")), ("B", "R", ("2", "3"))]
    assert topo.pairs[2].at == pytest.approx((0.13, 0.04), rel=1e-15)  # mm → m


def test_a_topology_without_coordinates_has_no_geometry():
    data = {"structure": {"frame": "1", "drivers": ["2"], "pair": [
        {"kind": "R", "links": ["1", "2"]}, {"kind": "R", "links": ["2", "3"]}, {"kind": "R", "links": ["3", "4"]},
        {"kind": "R", "links": ["4", "1"]}]}}
    st = parse_scene(data, "s.toml").problem
    assert not st.geometry and all(p.at is None for p in st.topology.pairs)
    assert st.topology.links == ("2", "3", "4")  # the moving links, found from the pairs


def test_printed_counts_are_read_as_cases():
    st = load_scene(SCENES / "dof.hfut_cases.toml").problem
    assert st.topology is None and not st.geometry
    cases = {c.label: c for c in st.cases}
    assert cases["3-1"] == Case("3-1", 7, 10, 0, 0, 0)
    assert cases["precision_press_1"] == Case("precision_press_1", 10, 15, 0, 1, 0)
    assert cases["closed_gear_train"].ph == 8 and len(st.cases) == 10
