"""Reading the [efficiency] table: each bad scene is refused in one line naming its key."""
from __future__ import annotations


import pytest

from graphmech.errors import SceneError
from graphmech.scene import load_scene
from tests.conftest import run_cli


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
