"""The panel "helix" (graphmech/problems/gears/helix_figure.py): what each drawing holds."""
from __future__ import annotations

import math
import tomllib

from graphmech.drawing.primitives import Label, Segment
from graphmech.problems.gears.helix_figure import (
    development_items,
    helix_sheet,
    thread_items,
)
from graphmech.problems.gears.spatial import analyse_spatial
from graphmech.scene import parse_scene


def analysed(text: str):
    return analyse_spatial(parse_scene(tomllib.loads(text), "g.toml"), ())


HELICAL = ('[gear]\nm_mm = 8\nz = [20, 40]\nmeshing = "helical"\nbeta_deg = 15\ncentre_distance_mm = 250\n'
           'face_width_mm = 30\n')


def test_the_development_draws_the_tooth_lines_at_beta():
    an = analysed(HELICAL)
    mu = an.scales["l"]
    items = development_items(an.construction, mu)
    thick = [i for i in items if isinstance(i, Segment) and i.role == "result"]
    for s in thick:
        dx, dy = s.p1[0] - s.p0[0], s.p1[1] - s.p0[1]
        assert math.degrees(math.atan2(dx, dy)) == math.degrees(an.construction.angle.beta) or \
            abs(math.atan2(dx, dy) - an.construction.angle.beta) < 1e-12
        assert dy * mu == 0.03 or abs(dy * mu - 0.03) < 1e-12
    texts = {i.text for i in items if isinstance(i, Label)}
    assert {"p_{t} = 26.18 mm", "p_{n} = 25.13 mm", "B = 30 mm", "β"} <= texts


def test_the_sheets_panels():
    assert [p.name for p in helix_sheet(analysed(HELICAL), (297.0, 210.0)).panels] == \
        ["development", "section", "lead", "transverse"]
    no_lead = analysed('[gear]\nm_mm = 8\nz = [20, 40]\nmeshing = "helical"\nbeta_deg = 0\n')
    assert "lead" not in [p.name for p in helix_sheet(no_lead, (297.0, 210.0)).panels]
    bevel = analysed('[gear]\nm_mm = 4\nz = [20, 40]\nmeshing = "bevel"\n')
    assert [p.name for p in helix_sheet(bevel, (297.0, 210.0)).panels] == ["cones", "virtual"]


def test_the_worms_threads_one_per_start_and_their_wraps():
    an = analysed('[gear]\nm_mm = 5\nz = [6]\nratio = 7\nmeshing = "worm"\nq = 10\n')
    items = thread_items(an.construction, an.scales["l"])
    texts = {i.text for i in items if isinstance(i, Label)}
    assert "γ_{1}" in texts and any(t.startswith("p_{z} = z_{1}p_{x} = 94.25") for t in texts)



def test_the_lead_angle_is_lettered_inside_its_angle():
    # the bank's worm (γ₁ = 11.3°): at 1.1r the wedge was lower than the letter and γ₁ went across the
    # thread, outside the angle, on a leader
    from graphmech.problems.gears.helix_figure import worm_panels
    from graphmech.render.sheet import panel_labels, panel_shapes
    an = analysed('[gear]\nm_mm = 5\nz = [2]\nratio = 20.5\nmeshing = "worm"\nq = 10\n')
    (panel,) = worm_panels(an, "en")
    (placed,) = [p for p in panel_labels(panel, panel_shapes(panel)) if p.label.text == "γ_{1}"]
    x0, y0, x1, y1 = placed.box
    tg, w = math.tan(an.construction.gamma1), an.construction.pi_d1 / an.scales["l"]
    assert placed.leader is None
    assert 0.0 < y0 and y1 < x0 * tg and x1 < w / 2, placed.box   # under the thread, short of the wrap
