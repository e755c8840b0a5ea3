"""Mobility and structure: the bank's printed counts, topologies with compound hinges, a roller,
redundant constraints exposed by the Jacobian's rank, Assur groups and the mechanism's class."""
from __future__ import annotations

import tomllib

import pytest

from graphmech.errors import SceneError
from graphmech.mechanisms.topology import Pair, Topology, mobility, structure
from graphmech.scene import load_scene, parse_scene
from graphmech.problems.structure.check import analyse_structure
from tests.conftest import SCENES, check_json, run_cli


def cases_of(doc):
    return {c["label"]: c for c in doc["structure"]["cases"]}


@pytest.mark.parametrize("pid,ph_key,pl_key", [("dof.hfut_cases", "ph", "pl"), ("dof.chen_ch3_cases", "P4", "P5")])
def test_bank_counts_give_the_books_mobility(problems, pid, ph_key, pl_key):
    p = problems[pid]
    doc = check_json(SCENES / f"{pid}.toml")
    cases = cases_of(doc)
    inp = p["inputs"]
    assert list(cases) == inp["labels"]
    for k, label in enumerate(inp["labels"]):
        c = cases[label]
        assert (c["n"], c["pl"], c["ph"]) == (inp["n"][k], inp[pl_key][k], inp[ph_key][k])
        assert c["p_redundant"] == inp.get("p_redundant", [0] * len(inp["n"]))[k]
        assert c["F"] == p["exact"]["F"][k] == p["book"]["F"][k]
    rigid = [w for w in doc["warnings"] if "cannot move" in w]
    assert len(rigid) == 1  # the punch press's first design / Chen's 3-5 original


def summary(name):
    doc = check_json(SCENES / f"{name}.toml")
    return doc, doc["structure"]


def test_compound_hinges_count_k_minus_1(problems):
    doc, s = summary("dof.hfut_cases-3-1")
    k = problems["dof.hfut_cases"]["inputs"]["labels"].index("3-1")
    assert (s["n"], s["pl"], s["ph"]) == (problems["dof.hfut_cases"]["inputs"]["n"][k],
                                          problems["dof.hfut_cases"]["inputs"]["pl"][k], 0)
    assert s["compound_hinges"] == ["C", "E"]
    assert s["F"] == s["jacobian"]["F_actual"] == 1 and s["jacobian"]["rank"] == 20
    assert [g["links"] for g in s["groups"]] == [["3", "4"], ["5", "6"], ["7", "8"]] and s["class"] == 2


def test_roller_local_freedom_is_recognised(problems):
    doc, s = summary("dof.hfut_cases-3-2")
    inp = problems["dof.hfut_cases"]["inputs"]
    k = inp["labels"].index("3-2")
    # the book's counts leave the roller out; with it, one more link, one more revolute, F' = 1
    assert (s["n"] - 1, s["pl"] - 1, s["ph"]) == (inp["n"][k], inp["pl"][k], inp["ph"][k])
    assert s["rollers"] == ["3"] and s["F_local"] == 1
    assert s["F"] == 1 and s["F_count"] == 2
    assert s["jacobian"]["F_actual"] == 1  # the spin is a free motion of the Jacobian too
    assert s["higher_pairs_replaced"] == ["K"] and s["class"] == 2
    assert ["4", "hK"] in [g["links"] for g in s["groups"]]


def test_a_roller_whose_normal_misses_its_pin_has_no_local_freedom():
    scene = load_scene(SCENES / "dof.hfut_cases-3-2.toml")
    topo = scene.problem.topology
    pairs = tuple(Pair(p.kind, p.links, p.name, p.at, 1.2 if p.kind == "higher" else p.angle) for p in topo.pairs)
    m = mobility(Topology(topo.frame, topo.links, pairs, topo.drivers), True)
    assert m.F_local == 1  # the count still says roller …
    # … but a "roller" whose contact normal misses its pin is no round roller: turning it moves the
    # follower, so its turn is a second freedom of the mechanism, not a local one
    assert m.rank == 25 and m.F_actual == 2


def test_ic_engine_is_class_ii_from_ab_and_class_iii_from_eg():
    _, ab = summary("dof.hfut_cases-ic_engine")
    doc, eg = summary("dof.hfut_cases-ic_engine_EG")
    assert ab["class"] == 2 and [g["class"] for g in ab["groups"]] == [2, 2, 2]
    assert eg["class"] == 3 and {"links": ["2", "3", "4", "5"], "class": 3,
                                 "pairs": ["A", "B", "C", "C′", "D", "E"]} in eg["groups"]
    assert any("class III group (2, 3, 4, 5)" in w and "special construction" in w for w in doc["warnings"])
    assert ab["F"] == eg["F"] == 1 == ab["jacobian"]["F_actual"]


def test_punch_press_cannot_move():
    doc, s = summary("dof.hfut_cases-punch_press")
    assert s["F"] == 0 and s["jacobian"]["F_actual"] == 0 and s["jacobian"]["rank"] == 9
    assert any("cannot move" in w for w in doc["warnings"])


def test_jacobian_rank_exposes_the_redundant_parallel_link():
    doc, s = summary("structure.parallelogram_redundant")
    assert s["jacobian"] == {**s["jacobian"], "rank": 11, "equations": 12, "F_actual": 1, "p_redundant": 1}
    assert s["F_count"] == 0 and s["F"] == 1  # with redundant = 1 stated
    rows = {q["name"]: q for q in doc["quantities"]}
    assert rows["F"]["graphical"] == rows["F"]["exact"] == 1.0
    assert rows["p_redundant"]["graphical"] == rows["p_redundant"]["exact"] == 1.0
    sv = s["jacobian"]["singular_values"]
    assert sv[-1] < 1e-12 * sv[0] and sv[-2] > 1e-3 * sv[0]  # one clean zero, well apart from the rest


def parallelogram(f_at, redundant=None):
    text = (SCENES / "structure.parallelogram_redundant.toml").read_text()
    data = tomllib.loads(text)
    if redundant is None:
        del data["structure"]["redundant"]
    data["structure"]["pair"][5]["at"] = f_at
    return parse_scene(data, "p.toml")


def test_without_the_stated_redundancy_the_count_and_the_rank_disagree_and_say_why():
    an = analyse_structure(parallelogram([80, 40]))
    assert [(r.name, r.graphical, r.exact) for r in an.rows] == [("F", 0.0, 1.0)]
    assert any("1 redundant constraint" in w for w in an.warnings)
    assert not any("cannot move" in w for w in an.warnings)


def test_a_non_parallel_extra_link_locks_the_linkage():
    an = analyse_structure(parallelogram([90, 40]))
    assert an.mobility.rank == 12 and an.mobility.F_actual == 0 and an.mobility.p_redundant_actual == 0
    assert any("cannot move" in w for w in an.warnings)


def test_only_what_is_asked_is_computed():
    data = tomllib.loads((SCENES / "dof.hfut_cases-3-1.toml").read_text())
    data["find"], data["show"] = ["n"], ["structure"]
    data["show"] = ["structure"]
    an = analyse_structure(parse_scene({**data, "show": ["structure"]}, "x.toml"))
    assert an.mobility is not None
    data2 = {**data, "find": ["n"]}
    data2.pop("show")
    scene = parse_scene(data2, "x.toml")
    assert scene.show == ("structure",)
    topo = scene.problem.topology
    assert mobility(topo, False).rank is None
    s = structure(topo)
    assert s.grade == 2


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


def test_structure_sheet_outlines_the_groups():
    from graphmech.scene import render_scene

    svg, warnings = render_scene(SCENES / "dof.hfut_cases-ic_engine_EG.toml")
    assert "III (2,3,4,5)" in svg and "II (7,8)" in svg and "special construction" in svg
    assert "I: 1 + 6" in svg and "rank J = 20 of 20" in svg


def test_measured_counts_are_judged_exactly_and_mixed_scenes_refused(tmp_path):
    code, out, err = run_cli("check", str(SCENES / "dof.hfut_cases-ic_engine_EG.toml"), "--json",
                             "--measured", "F=1,class=2,rank=20")
    import json

    doc = json.loads(out)
    assert code == 1  # the class is III from EG, not II
    assert [(v["name"], v["ok"]) for v in doc["measured"]] == [("F", True), ("class", False), ("rank", True)]
    code, _, err = run_cli("check", str(SCENES / "dof.hfut_cases-ic_engine_EG.toml"), "--measured", "v_C=1")
    assert code == 2 and "--measured v_C" in err
    code, _, err = run_cli("check", str(SCENES / "dof.hfut_cases-ic_engine_EG.toml"), "--measured", "F=1.5")
    assert code == 2 and err.strip().endswith("--measured F: F is a count: a whole number, not 1.5")
    p = tmp_path / "mix.toml"
    p.write_text('[cam]\nbase_radius_mm = 30\n[structure]\nframe = "1"\n')
    code, _, err = run_cli("check", str(p))
    assert code == 2 and "cam: belongs to a cam scene; this is a structure scene" in err


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


def test_precision_press_symmetric_half_is_found_redundant_only_when_symmetric(problems):
    inp = problems["dof.hfut_cases"]["inputs"]
    k = inp["labels"].index("precision_press_1")
    doc, s = summary("dof.hfut_cases-precision_press_1")
    assert (s["n"], s["pl"], s["ph"], s["p_redundant"]) == (inp["n"][k], inp["pl"][k], inp["ph"][k],
                                                            inp["p_redundant"][k])
    assert s["compound_hinges"] == ["M", "K1", "K2", "E"]
    j = s["jacobian"]
    assert (j["rank"], j["equations"], j["F_actual"], j["p_redundant"]) == (29, 30, 1, 1)
    assert s["F"] == problems["dof.hfut_cases"]["book"]["F"][k] == 1
    # move the right toggle's frame pivot 5 mm: no longer a mirror image, the press locks
    data = tomllib.loads((SCENES / "dof.hfut_cases-precision_press_1.toml").read_text())
    d2 = next(p for p in data["structure"]["pair"] if p["name"] == "D2")
    d2["at"] = [75, 100]
    an = analyse_structure(parse_scene(data, "asym.toml"))
    assert (an.mobility.rank, an.mobility.F_actual, an.mobility.p_redundant_actual) == (30, 0, 0)
    assert [(r.name, r.graphical, r.exact) for r in an.rows] == [("F", 1.0, 0.0), ("p_redundant", 1.0, 0.0)]
    assert any("cannot move" in w for w in an.warnings)


def test_a_five_bar_with_two_drivers_is_one_dyad():
    pairs = (Pair("R", ("1", "2"), "A", (0.0, 0.0)), Pair("R", ("2", "3"), "B", (0.02, 0.05)),
             Pair("R", ("3", "4"), "C", (0.08, 0.09)), Pair("R", ("4", "5"), "D", (0.13, 0.04)),
             Pair("R", ("5", "1"), "E", (0.15, 0.0)))
    five = Topology("1", ("2", "3", "4", "5"), pairs, ("2", "5"))
    m = mobility(five, True)
    assert (m.F, m.F_actual, m.rank) == (2, 2, 10)
    s = structure(five)
    assert [(g.links, g.grade) for g in s.groups] == [(("3", "4"), 2)] and not s.messages
    one = structure(Topology("1", ("2", "3", "4", "5"), pairs, ("2",)))
    assert one.leftover == ("3", "4", "5") and "drivers differs from the mobility" in one.messages[0]


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


def test_an_oscillating_follower_pivoted_on_the_frame_is_not_a_roller():
    """Cam 2 and a follower 3 pinned to the frame and touching the cam: F = 3·2 − (2·2 + 1) = 1.
    The follower (one R, one higher pair) was taken for a roller: F′ = 1, F = 0, "cannot move"."""
    data = {"structure": {"frame": "1", "drivers": ["2"], "pair": [
        {"kind": "R", "links": ["1", "2"]}, {"kind": "higher", "links": ["2", "3"]},
        {"kind": "R", "links": ["3", "1"]}]}}
    topo = parse_scene(data, "cam.toml").problem.topology
    assert topo.rollers() == ()
    m = mobility(topo, False)
    assert (m.F_local, m.F) == (0, 1)
    assert structure(topo).grade == 2  # the contact replaced by a link and two revolutes: one dyad
    # with the roller on a translating follower it is still recognised (HFUT 3-2 has one)
    data["structure"]["pair"] = [
        {"kind": "R", "links": ["1", "2"]}, {"kind": "higher", "links": ["2", "3"]},
        {"kind": "R", "links": ["3", "4"]}, {"kind": "P", "links": ["4", "1"]}]
    m = mobility(parse_scene(data, "roller.toml").problem.topology, False)
    assert (m.F_local, m.F) == (1, 1)
