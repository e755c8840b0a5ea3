"""The gear-train figures (graphmech/problems/trains/figures.py): the schematic in the book's
symbols and the velocity diagram, for scenes built as TrainScene objects (the conveyor's planetary
reducer, the electric screwdriver's two stages, the closed differential, an ordinary three-stage
chain, a worm and bevel spatial train); what each panel holds, the arrows of rotation against the
speeds' signs, the velocity diagram's ω against the exact solve, byte-identical output."""
from __future__ import annotations

import math
import warnings

import pytest

from graphmech.drawing.primitives import (
    ArcArrow,
    Arrow,
    Circle,
    GuideLine,
    Label,
    Polyline,
    Segment,
)
from graphmech.errors import NoSolution, OutOfDomain
from graphmech.exact.gear_train import solve
from graphmech.mechanisms.gear_train import Mesh, rpm
from graphmech.methods.train_layout import layout
from graphmech.problems.reader import Page, Scene
from graphmech.problems.trains.diagram import SLOT_MM, drawn, train_velocity
from graphmech.problems.trains.figures import CLIP_MM, schematic, train_sheet
from graphmech.problems.trains.scene import TrainScene
from graphmech.render.sheet import LayoutWarning
from graphmech.render.svg import render_svg
from graphmech.scene import load_scene
from tests.conftest import ROOT, reference_problem
from tests.conftest import SCENES as SCENE_DIR
from tests.methods.test_train_velocity import (
    bank,
    closed_differential,
    screwdriver,
    train,
)


def scene(problem: TrainScene, title: str, find=(), show=(), scales=None) -> Scene[TrainScene]:
    return Scene("t.toml", title, tuple(show), tuple(find), dict(scales or {}), kind="trains", problem=problem)


def conveyor() -> Scene[TrainScene]:
    t, _ = bank()["conveyor_planetary_n4"]
    return scene(TrainScene(t, module=2e-3, module_stated=True, axes={m.name: "+x" for m in t.members},
                            sides={0: 1, 1: 1, 2: 1}, solved_z={"3": 74}),
                 "Conveyor planetary reducer", ("n4", "nH", "i14"))


def screwdriver_scene() -> Scene[TrainScene]:
    return scene(TrainScene(screwdriver(), module=0.5e-3), "Electric screwdriver", ("i1H2", "nH2"))


def closed_differential_scene() -> Scene[TrainScene]:
    return scene(TrainScene(closed_differential(), module=2e-3, sides={2: -1, 3: -1, 6: -1, 7: -1}),
                 "Closed differential", ("n3", "n5"))


def chain() -> Scene[TrainScene]:
    # 1 (20) – 2 (40) | 2′ (18) – 3 (36) | 3′ (20) – 4 (50): three external stages on fixed axes
    t = train({"1": None, "2": None, "3": None, "4": None},
              [("1", 20, "1"), ("2", 40, "2"), ("2'", 18, "2"), ("3", 36, "3"), ("3'", 20, "3"), ("4", 50, "4")],
              [("1", "2"), ("2'", "3"), ("3'", "4")], inputs={"1": rpm(960.0)})
    return scene(TrainScene(t, module=2e-3, sides={2: -1}), "Three-stage reducer", ("i14", "n4"))


def worm_bevel() -> Scene[TrainScene]:
    # worm 1 (axis +x, 2 starts, right-hand) drives the wheel 2 (axis +z, 40) below it; the bevel
    # pinion 2′ (20) on the wheel's shaft drives the bevel 3 (axis +y, 30) below its axis;
    # the signs as the reader resolves them from the arrows (docs: the pitch points move together)
    t = train({"1": None, "2": None, "3": None}, [("1", 2, "1"), ("2", 40, "2"), ("2'", 20, "2"), ("3", 30, "3")],
              [Mesh("1", "2", "worm", +1), Mesh("2'", "3", "bevel", +1)], inputs={"1": rpm(1450.0)})
    return scene(TrainScene(t, module=2e-3, axes={"1": "+x", "2": "+z", "3": "+y"},
                            towards={0: ("-y", "+y"), 1: ("-y", "+z")}, hands={0: "right"}),
                 "Worm and bevel train", ("n3",))


SCENES = {"conveyor": conveyor, "screwdriver": screwdriver_scene, "closed_differential": closed_differential_scene,
          "chain": chain, "worm_bevel": worm_bevel}


def panels(sc):
    sheet, warnings = train_sheet(sc, ("footer",))
    return {p.name: p for p in sheet.panels}, warnings


def labels(panel):
    return [it.text for it in panel.items if isinstance(it, Label)]


def arrow_agrees(a, w, axis):
    """A straight arrow shows where the near side moves: ω·û × ẑ (down for +x, right for +y); a
    curved one turns counter-clockwise for a positive speed toward the viewer."""
    if isinstance(a, ArcArrow):
        return (a.sweep > 0) == (w * axis[2] > 0)
    d = (a.p1[0] - a.p0[0], a.p1[1] - a.p0[1])
    want = (axis[1] * w, -axis[0] * w)  # (ω·û) × ẑ
    return d[0] * want[0] + d[1] * want[1] > 0 and abs(d[0] * want[1] - d[1] * want[0]) < 1e-9


@pytest.mark.parametrize("name", list(SCENES))
def test_every_moving_member_has_its_arrow_of_rotation(name):
    sc = SCENES[name]()
    t = sc.problem.train
    w = solve(t).omega
    lay = layout(t, sc.problem.module, sc.problem.axes, sc.problem.sides, sc.problem.towards, sc.problem.coaxial)
    sch = schematic(lay, 0.002, w, list(t.inputs))
    moving = {m for m, v in w.items() if v != 0.0 and m not in t.fixed}
    assert set(sch.arrows) == moving
    for m, a in sch.arrows.items():
        assert arrow_agrees(a, w[m], lay.axis[m]), m


def test_an_arrow_follows_a_reversed_axis():
    sc = conveyor()
    t = sc.problem.train
    w = solve(t).omega
    plain = schematic(layout(t, 2e-3), 0.002, w).arrows["4"]
    flipped = schematic(layout(t, 2e-3, axes={"4": "-x"}), 0.002, {**w, "4": -w["4"]}).arrows["4"]
    assert isinstance(plain, Arrow) and isinstance(flipped, Arrow)
    # the same motion, the speed read along −x: the same arrow
    assert (plain.p1[1] - plain.p0[1]) == pytest.approx(flipped.p1[1] - flipped.p0[1]) and plain.p1[1] < plain.p0[1]


def test_the_conveyors_sheet():
    ps, warnings = panels(conveyor())
    assert list(ps) == ["schematic", "velocity"] and warnings == []
    sch, vel = ps["schematic"], ps["velocity"]
    assert {"1", "2", "2′", "3", "4", "H"} <= set(labels(sch))
    assert sch.notes[0] == "μ_{l} = 0.002 m/mm" and sch.scales == (("l", 0.002),)
    # the fixed ring 3 is hatched to the frame at both rims; the input 1 in one bearing at the left,
    # H and the hollow shaft of 4 in one each at the right: three bearings on the hatched frame
    guides = [it for it in sch.items if isinstance(it, GuideLine)]
    assert len(guides) == 2 + 3
    # the gears: 1, 2, 2′ rectangles and the planet 2–2′ again below the axis, the rings' rims (two
    # each), the three bearings' boxes
    closed = [it for it in sch.items if isinstance(it, Polyline) and it.closed]
    assert len(closed) == 3 + 2 + 4 + 3
    # the velocity diagram: every moving member's line labelled, the pitch points, the pole and H
    assert {"1", "2", "4", "H", "O", "P_{12}", "P_{23}", "P_{2′4}"} <= set(labels(vel))
    # μv coarsened so that the fast sun's ray stays on the sheet at H = 10 mm (60.74 mm at 0.05)
    assert vel.notes[:3] == ("μ_{l} = 0.002 m/mm", "μ_{v} = 0.1 (m/s)/mm", "H = 10 mm, μ_{ω} = 5 (rad/s)/mm")
    assert vel.notes[3] == "ℓ_{1} = 30.37 mm, ω_{1} = 151.8 rad/s; ℓ_{2} = −4.745 mm, ω_{2} = −23.73 rad/s"
    assert vel.notes[4] == "ℓ_{4} = 0.1318 mm, ω_{4} = 0.659 rad/s; ℓ_{H} = 3.615 mm, ω_{H} = 18.08 rad/s"


@pytest.mark.parametrize("name", ["conveyor", "screwdriver", "closed_differential", "chain"])
def test_the_velocity_diagram_reads_the_exact_speeds(name):
    sc = SCENES[name]()
    t = sc.problem.train
    lay = layout(t, sc.problem.module, sc.problem.axes, sc.problem.sides, sc.problem.towards, sc.problem.coaxial,
                 gap=SLOT_MM * 0.002)
    d = train_velocity(lay, sc, 0.002)
    exact = solve(t).omega
    top = max(abs(v) for v in exact.values())
    assert max(abs(d.omega(m) - v) for m, v in exact.items()) <= 1e-9 * top
    assert d.H >= 10.0 and d.mu_omega == pytest.approx(d.mu_v / (d.mu_l * d.H), rel=1e-15)


def test_the_scenes_scales_and_pole_distance_are_kept():
    sc = conveyor()
    sc = Scene(sc.source, sc.title, sc.show, sc.find, {"l": 0.0025, "v": 0.1}, kind="trains",
               problem=TrainScene(sc.problem.train, module=2e-3, pole_distance=25.0))
    vel = panels(sc)[0]["velocity"]
    assert vel.notes[:3] == ("μ_{l} = 0.0025 m/mm", "μ_{v} = 0.1 (m/s)/mm", "H = 25 mm, μ_{ω} = 1.6 (rad/s)/mm")
    sc = Scene(sc.source, sc.title, ("velocity",), sc.find, {"l": 0.0025, "v": 0.1, "omega": 4.0}, kind="trains",
               problem=TrainScene(sc.problem.train, module=2e-3))
    ps, _ = panels(sc)
    assert list(ps) == ["velocity"] and ps["velocity"].notes[2] == "H = 10 mm, μ_{ω} = 4 (rad/s)/mm"


def test_the_closed_differential_says_its_trial_line():
    vel = panels(closed_differential_scene())[0]["velocity"]
    assert vel.notes[-1] == "the loop closed by false position (trial line 2)"
    assert {"P_{12}", "P_{16}", "P_{3′4}", "P_{3′7}"} <= set(labels(vel))


def test_the_screwdrivers_two_carriers():
    sch = panels(screwdriver_scene())[0]["schematic"]
    assert {"1", "2", "3", "4", "5", "6", "H1", "H2"} <= set(labels(sch))
    # the two fixed rings hatched at both rims, the input and the output each in a bearing
    assert len([it for it in sch.items if isinstance(it, GuideLine)]) == 4 + 2


def test_the_chains_shafts_each_in_two_bearings():
    sch = panels(chain())[0]["schematic"]
    assert len([it for it in sch.items if isinstance(it, GuideLine)]) == 4 * 2
    assert {"1", "2", "2′", "3", "3′", "4"} <= set(labels(sch))
    # four gears' rectangles and eight bearings' boxes; the pitch points marked dash-dot
    assert len([it for it in sch.items if isinstance(it, Polyline) and it.closed]) == 6 + 8
    assert len([it for it in sch.items if isinstance(it, Segment) and it.dashdot]) == 3


def test_a_spatial_train_has_the_schematic_only():
    ps, warnings = panels(worm_bevel())
    assert list(ps) == ["schematic"] and warnings == []
    sc = worm_bevel()
    sc = Scene(sc.source, sc.title, ("schematic", "velocity"), sc.find, {}, kind="trains", problem=sc.problem)
    ps, warnings = panels(sc)
    assert list(ps) == ["schematic"] and warnings == [
        "the velocity diagram is drawn for trains whose axes are all parallel: not drawn for this spatial train"]
    assert ps["schematic"].notes[-1] == "a spatial train: no velocity diagram (its axes are not parallel)"
    sch = ps["schematic"]
    # the worm: a box and five thread lines; the wheel and the bevel 2′ seen along their axis:
    # circles; the bevel 3 a trapezoid
    threads = [it for it in sch.items if isinstance(it, Segment) and it.role == "construction" and not it.dashdot]
    assert len(threads) == 5
    # a right-hand worm's near threads fall to the right: down as x grows
    assert all((s.p1[0] - s.p0[0]) * (s.p1[1] - s.p0[1]) < 0 for s in threads)
    assert len([it for it in sch.items if isinstance(it, Circle) and it.r > 5.0]) == 2
    trapezoids = [it for it in sch.items if isinstance(it, Polyline) and it.closed and len(it.points) == 4
                  and abs(abs(it.points[0][0] - it.points[3][0]) - abs(it.points[1][0] - it.points[2][0])) > 1.0]
    assert len(trapezoids) == 1


def test_unknown_panels_are_refused():
    sc = conveyor()
    sc = Scene(sc.source, sc.title, ("schematic", "polygon"), sc.find, {}, kind="trains", problem=sc.problem)
    with pytest.raises(OutOfDomain, match="unknown panel"):
        panels(sc)


@pytest.mark.parametrize("name", list(SCENES))
def test_the_svg_is_byte_identical_twice(name):
    # (the closed differential built here asks nothing, so every ray counts and its sheet runs a
    # little off A4: the renderer's warning says so, and is not what this test is about)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", LayoutWarning)
        a = render_svg(train_sheet(SCENES[name](), ("f",))[0], "gtest")
        b = render_svg(train_sheet(SCENES[name](), ("f",))[0], "gtest")
    assert a == b
    assert "<svg" in a and a.count("<line") > 10


def test_captions_in_the_scenes_notation():
    sc = conveyor()
    sc = Scene(sc.source, sc.title, (), sc.find, {}, page=Page(notation="zh"), kind="trains", problem=sc.problem)
    sheet, _ = train_sheet(sc, ())
    assert [p.title for p in sheet.panels] == ["轮系运动简图", "速度图"]
    assert sheet.panels[0].notes[1] == "轴向位置未按比例"


def test_a_train_that_is_not_coaxial_at_one_module_is_refused():
    # the bank's winch reducer (ysj10_8): z1 + z2 = 76 but z4 − z3 = 57 — its figure has two modules
    i = reference_problem("train.ysj10_8_winch_reducer")["inputs"]
    t = train({"1": None, "2": "7", "4": None, "7": None},
              [("1", i["z1"], "1"), ("2", i["z2"], "2"), ("3", i["z3"], "2"), ("4", i["z4"], "4"),
               ("7", i["z7"], "7")], [("1", "2"), ("3", "4", "internal")], ["7"], {"1": 1.0})
    with pytest.raises(NoSolution, match="the planet 2–3 is not coaxial: arms 38 mm and 28.5 mm"):
        train_sheet(scene(TrainScene(t, module=1e-3), "winch"), ())


@pytest.mark.parametrize("name", ["conveyor", "screwdriver", "closed_differential"])
def test_a_planet_set_is_drawn_symmetric_about_its_carriers_axis(name):
    # the book's planetary train: a planet above the central axis and its copy below, the carrier a
    # fork to both; the copy has no letter and no arrow (it turns as the one above). The closed
    # differential lists its copies itself (6–6′ below, 3′… above): nothing is added there.
    sc = SCENES[name]()
    t = sc.problem.train
    w = solve(t).omega
    lay = layout(t, sc.problem.module, sc.problem.axes, sc.problem.sides, sc.problem.towards, sc.problem.coaxial)
    sch = schematic(lay, 0.002, w, list(t.inputs))
    rects = [(round(sum(p[0] for p in r.points) / 4, 6), round(sum(p[1] for p in r.points) / 4, 6),
              round(max(p[1] for p in r.points) - min(p[1] for p in r.points), 6))
             for r in sch.items if isinstance(r, Polyline) and r.closed and len(r.points) == 4]
    copies = 0
    for g in t.gears:
        h = t.member(g.member).carrier
        if h is None:
            continue
        x, y = lay.centre(g.name)[0] / 0.002, lay.centre(g.name)[1] / 0.002
        mirror = (round(x, 6), round(2 * lay.height(h) / 0.002 - y, 6), round(2 * lay.radius[g.name] / 0.002, 6))
        copies += mirror in rects
    n_planet_gears = len([g for g in t.gears if t.member(g.member).carrier is not None])
    assert copies == n_planet_gears
    # one rectangle per planet gear and one per copy: the scene's own copies are not drawn again
    heights = {round(2 * lay.radius[g.name] / 0.002, 6) for g in t.gears if t.member(g.member).carrier is not None}
    assert len([r for r in rects if r[2] in heights]) >= n_planet_gears
    assert set(sch.arrows) == {m for m, v in w.items() if v != 0.0 and m not in t.fixed}
    # a letter per gear and per carrier, none for a copy
    assert len([it for it in sch.items if isinstance(it, Label)]) == len(t.gears) + len(t.carriers)

@pytest.mark.parametrize("name", list(SCENES))
def test_no_two_velocity_lines_are_named_at_one_point(name):
    if name == "worm_bevel":
        return
    vel = panels(SCENES[name]())[0]["velocity"]
    t = SCENES[name]().problem.train
    members = {m.name for m in t.members} - set(t.fixed)
    # the velocity lines' names come before the ω line's (which follow the pole "O")
    names = [it for it in vel.items if isinstance(it, Label) and it.text.replace("′", "'") in members]
    lines = names[:len(names) - len([n for n in names if n.anchor[1] == names[-1].anchor[1]])]
    for i, a in enumerate(lines):
        for b in lines[i + 1:]:
            d = ((a.anchor[0] - b.anchor[0]) ** 2 + (a.anchor[1] - b.anchor[1]) ** 2) ** 0.5
            assert d >= 5.0, (a.text, b.text, d)


def test_the_pole_distance_is_dimensioned_apart_from_the_carriers_rays():
    # the screwdriver's rays H1, H2 on the ω line: the pole distance is "H = 10 mm", a dimension
    vel = panels(screwdriver_scene())[0]["velocity"]
    texts = labels(vel)
    assert "H" not in texts and texts.count("H = 10 mm") == 1 and {"H1", "H2"} <= set(texts)
    dim = next(it for it in vel.items if isinstance(it, Label) and it.text == "H = 10 mm")
    o = next(it for it in vel.items if isinstance(it, Label) and it.text == "O").anchor
    assert dim.anchor[0] < min(it.anchor[0] for it in vel.items if isinstance(it, Label) and it.text in ("H1", "H2"))
    assert o[1] < dim.anchor[1] < o[1] + 10.0  # halfway up the pole distance
    assert vel.notes[2].startswith("H = 10 mm, μ_{ω} = ")


def test_rays_past_the_omega_line_s_end_are_clipped_and_said():
    sc = load_scene(SCENE_DIR / "train.closed_differential_n3_n5.toml")
    vel = panels(sc)[0]["velocity"]
    assert vel.notes[-2] == "the rays of 1, 2, 6 clipped at the ω line's end (ℓ above: H is chosen for the speeds asked)"
    assert any(n.startswith("ℓ_{1} = 164.2 mm") for n in vel.notes)
    o = next(it for it in vel.items if isinstance(it, Label) and it.text == "O").anchor
    rays = [it for it in vel.items if isinstance(it, Arrow) and it.p0 == o]
    assert len(rays) == 2  # 1 to the right; 2 and 6 (one ray) to the left, each to the ω line's end
    assert sorted(abs(r.p1[0] - o[0]) for r in rays) == pytest.approx([CLIP_MM, CLIP_MM])
    assert all(r.p1[1] < o[1] + 40.0 for r in rays)  # below the ω line: they run on past its end


def test_an_identical_planet_is_drawn_across_the_carrier_s_axis(tmp_path):
    # 2 and 2a both mesh the sun and the ring: one above, one below, neither drawn twice
    lay_planets = panels(load_scene(ROOT / "tests" / "scenes" / "trains" / "twin_planets.toml"))
    sch = lay_planets[0]["schematic"]
    assert {"2", "2a"} <= set(labels(sch))
    rects = [it for it in sch.items if isinstance(it, Polyline) and it.closed and len(it.points) == 4
             and abs(it.points[1][0] - it.points[0][0]) == pytest.approx(3.0)]
    ys = sorted(round(sum(p[1] for p in r.points) / 4, 6) for r in rects)
    assert len(ys) == len(set(ys)) == 3  # the sun and the two planets, none on top of another


def test_the_bevel_differential_s_case_cross_pin_and_side_gears():
    sc = load_scene(ROOT / "tests" / "scenes" / "trains" / "bevel_differential.toml")
    sheet_panels, warnings = panels(sc)
    sch = sheet_panels["schematic"]
    assert warnings == [] and {"1", "2", "3", "4", "5", "H"} <= set(labels(sch))
    lay = drawn(sc).layout
    mu = 0.001  # the scene's μl (the figure's note)
    assert sch.notes[0] == "μ_{l} = 0.001 m/mm"
    x1, x3 = lay.centre("1")[0] / mu, lay.centre("3")[0] / mu
    bevels = {round(sum(p[0] for p in it.points) / 4, 3): it for it in sch.items
              if isinstance(it, Polyline) and it.closed and len(it.points) == 4}
    # the side gears' trapezoids narrow toward each other (their apexes meet at the cross pin)
    left = next(it for x, it in bevels.items() if abs(it.points[0][0] - x1) < 1e-6 and abs(it.points[3][0] - x1) < 1e-6)
    right = next(it for x, it in bevels.items() if abs(it.points[0][0] - x3) < 1e-6 and abs(it.points[3][0] - x3) < 1e-6)
    assert left.points[1][0] > x1 and right.points[1][0] < x3
    # the case: a rectangle round both side gears and the planet (and its twin below the axis)
    case = max((it for it in sch.items if isinstance(it, Polyline) and it.closed and len(it.points) == 4),
               key=lambda it: abs(it.points[2][0] - it.points[0][0]) * abs(it.points[2][1] - it.points[0][1]))
    xs, ys = [p[0] for p in case.points], [p[1] for p in case.points]
    assert min(xs) < x1 and max(xs) > x3 and min(ys) < -10.0 and max(ys) > 10.0
    # the cross pin: a vertical segment across the case at the apexes' point, midway between 1 and 3
    mid = (x1 + x3) / 2
    assert any(isinstance(it, Segment) and abs(it.p0[0] - mid) < 1e-6 and abs(it.p1[0] - mid) < 1e-6
               and it.p0[1] == pytest.approx(min(ys)) and it.p1[1] == pytest.approx(max(ys)) for it in sch.items)


SPATIAL_BANK = ("train.ysj10_11_worm_differential", "train.hand_hoist_i15", "train.ysj10_4_worm_train")


def _meshing(lay):
    return {frozenset((m.a, m.b)) for m in lay.train.meshes}


@pytest.mark.parametrize("name", SPATIAL_BANK)
def test_no_two_gears_of_a_spatial_bank_train_overlap(name):
    """Side-on symbols (a gear's width across its pitch diameter, a worm its length) do not overlap
    unless the gears mesh; end-on circles in one plane do not either; an end-on circle behind a
    nearer end-on gear is dashed where that gear hides it, solid elsewhere."""
    from graphmech.problems.trains.figures import GEAR_W, WORM_L

    sc = load_scene(SCENE_DIR / f"{name}.toml")
    dr = drawn(sc)
    lay, mu = dr.layout, dr.mu_l
    worms = {m.a for m in lay.train.meshes if m.kind == "worm"}
    meshing = _meshing(lay)
    boxes, discs = {}, {}
    for g in lay.radius:
        e = lay.line(lay.train.gear(g).member)
        c = [v / mu for v in lay.centre(g)]
        R = lay.radius[g] / mu
        if e[2] > 0.5:
            discs[g] = ((c[0], c[1]), c[2], R)
            continue
        half = WORM_L * R if g in worms else GEAR_W / 2
        ax, ay = (half, R) if e[0] > 0.5 else (R, half)
        boxes[g] = (c[0] - ax, c[0] + ax, c[1] - ay, c[1] + ay)
    names = sorted(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if frozenset((a, b)) in meshing:
                continue
            A, B = boxes[a], boxes[b]
            ox = min(A[1], B[1]) - max(A[0], B[0])
            oy = min(A[3], B[3]) - max(A[2], B[2])
            assert ox <= 1e-6 or oy <= 1e-6, (a, b, ox, oy)
    ends = sorted(discs)
    for i, a in enumerate(ends):
        for b in ends[i + 1:]:
            (ca, za, ra), (cb, zb, rb) = discs[a], discs[b]
            same_member = lay.train.gear(a).member == lay.train.gear(b).member
            if abs(za - zb) < GEAR_W and not same_member:
                assert math.dist(ca, cb) >= ra + rb - 1e-6, (a, b)
    sch = schematic(lay, mu, solve(lay.train).omega)
    hidden = [it for it in sch.items if isinstance(it, Polyline) and it.dashed and not it.closed]
    covered = [(a, b) for a in ends for b in ends
               if discs[b][1] > discs[a][1] + GEAR_W / 2 and lay.train.gear(a).member != lay.train.gear(b).member
               and abs(discs[a][2] - discs[b][2]) < math.dist(discs[a][0], discs[b][0]) < discs[a][2] + discs[b][2]]
    assert bool(hidden) == bool(covered)
    for a, b in covered:  # a's circle: dashed inside b's disc, solid outside it
        (ca, _, ra), (cb, _, rb) = discs[a], discs[b]
        runs = [it for it in sch.items if isinstance(it, Polyline) and not it.closed
                and all(abs(math.dist(p, ca) - ra) < 1e-6 for p in it.points)]
        assert any(it.dashed for it in runs) and any(not it.dashed for it in runs)
        for it in runs:
            inner = it.points[1:-1]
            assert all((math.dist(p, cb) < rb) == it.dashed for p in inner)


@pytest.mark.parametrize("name", SPATIAL_BANK)
def test_each_worm_reaches_its_wheel_s_pitch_circle(name):
    # the worm's axis at r_worm + r_wheel from the wheel's centre, the two centred on each other's axis
    lay = drawn(load_scene(SCENE_DIR / f"{name}.toml")).layout
    worms = [m for m in lay.train.meshes if m.kind == "worm"]
    assert worms
    for m in worms:
        cw, cg = lay.centre(m.a), lay.centre(m.b)
        ew, eg = (lay.line(lay.train.gear(g).member) for g in (m.a, m.b))
        d = [q - p for p, q in zip(cw, cg)]
        along_w = sum(u * v for u, v in zip(d, ew))
        along_g = sum(u * v for u, v in zip(d, eg))
        assert abs(along_w) < 1e-12 and abs(along_g) < 1e-12  # the wheel's mid-plane through the worm's centre
        assert math.hypot(*d) == pytest.approx(lay.radius[m.a] + lay.radius[m.b], rel=1e-12)


def test_a_bevel_planet_s_pin_runs_from_the_carrier_s_axis_past_its_gear():
    # the side gears 1 and 3 (20) and the case H seen end-on (axis +z); the planet 2 (12, axis +x) on
    # H's pin: the pin from H's axis (the apex) through the planet's centre to past its back
    from graphmech.problems.trains.figures import GEAR_W

    t = train({"1": None, "2": "H", "3": None, "H": None}, [("1", 20, "1"), ("2", 12, "2"), ("3", 20, "3")],
              [Mesh("1", "2", "bevel", -1), Mesh("2", "3", "bevel", -1)], inputs={"H": 1.0}, fixed=("3",))
    lay = layout(t, 1e-3, axes={"1": "+z", "3": "+z", "H": "+z", "2": "+x"}, gap=0.016,
                 towards={0: ("+x", "-z"), 1: ("-z", "+x")})
    mu = 1e-3
    c2 = (lay.centre("2")[0] / mu, lay.centre("2")[1] / mu)
    h = (lay.origin["H"][0] / mu, lay.origin["H"][1] / mu)
    assert c2 == pytest.approx((10.0, 0.0)) and h == pytest.approx((0.0, 0.0))
    sch = schematic(lay, mu, solve(t).omega)
    pins = [it for it in sch.items if isinstance(it, Segment) and it.p0 == pytest.approx(h)]
    assert len(pins) == 1 and pins[0].p1 == pytest.approx((c2[0] + GEAR_W, 0.0))
