"""Scenes that give the cam's profile: values against the closed forms, refusals in one line."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from tests.conftest import ROOT, assert_refused, check_json, run_cli, values

SCENES = ROOT / "figures" / "scenes"


def test_000_cam_5a_translating_roller() -> None:
    v = values(check_json(SCENES / "cam.eccentric_disc_translating.toml"))
    # R = 30, |OC| = 10, e = 15, r_T = 5: r0 = 25 mm, h = √(45² − 15²) − √(25² − 15²)
    assert v["r0"]["exact"] == pytest.approx(0.025) and v["r0_actual"]["exact"] == pytest.approx(0.020)
    assert v["h"]["graphical"] == pytest.approx(math.sqrt(45**2 - 15**2) * 1e-3 - 0.020, rel=1e-13)
    # at δ = 90° C stands at (10, 0): the roller centre at (15, √(35² − 5²)), α from sin α = 5/35
    assert v["s@90"]["exact"] == pytest.approx(math.sqrt(35**2 - 5**2) * 1e-3 - 0.020, rel=1e-13)
    assert v["alpha@90"]["exact"] == pytest.approx(math.degrees(math.asin(5 / 35)), rel=1e-13)
    # the largest pressure angle, where C stands on the line ⟂ the axis: sin α = (e + |OC|)/ρ = 25/35
    assert v["alpha_max"]["exact"] == pytest.approx(math.degrees(math.asin(25 / 35)), rel=1e-12)
    assert v["alpha_max_at"]["exact"] == pytest.approx(270.0, abs=1e-6)  # C at (−10, 0), away from the axis
    for q in v.values():
        assert q["rel_error"] < 1e-12, q
    assert 0.0 < v["delta@E-F"]["graphical"] < 360.0


def test_001_1_17_flat_rocker_omega2() -> None:
    v = values(check_json(SCENES / "cam.eccentric_disc_flat_rocker.toml"))
    assert abs(v["v@0"]["graphical"]) == pytest.approx(2.0, rel=1e-12)  # ω1·AC/BC = 10·15/75
    assert abs(v["v@180"]["graphical"]) == pytest.approx(10 * 15 / 105, rel=1e-12)
    assert v["v@0"]["unit"] == "rad/s"
    assert v["r0"]["exact"] == pytest.approx(0.005)


def test_centred_roller_rise_is_2e(tmp_path: Path) -> None:
    text = (SCENES / "cam.eccentric_disc_translating.toml").read_text().replace("offset = 15", "offset = 0")
    scene = tmp_path / "c.toml"
    scene.write_text(text.replace('find = [', 'find = ["s@E", ', 1))
    doc = check_json(scene)
    v = values(doc)
    assert v["h"]["exact"] == pytest.approx(0.020, rel=1e-14) and v["h"]["graphical"] == pytest.approx(0.020, rel=1e-14)
    assert v["s@E"]["exact"] >= 0.0 and v["s@E"]["rel_error"] < 1e-12
    assert len(doc["divisions"]) == 13 and set(doc["contacts"]) == {"E", "F"}


def test_oscillating_swing_and_contacts() -> None:
    doc = check_json(SCENES / "cam.eccentric_disc_oscillating.toml")
    v = values(doc)
    a, l, r_lo, r_hi = 50.0, 40.0, 25.0, 45.0
    swing = math.acos((a * a + l * l - r_hi**2) / (2 * a * l)) - math.acos((a * a + l * l - r_lo**2) / (2 * a * l))
    assert v["h"]["exact"] == pytest.approx(math.degrees(swing), rel=1e-13) and v["h"]["unit"] == "deg"
    c = doc["contacts"]
    turned = (c["F"]["delta_exact_deg"] - c["E"]["delta_exact_deg"]) % 360.0
    assert v["delta@E-F"]["exact"] == pytest.approx(turned, rel=1e-13)
    assert v["delta@E-F"]["rel_error"] < 1e-12


def test_measured_reading_is_judged() -> None:
    doc = check_json(SCENES / "cam.eccentric_disc_knife.toml", "--measured", "r0=0.0151")
    (verdict,) = doc["measured"]
    assert verdict["expected"] == pytest.approx(0.015) and verdict["ok"]  # 0.1 mm off, within 0.5 mm × μl


@pytest.mark.parametrize("edit, words", [
    (("centre = [-10, 0]", "centre = [-30, 0]"), ("cam.profile.centre", "inside the disc")),
    (("offset = 8", "offset = 20"), ("cam.follower.offset", "misses")),
    (('find = ["h"', 'find = ["q@3", "h"'), ("find[0]", "write s@<cam angle")),
    (('find = ["h"', 'find = ["delta@E-Z", "h"'), ("find[0]", "no contact named")),
    (("[cam.profile]", "base_radius = 30\n\n[cam.profile]"), ("cam.base_radius", "profile is given")),
])
def test_bad_input_refused_in_one_line(tmp_path: Path, edit: tuple[str, str], words: tuple[str, ...]) -> None:
    text = (SCENES / "cam.eccentric_disc_knife.toml").read_text()
    assert edit[0] in text
    scene = tmp_path / "bad.toml"
    scene.write_text(text.replace(edit[0], edit[1]) + '\n[[cam.contact]]\nname = "E"\npolar = 10\n')
    assert_refused(run_cli("check", str(scene)), "bad.toml", *words)


@pytest.mark.parametrize("path", sorted(SCENES.glob("cam.eccentric_disc_*.toml")), ids=lambda p: p.stem)
def test_every_row_is_a_construction_to_round_off(path: Path) -> None:
    doc = check_json(path)
    assert doc["quantities"]
    for r in doc["quantities"]:
        if r["name"].startswith("alpha_max"):  # read at the divisions: here it falls on one
            assert r["error_source"] == "reading" and r["error_estimate"] < 1e-9, r
        else:
            assert r["error_source"] == "construction", r
        assert r["rel_error"] < 1e-12, r
    for row in doc["divisions"]:  # the s–δ (ψ–δ) table as drawn, beside the closed form
        key = "psi_deg" if "psi_deg" in row else "s"
        assert row[key] == pytest.approx(row[key.replace("_deg", "") + ("_exact_deg" if key == "psi_deg" else "_exact")],
                                         abs=1e-12)


def test_points_profile_rows_carry_their_discretisation() -> None:
    doc = check_json(SCENES / "cam.given_profile_points.toml")
    v = values(doc)
    assert {"h", "r0", "delta@E-F", "alpha@F", "v@90"} <= v.keys()
    for q in v.values():
        if q["name"].startswith("alpha_max"):  # read at the divisions, its estimate from 2, 4, 8 times as many
            assert q["error_source"] == "reading" and "divisions" in q["basis"], q
            assert q["rel_error"] < 2 * q["error_estimate"] + 1e-4, q
            continue
        assert q["error_source"] == "discretisation" and "720 chords" in q["basis"], q
        assert q["rel_error"] < 1e-4, q
        if q["rel_error"] > 1e-9:  # the estimate from 1440 and 2880 chords tells the true error's size
            assert 0.1 <= q["error_estimate"] / q["rel_error"] <= 10, q


@pytest.mark.parametrize("points, words", [
    ("[[30, 0], [0, 30], [-30, 0], [-5, -5], [0, -30]]", "not convex"),
    ("[[30, 0], [0, 30], [-30, 0], [0, -30]]", "5 … "),
    ("[[30, 0], [0, 30], [-30, 0], [0, -30], [30, 0]]", "given twice"),
])
def test_a_bad_points_profile_is_refused(tmp_path: Path, points: str, words: str) -> None:
    text = (SCENES / "cam.given_profile_points.toml").read_text()
    text = text.replace(text.split("points = ", 1)[1].split("\n", 1)[0], points)
    scene = tmp_path / "bad.toml"
    scene.write_text(text)
    assert_refused(run_cli("check", str(scene)), "bad.toml", "cam.profile.points", words)


def test_documented_refusals_are_real(tmp_path: Path) -> None:
    """The refusals listed under "A cam given by its profile" in docs/scene-format.md."""
    text = (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8")
    section = text.split("### A cam given by its profile", 1)[1].split("\n### ", 1)[0]
    documented = section.split("```text\n", 1)[1].split("```", 1)[0].strip().splitlines()
    base = (SCENES / "cam.eccentric_disc_knife.toml").read_text() + '\n[[cam.contact]]\nname = "E"\npolar = 10\n'
    edits = [("centre = [-10, 0]", "centre = [-30, 0]"), ("[cam.profile]", "base_radius = 30\n\n[cam.profile]"),
             ('find = ["h"', 'find = ["delta@E-Z"')]
    got = []
    for old, new in edits:
        scene = tmp_path / "cam.toml"
        scene.write_text(base.replace(old, new, 1))
        got.append(run_cli("check", str(scene))[2].strip())
    assert got == documented


def test_steps_say_the_inversion_with_its_numbers() -> None:
    code, out, err = run_cli("steps", str(SCENES / "cam.eccentric_disc_oscillating.toml"))
    assert code == 0, err
    assert "pitch (theoretical) circle R + r_r = 35 mm" in out and "base circle r0 = 25 mm" in out
    assert "circle of the pivots a = 50 mm" in out and "δ_E = " in out and "read delta@E-F = " in out
    code, out, err = run_cli("steps", str(SCENES / "cam.given_profile_points.toml"))
    assert code == 0 and "through the 8 given points" in out, err


@pytest.mark.parametrize("contact, words", [
    ('name = "F"\npolar = 10\ndelta = 20', ("cam.contact[1].delta", "not both")),
    ('name = "E"\npolar = 10', ("cam.contact[1].name", "named twice")),
    ('name = "2E"\npolar = 10', ("cam.contact[1].name", "a contact's name")),
    ('name = "F"', ("cam.contact[1].polar", "missing")),
])
def test_a_bad_contact_is_refused(tmp_path: Path, contact: str, words: tuple[str, ...]) -> None:
    text = (SCENES / "cam.eccentric_disc_knife.toml").read_text()
    scene = tmp_path / "bad.toml"
    scene.write_text(text + '\n[[cam.contact]]\nname = "E"\npolar = 10\n\n[[cam.contact]]\n' + contact + "\n")
    assert_refused(run_cli("check", str(scene)), "bad.toml", *words)


def test_contact_given_by_cam_angle_reads_there(tmp_path: Path) -> None:
    text = (SCENES / "cam.eccentric_disc_knife.toml").read_text().replace('find = ["h"', 'find = ["s@K", "h"')
    scene = tmp_path / "k.toml"
    scene.write_text(text + '\n[[cam.contact]]\nname = "K"\ndelta = 90\n')
    v = values(check_json(scene))
    assert v["s@K"]["exact"] == pytest.approx(values(check_json(SCENES / "cam.eccentric_disc_knife.toml"))["s@90"]["exact"])


def test_a_point_so_far_out_that_the_chords_are_lost_is_refused(tmp_path: Path) -> None:
    # fuzz seeds 97/98: a point at 1e300 mm made the chord lengths stop increasing (scipy's ValueError)
    import tomllib

    scene = ROOT / "figures" / "scenes" / "cam.given_profile_points.toml"
    data = tomllib.loads(scene.read_text(encoding="utf-8"))
    pts = data["cam"]["profile"]["points"]
    text = scene.read_text(encoding="utf-8")
    first = f"[{pts[2][0]}, {pts[2][1]}]"
    assert first in text
    p = tmp_path / "far.toml"
    p.write_text(text.replace(first, f"[{pts[2][0]}, 1e300]", 1), encoding="utf-8")
    assert_refused(run_cli("check", str(p)), "far.toml", "cam.profile.points", "lost")
