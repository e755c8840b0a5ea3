"""Higher pairs inside a linkage scene (高副低代): the substituted linkage's polygons and instant
centres against closed forms worked here from the cam's or the gear's own geometry, the common
normal and the sliding speed, the drawing, and bad tables refused in one line."""
from __future__ import annotations

import math

import pytest

from graphmech.drawing.primitives import Label, Polyline, Segment
from graphmech.exact.higher_pair import (
    eccentric_cam_flat,
    eccentric_cam_roller,
    rolling_wheel_omega,
)
from graphmech.problems.linkage.higher_pair import HigherPairs, claims, decorate
from graphmech.scene import load_scene
from tests.conftest import (
    SCENES,
    assert_refused,
    check_json,
    fourbar_scene,
    run_cli,
    values,
)

CAM = SCENES / "kin.eccentric_cam_substitute.toml"
IC = SCENES / "ic.cam_higher_pair.toml"
RACK = SCENES / "kin.gear_rack_linkage.toml"
FLAT = SCENES / "kin.eccentric_cam_flat_substitute.toml"

# kin.eccentric_cam_substitute: e, R, r, the guide's offset d, ω2
E, R, ROLLER, D, W = 0.02, 0.04, 0.015, 0.01, 10.0


def _cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _meet(p1, p2, q1, q2):
    """Where line p1p2 meets line q1q2."""
    d1 = (p2[0] - p1[0], p2[1] - p1[1])
    d2 = (q2[0] - q1[0], q2[1] - q1[1])
    t = ((q1[0] - p1[0]) * d2[1] - (q1[1] - p1[1]) * d2[0]) / (d1[0] * d2[1] - d1[1] * d2[0])
    return p1[0] + t * d1[0], p1[1] + t * d1[1]


# ---------------------------------------------------------------------------- the cam's substitute


@pytest.mark.parametrize("deg", [45, 210])
def test_substitute_polygons_give_the_followers_closed_form_motion(deg):
    """v and a of the follower from the slider-crank A–C–B equal the eccentric cam's closed form."""
    v = values(check_json(CAM))
    _, vb, ab = eccentric_cam_roller(E, R, ROLLER, D, math.radians(deg), W)
    for name, want in ((f"v_B@{deg}", vb), (f"a_B@{deg}", ab)):
        assert v[name]["exact"] == pytest.approx(want, rel=1e-9)
        assert v[name]["graphical"] == pytest.approx(want, rel=1e-9)
    assert abs(v[f"a_B@{deg}"]["graphical"]) > 1.6  # a real acceleration, not a zero that matches anything


@pytest.mark.parametrize("deg", [45, 210])
def test_common_normal_and_sliding_speed_of_the_cam(deg):
    phi = math.radians(deg)
    y, vb, _ = eccentric_cam_roller(E, R, ROLLER, D, phi, W)
    c, b = (E * math.cos(phi), E * math.sin(phi)), (D, y)
    k = (c[0] + R / (R + ROLLER) * (b[0] - c[0]), c[1] + R / (R + ROLLER) * (b[1] - c[1]))
    v_cam = (-W * k[1], W * k[0])  # the cam's point at K turns about A
    slip = math.hypot(v_cam[0] - 0.0, v_cam[1] - vb)  # the follower translates at vb along y
    v = values(check_json(CAM))
    normal = math.degrees(math.atan2(b[1] - c[1], b[0] - c[0])) % 180.0
    assert v[f"dir_normal_23@{deg}"]["graphical"] == pytest.approx(normal, abs=1e-9)
    assert v[f"v_slip_23@{deg}"]["graphical"] == pytest.approx(slip, rel=1e-9)
    assert v[f"v_slip_23@{deg}"]["exact"] == pytest.approx(slip, rel=1e-9)


@pytest.mark.parametrize("deg", [45, 210])
def test_flat_face_substitute_is_the_scotch_yoke(deg):
    """The block at C in the follower's slot: v, a of the face = e·ω·cosφ, −e·ω²·sinφ; the normal is
    the vertical through C, the slip at K (R above C) the cam's speed there less the follower's."""
    phi = math.radians(deg)
    _, vf, af = eccentric_cam_flat(E, R, phi, W)
    v = values(check_json(FLAT))
    assert v[f"v_F@{deg}"]["graphical"] == pytest.approx(vf, rel=1e-9)
    assert v[f"a_F@{deg}"]["graphical"] == pytest.approx(af, rel=1e-9)
    assert v[f"dir_normal_23@{deg}"]["graphical"] == pytest.approx(90.0, abs=1e-9)
    k = (E * math.cos(phi), E * math.sin(phi) + R)
    slip = math.hypot(-W * k[1] - 0.0, W * k[0] - vf)
    assert v[f"v_slip_23@{deg}"]["graphical"] == pytest.approx(slip, rel=1e-9)
    assert v[f"v_slip_23@{deg}"]["exact"] == pytest.approx(slip, rel=1e-9)


OSCILLATING_FLAT = """
title = "oscillating flat-faced follower"
show = ["mechanism", "velocity"]
find = ["omega_3", "dir_normal_23", "v_slip_23"]
[units]
length = "mm"
angle = "deg"
omega = "rad/s"
[frame]
link = "1"
A = [0, 0]
B = [90, 0]
[driver]
type = "crank"
link = "2"
pivot = "A"
tip = "C"
length = 15
angle = [0, 60, 180]
omega = 10
[[dyad]]
type = "RPR"
joints = ["C", "B"]
links = ["4", "3"]
bar = "second"
offset = 20
[[higher_pair]]
links = ["2", "3"]
relative_motion = "sliding"
centres_of_curvature = ["C"]
radii_of_curvature = [20]
substitute_link = "4"
face_side = "right"
"""


def test_oscillating_flat_face_on_an_offset_guide_bar(tmp_path):
    """The face through the pivot B, tangent to the disc (R = 20 mm, AC = 15, AB = 90 mm): its angle
    ψ = ∠(BC) − asin(R/|BC|), ω3 = dψ/dt by central differences; ω3 = −2 and 10/7 rad/s at φ = 0
    and 180° (ω2·AC/(AB ∓ AC)); K the foot of the perpendicular from C, the slip from both motions."""
    path = tmp_path / "f.toml"
    path.write_text(OSCILLATING_FLAT, encoding="utf-8")
    v = values(check_json(path))
    a, b = (0.0, 0.0), (0.09, 0.0)

    def psi(phi):
        c = (0.015 * math.cos(phi), 0.015 * math.sin(phi))
        return math.atan2(c[1] - b[1], c[0] - b[0]) - math.asin(0.02 / math.dist(c, b))

    for deg in (0, 60, 180):
        phi, h = math.radians(deg), 1e-6
        turn = (psi(phi + h) - psi(phi - h) + math.pi) % (2 * math.pi) - math.pi
        w3 = 10.0 * turn / (2 * h)
        assert v[f"omega_3@{deg}"]["graphical"] == pytest.approx(w3, rel=1e-6)
        assert v[f"dir_normal_23@{deg}"]["graphical"] == pytest.approx(math.degrees(psi(phi) + math.pi / 2) % 180, abs=1e-9)
        c = (0.015 * math.cos(phi), 0.015 * math.sin(phi))
        u = (math.cos(psi(phi)), math.sin(psi(phi)))
        t = (c[0] - b[0]) * u[0] + (c[1] - b[1]) * u[1]
        k = (b[0] + t * u[0], b[1] + t * u[1])
        assert math.dist(c, k) == pytest.approx(0.02, rel=1e-12)
        v2 = (-10.0 * (k[1] - a[1]), 10.0 * (k[0] - a[0]))
        v3 = (-w3 * (k[1] - b[1]), w3 * (k[0] - b[0]))
        assert v[f"v_slip_23@{deg}"]["graphical"] == pytest.approx(math.dist(v2, v3), rel=1e-6)
    assert v["omega_3@0"]["graphical"] == pytest.approx(-2.0, rel=1e-12)
    assert v["omega_3@180"]["graphical"] == pytest.approx(10.0 / 7.0, rel=1e-12)


# ---------------------------------------------------------------------------- instant centres


def _cam_rocker(phi):
    """ic.cam_higher_pair's C and B at cam angle φ: B at 55 mm from C and 80 from D, left of C→D."""
    a, d = (0.0, 0.0), (0.09, -0.02)
    c = (0.02 * math.cos(phi), 0.02 * math.sin(phi))
    dist = math.dist(c, d)
    along = (0.055 ** 2 - 0.08 ** 2 + dist ** 2) / (2 * dist)
    h = math.sqrt(0.055 ** 2 - along ** 2)
    u = ((d[0] - c[0]) / dist, (d[1] - c[1]) / dist)
    b = (c[0] + along * u[0] - h * u[1], c[1] + along * u[1] + h * u[0])
    return a, c, b, d


def test_the_pairs_instant_centre_is_on_the_common_normal():
    """P23 = CB ∩ AD (Kennedy: on the common normal and on P12P13); ω3 and the slip from it."""
    a, c, b, d = _cam_rocker(math.radians(120))
    p23 = _meet(c, b, a, d)
    v = values(check_json(IC))
    got = (v["x_P23"]["graphical"], v["y_P23"]["graphical"])
    assert got == pytest.approx(p23, abs=1e-12)
    assert abs(_cross(c, b, got)) < 1e-15 and abs(_cross(a, d, got)) < 1e-15
    # ω3 from the angle of DB turned by a small step of the cam (not from any centre)
    h = 1e-6
    ang = [math.atan2(q[1] - d[1], q[0] - d[0]) for q in (_cam_rocker(math.radians(120) + s)[2] for s in (-h, h))]
    w3 = 10.0 * (ang[1] - ang[0]) / (2 * h)
    assert v["omega_3_ic"]["graphical"] == pytest.approx(w3, rel=1e-6)
    assert v["omega_3_ic"]["graphical"] == pytest.approx(10.0 * math.dist(a, p23) / math.dist(d, p23), rel=1e-12)
    k = (c[0] + 40 / 55 * (b[0] - c[0]), c[1] + 40 / 55 * (b[1] - c[1]))
    assert v["v_slip_23"]["graphical"] == pytest.approx(abs(10.0 - w3) * math.dist(p23, k), rel=1e-6)
    assert v["dir_normal_23"]["exact"] == pytest.approx(math.degrees(math.atan2(b[1] - c[1], b[0] - c[0])) % 180, abs=1e-9)


def test_gear_rolling_on_the_fixed_rack():
    """v_C of the slider-crank A–B–C on the line y = 0 and ω3 = −v_C/r3; the contact is P37."""
    bx, by = 0.03 * math.cos(math.radians(60)), 0.03 * math.sin(math.radians(60))
    cx = bx + math.sqrt(0.09 ** 2 - by ** 2)
    vbx, vby = 10.0 * by, -10.0 * bx  # ω1 = −10 rad/s: v_B = ω1 k × AB
    vcx = vbx - by * vby / (cx - bx)  # (C − B)·(v_C − v_B) = 0 with v_C ∥ the rack
    v = values(check_json(RACK))
    assert v["v_C"]["exact"] == pytest.approx(abs(vcx), rel=1e-9)
    assert v["v_C"]["graphical"] == pytest.approx(0.305034323, rel=1e-8)
    assert v["omega_3"]["graphical"] == pytest.approx(rolling_wheel_omega(vcx, 0.04), rel=1e-8)
    assert v["omega_3_ic"]["graphical"] == pytest.approx(rolling_wheel_omega(vcx, 0.04), rel=1e-8)
    assert (v["x_P37"]["graphical"], v["y_P37"]["graphical"]) == pytest.approx((cx, -0.04), abs=1e-9)
    assert v["v_slip_37"]["graphical"] == pytest.approx(0.0, abs=1e-12)
    assert v["v_E"]["graphical"] == pytest.approx(v["v_E_ic"]["graphical"], rel=1e-9)


# ---------------------------------------------------------------------------- scene and drawing


def test_the_scene_carries_its_pairs_and_a_plain_linkage_none(tmp_path):
    pairs = load_scene(CAM).problem
    assert isinstance(pairs, HigherPairs)
    (p,) = pairs.pairs
    assert (p.links, p.motion, p.centres, p.substitute) == (("2", "3"), "sliding", ("C", "B"), "4")
    assert p.radii == pytest.approx((0.04, 0.015))
    plain = tmp_path / "plain.toml"
    plain.write_text(fourbar_scene(), encoding="utf-8")
    assert load_scene(plain).problem is None
    assert claims("v_slip_23@45") and claims("dir_normal_37") and not claims("v_C") and not claims("P23")


def test_the_sheet_draws_the_substitute_dashed_and_the_profiles():
    from graphmech.problems.linkage.sheet import scene_sheet

    sheet, _ = scene_sheet(load_scene(CAM), ())
    mech = [p for p in sheet.panels if p.name.startswith("mechanism-")]
    assert len(mech) == 2
    for panel in mech:
        circles = [i for i in panel.items if isinstance(i, Polyline) and i.closed]
        assert len(circles) == 2  # the disc and the roller, about C and B
        (c, b) = (circle.points for circle in circles)
        rc = math.dist(c[0], (sum(x for x, _ in c[:-1]) / (len(c) - 1), sum(y for _, y in c[:-1]) / (len(c) - 1)))
        rb = math.dist(b[0], (sum(x for x, _ in b[:-1]) / (len(b) - 1), sum(y for _, y in b[:-1]) / (len(b) - 1)))
        assert rc / rb == pytest.approx(40 / 15, rel=1e-9)  # drawn at μl: 20 mm and 7.5 mm
        dashed = [i for i in panel.items if isinstance(i, Segment) and i.dashed]
        assert len(dashed) == 1 and math.dist(dashed[0].p0, dashed[0].p1) == pytest.approx(55 / 2, rel=1e-9)
        assert any(isinstance(i, Segment) and i.dashdot for i in panel.items)  # the common normal
        assert [i.text for i in panel.items if isinstance(i, Label) and i.text in ("K", "n")] == ["K", "n"]


def test_a_sheet_without_higher_pairs_is_left_alone(tmp_path):
    from graphmech.problems.linkage.check import analyse
    from graphmech.problems.linkage.sheet import scene_sheet

    path = tmp_path / "f.toml"
    path.write_text(fourbar_scene(), encoding="utf-8")
    scene = load_scene(path)
    sheet, _ = scene_sheet(scene, ())
    assert decorate(sheet, analyse(scene)) is sheet


# ---------------------------------------------------------------------------- refusals


@pytest.mark.parametrize("scene, old, new, words", [
    (CAM, "radii_of_curvature = [40, 15]", "radii_of_curvature = [40, 10]",
     ("higher_pair[0].substitute_link", "55 mm", "50 mm")),
    (CAM, 'substitute_link = "4"', 'substitute_link = "3"', ("higher_pair[0].substitute_link", "link 3")),
    (CAM, 'links = ["2", "3"]\nrelative', 'links = ["2", "9"]\nrelative', ("higher_pair[0].links[1]", "link 9")),
    (CAM, 'centres_of_curvature = ["C", "B"]', 'centres_of_curvature = ["B", "C"]',
     ("centres_of_curvature[0]", "B is not a point of link 2")),
    (CAM, '"v_slip_23"]', '"v_slip_24"]', ("find[5]", "no [[higher_pair]] of links 24")),
    (CAM, 'relative_motion = "sliding"', 'relative_motion = "slipping"', ("relative_motion", "slipping")),
    (CAM, "radii_of_curvature = [40, 15]", "radii_of_curvature = [40, -15]", ("radii_of_curvature[1]", "> 0")),
    (CAM, 'substitute_link = "4"', 'contact_point = "A"', ("substitute_link", "missing")),
    (FLAT, 'face_side = "left"', "", ("face_side", "missing")),
    (CAM, 'substitute_link = "4"', 'substitute_link = "4"\nface_side = "left"', ("face_side", "only for a flat face")),
    (FLAT, 'substitute_link = "4"', 'substitute_link = "3"', ("substitute_link", "not a block pinned at C")),
    (RACK, "angle = 60", "angle = [60, 70]", ("relative_motion", "one driver position")),
    (RACK, 'show = ["mechanism", "velocity"]', 'show = ["mechanism", "acceleration"]',
     ("relative_motion", "velocities only")),
    (RACK, '"v_C", ', '"a_C", ', ("relative_motion", "not a_C")),
    (RACK, 'contact_point = "D"', 'contact_point = "F"', ("contact_point", "F is not carried by link 3")),
    (RACK, "radii_of_curvature = [40]", "radii_of_curvature = [41]", ("contact_point", "41 mm")),
    (RACK, 'links = ["3", "7"]', 'links = ["3", "2"]', ("links[1]", "the frame, 7")),
])
def test_bad_higher_pairs_are_refused_in_one_line(tmp_path, scene, old, new, words):
    text = scene.read_text(encoding="utf-8")
    assert text.count(old) == 1
    path = tmp_path / "t.toml"
    path.write_text(text.replace(old, new), encoding="utf-8")
    assert_refused(run_cli("check", str(path)), "t.toml", *words)


def test_a_higher_pair_elsewhere_is_an_unknown_table(tmp_path):
    text = (SCENES / "cam.offset_roller_translating-pos.toml").read_text(encoding="utf-8")
    path = tmp_path / "t.toml"
    path.write_text(text + '\n[[higher_pair]]\nlinks = ["2", "3"]\n', encoding="utf-8")
    assert_refused(run_cli("check", str(path)), "t.toml", "higher_pair")


def test_a_measured_higher_pair_value_is_refused_not_misjudged(tmp_path):
    path = tmp_path / "t.toml"
    path.write_text(CAM.read_text(encoding="utf-8") + '\n[measured]\n"v_slip_23@45" = 0.54\n', encoding="utf-8")
    assert_refused(run_cli("check", str(path)), "t.toml", "measured.v_slip_23@45", "not judged")


def test_the_rolling_gears_velocity_image_is_the_circle_about_c_through_p():
    """g3: the gear's pitch circle maps to the circle about c of radius |ω3|·r3/μv = v_C/μv (p is D's image)."""
    from graphmech.problems.linkage.sheet import scene_sheet

    sheet, _ = scene_sheet(load_scene(RACK), ())
    (panel,) = [p for p in sheet.panels if p.name.startswith("velocity-")]
    (circle,) = [i for i in panel.items if isinstance(i, Polyline) and i.closed]
    pts = circle.points[:-1]
    centre = (sum(x for x, _ in pts) / len(pts), sum(y for _, y in pts) / len(pts))
    v_c = values(check_json(RACK))["v_C"]["exact"]
    assert math.dist(centre, (0.0, 0.0)) == pytest.approx(v_c / 0.004, rel=1e-9)  # c, seen from p
    assert all(math.dist(q, centre) == pytest.approx(v_c / 0.004, rel=1e-9) for q in pts)
    assert any(isinstance(i, Label) and i.text == "g3" for i in panel.items)
