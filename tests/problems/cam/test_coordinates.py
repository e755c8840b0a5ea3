"""Cam tables as handed in (issue 22 item 2): the working profile's coordinates at every division,
s₀ and ψ₀, a rocker's ψ named psi@δ (s@δ its alias) and its swing h in degrees, and the readings at a
division judged as measured values."""
from __future__ import annotations

import math

import numpy as np
import pytest

from tests.conftest import SCENES, assert_refused, check_json, run_cli, values

TABLE = SCENES / "cam.offset_roller_translating-table.toml"
ROCKER = SCENES / "cam.oscillating_roller.toml"

CENTRED = """
title = "centred roller"
show = ["profile"]
find = {find}

[units]
length = "mm"
angle = "deg"

[cam]
base_radius = 40
rotation = "ccw"
omega_rad_s = 1
step = {step}
coordinates = true

[cam.follower]
type = "translating"
contact = "{contact}"
{roller}

[cam.program]
stroke = 20

[[cam.segment]]
kind = "rise"
angle = 120
law = "{law}"

[[cam.segment]]
kind = "dwell"
angle = 60

[[cam.segment]]
kind = "return"
angle = 120
law = "sine"

[[cam.segment]]
kind = "dwell"
angle = 60
"""


def centred(tmp_path, *, find='["s0"]', step=15, contact="roller", law="uniform", name="c.toml"):
    p = tmp_path / name
    roller = "roller_radius = 10" if contact == "roller" else ""
    p.write_text(CENTRED.format(find=find, step=step, contact=contact, roller=roller, law=law), encoding="utf-8")
    return p


def book_roller_point(delta: float, s0: float, e: float, rr: float, h: float, phi: float) -> tuple[float, float]:
    """The book's closed form for a uniform rise, cam CCW: the pitch point x = (s0 + s) sin δ + e cos δ,
    y = (s0 + s) cos δ − e sin δ, and the working profile's point pitch − r_r along the outward normal
    (x′ = x − r_r cos θ, y′ = y − r_r sin θ with sin θ = x_δ/√(x_δ² + y_δ²), cos θ = −y_δ/√…)."""
    s, ds = h * delta / phi, h / phi
    x = (s0 + s) * math.sin(delta) + e * math.cos(delta)
    y = (s0 + s) * math.cos(delta) - e * math.sin(delta)
    dx = ds * math.sin(delta) + (s0 + s) * math.cos(delta) - e * math.sin(delta)
    dy = ds * math.cos(delta) - (s0 + s) * math.sin(delta) - e * math.cos(delta)
    n = math.hypot(dx, dy)
    return x - rr * (-dy / n), y - rr * (dx / n)


def test_a_centred_roller_profile_point_is_the_pitch_point_less_r_r_along_the_normal(tmp_path):
    doc = check_json(centred(tmp_path))
    rows = {round(d["delta_deg"], 6): d for d in doc["divisions"]}
    for deg in (15.0, 45.0, 90.0, 105.0):  # inside the uniform rise, off its corners
        x, y = book_roller_point(math.radians(deg), 0.040, 0.0, 0.010, 0.020, math.radians(120))
        d = rows[deg]
        assert (d["x_exact"], d["y_exact"]) == pytest.approx((x, y), abs=1e-12)
        assert d["r_exact"] == pytest.approx(math.hypot(x, y), abs=1e-12)
        assert d["theta_exact_deg"] == pytest.approx(math.degrees(math.atan2(y, x)) % 360.0, abs=1e-9)
        # read off the drawing at 15°: the envelope's point nearest B_k, within a tenth of a mm
        assert math.hypot(d["x"] - x, d["y"] - y) < 1e-4
        assert d["r"] == pytest.approx(math.hypot(d["x"], d["y"]), rel=1e-12)
    # on the far dwell the profile is the circle r0 + h − r_r = 50 mm, drawn and exact
    for deg in (135.0, 150.0, 165.0):
        assert rows[deg]["r_exact"] == pytest.approx(0.050, abs=1e-12)
        assert rows[deg]["r"] == pytest.approx(0.050, abs=1e-9)
        assert rows[deg]["theta_exact_deg"] == pytest.approx((90.0 - deg) % 360.0, abs=1e-9)  # OB turned back by δ
    assert values(doc)["s0"]["graphical"] == pytest.approx(0.040, abs=1e-15)  # centred: s0 = r0


def test_the_drawn_coordinates_converge_as_the_step_gets_finer(tmp_path):
    def worst(step: float) -> float:
        doc = check_json(centred(tmp_path, step=step, law="poly345", name=f"c{step}.toml"))
        return max(math.hypot(d["x"] - d["x_exact"], d["y"] - d["y_exact"]) for d in doc["divisions"])

    coarse, fine = worst(15), worst(3)
    assert coarse > 5 * fine and fine < 2e-5


def test_the_offset_roller_table_is_the_banks(problems):
    """The bank lists the working profile point at every 15° for e = +10 mm: the exact side agrees to its
    four decimals except at 150°, a convex corner where the bank lists the profile's vertex and the
    table the right-hand limit (the roller beyond the corner: checked apart); the drawing to 0.1 mm
    where the profile is smooth."""
    p = problems["cam.offset_roller_translating"]
    doc = check_json(TABLE)
    by_angle = {round(d["delta_deg"], 6): d for d in doc["divisions"]}
    assert len(doc["divisions"]) == 24
    smooth = 0
    for deg, x, y in zip(p["inputs"]["profile_angles_deg"], p["exact"]["actual_x_mm_pos"], p["exact"]["actual_y_mm_pos"]):
        d = by_angle[deg]
        if deg == 150.0:
            vertex = p["exact"]["actual_vertex_at_150_xy_mm_pos"]
            assert (d["x_exact"] * 1e3, d["y_exact"] * 1e3) != pytest.approx(vertex, abs=0.1)
            continue
        assert (d["x_exact"] * 1e3, d["y_exact"] * 1e3) == pytest.approx((x, y), abs=6e-5)
        if deg not in (0.0, 180.0, 240.0, 300.0):  # the corner at 0° and the soft impacts' joints
            assert math.hypot(d["x"] * 1e3 - x, d["y"] * 1e3 - y) < 0.1, deg
            smooth += 1
    assert smooth == 19
    q = values(doc)
    assert q["s0"]["graphical"] * 1e3 == pytest.approx(p["exact"]["s0_mm"], rel=1e-12)
    assert q["s0"]["drawn_mm"] == pytest.approx(28.2843, abs=1e-4)  # at μl = 0.001 m/mm
    # the book's s-table as measured values: judged, both right
    assert [(m["name"], m["ok"]) for m in doc["measured"]] == [("s@45", True), ("s@195", True)]


def test_without_the_key_the_division_table_is_as_it_was():
    doc = check_json(SCENES / "cam.offset_roller_translating-pos.toml")
    assert set(doc["divisions"][0]) == {"division", "delta_deg", "s", "s_unit", "alpha_deg", "alpha_exact_deg",
                                        "rho_pitch", "rho_pitch_exact"}


def test_the_sheet_has_the_table_only_when_asked(tmp_path):
    from graphmech.problems.cam import _sheet
    from graphmech.scene import load_scene

    sheet, _ = _sheet(load_scene(TABLE), ())
    assert [p.name for p in sheet.panels] == ["profile", "displacement", "coordinates"]
    table = sheet.panels[-1]
    texts = [i.text for i in table.items if hasattr(i, "text")]
    # the head twice (two blocks of 12 rows), and division 3's row as the check reads it
    assert texts.count("x/mm") == 2 and texts.count("θ/°") == 2
    row3 = texts[texts.index("3"):texts.index("3") + 7]
    assert row3[:3] == ["3", "45.00", "4.80"]  # δ in degrees, s in mm
    d3 = check_json(TABLE)["divisions"][3]
    assert row3[3:] == [f"{d3['x'] * 1e3:.2f}", f"{d3['y'] * 1e3:.2f}", f"{d3['r'] * 1e3:.2f}", f"{d3['theta_deg']:.2f}"]
    assert table.notes == ("O at the origin, the follower along +y at δ = 0; θ from +x counter-clockwise",)
    plain, _ = _sheet(load_scene(SCENES / "cam.offset_roller_translating-pos.toml"), ())
    assert [p.name for p in plain.panels] == ["profile", "displacement"]


def test_a_rockers_table_lists_psi_in_degrees_every_kth_division_when_fine(tmp_path):
    from graphmech.problems.cam import _sheet
    from graphmech.problems.cam.coordinates import MAX_ROWS
    from graphmech.scene import load_scene

    p = tmp_path / "r.toml"
    p.write_text(ROCKER.read_text(encoding="utf-8").replace("step = 15", "step = 5\ncoordinates = true"), encoding="utf-8")
    table = _sheet(load_scene(p), ())[0].panels[-1]
    texts = [i.text for i in table.items if hasattr(i, "text")]
    assert texts.count("ψ/°") == 3 and "s/mm" not in texts  # 72 divisions: every 2nd, in three blocks
    assert table.notes == ("O at the origin, the rocker's pivot A on +x; θ from +x counter-clockwise",
                           "one division in 2 listed")
    assert sum(t.isdigit() for t in texts) == 36 <= MAX_ROWS
    doc = check_json(p)
    assert len(doc["divisions"]) == 72 and all(d["x"] is not None for d in doc["divisions"])


def test_a_flat_face_contact_is_read_at_the_middle_of_its_stretch(tmp_path):
    doc = check_json(centred(tmp_path, contact="flat", law="poly345", step=5))
    worst = max(math.hypot(d["x"] - d["x_exact"], d["y"] - d["y_exact"]) for d in doc["divisions"])
    assert worst < 2e-4
    # on the near dwell the face touches the base circle at the foot of the perpendicular from O,
    # (r0 sin δ, r0 cos δ): the middle of its stretch between the symmetric corners
    d = next(d for d in doc["divisions"] if round(d["delta_deg"], 6) == 330.0)
    assert (d["x"], d["y"]) == pytest.approx((0.040 * math.sin(math.radians(330)), 0.040 * math.cos(math.radians(330))),
                                             abs=1e-14)


# ------------------------------------------------------------------ a rocker's ψ, ψ0 and h in degrees

def test_a_rockers_psi_and_its_alias_s_and_its_swing_in_degrees(tmp_path, problems):
    text = ROCKER.read_text(encoding="utf-8").replace('find = ["alpha_max", "alpha_max_at", "h",',
                                                      'find = ["psi0", "s0", "psi@45", "alpha_max", "alpha_max_at", "h",')
    p = tmp_path / "r.toml"
    p.write_text(text, encoding="utf-8")
    q = values(check_json(p))
    assert q["psi@45"]["unit"] == "deg" and q["psi@45"]["graphical"] == q["s@45"]["graphical"]
    angles = problems["cam.oscillating_roller"]["inputs"]["table_angles_deg_corrected"]
    assert q["psi@45"]["graphical"] == pytest.approx(
        problems["cam.oscillating_roller"]["exact"]["phi_table_deg"][angles.index(45)], rel=1e-9)
    assert (q["h"]["unit"], q["h"]["graphical"], q["h"]["drawn_mm"], q["h"]["scale"]) == ("deg", pytest.approx(25.0), 50.0, 0.5)
    assert q["psi0"]["graphical"] == pytest.approx(27.0122939589, abs=1e-9)  # cos ψ0 = (a² + l² − r0²)/2al
    assert q["psi0"]["exact"] == pytest.approx(27.0122939589, abs=1e-9)
    assert q["s0"]["graphical"] == q["psi0"]["graphical"]


def test_a_rockers_names_are_refused_for_a_translating_follower(tmp_path):
    p = centred(tmp_path, find='["psi@45"]')
    assert_refused(run_cli("check", str(p)), p.name, "find[0]", "psi@45 is a rocker's angle", "ask for s@45")
    q = centred(tmp_path, find='["psi0"]', name="d.toml")
    assert_refused(run_cli("check", str(q)), q.name, "find[0]", "ask for s0")


# ------------------------------------------------------------------ readings at a division as measured values

def test_s_at_a_division_is_a_measured_value_on_the_command_line_and_in_the_scene(tmp_path):
    code, out, err = run_cli("check", str(TABLE), "--measured", "s@60=0.0064", "--measured", "s@90=0.0096")
    assert code == 0, err
    assert "s@60" in out and "s@90" in out
    code, out, _ = run_cli("check", str(TABLE), "--measured", "s@60=0.0075")  # 1.1 mm off at μs = 0.0005: wrong
    assert code == 1 and "s@60" in out
    # a rocker's reading in degrees, judged at μψ = 0.5 °/mm and the 0.5 mm precision: ±0.25°
    rocker = check_json(ROCKER, "--measured", "psi@45=4.2", "--measured", "s@45=4.4")
    exact = values(check_json(ROCKER))["s@45"]["exact"]
    assert [(m["name"], m["ok"], m["tolerance"]) for m in rocker["measured"]] == [
        ("psi@45", abs(4.2 - exact) <= 0.25, 0.25), ("s@45", abs(4.4 - exact) <= 0.25, 0.25)]


def test_a_measured_reading_off_the_divisions_is_refused_at_its_key(tmp_path):
    assert_refused(run_cli("check", str(TABLE), "--measured", "s@40=0.004"), TABLE.name, "--measured s@40",
                   "40° is not a division")
    text = TABLE.read_text(encoding="utf-8").replace('"s@195" = 0.0155', '"s@40" = 0.004')
    p = tmp_path / "m.toml"
    p.write_text(text, encoding="utf-8")
    assert_refused(run_cli("check", str(p)), p.name, "measured.s@40", "40° is not a division")
    bad = tmp_path / "b.toml"
    bad.write_text(text.replace('"s@40" = 0.004', '"s@top" = 0.004'), encoding="utf-8")
    assert_refused(run_cli("check", str(bad)), bad.name, "measured.s@top", "no driver positions")


def test_the_coordinates_key_is_a_flag(tmp_path):
    p = tmp_path / "f.toml"
    p.write_text(TABLE.read_text(encoding="utf-8").replace("coordinates = true", 'coordinates = "yes"'), encoding="utf-8")
    assert_refused(run_cli("check", str(p)), p.name, "cam.coordinates", "must be true or false")


def test_drawn_contacts_of_a_knife_are_its_tips():
    from graphmech.mechanisms.cam import (
        DiscCam,
        MotionProgram,
        Segment,
        TranslatingFollower,
    )
    from graphmech.mechanisms.motion import breakpoints, displacement
    from graphmech.methods.cam_inversion import divisions, draw_profile
    from graphmech.problems.cam.coordinates import drawn_contacts

    program = MotionProgram(0.016, (Segment("rise", math.pi, "cosine"), Segment("return", math.pi, "cosine")))
    cam = DiscCam(0.03, TranslatingFollower(0.005), program)
    delta = divisions(cam, math.radians(30), breakpoints(program))
    drawn = draw_profile(cam, delta, displacement(program, delta))
    pts = drawn_contacts(cam, drawn)
    assert np.array_equal(pts, drawn.pitch) and pts is not drawn.pitch
    assert pts[0] == pytest.approx((0.005, math.sqrt(0.03 ** 2 - 0.005 ** 2)), abs=1e-15)
