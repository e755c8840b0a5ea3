"""Reading a helical, bevel or worm pair (graphmech/problems/gears/spatial_scene.py): the keys in SI,
z₂ from the ratio, and each bad table refused in one line naming its key."""
from __future__ import annotations

import math
import tomllib

import pytest

from graphmech.problems.gears.scene import known_names, quantity_unit
from graphmech.scene import parse_scene
from tests.scenes import only_problem


def read(text: str):
    return parse_scene(tomllib.loads(text), "g.toml").problem


def test_the_keys_in_si():
    p = read('[gear]\nm_mm = 8\nz = [20, 40]\nmeshing = "helical"\nbeta_deg = 15\nface_width_mm = 30\n'
             'centre_distance_mm = 250\n')
    sp = p.gears.spatial
    assert (sp.beta, sp.face_width, p.gears.centre_distance) == (math.radians(15), 0.03, 0.25)
    w = read('[gear]\nm_mm = 5\nz = [2]\nratio = 20.5\nmeshing = "worm"\nq = 10\n')
    assert [g.z for g in w.gears.gears] == [2, 41] and w.gears.spatial.worm_diameter == pytest.approx(0.05)
    b = read('[gear]\nm_mm = 4\nz = [20, 40]\nmeshing = "bevel"\n')
    assert b.gears.spatial.shaft_angle == math.pi / 2


def test_the_names_of_each_meshing():
    h = read('[gear]\nm_mm = 8\nz = [20, 40]\nmeshing = "helical"\nbeta_deg = 15\n')
    assert quantity_unit("zv2", h) == "" and quantity_unit("alpha_at1", h) == "deg"
    assert quantity_unit("eps_beta", h) is None and "eps_beta" not in known_names(h)  # no face width
    w = read('[gear]\nm_mm = 5\nz = [2, 41]\nmeshing = "worm"\nworm_diameter_mm = 50\n')
    assert quantity_unit("gamma1", w) == "deg" and quantity_unit("beta", w) is None


BASE = '[gear]\nm_mm = 8\nz = [20, 40]\n'


@pytest.mark.parametrize("body, where, words", [
    ('meshing = "helical"\nbeta_deg = 45', "gear.beta_deg", "0 ≤ β < 45°"),
    ('meshing = "helical"\nbeta_deg = -5', "gear.beta_deg", "helical gears are cut with"),
    ('meshing = "helical"', "gear.beta", "missing"),
    ('meshing = "helical"\nbeta_deg = 10\nx = [0.2, 0]', "gear.x", "not posed yet"),
    ('meshing = "external"\nbeta_deg = 10', "gear.beta_deg", 'belongs to meshing = "helical"'),
    ('meshing = "worm"', "gear.worm_diameter", "worm needs its reference diameter"),
    ('meshing = "worm"\nq = 10\nworm_diameter_mm = 80', "gear.q", "not both"),
    ('meshing = "worm"\nq = 10\ncentre_distance_mm = 200', "gear.centre_distance_mm", "(d₁ + d₂)/2"),
    ('meshing = "bevel"\nshaft_angle_deg = 180', "gear.shaft_angle_deg", "0 < Σ < 180°"),
    ('meshing = "bevel"\ncentre_distance_mm = 200', "gear.centre_distance_mm", "no centre distance"),
    ('meshing = "bevel"\nbeta_deg = 10', "gear.beta_deg", "not a bevel pair"),
    ('meshing = "helical"\nbeta_deg = 10\nratio = 3', "gear.ratio", "disagrees with z2/z1"),
    ('meshing = "helical"\nbeta_deg = 10\nspan_teeth = 3', "gear.span_teeth", "spur gear's"),
    # β so small that the helix and x = πd are parallel to double precision: it ended in a keyless line
    ('meshing = "helical"\nbeta_deg = 1e-12', "gear.beta_deg", "no drawable lead"),
    # a strip 10²⁰ mm long left p_t no drawn length: an internal error in render
    ('meshing = "helical"\nbeta_deg = 15\nface_width_mm = 1e20', "gear.face_width_mm", "at most 1000·m = 8000 mm"),
])
def test_bad_tables_refused(body, where, words):
    path, reason = only_problem(BASE + body + "\n", "g.toml")
    assert path == where and words in reason, (path, reason)


def test_a_ratio_giving_a_fraction_of_a_tooth():
    path, reason = only_problem('[gear]\nm_mm = 5\nz = [3]\nratio = 20.5\nmeshing = "worm"\nq = 10\n', "g.toml")
    assert path == "gear.ratio" and "not a whole number" in reason


def test_misspelt_and_foreign_names():
    for find, words in (('["zv3"]', "did you mean zv2, zv1"), ('["delta1"]', "a bevel pair's quantity"),
                        ('["eps_beta"]', "needs the face width")):
        path, reason = only_problem(f'find = {find}\n' + BASE + 'meshing = "helical"\nbeta_deg = 10\n', "g.toml")
        assert path == "find[0]" and words in reason, reason
