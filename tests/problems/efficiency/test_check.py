"""Efficiency scenes: the polygons against the closed forms, the extreme cases, the format's errors."""
from __future__ import annotations

import json
import math
import subprocess
import sys
import tomllib

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.problems.efficiency.check import analyse_efficiency, efficiency_figure
from graphmech.errors import SceneError
from graphmech.exact import efficiency as ex
from graphmech.methods import efficiency as gm
from graphmech.drawing.primitives import Arrow, Segment
from graphmech.scene import load_scene, parse_scene
from tests.conftest import ROOT, SCENES, check_json, run_cli, values


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


@settings(max_examples=60, deadline=None)
@given(alpha=st.floats(1.0, 80.0), f=st.floats(0.0, 0.6), push=st.sampled_from(["horizontal", "parallel"]),
       direction=st.sampled_from(["forward", "reverse"]))
def test_incline_polygon_is_the_closed_form(alpha, f, push, direction):
    a, phi = math.radians(alpha), math.atan(f)
    if push == "horizontal" and direction == "forward" and a + phi > math.radians(89.0):
        return  # beyond the forward stroke's locking: tested below
    s = gm.incline(1000.0, a, phi, direction, 10.0, push)
    assert s.F == pytest.approx(ex.incline_force(1000.0, a, phi, direction, push), rel=1e-11, abs=1e-9)
    assert s.F0 == pytest.approx(ex.incline_force(1000.0, a, 0.0, direction, push), rel=1e-12)
    eta = ex.incline_efficiency(a, phi, direction, push)
    assert s.eta == pytest.approx(eta, rel=1e-10, abs=1e-10)
    assert dict(s.reactions)["R"] == pytest.approx(ex.incline_reaction(1000.0, a, phi, direction, push), rel=1e-11)


@settings(max_examples=60, deadline=None)
@given(gamma=st.floats(3.0, 85.0), beta=st.floats(5.0, 85.0), f=st.floats(0.0, 0.2),
       direction=st.sampled_from(["forward", "reverse"]))
def test_wedge_polygons_are_the_sine_rule(gamma, beta, f, direction):
    if abs(gamma + beta - 90.0) < 3.0 or gamma + beta > 170.0:
        return  # the contact side of guide 1 undecided, or the reconstruction's other regime
    g, b, phi = math.radians(gamma), math.radians(beta), math.atan(f)
    try:
        s = gm.wedge(1000.0, g, b, phi, direction, 20.0)
    except Exception as e:  # a side reversed by friction is refused, never mis-answered
        assert "reverses the side" in str(e)
        return
    w = ex.wedge_forces(1000.0, g, b, phi, direction)
    assert s.F == pytest.approx(w.F, rel=1e-10)
    r = dict(s.reactions)
    assert (r["R12"], r["R32"], r["R31"]) == pytest.approx((w.R12, w.R32, w.R31), rel=1e-9, abs=1e-9)
    assert s.F0 == pytest.approx(ex.wedge_ideal_force(1000.0, g, b), rel=1e-12)


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


def test_every_polygon_closes():
    s = gm.wedge(1000.0, math.radians(60), math.radians(60), math.atan(0.15), "forward", 25.0)
    for poly in s.polygons:
        sx = sum(f.end[0] - f.start[0] for f in poly.forces)
        sy = sum(f.end[1] - f.start[1] for f in poly.forces)
        assert abs(sx) < 1e-12 and abs(sy) < 1e-12
        assert poly.forces[0].start == poly.forces[-1].end


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


def test_polygon_panels_hold_the_ideal_dashed_and_the_real_bold():
    an = analyse_efficiency(load_scene(SCENES / "force.wedge_F1430.toml"))
    sheet = efficiency_figure(an, (297.0, 210.0))
    assert [p.name for p in sheet.panels] == ["diagram", "polygon-forward", "polygon-reverse"]
    poly = sheet.panels[1]
    bold = [i for i in poly.items if isinstance(i, Arrow) and i.role == "result"]
    dashed = [i for i in poly.items if isinstance(i, Segment) and i.dashed]
    assert len(bold) == 4 and len(dashed) == 6  # F, R12, R32, R31 bold (Q given); two ideal triangles
    assert any("μF = 25 N/mm" in n for n in poly.notes)
    f_arrow = next(i for i in poly.items if isinstance(i, Arrow) and any(
        getattr(l, "text", "") == "F" and l.anchor == ((i.p0[0] + i.p1[0]) / 2, (i.p0[1] + i.p1[1]) / 2)
        for l in poly.items))
    assert math.dist(f_arrow.p0, f_arrow.p1) * 25 == pytest.approx(1430.7004224765801, rel=1e-12)


def test_render_is_byte_stable_and_lazy(tmp_path):
    code = ("import sys; from graphmech.cli import main; "
            f"rc = main(['render', r'{SCENES / 'force.wedge_F1430.toml'}', '-o', r'{tmp_path / 'a.svg'}']); "
            f"main(['render', r'{SCENES / 'bal.rotor_dynamic.toml'}', '-o', r'{tmp_path / 'b.svg'}']); "
            "assert 'matplotlib' not in sys.modules, 'matplotlib imported'; sys.exit(rc)")
    r = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    run_cli("render", str(SCENES / "force.wedge_F1430.toml"), "-o", str(tmp_path / "c.svg"))
    assert (tmp_path / "a.svg").read_bytes() == (tmp_path / "c.svg").read_bytes()
    assert (tmp_path / "a.svg").read_bytes() == (ROOT / "figures" / "force.wedge_F1430.svg").read_bytes()


def test_measured_values_are_judged(tmp_path):
    p = SCENES / "force.wedge_F1430.toml"
    code, out, err = run_cli("check", str(p), "--json", "--measured", "F@forward=1440,eta@forward=0.6")
    doc = json.loads(out)
    v = {m["name"]: m for m in doc["measured"]}
    assert v["F@forward"]["ok"] and v["F@forward"]["tolerance"] == pytest.approx(12.5)  # 0.5 mm × 25 N/mm
    assert not v["eta@forward"]["ok"] and code == 1


# ---------------------------------------------------------------------------- bad input


@pytest.mark.parametrize("body, where, words", [
    ('[efficiency]\ntype = "wegde"\n', "efficiency.type", "did you mean wedge"),
    ('[efficiency]\ntype = "incline"\nangle_deg = 30\nload_N = 10\n', "efficiency.f", "friction coefficient"),
    ('[efficiency]\ntype = "incline"\nangle_deg = 90\nf = 0.1\nload_N = 10\n', "efficiency.angle_deg", "between"),
    ('[efficiency]\ntype = "screw"\nf = 0.1\nf_v = 0.1\nd2_mm = 10\npitch_mm = 1\nload_N = 1\n', "efficiency.f_v",
     "not both"),
    ('[efficiency]\ntype = "screw"\nf = 0.1\nd2_mm = 10\npitch_mm = 1\nlead_angle_deg = 3\nload_N = 1\n',
     "efficiency.lead_angle_deg", "exactly one"),
    ('[efficiency]\ntype = "wedge"\ngamma_deg = 40\nbeta_deg = 50.5\nf = 0.1\nload_N = 1\n', "efficiency.beta_deg",
     "90°"),
    ('[efficiency]\ntype = "incline"\nangle_deg = 30\nf = 0.1\nload_N = 1\ndirection = "up"\n',
     "efficiency.direction", "forward"),
    ('[efficiency]\ntype = "chain"\nload_N = 1\nspeed_m_s = 1\n[[efficiency.stage]]\neta = 1.2\n',
     "efficiency.stage[0].eta", "(0, 1]"),
    ('show = ["polygon"]\n[efficiency]\ntype = "chain"\nload_N = 1\nspeed_m_s = 1\n[[efficiency.stage]]\neta = 0.9\n',
     "show[0]", "no force polygon"),
    ('[efficiency]\ntype = "incline"\nangle_deg = 30\nf = 0.1\nload_N = 1\ngamma_deg = 3\n', "efficiency.gamma_deg",
     "belongs to 'wedge'"),
    ('[efficiency]\ntype = "incline"\nangle_deg = 30\nf = 0.1\nload_N = 1\n[driver]\n', "driver", "one problem"),
    # a minor diameter larger than the pitch diameter was taken (σ = 4Q/(π·d1²) from it)
    ('[efficiency]\ntype = "screw"\nf = 0.1\nd2_mm = 10\npitch_mm = 1\nd1_mm = 12\nload_N = 1\n', "efficiency.d1_mm",
     "the minor diameter d1 = 12 mm must be smaller than the pitch diameter d2 = 10 mm"),
])
def test_bad_scenes_are_one_line(body, where, words, tmp_path):
    p = scene(body, tmp_path)
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert e.value.problems[0][0] == where, e.value.problems
    assert words in e.value.problems[0][1]
    code, out, err = run_cli("check", str(p))
    assert code == 2 and err.count("\n") == 1 and err.startswith("s.toml: ")
    code, out, err = run_cli("render", str(p), "-o", str(tmp_path / "never.svg"))
    assert code == 2 and not (tmp_path / "never.svg").exists()


def test_unknown_quantity_is_named(tmp_path):
    p = scene('find = ["etta"]\n[efficiency]\ntype = "incline"\nangle_deg = 30\nf = 0.1\nload_N = 1\n', tmp_path)
    code, out, err = run_cli("check", str(p))
    assert code == 2 and err == "s.toml: find[0]: unknown incline quantity 'etta'; did you mean eta?\n"


def test_frozen_results():
    s = gm.incline(10.0, 0.3, 0.1, "forward", 1.0)
    with pytest.raises(AttributeError):
        s.F = 3.0  # type: ignore[misc]


# ---------------------------------------------------------------------------- fuzzing


def _forces_blocks() -> list[str]:
    import re

    text = (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8")
    blocks = re.findall(r"^```toml\n(.*?)^```", text, re.S | re.M)
    return [b for b in blocks if "[efficiency]" in b or "[balancing]" in b] + [
        p.read_text(encoding="utf-8") for p in sorted(SCENES.glob("*.toml"))
        if p.stem.startswith(("force.", "eff.", "thread.", "bal."))]


_values_to_try = st.one_of(st.booleans(), st.integers(-5, 400), st.floats(allow_nan=True, allow_infinity=True),
                           st.sampled_from([0, 0.0, 1e-300, 89.999999, 90, 45, -1, "forward", "V", "x", [], [0, 0],
                                            [1, 1], {}]))


def _leaves(data, path=()):
    if isinstance(data, dict):
        return [path] + [q for k, v in data.items() for q in _leaves(v, path + (k,))]
    if isinstance(data, list):
        return [path] + [q for i, v in enumerate(data) for q in _leaves(v, path + (i,))]
    return [path]


@settings(max_examples=150, deadline=None)
@given(st.data())
def test_any_mutation_checks_or_is_refused_in_one_line(data):
    """Whatever a mutated efficiency or balancing scene holds: a table without NaN and its figure, or
    a refusal in one line — never an internal error."""
    import copy

    from graphmech.problems.balancing.check import analyse_balancing
    from graphmech.problems.efficiency.check import analyse_efficiency
    from graphmech.errors import GraphmechError

    base = tomllib.loads(data.draw(st.sampled_from(_forces_blocks())))
    mutated = copy.deepcopy(base)
    path = data.draw(st.sampled_from(_leaves(mutated)[1:]))
    parent = mutated
    for step in path[:-1]:
        parent = parent[step]
    if data.draw(st.booleans()) and isinstance(parent, dict):
        del parent[path[-1]]
    else:
        parent[path[-1]] = data.draw(_values_to_try)
    try:
        sc = parse_scene(mutated, "fuzz.toml")
        an = analyse_efficiency(sc) if sc.kind == "efficiency" else analyse_balancing(sc) \
            if sc.kind == "balancing" else None
    except GraphmechError as err:
        assert "\n" not in str(err)
        return
    if an is None:
        return
    for row in an.rows:
        assert math.isfinite(row.graphical) and math.isfinite(row.exact) and math.isfinite(row.rel_error), row
    from graphmech.problems.balancing.check import balancing_figure
    from graphmech.render.svg import render_svg

    try:  # and its figure draws, or a stated scale that cannot draw it is refused in one line
        sheet = efficiency_figure(an, (297.0, 210.0)) if sc.kind == "efficiency" else \
            balancing_figure(an, (297.0, 210.0))
    except GraphmechError as err:
        assert "\n" not in str(err)
        return
    svg = render_svg(sheet, "gfuzz", on_warning=lambda w: None)
    assert "nan" not in svg.lower().replace("nane", "") and "inf" not in svg.lower().replace("info", "")


def test_scene_text_is_escaped_in_the_svg(tmp_path):
    import xml.etree.ElementTree as ET

    p = scene('title = "a <b> & \\"c\\""\n[efficiency]\ntype = "chain"\nload_N = 1\nspeed_m_s = 1\n'
              '[[efficiency.stage]]\nname = "</text><script>x</script>"\neta = 0.9\n', tmp_path)
    code, out, err = run_cli("render", str(p), "-o", str(tmp_path / "e.svg"))
    assert code == 0, err
    svg = (tmp_path / "e.svg").read_text(encoding="utf-8")
    ET.fromstring(svg)  # well-formed
    assert "<script>" not in svg and "&lt;script&gt;" in svg


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


def test_the_library_refuses_an_unknown_direction_or_push():
    # incline(..., "up", ...) was drawn as a reverse stroke, push="vertical" as a parallel one
    with pytest.raises(ValueError, match="'forward' or 'reverse', not 'up'"):
        gm.incline(100.0, 0.3, 0.1, "up", 1.0)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="'horizontal' or 'parallel', not 'vertical'"):
        gm.incline(100.0, 0.3, 0.1, "forward", 1.0, "vertical")
    with pytest.raises(ValueError, match="not 'down'"):
        gm.wedge(1000.0, 1.0, 1.0, 0.1, "down", 20.0)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="not 'up'"):
        ex.incline_force(100.0, 0.3, 0.1, "up")  # type: ignore[arg-type]
    assert gm.incline(100.0, 0.3, 0.1, "reverse", 1.0).F == pytest.approx(ex.incline_force(100.0, 0.3, 0.1, "reverse"),
                                                                          rel=1e-12)


def test_a_long_chain_of_machines_wraps_on_its_page(tmp_path):
    # the boxes stood in one row: 4 stages were 288.6 mm wide on an A4 page leaving 277 mm, 6 were 408.6
    stages = "".join(f'[[efficiency.stage]]\nname = "gear pair {k}"\neta = 0.97\n' for k in range(6))
    p = scene('find = ["eta", "P_in"]\n[efficiency]\ntype = "chain"\nload_N = 5500\nspeed_m_s = 1.2\n' + stages,
              tmp_path)
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "c.svg"))
    assert code == 0 and "runs off the page" not in err and "run off the page" not in err
    an = analyse_efficiency(load_scene(p))
    assert an.rows[0].exact == pytest.approx(0.97 ** 6, rel=1e-14)
    panel = efficiency_figure(an, (297.0, 210.0)).panels[0]
    xs = [q[0] for item in panel.items if hasattr(item, "points") for q in item.points]
    assert max(xs) - min(xs) < 277.0 and len({round(q[1]) for item in panel.items if hasattr(item, "points")
                                               for q in item.points}) > 4  # two rows of boxes
