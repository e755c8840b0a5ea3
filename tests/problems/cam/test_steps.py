"""The construction protocol of a cam scene (graphmech/problems/cam/steps.py): the s–δ diagram,
the profile by inversion and what is read off it, in the book's order and in the scene's
notation, every number the one the check table (and so the drawing) has."""
from __future__ import annotations

import math
import re
import tomllib

import pytest

from graphmech.problems import check, steps
from graphmech.problems.protocol import num
from graphmech.scene import load_scene
from graphmech.scene import parse_scene as parse
from tests.conftest import ROOT, SCENES, run_cli

CAM_SCENES = ROOT / "tests" / "scenes" / "cam"


def parse_scene(text: str, source: str = "cam.toml"):
    return parse(tomllib.loads(text), source)


def _index(lines: list[str], text: str) -> int:
    found = [k for k, line in enumerate(lines) if text in line]
    assert found, (text, lines)
    return found[0]


def _has(line: str, number: str) -> bool:
    """``number`` stands in ``line`` as a whole number (not the head of a longer one)."""
    return re.search(rf"(?<![\d.]){re.escape(number)}(?![\d])", line) is not None


#: The text of the line each reading is in.
ANCHOR = {"alpha_max": "the largest: α_max", "alpha_max_at": "the largest: α_max", "rho_min_pitch": "ρ_min = ",
          "rho_min_pitch_at": "ρ_min = ", "rho_min_actual": "ρ_a,min = ", "profile_deviation": "departs from it",
          "h": "measure the stroke", "r0_min": "r₀,min = ", "v_max": "v_max = ", "a_max": "a_max = ",
          "j_max": "j_max = "}


def _anchor(name: str) -> str:
    base, _, at = name.partition("@")
    if base == "s":
        return f"(δ = {num(float(at))}°, "
    if base == "alpha":
        return f"(δ = {num(float(at))}°): measure α"
    return ANCHOR[base]


def _agrees(lines: list[str], rows: list) -> None:
    """Every row's reading is in the protocol with the check's numbers: the drawn length in mm and
    the value, both to the printed four significant figures."""
    for r in rows:
        anchor = f"{r.name[0]}_max is at δ = " if r.name in ("v_max_at", "a_max_at", "j_max_at") else _anchor(r.name)
        mine = [line for line in lines if anchor in line]
        assert mine, r.name
        line = mine[0]
        assert _has(line, num(r.graphical)), (r.name, r.graphical, line)
        if r.drawn_mm is not None and not r.name.startswith("j_"):  # no j–δ diagram: its "drawn" is the value at μ = 1
            assert _has(line, num(abs(r.drawn_mm))) and f"{num(abs(r.drawn_mm))} mm" in line, (r.name, r.drawn_mm, line)


def test_the_offset_roller_cam_is_protocolled_in_the_books_order():
    scene = load_scene(SCENES / "cam.offset_roller_translating-pos.toml")
    lines = steps(scene)
    order = [
        "choose μs = 0.0005 m/mm (as the scene gives it) and μφ = 2.5 °/mm (as the scene gives it) and draw the axes "
        "of the s–δ diagram",
        "along the δ axis lay off rise 150° = 60 mm, dwell 30° = 12 mm, return 120° = 48 mm, dwell 60° = 24 mm",
        "divide the δ axis every 15° (6 mm), the segments' joints among the divisions: 24 divisions, numbered 0 … 23",
        "at division 3 (δ = 45°, 18 mm along the axis) draw the ordinate 3′: s₃/μs = 0.0048/0.0005 = 9.6 mm "
        "(rise, uniform motion)",
        "at division 13 (δ = 195°, 78 mm along the axis) draw the ordinate 13′: s₁₃/μs = 0.0155/0.0005 = 31 mm "
        "(return, constant acceleration and deceleration)",
        "join 0′, 1′ … 23′ with a smooth curve: the s–δ diagram",
        "δ = 150°: the velocity jumps — a rigid impact",
        "measure the stroke: 32 mm: h = 32 × 0.0005 = 0.016 m",
        "choose μl = 0.001 m/mm (as the scene gives it); about O draw the base circle r₀/μl = 0.03/0.001 = 30 mm",
        "about O draw the offset circle e/μl = 0.01/0.001 = 10 mm; the follower's axis at the start is its tangent at "
        "K₀ (right of O, ∥ the y axis); it meets the base circle at B₀, 28.28 mm from K₀ (√(r₀² − e²))",
        "the cam turns counter-clockwise: keep it still and turn the follower the opposite way, −ω (clockwise)",
        "from K₀ divide the offset circle clockwise at the divisions' angles δₖ: K₁ … K₂₃",
        "position 1 (δ = 15°): on axis 1 lay off from the base circle C₁B₁ = s₁/μl = 0.0016/0.001 = 1.6 mm: B₁ "
        "(OB₁ = 31.51 mm)",
        "join B₀, B₁ … B₂₃ with a smooth curve: the pitch curve (theoretical profile)",
        "about each Bₖ draw the roller circle r_r/μl = 0.01/0.001 = 10 mm; the curve touching them all inside "
        "(their envelope) is the actual profile",
        "the pressure angle αₖ is the acute angle between them",
        "position 17 (δ = 255°): measure α₁₇ = 32.49°",
        "the largest: α_max = 32.49° in position 17 (δ = 255°) (read at 24 divisions of 15°)",
        "the circle through B₂₀, B₂₁, B₂₂ is the pitch curve's smallest convex one",
        "laid over the exact profile, the drawn one departs from it by at most 0.5481 mm",
    ]
    at = [_index(lines, text) for text in order]
    assert at == sorted(at), at
    assert lines[0] == order[0] and len(lines) == 92
    # one ordinate, one laid-off position and one pressure angle per division
    assert sum("draw the ordinate" in x for x in lines) == sum("lay off from the base circle" in x for x in lines) \
        == sum(": measure α" in x for x in lines) == 24


@pytest.mark.parametrize("name", ["cam.offset_roller_translating-pos", "cam.offset_roller_translating-neg",
                                  "cam.oscillating_roller", "cam.law_maxima-sine", "cam.law_maxima-parabolic"])
def test_every_number_read_is_the_check_tables(name):
    scene = load_scene(SCENES / f"{name}.toml")
    an = check(scene)[0]
    assert an.rows
    _agrees(steps(scene), an.rows)


def test_the_laid_off_lengths_are_the_drawings():
    # B_k is where the figure puts it: its distance from O is the drawn pitch point's, at μl
    scene = load_scene(SCENES / "cam.offset_roller_translating-neg.toml")
    an = check(scene)[0]
    lines = steps(scene)
    mu = an.scales["l"]
    for k, (x, y) in enumerate(an.drawn.pitch):
        line = next(x for x in lines if x.startswith(f"position {k} (δ = "))
        assert line.endswith(f"(OB{_sub(k)} = {num(math.hypot(x, y) / mu)} mm)"), line
        assert f"= {num(an.s[k] / mu)} mm: B{_sub(k)} " in line
    assert "left of O" in lines[_index(lines, "offset circle")]


def _sub(k: int) -> str:
    return str(k).translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))


def test_an_oscillating_follower_turns_its_pivot_and_lays_off_the_rocker_angle():
    lines = steps(load_scene(SCENES / "cam.oscillating_roller.toml"))
    assert "choose μψ = 0.5 °/mm (as the scene gives it)" in lines[0]
    psi0 = math.degrees(math.acos((55 ** 2 + 50 ** 2 - 25 ** 2) / (2 * 55 * 50)))
    assert lines[_index(lines, "meets the base circle at B₀")].endswith(f"ψ₀ = ∠OA₀B₀ = {num(psi0)}°")
    assert "from A₀ divide the pivot circle clockwise" in lines[_index(lines, "divide the pivot circle")]
    assert ("position 6 (δ = 90°): at A₆ lay off ∠OA₆B₆ = ψ₀ + ψ(6) = 27.01 + 12.5 = 39.51° (clockwise from A₆O) "
            "and A₆B₆ = 50 mm: B₆") in lines[_index(lines, "position 6 (δ = 90°)")]
    assert "measure the stroke: 50 mm: ψ_max = 50 × 0.5 = 25° = 0.4363 rad" in lines
    assert "along ⟂ AₖBₖ" not in " ".join(lines) and "(⟂ AₖBₖ)" in lines[_index(lines, "pressure angle αₖ")]


def test_a_scene_of_the_diagrams_alone_has_no_inversion():
    lines = steps(load_scene(SCENES / "cam.law_maxima-sine.toml"))
    assert not any("base circle" in x for x in lines)
    assert "choose μv = 0.05 (m/s)/mm (chosen to fit the page) and draw the v–δ diagram" in lines[_index(lines, "v–δ")]
    v = lines[_index(lines, "v_max = ")]
    assert v.startswith("the largest ordinate of the v–δ diagram is at division 6: measure 12.73 mm")
    assert lines[_index(lines, "v_max = ") + 1] == "v_max is at δ = 45°"


def test_what_is_asked_of_the_profile_is_read_off_it(tmp_path):
    text = (CAM_SCENES / "offset_roller.toml").read_text(encoding="utf-8").replace(
        'find = ["alpha_max", "alpha_max_at", "rho_min_pitch"]',
        'find = ["alpha@90", "rho_min_actual", "r0_min", "rho_min_pitch_at"]')
    scene = parse_scene(text)
    lines, rows = steps(scene), check(scene)[0].rows
    _agrees(lines, rows)
    assert any(x.startswith("redraw with trial base radii until α_max = [α] = 30°: r₀ = ") for x in lines)
    assert not any("the largest: α_max" in x for x in lines)  # not asked for


def test_a_flat_face_has_no_pressure_angle_and_envelopes_its_faces():
    lines = steps(load_scene(CAM_SCENES / "flat_translating.toml"))
    assert lines[_index(lines, "position 3 (δ = 45°)")].endswith("; through B₃ draw the face ⟂ axis 3")
    assert "the curve touching all the faces (their envelope) is the actual profile" in lines
    assert "from K₀ divide the offset circle counter-clockwise" in lines[_index(lines, "divide the offset circle")]
    face = steps(load_scene(CAM_SCENES / "oscillating_flat.toml"))
    assert "ψ₀ = arcsin(r₀/l_OA) = 22.02°" in face[_index(face, "the face at the start")]


def test_chinese_and_russian_wording():
    text = (SCENES / "cam.offset_roller_translating-pos.toml").read_text(encoding="utf-8")
    zh = steps(parse_scene(text.replace("[page]", '[page]\nnotation = "zh"'), "zh.toml"))
    assert zh[0] == "取μs = 0.0005 m/mm（题给）、μφ = 2.5 °/mm（题给），作s–δ位移线图的坐标轴"
    assert "推程150° = 60 mm、远休止30° = 12 mm、回程120° = 48 mm、近休止60° = 24 mm" in zh[1]
    assert "令凸轮静止，使推杆沿−ω方向（顺时针）反转" in zh[_index(zh, "凸轮逆时针转动")]
    assert zh[_index(zh, "位置1（δ = 15°）")] == \
        "位置1（δ = 15°）：在导路1上自基圆量取C₁B₁ = s₁/μl = 0.0016/0.001 = 1.6 mm，得B₁（OB₁ = 31.51 mm）"
    assert any(x.startswith("以理论廓线上各点Bₖ为圆心") and x.endswith("其内包络线即为凸轮的实际廓线") for x in zh)
    assert "最大压力角α_max = 32.49°，在位置17（δ = 255°）（按24等分、每份15°读取）" in zh
    ru = steps(parse_scene(text.replace("[page]", '[page]\nnotation = "ru"'), "ru.toml"))
    assert ru[0] == "выбираем μs = 0.0005 m/mm (задан) и μφ = 2.5 °/mm (задан) и проводим оси графика s–φ"
    assert any("по методу обращения движения останавливаем кулачок" in x for x in ru)
    assert "соединяем B₀, B₁ … B₂₃ плавной кривой: центровой (теоретический) профиль" in ru
    assert any(x.startswith("наибольший: α_max = 32.49° в положении 17 (φ = 255°)") for x in ru)
    assert len(zh) == len(ru) == 92


def test_the_cli_prints_it_numbered():
    code, out, err = run_cli("steps", str(SCENES / "cam.oscillating_roller.toml"))
    lines = out.splitlines()
    assert code == 0 and "Traceback" not in err
    assert [line.split(". ", 1)[0] for line in lines] == [str(k) for k in range(1, len(lines) + 1)]
    assert lines[0].startswith("1. choose μψ = 0.5 °/mm")
    assert lines[-1].startswith(f"{len(lines)}. the largest: α_max = ")


def test_a_clockwise_cam_reads_its_maxima_and_places_off_the_diagrams():
    text = (CAM_SCENES / "offset_roller.toml").read_text(encoding="utf-8").replace(
        'rotation = "ccw"', 'rotation = "cw"').replace(
        'find = ["alpha_max", "alpha_max_at", "rho_min_pitch"]', 'find = ["alpha@90", "v_max", "a_max_at", "j_max"]')
    scene = parse_scene(text)
    lines, rows = steps(scene), check(scene)[0].rows
    _agrees(lines, rows)
    assert "the cam turns clockwise: keep it still and turn the follower the opposite way, −ω (counter-clockwise)" in lines
    # a place asked for without its maximum still names what it is the place of
    assert any(x.startswith("a_max is at δ = ") for x in lines)
    assert _index(lines, "a_max is at") > _index(lines, "the a–δ diagram")


def _notation(path, notation: str):
    text = path.read_text(encoding="utf-8")
    return steps(parse_scene(text.replace("[page]", f'[page]\nnotation = "{notation}"'), f"{notation}.toml"))


def test_the_forces_are_one_step_naming_r12_culmanns_points_and_the_polygon_with_the_checks_numbers():
    scene_path = SCENES / "cam.follower_forces_friction.toml"
    lines = steps(load_scene(scene_path))
    rows = {r.name: r for r in check(load_scene(scene_path))[0].rows}
    mine = [line for line in lines if "force polygon" in line]
    assert len(mine) == 1 and mine[0] is lines[-1]  # after the profile's readings, as the book works
    line = mine[0]
    for words in ("δ = 60°", "Q = 500 N", "R₁₂ at K along the common normal n–n leant by φ = 6°",
                  "φ′ = atan f = 8.531°", "Q and R₁₂ meet at P, R′₃₂ and R″₃₂ at S", "μF = 10 N/mm", "Q = 50 mm"):
        assert words in line, words
    for name, sym in (("R_K", "R₁₂"), ("R_B1", "R′₃₂"), ("R_B2", "R″₃₂")):
        r = rows[name]
        assert f"{sym} = {num(r.drawn_mm)} mm = {num(r.graphical)} N" in line
    assert line.endswith(f"= {num(rows['M_1'].graphical)} N·m")
    zh, ru = (_notation(scene_path, n)[-1] for n in ("zh", "ru"))
    assert "力多边形" in zh and "R₁₂" in zh and f"{num(rows['R_K'].graphical)} N" in zh
    assert "многоугольник сил" in ru and "Кульман" in ru and f"{num(rows['R_K'].graphical)} N" in ru


def test_the_coordinates_table_is_one_step_with_its_first_row_as_the_check_gives_it():
    scene_path = SCENES / "cam.offset_roller_translating-table.toml"
    lines = steps(load_scene(scene_path))
    first = check(load_scene(scene_path))[2]["divisions"][0]
    mine = [line for line in lines if "tabulate the working profile" in line]
    assert len(mine) == 1
    assert "each of the 24 divisions" in mine[0] and "θ from +x counter-clockwise" in mine[0]
    assert (f"division 0: x = {num(first['x'] * 1e3)} mm, y = {num(first['y'] * 1e3)} mm, "
            f"r = {num(first['r'] * 1e3)} mm, θ = {num(first['theta_deg'])}°") in mine[0]
    assert not any("tabulate" in line for line in steps(load_scene(SCENES / "cam.offset_roller_translating-pos.toml")))
    assert "实际廓线" in _notation(scene_path, "zh")[-1]
    assert "координат действительного профиля" in _notation(scene_path, "ru")[-1]
