"""The sheet of a given cam: the inversion panel and the s–δ diagram are drawn."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from tests.conftest import ROOT, run_cli


def test_render_draws_both_panels(tmp_path: Path) -> None:
    out = tmp_path / "c.svg"
    code, _, err = run_cli("render", str(ROOT / "figures/scenes/cam.eccentric_disc_oscillating.toml"), "-o", str(out))
    assert code == 0, err
    svg = out.read_text()
    assert "Cam profile by inversion" in svg and "ψ–δ" in svg
    assert ">rise " in svg and ">return " in svg  # the rise and the return named under the δ axis


def _marks(name: str):
    from graphmech.problems.cam.given_figures import profile_items
    from graphmech.problems.cam.profile_given import analyse_given
    from graphmech.scene import load_scene

    an = analyse_given(load_scene(ROOT / f"figures/scenes/{name}.toml"), ())
    return an, profile_items(an)


@pytest.mark.parametrize("name", ["cam.eccentric_disc_translating", "cam.eccentric_disc_oscillating",
                                  "cam.given_profile_points"])
def test_each_contact_has_its_pressure_angle_arced_between_the_normal_and_the_velocity(name: str) -> None:
    from graphmech.drawing.primitives import Label, Polyline

    an, items = _marks(name)
    mu = an.scales["l"]
    assert len(an.contacts) == 2
    for letter, (g, _) in an.contacts.items():
        p = an.inversion.at(g)
        B = (p.point[0] / mu, p.point[1] / mu)
        assert any(isinstance(i, Label) and i.text == f"α_{{{letter}}}" for i in items)
        arcs = [i for i in items if isinstance(i, Polyline) and i.role == "label"
                and all(abs(math.dist(q, B) - math.dist(i.points[0], B)) < 1e-9 for q in i.points)]
        assert len(arcs) == 1, letter
        (a0, a1) = (math.atan2(q[1] - B[1], q[0] - B[0]) for q in (arcs[0].points[0], arcs[0].points[-1]))
        assert abs((a1 - a0 + math.pi) % math.tau - math.pi) == pytest.approx(p.alpha, abs=1e-9)
        # its first arm is the common normal: through B and the roller's contact with the disc
        n = (arcs[0].points[0][0] - B[0], arcs[0].points[0][1] - B[1])
        c = (p.contact[0] / mu - B[0], p.contact[1] / mu - B[1])
        assert abs(n[0] * c[1] - n[1] * c[0]) / (math.hypot(*n) * math.hypot(*c)) < 1e-9
        r = math.dist(arcs[0].points[0], B)  # 8 mm, or wider for a small angle: an arc at least 0.4 mm long
        assert r >= 8.0 - 1e-9 and r * p.alpha >= 0.4 - 1e-9

