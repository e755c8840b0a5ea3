"""The cam figures in textbook conventions, asserted on the primitives and the stream of draw calls."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from graphmech.mechanisms.cam import Contact, DiscCam, MotionProgram, OscillatingFollower, Segment, TranslatingFollower
from graphmech.mechanisms.motion import breakpoints, displacement
from graphmech.problems.cam.figures import cam_sheet, numbered_every, smooth_drawing
from graphmech.methods.cam_inversion import divisions, draw_profile
from graphmech.render.layout import item_box, layout_sheet
from graphmech.drawing.primitives import (Arrow, Circle, FixedPivot, Label, Panel, Polyline, Segment as Line, Sheet)
from graphmech.render.recording import RecordingBackend
from graphmech.render.sheet import dash_pieces, draw_sheet, panel_labels, panel_shapes
from graphmech.render.svg import render_svg
from graphmech.render.style import DEFAULT
from tests.conftest import SCENES, run_cli

MU_L, MU_S, MU_PHI, MU_V, MU_A = 0.001, 0.0005, math.radians(2.0), 0.0005, 0.0005
SCALES = {"l": MU_L, "s": MU_S, "phi": MU_PHI, "v": MU_V, "a": MU_A}
A3 = (420.0, 297.0)
ALL = ["profile", "displacement", "velocity", "acceleration"]


def reference_cam(contact: Contact = "roller", roller: float = 0.010, offset: float = 0.010) -> DiscCam:
    """cam.offset_roller_translating: e = +10, r0 = 30, r_r = 10, h = 16 mm; uniform rise 150°,
    dwell 30°, parabolic return 120°, dwell 60°; cam CCW."""
    program = MotionProgram(0.016, (Segment("rise", math.radians(150), "uniform"),
                                     Segment("dwell", math.radians(30)),
                                     Segment("return", math.radians(120), "parabolic"),
                                     Segment("dwell", math.radians(60))))
    return DiscCam(0.030, TranslatingFollower(offset, contact, roller), program, rotation=1, omega=1.0)


def drawn_at(cam: DiscCam, step_deg: float = 15.0):
    delta = divisions(cam, math.radians(step_deg), breakpoints(cam.program))
    return draw_profile(cam, delta, displacement(cam.program, delta))


def make(cam: DiscCam | None = None, show=ALL, scales=SCALES, **kw):
    cam = cam or reference_cam()
    drawn = drawn_at(cam)
    return cam, drawn, cam_sheet("cam", cam, drawn, scales, show, A3, **kw)


def panel(sheet: Sheet, name: str) -> Panel:
    return next(p for p in sheet.panels if p.name == name)


def record(sheet: Sheet) -> tuple:
    return draw_sheet(sheet, RecordingBackend(), on_warning=lambda w: None)


def group(calls: tuple, name: str) -> list:
    """The calls drawn inside the panel group whose name ends with ``name`` (its labels' groups
    included)."""
    out, depth = [], 0  # how deep inside that panel's group (0: outside)
    for c in calls:
        if c[0] == "begin_group":
            depth = depth + 1 if depth else int(c[1].endswith("-" + name))
        elif c[0] == "end_group":
            depth = max(depth - 1, 0)
        elif depth:
            out.append(c)
    return out


def numbers(p: Panel) -> list[str]:
    return [i.text for i in p.items if isinstance(i, Label) and i.text.isdigit()]


# ----------------------------------------------------------------------------- the primitive
def test_polyline_keeps_float_points_is_frozen_and_needs_two_finite_points():
    line = Polyline(np.array([[0, 0], [10, 0], [10, 5]]))
    assert line.points == ((0.0, 0.0), (10.0, 0.0), (10.0, 5.0)) and line.role == "result"
    with pytest.raises(dataclasses.FrozenInstanceError):
        line.closed = True  # type: ignore[misc]
    with pytest.raises(ValueError):
        Polyline(((0.0, 0.0),))
    with pytest.raises(ValueError):
        Polyline(((0.0, 0.0), (math.nan, 1.0)))


def test_polyline_is_one_unfilled_backend_polyline_and_has_its_box():
    pts = ((0.0, 0.0), (30.0, 0.0), (30.0, 20.0))
    sheet = Sheet("", (Panel("p", "", (Polyline(pts, "result", closed=True),)),))
    calls = record(sheet)
    [poly] = [c for c in calls if c[0] == "polyline"]
    lay = layout_sheet(sheet, DEFAULT, [[]]).panels[0]
    assert poly[1] == tuple(lay.to_page(p) for p in pts) and poly[2:] == ("result", True, False)
    w = DEFAULT.result.width / 2
    assert item_box(Polyline(pts)) == pytest.approx((-w, -w, 30.0 + w, 20.0 + w))


def test_dashed_polyline_is_cut_into_dashes_that_follow_the_curve_with_the_pens_pattern():
    square = ((0.0, 0.0), (20.0, 0.0), (20.0, 20.0), (0.0, 20.0))
    on, off = DEFAULT.construction.dash
    pieces = dash_pieces(square, True, (on, off))
    lengths = [sum(math.dist(a, b) for a, b in zip(d[:-1], d[1:])) for d in pieces]
    assert all(length == pytest.approx(on) for length in lengths[:-1]) and lengths[-1] <= on + 1e-9
    assert sum(lengths) == pytest.approx(80.0 * on / (on + off), abs=on)
    assert any(len(d) == 3 for d in pieces)  # a dash turns the corner with the curve
    shapes = panel_shapes(Panel("p", "", (Polyline(square, "construction", closed=True, dashed=True),)))
    assert len(shapes) == len(pieces) and all(not s.closed and not s.filled for s in shapes)


# ----------------------------------------------------------------------------- the profile
def test_base_and_offset_circles_and_the_centre_lines_through_o_are_thin_dash_dot():
    cam, drawn, sheet = make()
    items = panel(sheet, "profile").items
    circles = [i for i in items if isinstance(i, Circle) and i.center == (0.0, 0.0)]
    assert [c.r for c in circles] == [pytest.approx(0.030 / MU_L), pytest.approx(0.010 / MU_L)]  # r0, e
    assert all(c.role == "construction" and c.dashdot and not c.dashed for c in circles)
    centre = [i for i in items if isinstance(i, Line) and i.dashdot]
    assert sorted((c.p0, c.p1) for c in centre) == sorted([((-centre[0].p1[0], 0.0), (centre[0].p1[0], 0.0)),
                                                           ((0.0, -centre[0].p1[0]), (0.0, centre[0].p1[0]))])
    reach = max(np.hypot(*smooth_drawing(cam, drawn, MU_L).actual.T)) / MU_L
    assert centre[0].p1[0] == pytest.approx(reach + 4.0)  # just past the working profile


def test_one_number_per_division_at_the_outer_end_of_its_line():
    cam, drawn, sheet = make(show=["profile"])
    prof = panel(sheet, "profile")
    assert numbers(prof) == [str(k) for k in range(len(drawn.delta))] == [str(k) for k in range(24)]
    lines = [i for i in prof.items if isinstance(i, Line) and i.role == "construction"]
    for k in range(len(drawn.delta)):  # line k: from its foot K_k on the offset circle past B_k
        label = next(i for i in prof.items if isinstance(i, Label) and i.text == str(k))
        line = next(s for s in lines if s.p1 == label.anchor)
        assert math.hypot(*line.p0) == pytest.approx(0.010 / MU_L)
        b = drawn.pitch[k] / MU_L
        assert math.dist(line.p0, b) + math.dist(b, line.p1) == pytest.approx(math.dist(line.p0, line.p1))
        assert math.dist(b, line.p1) == pytest.approx(0.010 / MU_L + 5.0)  # past the roller circle


def test_working_profile_is_the_inversions_envelope_drawn_smooth_at_mu_l():
    cam, drawn, sheet = make(show=["profile"])
    [work] = [i for i in panel(sheet, "profile").items if isinstance(i, Polyline) and i.role == "result"]
    assert work.closed and not work.dashed
    fine = smooth_drawing(cam, drawn, MU_L)
    # the same inversion at 1° (and the joints): 360 divisions, not the 24 numbered ones
    assert len(fine.delta) == 360 and np.max(np.diff(fine.delta)) <= math.radians(1.0) + 1e-12
    np.testing.assert_array_equal(np.array(work.points), fine.actual / MU_L)
    chords = np.hypot(*np.diff(np.array(work.points), axis=0).T)
    assert np.max(chords) < 1.0 and len(work.points) > 300  # no chords between the 15° points
    # the smooth profile is the rollers' envelope: every point r_r from the pitch curve
    gap = np.min(np.hypot(*(fine.actual[:, None, :] - fine.pitch[None, :, :]).transpose(2, 0, 1)), axis=1)
    np.testing.assert_allclose(gap, 0.010, rtol=2e-4)
    # on the page: one closed result polyline, the same points translated and flipped
    calls = group(record(sheet), "profile")
    [poly] = [c for c in calls if c[0] == "polyline" and c[2] == "result" and c[3]]
    page = np.array(poly[1])
    model = np.array(work.points) * [1.0, -1.0]
    np.testing.assert_allclose(page - page[0], model - model[0], atol=1e-9)


def test_pitch_curve_is_thin_dash_dot_smooth_through_the_pitch_points_drawn_as_dots_for_a_roller():
    cam, drawn, sheet = make(show=["profile"])
    items = panel(sheet, "profile").items
    [pitch] = [i for i in items if isinstance(i, Polyline) and i.role == "construction"]
    assert pitch.closed and pitch.dashdot and not pitch.dashed
    np.testing.assert_array_equal(np.array(pitch.points), smooth_drawing(cam, drawn, MU_L).pitch / MU_L)
    on_curve = {tuple(np.round(p, 9)) for p in np.array(pitch.points)}
    assert all(tuple(np.round(b, 9)) in on_curve for b in drawn.pitch / MU_L)  # B_k are its points
    dots = [i.center for i in items if isinstance(i, Circle) and i.role == "result" and i.r < 0.5]
    np.testing.assert_allclose(np.array(dots), drawn.pitch / MU_L)  # a solid dot at each B_k


def roller_circle_calls(calls: tuple, r: float) -> list:
    return [c for c in calls if c[0] == "circle" and c[3] == "construction" and c[2] == pytest.approx(r)]


def test_roller_circles_at_every_pitch_point_unless_switched_off():
    cam, drawn, sheet = make(show=["profile"])
    r = 0.010 / MU_L
    assert len(roller_circle_calls(group(record(sheet), "profile"), r)) == 24
    centres = [i.center for i in panel(sheet, "profile").items  # (the offset circle about O is 10 mm too)
               if isinstance(i, Circle) and i.role == "construction" and i.r == pytest.approx(r) and not i.dashdot]
    np.testing.assert_allclose(np.array(centres), drawn.pitch / MU_L)
    _, _, bare = make(show=["profile"], roller_circles=False)
    calls = group(record(bare), "profile")
    assert roller_circle_calls(calls, r) == []
    assert [c for c in calls if c[0] == "circle" and c[3] == "construction"] == []  # r0, e: dash-dot pieces


def test_knife_edge_follower_draws_no_roller_circles_and_its_pitch_curve_is_the_profile():
    cam, drawn, sheet = make(reference_cam("knife", 0.0), show=["profile"])
    calls = group(record(sheet), "profile")
    assert [c for c in calls if c[0] == "circle" and not c[4] and c[3] in ("construction", "given")] == []
    curves = [i for i in panel(sheet, "profile").items if isinstance(i, Polyline)]
    assert len(curves) == 1 and curves[0].role == "result" and not (curves[0].dashed or curves[0].dashdot)
    np.testing.assert_array_equal(np.array(curves[0].points), smooth_drawing(cam, drawn, MU_L).pitch / MU_L)


def test_offset_circle_is_thin_dash_dot_and_omega_turns_with_the_cam():
    cam, _, sheet = make(show=["profile"])
    items = panel(sheet, "profile").items
    [offset] = [i for i in items if isinstance(i, Circle) and i.center == (0.0, 0.0) and i.r < 20.0]
    assert offset.role == "construction" and offset.dashdot and offset.r == pytest.approx(10.0)
    arc = next(i for i in items if type(i).__name__ == "ArcArrow")
    assert arc.sweep > 0  # CCW cam
    _, _, cw = make(dataclasses.replace(cam, rotation=-1), show=["profile"])
    assert next(i for i in panel(cw, "profile").items if type(i).__name__ == "ArcArrow").sweep < 0
    assert {"O", "ω"} <= {i.text for i in items if isinstance(i, Label)}
    assert panel(sheet, "profile").notes == ("μ_{l} = 0.001 m/mm", "r_{0} = 30 mm, e = 10 mm, r_{r} = 10 mm; "
                                             "ω counter-clockwise")
    assert panel(sheet, "profile").scales == (("l", MU_L),)


def test_the_follower_stands_at_division_0_with_its_roller():
    cam, drawn, sheet = make(show=["profile"])
    items = panel(sheet, "profile").items
    b0 = tuple(drawn.pitch[0] / MU_L)
    assert any(isinstance(i, Circle) and i.role == "given" and i.center == b0 and i.r == pytest.approx(10.0)
               for i in items)
    stem = next(i for i in items if isinstance(i, Line) and i.role == "given" and i.p0 == b0)
    assert stem.p1[0] == pytest.approx(b0[0]) and stem.p1[1] > b0[1]  # up along the axis x = e


def test_oscillating_follower_arms_from_the_pivot_circle():
    program = MotionProgram(math.radians(25), (Segment("rise", math.pi, "cosine"), Segment("return", math.pi, "sine")))
    cam = DiscCam(0.025, OscillatingFollower(0.055, 0.05, "roller", 0.008), program, rotation=1)
    scales = {"l": 0.001, "s": math.radians(0.5), "phi": MU_PHI}
    _, drawn, sheet = make(cam, show=["profile", "displacement"], scales=scales)
    items = panel(sheet, "profile").items
    arms = [i for i in items if isinstance(i, Line) and i.role == "construction"
            and math.hypot(*i.p0) == pytest.approx(55.0)]
    assert len(arms) == len(drawn.delta)
    assert all(math.dist(a.p0, a.p1) == pytest.approx(50.0) for a in arms)
    assert sum(isinstance(i, FixedPivot) for i in items) == 1
    # the swing's scale in degrees per mm, as the scene states it, and its key for the scale bar
    assert panel(sheet, "displacement").notes == ("μ_{ψ} = 0.5 °/mm", "μ_{φ} = 2 °/mm")
    assert panel(sheet, "displacement").scales == (("psi", math.radians(0.5)), ("phi", MU_PHI))
    assert "l_{OA} = 55 mm, l_{AB} = 50 mm" in panel(sheet, "profile").notes[1]


def test_marks_draw_the_largest_pressure_angle_and_the_undercut():
    marks = {"alpha_max_at": math.radians(240.0), "alpha_max": math.radians(34.86452563886296),
             "undercut_at": [math.radians(150.0)]}
    cam, drawn, sheet = make(show=["profile"], marks=marks)
    items = panel(sheet, "profile").items
    texts = [i.text for i in items if isinstance(i, Label)]
    assert "α_{max} = 34.86°" in texts and "undercut" in texts
    b16 = tuple(drawn.pitch[16] / MU_L)
    thin = [i for i in items if isinstance(i, Line) and i.role == "label" and i.p0 == b16]
    assert len(thin) == 2  # the normal and the follower's direction
    (ax, ay), (bx, by) = (np.subtract(s.p1, s.p0) for s in thin)
    drawn_angle = math.degrees(math.acos((ax * bx + ay * by) / math.hypot(ax, ay) / math.hypot(bx, by)))
    assert drawn_angle == pytest.approx(math.degrees(drawn.pressure_angle[16]), abs=1e-9)
    assert drawn_angle == pytest.approx(34.86, abs=3.0)  # read off 15° chords at the parabolic law's knot


# ----------------------------------------------------------------------------- the diagrams
def test_displacement_curve_reaches_h_over_mu_s_and_its_ordinates_stand_at_the_divisions():
    cam, drawn, sheet = make()
    disp = panel(sheet, "displacement")
    curves = [i for i in disp.items if isinstance(i, Polyline) and i.role == "result"]
    assert max(y for c in curves for _, y in c.points) == pytest.approx(0.016 / MU_S)
    assert min(y for c in curves for _, y in c.points) == pytest.approx(0.0, abs=1e-12)
    ordinates = sorted((s.p0[0], s.p1[1]) for s in disp.items if isinstance(s, Line) and s.role == "construction")
    expect = [(d / MU_PHI, s / MU_S) for d, s in zip(drawn.delta, displacement(cam.program, drawn.delta)) if s > 0]
    np.testing.assert_allclose(np.asarray(ordinates, dtype=float), np.asarray(expect, dtype=float), rtol=1e-6, atol=1e-12)
    assert numbers(disp) == [str(k) for k in range(24)]
    # 30° is 15 mm at 2 °/mm: room for the angle only
    assert {"rise 150°", "30°", "return 120°", "dwell 60°"} <= {i.text for i in disp.items if isinstance(i, Label)}
    assert disp.notes == ("μ_{s} = 0.0005 m/mm", "μ_{φ} = 2 °/mm")
    assert disp.scales == (("s", MU_S), ("phi", MU_PHI))
    # on the page: the curve's highest point is 32 mm above the δ axis
    calls = group(record(sheet), "displacement")
    axis = next(c for c in calls if c[0] == "line" and c[3] == "label" and c[1][1] == c[2][1])
    top = min(y for c in calls if c[0] == "polyline" and c[2] == "result" and not c[3] for _, y in c[1])
    assert axis[1][1] - top == pytest.approx(32.0)


def test_uniform_rise_shows_plus_and_minus_infinity_at_its_two_ends():
    cam, _, sheet = make()
    acc = panel(sheet, "acceleration")
    marks = {i.text: i.anchor for i in acc.items if isinstance(i, Label) and "∞" in i.text}
    assert marks == {"+∞": (0.0, pytest.approx(10.0)), "−∞": (pytest.approx(150.0 / 2.0), pytest.approx(-10.0))}
    arrows = [i for i in acc.items if isinstance(i, Arrow) and i.role == "result"]
    assert sorted(a.p1 for a in arrows) == sorted(marks.values())
    assert all(a.p0 == (a.p1[0], 0.0) for a in arrows)
    texts = [c[1] for c in group(record(sheet), "acceleration") if c[0] == "text"]
    assert "+∞" in texts and "−∞" in texts
    assert acc.notes == ("μ_{a} = 0.0005 (m/s²)/mm", "μ_{φ} = 2 °/mm")
    assert acc.scales == (("a", MU_A), ("phi", MU_PHI))


def test_acceleration_jumps_of_the_parabolic_return_are_dashed_and_pieces_are_apart():
    cam, _, sheet = make()
    acc = panel(sheet, "acceleration")
    a = 4 * 0.016 / math.radians(120) ** 2 / MU_A  # the parabolic law's |a|, mm
    jumps = sorted((round(s.p0[0], 9), s.p0[1], s.p1[1]) for s in acc.items if isinstance(s, Line) and s.dashed)
    assert [j[0] for j in jumps] == pytest.approx([90.0, 120.0, 150.0])  # 180°, 240°, 300° at 2°/mm
    np.testing.assert_allclose([(j[1], j[2]) for j in jumps], [(0.0, -a), (-a, a), (a, 0.0)], rtol=1e-6, atol=1e-12)
    curves = [i for i in acc.items if isinstance(i, Polyline)]
    assert len(curves) == 5  # rise, dwell, two halves of the return, dwell
    vel = panel(sheet, "velocity")
    v_jumps = [s for s in vel.items if isinstance(s, Line) and s.dashed]
    assert [s.p0[0] for s in v_jumps] == pytest.approx([0.0, 75.0])  # the uniform rise's two ends
    assert v_jumps[1].p0[1] == pytest.approx(0.016 / math.radians(150) / MU_V) and v_jumps[1].p1[1] == 0.0


def test_dense_numbering_writes_every_second_number():
    x = np.column_stack([np.arange(24) * 3.0, np.zeros(24)])
    assert numbered_every([x], 24) == 2 and numbered_every([x * 2.0], 24) == 1
    scales = dict(SCALES, phi=math.radians(5.0))  # 15° = 3 mm on the δ axis
    _, _, sheet = make(show=["profile", "displacement"], scales=scales)
    assert numbers(panel(sheet, "profile")) == numbers(panel(sheet, "displacement")) \
        == [str(k) for k in range(0, 24, 2)]
    labels = panel_labels(panel(sheet, "displacement"), panel_shapes(panel(sheet, "displacement")))
    boxes = sorted(p.box for p in labels if p.label.text.isdigit())
    assert all(a[2] <= b[0] for a, b in zip(boxes[:-1], boxes[1:]))  # the numbers do not touch


# ----------------------------------------------------------------------------- the sheet
def test_panels_stand_in_the_books_order_two_a_row_and_bad_requests_are_refused():
    cam, drawn, sheet = make(show=["acceleration", "profile", "displacement"])
    assert [p.name for p in sheet.panels] == ["profile", "displacement", "acceleration"]
    assert [p.row for p in sheet.panels] == [0, 0, 1]  # three panels: profile and s–δ above
    _, _, two = make(show=["displacement", "profile"])
    assert [p.row for p in two.panels] == [0, 0]
    with pytest.raises(ValueError, match="jerk"):
        cam_sheet("", cam, drawn, SCALES, ["jerk"], A3)
    with pytest.raises(ValueError, match="phi"):
        cam_sheet("", cam, drawn, {"l": MU_L, "s": MU_S}, ["displacement"], A3)
    with pytest.raises(ValueError, match="profile"):
        cam_sheet("", cam, None, SCALES, ["profile"], A3)


def test_everything_drawn_is_finite():
    marks = {"alpha_max_at": math.radians(240.0), "alpha_max": 0.6, "undercut_at": [math.radians(150.0)]}
    for cam in (reference_cam(), reference_cam("knife", 0.0, 0.0), reference_cam("flat", 0.0, -0.01)):
        _, _, sheet = make(cam, marks=marks)
        for c in record(sheet):
            flat = [v for a in c[1:] for v in (a if isinstance(a, tuple) else (a,))]
            nums = [w for v in flat for w in (v if isinstance(v, tuple) else (v,)) if isinstance(w, float)]
            assert all(math.isfinite(w) for w in nums), c


def test_the_sheet_renders_to_the_same_svg_every_time():
    marks = {"alpha_max_at": math.radians(240.0), "alpha_max": 0.6085, "undercut_at": [math.radians(150.0)]}
    _, _, one = make(show=["profile", "displacement", "acceleration"], marks=marks)
    _, _, two = make(show=["profile", "displacement", "acceleration"], marks=marks)
    svg = render_svg(one, "gtest", on_warning=lambda w: None)
    assert svg == render_svg(two, "gtest", on_warning=lambda w: None)
    assert svg.startswith("<?xml") or svg.startswith("<svg")
    assert "nan" not in svg.lower() and "−∞" in svg and "max</tspan>" in svg


# ----------------------------------------------------------------------------- notation
def with_notation(src, dst_dir, notation: str):
    """A copy of the scene ``src`` lettered in ``notation`` ([page] notation), same file name."""
    text = src.read_text(encoding="utf-8")
    if "\n[page]\n" in text:
        text = text.replace("\n[page]\n", f'\n[page]\nnotation = "{notation}"\n', 1)
    else:
        text += f'\n[page]\nnotation = "{notation}"\n'
    dst_dir.mkdir(exist_ok=True)
    out = dst_dir / src.name
    out.write_text(text, encoding="utf-8")
    return out


CAPTIONS = {"en": ("Cam profile by inversion", "Displacement diagram", "Acceleration diagram"),
            "zh": ("凸轮轮廓曲线", "位移线图", "加速度线图"),
            "ru": ("профиль кулачка", "график перемещений", "график ускорений")}


@pytest.mark.parametrize("name", sorted(p.stem for p in SCENES.glob("cam.*.toml")))
def test_each_reference_cam_scene_is_lettered_in_zh_and_ru_and_checks_the_same(tmp_path, name):
    src = SCENES / f"{name}.toml"
    shown: dict[str, str] = {}
    checked: dict[str, str] = {}
    for notation in ("en", "zh", "ru"):
        scene = with_notation(src, tmp_path / notation, notation)
        code, out, err = run_cli("render", str(scene), "-o", str(tmp_path / f"{notation}.svg"))
        assert code == 0, err
        shown[notation] = (tmp_path / f"{notation}.svg").read_text(encoding="utf-8")
        code, checked[notation], err = run_cli("check", str(scene))
        assert code in (0, 1), err
    assert checked["zh"] == checked["ru"] == checked["en"]  # drawn words only: check reads the same
    for notation, words in CAPTIONS.items():
        present = [w for w in words if w in shown[notation]]
        assert present, (notation, words)  # each scene shows a profile, an s–δ or an a–δ diagram
        for other in set(CAPTIONS) - {notation}:
            assert not any(w in shown[other] for w in present), (notation, other)
    # the segments under the s–δ axis are named in the book's words (where there is room)
    assert "推程" in shown["zh"] and ">rise " in shown["en"]
    assert ">rise " not in shown["zh"] + shown["ru"] and ">dwell " not in shown["zh"] + shown["ru"]
    if name.startswith("cam.offset_roller"):  # 150° at 2.5 °/mm: room for the Russian words too
        assert ">удаление 150°<" in shown["ru"] and ">近休止 60°<" in shown["zh"]


def test_every_composed_text_is_lettered_no_bare_underscore_and_at_least_3_5_mm():
    import re

    program = MotionProgram(math.radians(25), (Segment("rise", math.pi, "cosine"), Segment("return", math.pi, "sine")))
    rocker = DiscCam(0.025, OscillatingFollower(0.055, 0.05, "roller", 0.008), program, rotation=1)
    marks = {"alpha_max_at": math.radians(240.0), "alpha_max": 0.6085, "undercut_at": [math.radians(150.0)]}
    sheets = [make(marks=marks)[2], make(rocker, show=["profile", "displacement"],
                                         scales={"l": 0.001, "s": math.radians(0.5), "phi": MU_PHI})[2]]
    for sheet in sheets:
        for p in sheet.panels:
            texts = [p.title, *p.notes] + [i.text for i in p.items if isinstance(i, Label)]
            assert not [t for t in texts if re.search(r"_(?!\{)", t)], texts
            assert not [t for t in texts if re.search(r"\d\.\d{5}", t)], texts  # 4 significant figures
            assert min(i.size for i in p.items if isinstance(i, Label)) >= 3.5
