"""Helical, bevel and worm scenes (graphmech/problems/gears/spatial.py): the rows against the closed
forms, the bank's two problems with the book's slips pinned as the book's, β → 0 as the spur pair,
β near 45°, a worm of many starts, judging, the protocol, and a figure byte-identical twice."""
from __future__ import annotations

import math
import tomllib

import pytest

from graphmech.problems.gears.spatial import (
    SpatialAnalysis,
    analyse_spatial,
    judge,
    protocol,
)
from graphmech.scene import parse_scene
from tests.conftest import ROOT, SCENES, check_json, run_cli, values

HELICAL = "gear.helical_20_40_mn8"
WORM = "gear.worm_i20.5_m5"
BEVEL = ROOT / "tests" / "scenes" / "gears" / "bevel_20_40_s70.toml"


def analysed(text: str) -> SpatialAnalysis:
    return analyse_spatial(parse_scene(tomllib.loads(text), "g.toml"), ())


def bank_name(key: str) -> tuple[str, float]:
    """A bank key (``da1_mm``, ``beta_deg``, ``zv2``) → (check name, factor from SI)."""
    for suffix, factor in (("_mm", 1e3), ("_deg", 1.0)):
        if key.endswith(suffix):
            return key[: -len(suffix)], factor
    return key, 1.0


@pytest.mark.parametrize("pid", [HELICAL, WORM])
def test_the_bank_problems(problems, pid):
    p = problems[pid]
    q = values(check_json(SCENES / f"{pid}.toml"))
    checked = 0
    for key, want in p["exact"].items():
        name, factor = bank_name(key)
        if name == "z1":  # an input of the scene (the book's choice), not a row
            continue
        assert q[name]["exact"] * factor == pytest.approx(want, rel=1e-12), key
        assert q[name]["graphical"] * factor == pytest.approx(want, rel=1e-9), key
        book = p["book"].get(key)
        if book is not None:  # the book's rounding and slips, within its rel_diff (book − exact)/exact
            got = q[name]["graphical"] * factor
            assert abs(book - got) <= (abs(p["rel_diff"][key]) + 1e-4) * abs(got), key
        checked += 1
    assert checked == len(p["exact"]) - (pid == WORM)


def test_the_helical_books_slips_are_the_books(problems):
    book = problems[HELICAL]["book"]
    q = values(check_json(SCENES / f"{HELICAL}.toml"))
    # z_v2 printed as a copy of z_v1 (22.61): ours is z₂/cos³β, twice z_v1
    assert book["zv2"] == book["zv1"] and q["zv2"]["graphical"] == pytest.approx(2 * q["zv1"]["graphical"], rel=1e-12)
    assert abs(q["zv2"]["graphical"] - book["zv2"]) > 22.0
    # ε_α printed 1.592; the book's own tip and transverse angles give 1.548 (and ε_γ 1.882, not 1.92)
    a_at1, a_at2, a_t = (math.radians(book[k]) for k in ("alpha_at1_deg", "alpha_at2_deg", "alpha_t_deg"))
    from_book = (20 * (math.tan(a_at1) - math.tan(a_t)) + 40 * (math.tan(a_at2) - math.tan(a_t))) / (2 * math.pi)
    assert from_book == pytest.approx(q["eps_alpha"]["graphical"], rel=5e-4)
    assert book["eps_alpha"] - q["eps_alpha"]["graphical"] > 0.04
    assert book["eps_gamma"] - q["eps_gamma"]["graphical"] > 0.03


def test_beta_near_zero_is_the_spur_pair():
    spur = values(check_json(SCENES / "gear.contact_ratio_19_42.toml"))
    body = '[gear]\nm_mm = 5\nz = [19, 42]\nmeshing = "helical"\nface_width_mm = 20\nbeta_deg = {}\n'
    for beta in ("0", "1e-7"):
        an = analysed('find = ["eps_alpha", "zv1", "mt", "eps_beta"]\n' + body.format(beta))
        rows = {r.name: r for r in an.rows}
        assert rows["eps_alpha"].graphical == pytest.approx(spur["eps_alpha"]["exact"], rel=1e-9)
        assert rows["zv1"].graphical == pytest.approx(19.0, rel=1e-12)
        assert all(r.rel_error < 1e-9 for r in an.rows)
    assert any("spur pair" in w for w in analysed(body.format("0")).warnings)


def test_beta_near_45_and_the_undercut_of_the_virtual_gear():
    an = analysed('[gear]\nm_mm = 2\nz = [8, 30]\nmeshing = "helical"\nbeta_deg = 44.9\nface_width_mm = 40\n')
    rows = {r.name: r for r in an.rows}
    assert rows["zv1"].graphical == pytest.approx(8 / math.cos(math.radians(44.9)) ** 3, rel=1e-9)
    assert max(r.rel_error for r in an.rows) < 1e-9
    low = analysed('[gear]\nm_mm = 2\nz = [8, 30]\nmeshing = "helical"\nbeta_deg = 10\n')
    assert any("z_v = " in w and "undercut" in w for w in low.warnings)


def test_a_worm_of_many_starts():
    an = analysed('[gear]\nm_mm = 4\nz = [8]\nratio = 5\nmeshing = "worm"\nq = 8\nc_star = 0.2\n')
    rows = {r.name: r for r in an.rows}
    assert rows["z2"].graphical == 40 and rows["gamma1"].graphical == pytest.approx(45.0, rel=1e-12)
    assert max(r.rel_error for r in an.rows) < 1e-9


def test_the_bevel_scene():
    q = values(check_json(BEVEL))
    sigma = math.radians(70)
    d1 = math.atan2(math.sin(sigma), 2 + math.cos(sigma))
    assert q["delta1"]["graphical"] == pytest.approx(math.degrees(d1), rel=1e-12)
    assert q["delta1"]["graphical"] + q["delta2"]["graphical"] == pytest.approx(70.0, rel=1e-14)
    assert q["zv2"]["graphical"] == pytest.approx(40 / math.cos(sigma - d1), rel=1e-12)
    assert max(v["rel_error"] for v in q.values()) < 1e-9


def test_a_bevel_face_beyond_R_over_3_is_warned():
    an = analysed('[gear]\nm_mm = 4\nz = [20, 40]\nmeshing = "bevel"\nface_width_mm = 40\n')
    assert any("R/3" in w for w in an.warnings)


def test_judging_a_students_values():
    an = analysed('[gear]\nm_mm = 8\nz = [20, 40]\nmeshing = "helical"\nbeta_deg = 15\ncentre_distance_mm = 250\n'
                  'face_width_mm = 30\n[measured]\npt = 0.0262\nbeta = 16.3\nzv2 = 22.61\n')
    got = {v.name: v.ok for v in judge(an)}
    assert got == {"pt": True, "beta": True, "zv2": False}


def test_the_protocol_names_the_constructions():
    an = analysed('[gear]\nm_mm = 8\nz = [20, 40]\nmeshing = "helical"\nbeta_deg = 15\ncentre_distance_mm = 250\n')
    text = "\n".join(protocol(an))
    assert "β = ∠LOA = 16.26°" in text and "z_v = 2ρ/m_n" in text and "p_t = 26.18 mm" in text


@pytest.mark.parametrize("scene", [SCENES / f"{HELICAL}.toml", SCENES / f"{WORM}.toml", BEVEL])
def test_the_figure_is_the_same_twice(tmp_path, scene):
    out = []
    for n in (1, 2):
        path = tmp_path / f"x{n}.svg"
        code, _, err = run_cli("render", str(scene), "-o", str(path))
        assert code == 0, err
        assert "run off the page" not in err, err
        out.append(path.read_bytes())
    assert out[0] == out[1] and b"<svg" in out[0]


def test_the_committed_figures_are_current(tmp_path):
    for pid in (HELICAL, WORM):
        path = tmp_path / f"{pid}.svg"
        code, _, err = run_cli("render", str(SCENES / f"{pid}.toml"), "-o", str(path))
        assert code == 0, err
        assert path.read_bytes() == (ROOT / "figures" / f"{pid}.svg").read_bytes()
