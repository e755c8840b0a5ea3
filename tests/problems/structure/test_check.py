"""The structure check on scenes: the bank's printed counts, compound hinges, a roller, redundant
constraints exposed by the Jacobian's rank, Assur groups and the class, measured counts judged."""
from __future__ import annotations

import tomllib

import pytest

from graphmech.mechanisms.topology import mobility, structure
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




def test_the_count_is_written_out_as_the_book_does():
    from graphmech.problems.structure.check import case_formula, formula, formula_text

    assert formula_text(3, 4, 0, 0, 0, 1) == "F = 3·3 − (2·4 + 0 − 0) − 0 = 1"
    assert case_formula({"n": 8, "pl": 11, "ph": 1, "p_redundant": 0, "F_local": 1, "F": 1}) == \
        "F = 3·8 − (2·11 + 1 − 0) − 1 = 1"
    an = analyse_structure(load_scene(SCENES / "structure.parallelogram_redundant.toml"))
    assert formula(an.mobility) == "F = 3·4 − (2·6 + 0 − 1) − 0 = 1"
