"""The efficiency check: its rows against the closed forms, the extreme cases, only what is asked,
unknown names, measured values judged at the drawing's precision."""
from __future__ import annotations

import json
import math

import pytest

from graphmech.problems.efficiency.check import analyse_efficiency, efficiency_figure
from graphmech.scene import load_scene
from tests.conftest import SCENES, check_json, run_cli, values


def scene(text: str, tmp_path, name: str = "s.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


INCLINE = """
title = "block on an incline"
show = {show}
find = {find}
[efficiency]
type = "incline"
angle_deg = {alpha}
f = {f}
load_N = 1000
push = "{push}"
"""


def incline_scene(tmp_path, alpha=30, f=0.1, push="horizontal", find='["F", "eta", "R", "F0"]',
                  show='["diagram", "polygon"]'):
    return scene(INCLINE.format(alpha=alpha, f=f, push=push, find=find, show=show), tmp_path)


# ---------------------------------------------------------------------------- agreement


def test_wedge_below_its_locking_angle_is_self_locking_not_an_error(tmp_path):
    """γ = 10° < 2φ = 17.06°: friction turns R12 past R32 — the forward stroke cannot be driven."""
    p = scene('find = ["eta", "gamma_limit"]\n[efficiency]\ntype = "wedge"\ngamma_deg = 10\nbeta_deg = 30\n'
              'f = 0.15\nload_N = 1000\n', tmp_path)
    doc = check_json(p)
    q = values(doc)
    assert q["eta@forward"]["graphical"] < 0 and q["eta@forward"]["rel_error"] < 1e-14
    assert q["eta@reverse"]["graphical"] > 0
    assert q["gamma_limit"]["graphical"] == pytest.approx(2 * math.degrees(math.atan(0.15)), rel=1e-10)
    assert any("forward stroke" in w and "however large" in w for w in doc["warnings"])


def test_screw_V_thread_uses_the_equivalent_friction_angle(tmp_path):
    p = scene("""
find = ["phi_v", "eta@forward", "eta@reverse", "M@forward"]
show = ["polygon"]
[efficiency]
type = "screw"
thread = "V"
half_angle_deg = 30
f = 0.15
d2_mm = 18.376
pitch_mm = 2.5
load_N = 10000
""", tmp_path)
    q = values(check_json(p))
    phi_v = math.atan(0.15 / math.cos(math.radians(30)))
    psi = math.atan(2.5 / (math.pi * 18.376))
    assert q["phi_v"]["graphical"] == pytest.approx(math.degrees(phi_v), rel=1e-14)
    assert q["eta@forward"]["graphical"] == pytest.approx(math.tan(psi) / math.tan(psi + phi_v), rel=1e-12)
    assert q["eta@reverse"]["graphical"] < 0  # ψ < φv: self-locking
    assert q["M@forward"]["graphical"] == pytest.approx(10000 * 0.018376 / 2 * math.tan(psi + phi_v), rel=1e-12)


def test_machines_in_series_and_parallel(tmp_path):
    p = scene("""
title = "mixed"
find = ["eta", "P_in"]
[efficiency]
type = "chain"
load_N = 1000
speed_m_s = 2
[[efficiency.stage]]
name = "belt"
eta = 0.95
[[efficiency.stage]]
name = "split"
[[efficiency.stage.branch]]
share = 3
eta = [0.97, 0.9]
[[efficiency.stage.branch]]
share = 1
eta = 0.8
""", tmp_path)
    q = values(check_json(p))
    eta = 0.95 * (3 * 0.97 * 0.9 + 1 * 0.8) / 4
    assert q["eta"]["graphical"] == pytest.approx(eta, rel=1e-14)
    assert q["P_in"]["graphical"] == pytest.approx(2000 / eta, rel=1e-14)
    code, out, err = run_cli("render", str(p), "-o", str(tmp_path / "m.svg"))
    assert code == 0, err
    svg = (tmp_path / "m.svg").read_text(encoding="utf-8")
    assert "and in parallel" in svg and "split: 3" in svg


# ---------------------------------------------------------------------------- extreme cases


@pytest.mark.parametrize("kind", ["incline", "wedge", "screw"])
def test_no_friction_means_eta_one(kind, tmp_path):
    body = {"incline": 'angle_deg = 25\nload_N = 500', "wedge": "gamma_deg = 50\nbeta_deg = 70\nload_N = 500",
            "screw": "d2_mm = 20\npitch_mm = 3\nload_N = 500"}[kind]
    p = scene(f'find = ["eta", "F", "F0"]\n[efficiency]\ntype = "{kind}"\nf = 0\n{body}\n', tmp_path)
    q = values(check_json(p))
    for d in ("forward", "reverse"):
        assert q[f"eta@{d}"]["graphical"] == pytest.approx(1.0, rel=1e-14)
        assert q[f"F@{d}"]["graphical"] == pytest.approx(q["F0"]["graphical"], rel=1e-14)


def test_incline_at_the_self_locking_limit_reports_zero(tmp_path):
    f = math.tan(math.radians(20))
    p = scene(f'find = ["eta", "F", "self_locking_angle"]\n[efficiency]\ntype = "incline"\nangle_deg = 20\n'
              f'f = {f!r}\nload_N = 1000\n', tmp_path)
    code, out, err = run_cli("check", str(p), "--json")
    assert code == 0 and "NaN" not in out and "Infinity" not in out
    doc = json.loads(out)
    q = values(doc)
    assert q["eta@reverse"]["graphical"] == 0.0 and q["eta@reverse"]["exact"] == 0.0
    assert abs(q["F@reverse"]["graphical"]) < 1e-9
    assert q["self_locking_angle"]["graphical"] == pytest.approx(20.0, rel=1e-11)
    assert any("self-locking limit, η = 0 exactly" in w for w in doc["warnings"])


def test_forward_stroke_that_cannot_move_is_said_not_divided_by_zero(tmp_path):
    """α + φ = 90° with F horizontal: F ∥ R, no finite force lifts the block: η = 0, F refused."""
    p = scene('find = ["eta"]\n[efficiency]\ntype = "incline"\nangle_deg = 45\nf = 1\nload_N = 1000\n'
              'direction = "forward"\n', tmp_path)
    code, out, err = run_cli("check", str(p), "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert values(doc)["eta"]["graphical"] == 0.0
    assert any("cannot close" in w and "η = 0" in w for w in doc["warnings"])
    p2 = scene('find = ["F"]\n[efficiency]\ntype = "incline"\nangle_deg = 45\nf = 1\nload_N = 1000\n'
               'direction = "forward"\n', tmp_path, "f.toml")
    code, out, err = run_cli("check", str(p2))
    assert code == 2 and err.count("\n") == 1 and "no finite force" in err and "Traceback" not in err
    code, out, err = run_cli("render", str(p), "-o", str(tmp_path / "x.svg"))
    assert code == 0 and "η = 0" in (tmp_path / "x.svg").read_text(encoding="utf-8")


def test_near_collinear_forces_are_flagged(tmp_path):
    """α + φ = 89.9°: the forward polygon closes at 0.1° — flagged, with a warning naming it."""
    p = incline_scene(tmp_path, alpha=80, f=math.tan(math.radians(9.9)), find='["F", "eta"]')
    doc = check_json(p)
    q = values(doc)
    assert q["F@forward"]["ill_conditioned"] and q["eta@forward"]["ill_conditioned"]
    assert not q["F@reverse"]["ill_conditioned"]
    assert q["F@forward"]["rel_error"] < 1e-9  # the exact construction still agrees; a hand one would not
    assert any("nearly collinear" in w and "forward" in w for w in doc["warnings"])


# ---------------------------------------------------------------------------- only what is asked


def test_a_lead_angle_scene_draws_no_polygon_and_needs_no_friction():
    sc = load_scene(SCENES / "thread.m20_lead_angles-coarse.toml")
    assert sc.problem.f is None and sc.problem.load is None
    an = analyse_efficiency(sc)
    assert an.strokes == {} and [r.name for r in an.rows] == ["psi"]
    sheet = efficiency_figure(an, (297.0, 210.0))
    assert [p.name for p in sheet.panels] == ["diagram"]


def test_measured_values_are_judged(tmp_path):
    p = SCENES / "force.wedge_F1430.toml"
    code, out, err = run_cli("check", str(p), "--json", "--measured", "F@forward=1440,eta@forward=0.6")
    doc = json.loads(out)
    v = {m["name"]: m for m in doc["measured"]}
    assert v["F@forward"]["ok"] and v["F@forward"]["tolerance"] == pytest.approx(12.5)  # 0.5 mm × 25 N/mm
    assert not v["eta@forward"]["ok"] and code == 1


# ---------------------------------------------------------------------------- unknown names


def test_unknown_quantity_is_named(tmp_path):
    p = scene('find = ["etta"]\n[efficiency]\ntype = "incline"\nangle_deg = 30\nf = 0.1\nload_N = 1\n', tmp_path)
    code, out, err = run_cli("check", str(p))
    assert code == 2 and err == "s.toml: find[0]: unknown incline quantity 'etta'; did you mean eta?\n"


# ---------------------------------------------------------------------------- measured values


def test_a_measured_value_that_depends_on_the_direction_must_say_which():
    code, out, err = run_cli("check", str(SCENES / "force.wedge_F1430.toml"), "--measured", "eta=0.7")
    assert code == 2 and err == ("force.wedge_F1430.toml: --measured eta: eta depends on the direction: write "
                                 "eta@forward or eta@reverse\n")


def test_eta_read_off_the_polygons_is_judged_at_their_precision():
    # F1430 drawn as 1440 N is within 0.5 mm × 25 N/mm; the η a student computes from it,
    # 1000/1440 = 0.6944, was judged wrong at 0.1 % (η = 0.69896)
    code, out, err = run_cli("check", str(SCENES / "force.wedge_F1430.toml"), "--json",
                             "--measured", "F@forward=1440", "--measured", "eta@forward=0.6944")
    doc = json.loads(out)
    verdicts = {v["name"]: v for v in doc["measured"]}
    assert verdicts["F@forward"]["ok"] and verdicts["eta@forward"]["ok"]
    eta = verdicts["eta@forward"]
    assert eta["expected"] == pytest.approx(0.69896, abs=1e-5)
    assert eta["tolerance"] == pytest.approx(eta["expected"] * 12.5 * (1 / 1430.7004224765808 + 1 / 1000.0), rel=1e-9)
    code, out, err = run_cli("check", str(SCENES / "force.wedge_F1430.toml"), "--json",
                             "--measured", "eta@forward=0.67")  # 4 % off: wrong
    assert code == 1 and not json.loads(out)["measured"][-1]["ok"]


