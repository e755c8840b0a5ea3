"""Reading the [efficiency] table: the problem in SI; each bad scene refused in one line naming its key."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import SceneError
from graphmech.problems.efficiency.scene import Stage
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, run_cli


def scene(text: str, tmp_path, name: str = "s.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


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


def test_the_wedge_is_read_in_si_with_both_strokes():
    p = load_scene(SCENES / "force.wedge_F1430.toml").problem
    assert (p.type, p.directions, p.f, p.load) == ("wedge", ("forward", "reverse"), 0.15, 1000.0)
    assert (math.degrees(p.gamma), math.degrees(p.beta)) == pytest.approx((60.0, 60.0), rel=1e-15)


def test_a_v_thread_keeps_f_and_its_half_angle():
    data = {"efficiency": {"type": "screw", "thread": "V", "half_angle_deg": 30, "f": 0.15, "d2_mm": 18.376,
                           "pitch_mm": 2.5, "load_N": 10000}}
    p = parse_scene(data, "s.toml").problem
    assert (p.thread, p.f, p.f_is_equivalent, p.load) == ("V", 0.15, False, 10000.0)
    assert math.degrees(p.half_angle) == pytest.approx(30.0, rel=1e-15)
    assert (p.d2, p.lead) == pytest.approx((0.018376, 0.0025), rel=1e-15)
    # f_v given instead: already the equivalent coefficient, the thread's angle no longer counts
    data["efficiency"] = {**{k: v for k, v in data["efficiency"].items() if k not in ("f", "half_angle_deg")},
                          "f_v": 0.17}
    p = parse_scene(data, "s.toml").problem
    assert (p.f, p.f_is_equivalent, p.half_angle) == (0.17, True, 0.0)


def test_a_chain_reads_its_stages_and_branches():
    data = {"efficiency": {"type": "chain", "load_N": 1000, "speed_m_s": 2, "stage": [
        {"name": "belt", "eta": 0.95},
        {"name": "split", "branch": [{"share": 3, "eta": [0.97, 0.9]}, {"share": 1, "eta": 0.8}]}]}}
    p = parse_scene(data, "c.toml").problem
    assert (p.load, p.speed) == (1000.0, 2.0)
    assert p.stages == (Stage("belt", ((1.0, (0.95,)),)), Stage("split", ((3.0, (0.97, 0.9)), (1.0, (0.8,)))))
