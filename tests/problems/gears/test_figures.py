"""The gear figures: the constructions' points at their panel's μ, circles cut to the panel's
window (z = 1000), words in three notations, byte-identical SVG, undercut and ε < 1 said."""
from __future__ import annotations

import math

import pytest

from graphmech.drawing.lettering import plain
from graphmech.drawing.primitives import (
    Arrow,
    Circle,
    Label,
    Polyline,
    Segment,
    Sheet,
    Text,
)
from graphmech.errors import OutOfDomain
from graphmech.mechanisms.gear import GearSet, SpurGear, ToothSystem
from graphmech.methods.gear_meshing import MeshConstruction
from graphmech.methods.involute import (
    AtRadius,
    Flank,
    PinMeasurement,
    SpanMeasurement,
    ToothOutline,
)
from graphmech.problems.gears.figures import (
    GearDrawing,
    circle_in,
    clipped_circle,
    dimension,
    gear_sheet,
    outline_runs,
)
from graphmech.render.layout import item_box
from graphmech.render.svg import render_svg
from tests.conftest import SCENES, run_cli

A3 = (420.0, 297.0)
ALPHA = math.radians(20.0)
SYSTEM = ToothSystem(0.008, ALPHA)


# ----------------------------------------------------------------------------- hand-made constructions
# Built here from the involute's closed form (the figures only lay off what they are given):
# tooth 0 centred on +y, its half angle at r_k ψ + inv α − inv α_k, ψ = (π/2 + 2x tan α)/z.
def inv(a: float) -> float:
    return math.tan(a) - a


def radii(s: ToothSystem, g: SpurGear) -> tuple[float, float, float, float]:
    r = s.m * g.z / 2.0
    return r, r * math.cos(s.alpha), r + (s.ha_star + g.x) * s.m, r - (s.ha_star + s.c_star - g.x) * s.m


def half(s: ToothSystem, g: SpurGear, rk: float) -> float:
    rb = radii(s, g)[1]
    ak = math.acos(min(rb / rk, 1.0))
    return (math.pi / 2.0 + 2.0 * g.x * math.tan(s.alpha)) / g.z + inv(s.alpha) - inv(ak)


def polar(r: float, a: float) -> tuple[float, float]:
    return (r * math.cos(a), r * math.sin(a))


def at(s: ToothSystem, g: SpurGear, rk: float) -> AtRadius:
    _, rb, _, _ = radii(s, g)
    b = half(s, g, rk)
    ak = math.acos(rb / rk)
    aL, aR = math.pi / 2 + b, math.pi / 2 - b
    return AtRadius(rk, polar(rk, aL), polar(rk, aR), polar(rb, aL - ak), polar(rb, aR + ak), ak, 2 * rk * b,
                    math.sqrt(rk * rk - rb * rb), inv(ak))


def outline(s: ToothSystem, g: SpurGear, teeth: int = 3, n: int = 8, undercut: bool = False) -> ToothOutline:
    r, rb, ra, rf = radii(s, g)
    lo = max(rb, rf)
    step = math.tau / g.z
    drawn, pts = [], []
    for j in range(teeth // 2, -(teeth // 2) - 1, -1):  # left to right: clockwise
        rot = j * step
        ks = [lo + (ra - lo) * i / (n - 1) for i in range(n)]
        left = [polar(rk, math.pi / 2 + half(s, g, rk) + rot) for rk in ks]
        right = [polar(rk, math.pi / 2 - half(s, g, rk) + rot) for rk in ks]
        strings = tuple((polar(rb, math.pi / 2 - half(s, g, rk) + rot + math.acos(rb / rk)), p)
                        for rk, p in zip(ks, right))
        lstr = tuple((polar(rb, math.pi / 2 + half(s, g, rk) + rot - math.acos(rb / rk)), p)
                     for rk, p in zip(ks, left))
        drawn.append((Flank(polar(rb, math.pi / 2 + half(s, g, rb) + rot), tuple(left), lstr),
                       Flank(polar(rb, math.pi / 2 - half(s, g, rb) + rot), tuple(right), strings)))
        a_root = math.pi / 2 + half(s, g, lo) + rot
        gap = step - 2.0 * half(s, g, lo)  # the root arc from the tooth on the left to this one
        pts += [polar(rf, a_root + gap * (1.0 - i / 6.0)) for i in range(6)]
        pts += [polar(rf, a_root)] + left + right[::-1] + [polar(rf, math.pi / 2 - half(s, g, lo) + rot)]
    pts.append((0.0, 0.0))  # the sector closed through O: the figure must leave that out
    return ToothOutline(r, rb, ra, rf, tuple(drawn), (), tuple(pts), undercut, lo)


def mesh(s: ToothSystem, z1: int, z2: int, meshing: str = "external") -> MeshConstruction:
    """The line of action through P = (0, r₁) rising to the right at α (standard centre distance)."""
    g1 = SpurGear(z1)
    r1, _, ra1, _ = radii(s, g1)
    r2 = s.m * z2 / 2.0
    u = (math.cos(s.alpha), math.sin(s.alpha))
    P = (0.0, r1)

    def on(t: float) -> tuple[float, float]:
        return (P[0] + t * u[0], P[1] + t * u[1])

    def cut(c: tuple[float, float], r: float, sign: float) -> float:  # the line meets circle (c, r)
        d = (P[0] - c[0], P[1] - c[1])
        b = d[0] * u[0] + d[1] * u[1]
        q = math.sqrt(b * b - (d[0] ** 2 + d[1] ** 2 - r * r))
        return min((t for t in (-b + q, -b - q) if sign * t > 0), key=abs)  # the nearer P on that side

    N1 = on(-r1 * math.sin(s.alpha))
    B1 = on(cut((0.0, 0.0), ra1, 1.0))
    if meshing == "rack":
        a, O2, N2, rw2 = r1, None, None, None
        B2 = on(-s.ha_star * s.m / math.sin(s.alpha))
    elif meshing == "internal":
        a = r2 - r1
        O2, N2, rw2 = (0.0, -a), on(-r2 * math.sin(s.alpha)), r2
        B2 = on(cut(O2, r2 - s.ha_star * s.m, -1.0))
    else:
        a = r1 + r2
        O2, N2, rw2 = (0.0, a), on(r2 * math.sin(s.alpha)), r2
        B2 = on(cut(O2, r2 + s.ha_star * s.m, -1.0))
    pb = math.pi * s.m * math.cos(s.alpha)
    L = math.dist(B1, B2)
    eps = L / pb
    w = ((B2[0] - B1[0]) / L, (B2[1] - B1[1]) / L)
    zp = ((B2[0] - pb * w[0], B2[1] - pb * w[1]), (B1[0] + pb * w[0], B1[1] + pb * w[1])) if 1 <= eps < 2 else ()
    return MeshConstruction((0.0, 0.0), O2, P, N1, N2, B1, B2, a, s.alpha, r1, rw2, pb, L,
                            None if N2 is None else math.dist(N1, N2), eps, zp, (2 - eps) * pb if zp else None,
                            (eps - 1) * pb if zp else None, {}, None, ())


def pair(z1: int = 19, z2: int = 42, s: ToothSystem = SYSTEM, meshing: str = "external",
         scales: dict | None = None) -> GearDrawing:
    g1 = SpurGear(z1)
    gears = (g1,) if meshing == "rack" else (g1, SpurGear(z2, internal=meshing == "internal"))
    return GearDrawing(GearSet(s, gears, meshing), scales or {"l": 0.002, "tooth": 0.0005, "zones": 0.0005},  # type: ignore[arg-type]
                       teeth=(("1", outline(s, g1)),),
                       at_radii=(("1", at(s, g1, radii(s, g1)[0])), ("1", at(s, g1, radii(s, g1)[2])),
                                 ("1", at(s, g1, (radii(s, g1)[0] + radii(s, g1)[2]) / 2.0))),
                       mesh=mesh(s, z1, z2, meshing))


def single(z: int = 20, undercut: bool = False, mu_tooth: float = 0.0005) -> GearDrawing:
    g = SpurGear(z)
    r, _, ra, _ = radii(SYSTEM, g)
    sp = span_of(SYSTEM, g, 3)
    return GearDrawing(GearSet(SYSTEM, (g,)), {"l": 0.001, "tooth": mu_tooth},
                       teeth=(("", outline(SYSTEM, g, undercut=undercut)),),
                       at_radii=(("", at(SYSTEM, g, r)), ("", at(SYSTEM, g, ra))), span=(("", sp),),
                       pins=(("", pins_of(SYSTEM, g)),), root_base=(41.45, float(z)))


def pins_of(s: ToothSystem, g: SpurGear) -> PinMeasurement:
    """Pins of 1.68m in the space right of tooth 0 and the one opposite (even z), centres at r + 0.3m."""
    d, rc = 1.68 * s.m, radii(s, g)[0] + 0.3 * s.m
    a = math.pi / 2 - math.pi / g.z
    return PinMeasurement(d, (polar(rc, a), polar(rc, a + math.pi)), (), 2 * rc + d)


def span_of(s: ToothSystem, g: SpurGear, k: int) -> SpanMeasurement:
    """Over k teeth centred on tooth 0 (odd k): the base tangent at the top, K on the outer flanks."""
    _, rb, _, _ = radii(s, g)
    W = s.m * math.cos(s.alpha) * ((k - 0.5) * math.pi + g.z * inv(s.alpha))
    N = (0.0, rb)
    return SpanMeasurement(k, N, (-W / 2, rb), (W / 2, rb), W)


def texts(sheet: Sheet, panel: str | None = None) -> list[str]:
    return [i.text for p in sheet.panels if panel is None or p.name == panel for i in p.items
            if isinstance(i, (Label, Text))]


def items(sheet: Sheet, panel: str) -> tuple:
    return next(p for p in sheet.panels if p.name == panel).items



def labels_at(sheet: Sheet, panel: str) -> dict[str, tuple[float, float]]:
    return {i.text: i.anchor for i in items(sheet, panel) if isinstance(i, Label)}


# ----------------------------------------------------------------------------- the panels
def test_meshing_letters_the_constructions_points_at_mu_l():
    d = pair()
    m, mu = d.mesh, d.scales["l"]
    got = labels_at(gear_sheet("g", ["meshing"], d, A3), "meshing")
    for name, p in (("B_{1}", m.B1), ("B_{2}", m.B2), ("P", m.P), ("N_{1}", m.N1), ("N_{2}", m.N2),
                    ("O_{1}", m.O1), ("O_{2}", m.O2)):
        assert got[name] == pytest.approx((p[0] / mu, p[1] / mu), abs=1e-12), name
    bold = [i for i in items(gear_sheet("g", ["meshing"], d, A3), "meshing") if isinstance(i, Segment) and i.role == "result"]
    assert len(bold) == 1 and math.dist(bold[0].p0, bold[0].p1) * mu == pytest.approx(m.B1B2, rel=1e-12)
    # the working pitch circles dash-dot through P, the base circles tangent to N₁N₂ at N₁, N₂
    circles = [i for i in items(gear_sheet("g", ["meshing"], d, A3), "meshing") if isinstance(i, Circle) and i.r > 5]
    pitch = sorted(c.r * mu for c in circles if c.dashdot)
    assert pitch == pytest.approx(sorted([m.r_w1, m.r_w2]), rel=1e-12)
    assert any(abs(c.r * mu - math.dist(m.O1, m.N1)) < 1e-12 and not c.dashdot for c in circles)


def test_rack_and_ring():
    """A rack: no O₂, its reference line dash-dot at a′, its velocity v₂; a ring: ω₂ the same sense as ω₁
    (both clockwise) and the ring's rim bold."""
    from graphmech.drawing.primitives import ArcArrow
    d = pair(meshing="rack")
    its = items(gear_sheet("g", ["meshing"], d, A3), "meshing")
    texts_ = {i.text for i in its if isinstance(i, Label)}
    assert "O_{2}" not in texts_ and "N_{2}" not in texts_ and {"v_{2}", "B_{2}", "rack"} <= texts_
    ref = [i for i in its if isinstance(i, Segment) and i.dashdot and i.p0[1] == i.p1[1]]
    assert [s.p0[1] * 0.002 for s in ref] == pytest.approx([d.mesh.a_w], rel=1e-12)
    ring = items(gear_sheet("g", ["meshing"], pair(19, 60, meshing="internal"), A3), "meshing")
    senses = [a.sweep for a in ring if isinstance(a, ArcArrow)]
    assert len(senses) == 2 and all(s < 0 for s in senses)
    assert any(isinstance(c, Circle) and c.role == "given" for c in ring)
    ext = items(gear_sheet("g", ["meshing"], pair(), A3), "meshing")
    assert sorted(math.copysign(1, a.sweep) for a in ext if isinstance(a, ArcArrow)) == [-1.0, 1.0]


def test_zones_double_at_both_ends_single_between_dimensioned():
    d = pair()
    m, mu = d.mesh, d.scales["zones"]
    its = items(gear_sheet("g", ["zones"], d, A3), "zones")
    words = [i.text for i in its if isinstance(i, Text)]
    assert words.count("two pairs") == 2 and words.count("one pair") == 1
    assert words.count("(ε_{α}−1)p_{b}") == 2 and words.count("(2−ε_{α})p_{b}") == 1 and words.count("p_{b}") == 2
    at = labels_at(gear_sheet("g", ["zones"], d, A3), "zones")
    assert at["B_{2}"] == (0.0, 0.0) and at["B_{1}"][0] * mu == pytest.approx(m.B1B2, rel=1e-12)
    # the zone points at p_b from each end: the single-contact zone (2 − ε)p_b long
    dots = sorted(c.center[0] for c in its if isinstance(c, Circle))
    assert len(dots) == 2 and (dots[1] - dots[0]) * mu == pytest.approx(m.single_contact, rel=1e-12)
    assert dots[0] * mu == pytest.approx(m.double_contact, rel=1e-12)
    assert "ε_{α} < 1: not continuous" not in words


def test_a_contact_ratio_below_one_is_said_and_its_gap_drawn():
    d = pair(s=ToothSystem(0.008, ALPHA, 0.5))
    assert d.mesh.eps_alpha < 1.0
    its = items(gear_sheet("g", ["zones"], d, A3), "zones")
    words = [i.text for i in its if isinstance(i, Text)]
    assert "ε_{α} < 1: not continuous" in words and "gap" in words and "one pair" not in words
    gap = [s for s in its if isinstance(s, Segment) and s.dashed and s.role == "result"]
    L, pb = d.mesh.B1B2 / 0.0005, d.mesh.pb / 0.0005
    assert len(gap) == 1 and (gap[0].p0[0], gap[0].p1[0]) == pytest.approx((L, pb), rel=1e-12)
    zh = gear_sheet("g", ["zones"], d, A3, notation="zh")
    assert "ε_{α} < 1：不能连续传动" in texts(zh)


def test_tooth_panel_draws_the_construction_by_points_and_its_dimensions():
    d = single()
    t, mu = d.teeth[0][1], d.scales["tooth"]
    its = items(gear_sheet("g", ["tooth"], d, A3), "tooth")
    names = [i.text for i in its if isinstance(i, Label)]
    assert {"s", "e", "p", "s_{a}", "h_{a}", "h_{f}", "ρ", "ρ_{a}"} <= set(names)
    # the strings N_iK_i of one flank, numbered from 0 at its start on the base circle
    flank = t.teeth[-1][0]  # the rightmost tooth's left flank
    strings = {(s.p0, s.p1) for s in its if isinstance(s, Segment) and s.role == "construction"}
    for n, k in flank.strings[1:]:
        assert ((n[0] / mu, n[1] / mu), (k[0] / mu, k[1] / mu)) in strings
    assert "0′" in names and "0" in names
    # s on the reference circle as long as the construction's s
    ref = d.at_radii[0][1]
    arcs = [p for p in its if isinstance(p, Polyline) and p.role == "label"
            and all(abs(math.hypot(*q) - t.r / mu) < 1e-9 for q in p.points)]
    lengths = sorted(sum(math.dist(a, b) for a, b in zip(p.points, p.points[1:])) * mu for p in arcs)
    assert any(abs(x - ref.s_k) < 1e-4 * ref.s_k for x in lengths)  # chords of 0.5 mm: within 1e-4
    assert "undercut" not in names


def test_undercut_is_said_on_the_figure():
    for notation, w in (("en", "undercut"), ("zh", "根切"), ("ru", "подрез")):
        sheet = gear_sheet("g", ["tooth"], single(12, undercut=True), A3, notation=notation)
        assert w in texts(sheet)


def test_z_1000_draws_only_arcs_over_the_teeth_shown():
    d = single(1000)
    sheet = gear_sheet("g", ["tooth"], d, A3)
    its = items(sheet, "tooth")
    assert not [c for c in its if isinstance(c, Circle) and c.r > 50.0]
    boxes = [item_box(i) for i in its if not isinstance(i, Label)]
    w = max(b[2] for b in boxes) - min(b[0] for b in boxes)
    h = max(b[3] for b in boxes) - min(b[1] for b in boxes)
    assert w < 250.0 and h < 150.0  # three teeth of m = 8 at μ 0.0005 (the strings cut at the window)
    svg = render_svg(sheet, "g", on_warning=lambda m: pytest.fail(m))
    assert "<circle" in svg  # the dots only


def test_circle_in_a_window():
    assert circle_in((0.0, 0.0), 10.0, (20.0, 20.0, 30.0, 30.0)) == []
    [(a, b)] = circle_in((0.0, -100.0), 101.0, (-5.0, -5.0, 5.0, 5.0))
    assert a < math.pi / 2 < b and (b - a) * 101.0 == pytest.approx(2 * 101.0 * math.asin(5.0 / 101.0), rel=1e-12)
    [arc] = clipped_circle((0.0, -4000.0), 4001.0, (-10.0, -10.0, 10.0, 10.0))
    assert isinstance(arc, Polyline) and all(abs(x) <= 10.0 + 1e-9 for p in arc.points for x in p)
    assert isinstance(clipped_circle((0.0, 0.0), 1.0, (-2.0, -2.0, 2.0, 2.0), dashdot=True)[0], Circle)


def test_measurement_span_and_pins():
    d = single()
    mu = d.scales["l"]  # the span and the pins are drawn with the whole gear
    sheet = gear_sheet("g", ["measurement"], d, A3)
    assert [p.name for p in sheet.panels] == ["measurement", "pins"]
    sp = d.span[0][1]
    at = labels_at(sheet, "measurement")
    assert at["K_{1}"] == pytest.approx((sp.K1[0] / mu, sp.K1[1] / mu)) and "W_{3} = 61.28 mm" in at
    pm = d.pins[0][1]
    pins = [c for c in items(sheet, "pins") if isinstance(c, Circle) and c.role == "given"]
    assert [c.r * mu for c in pins] == pytest.approx([pm.d_pin / 2] * 2, rel=1e-12)
    dims = [a for a in items(sheet, "pins") if isinstance(a, Arrow)]
    ends = [a.p1 for a in dims]
    assert math.dist(*ends) * mu == pytest.approx(pm.M, rel=1e-12)
    assert "M = 178.24 mm" in texts(sheet, "pins")


def test_root_base_lines_cross_at_the_stated_z():
    d = single()
    its = items(gear_sheet("g", ["root_base"], d, A3), "root_base")
    rb, rf = [p for p in its if isinstance(p, Polyline) and p.role == "result"]

    def at_x(line: Polyline, x: float) -> float:
        (x0, y0), (x1, y1) = line.points
        return y0 + (y1 - y0) * (x - x0) / (x1 - x0)

    [dot] = [c for c in its if isinstance(c, Circle)]
    assert at_x(rb, dot.center[0]) == pytest.approx(at_x(rf, dot.center[0]), abs=1e-9)
    assert at_x(rb, dot.center[0]) == pytest.approx(dot.center[1], abs=1e-9)
    assert any("r_{f} = r_{b} at z = 41.45" == t for t in texts(gear_sheet("g", ["root_base"], d, A3)))


# ----------------------------------------------------------------------------- the sheet
def test_only_the_asked_panels_each_with_its_scale():
    d = GearDrawing(pair().gears, pair().scales, pair().teeth, pair().at_radii, mesh=pair().mesh)
    assert [p.name for p in gear_sheet("g", ["zones"], d, A3).panels] == ["zones"]
    sheet = gear_sheet("g", ["tooth", "meshing", "zones"], d, A3)
    assert [p.name for p in sheet.panels] == ["tooth1", "meshing", "zones"]
    assert [p.scales for p in sheet.panels] == [(("l", 0.0005),), (("l", 0.002),), (("l", 0.0005),)]
    assert [p.notes[0] for p in sheet.panels] == ["μ_{l} = 0.0005 m/mm", "μ_{l} = 0.002 m/mm", "μ_{l} = 0.0005 m/mm"]
    with pytest.raises(OutOfDomain, match="unknown panel"):
        gear_sheet("g", ["teeth"], d, A3)
    with pytest.raises(OutOfDomain, match="root_base"):
        gear_sheet("g", ["root_base"], d, A3)
    with pytest.raises(OutOfDomain, match="'zones'"):
        gear_sheet("g", ["zones"], GearDrawing(d.gears, {"l": 0.002}, mesh=d.mesh), A3)


def test_three_notations_give_their_words():
    d = pair()
    want = {"en": ("Contact zones on B_{1}B_{2}", "two pairs", "one pair", "α′"),
            "zh": ("实际啮合线 B_{1}B_{2} 上的单、双齿啮合区", "两对齿啮合区", "单对齿啮合区", "α′"),
            "ru": ("Зоны зацепления на B_{1}B_{2}", "двухпарное зацепление", "однопарное зацепление", "α_{w}")}
    for notation, (caption, two, one, alpha) in want.items():
        sheet = gear_sheet("g", ["meshing", "zones"], d, A3, notation=notation)
        assert sheet.panels[1].title == caption
        assert {two, one, alpha} <= set(texts(sheet))
    assert plain(gear_sheet("g", ["tooth"], d, A3, notation="zh").panels[0].title) == "渐开线齿廓，齿轮 1"


def test_the_same_drawing_gives_byte_identical_svg():
    shown = ["tooth", "meshing", "zones"]
    one = render_svg(gear_sheet("g", shown, pair(), (841.0, 594.0)), "g", on_warning=lambda m: None)
    two = render_svg(gear_sheet("g", shown, pair(), (841.0, 594.0)), "g", on_warning=lambda m: None)
    assert one == two and one.count("<polyline") > 50
    mine = ["tooth", "measurement", "root_base"]
    s1 = render_svg(gear_sheet("g", mine, single(), (841.0, 594.0)), "g", on_warning=lambda m: None)
    assert s1 == render_svg(gear_sheet("g", mine, single(), (841.0, 594.0)), "g", on_warning=lambda m: None)


def test_outline_runs_leave_out_what_closes_the_sector():
    t = outline(SYSTEM, SpurGear(20))
    runs = outline_runs(t)
    assert len(runs) == 1 and (0.0, 0.0) not in runs[0] and len(runs[0]) == len(t.outline) - 1


# ----------------------------------------------------------------------------- on the real constructions
def test_the_constructions_drawn_a_pointed_tip_a_ring_and_contact_below_one():
    from graphmech.methods import involute
    from graphmech.methods.gear_meshing import construct_meshing

    s = ToothSystem(0.004, ALPHA)
    g = SpurGear(10, 0.8)  # x = 0.8 on 10 teeth: the flanks meet inside the tip circle
    ra = involute.circles(s, g)[2]
    tip = involute.pointed_tip(s, g)
    assert tip.r_k < ra
    d = GearDrawing(GearSet(s, (g,)), {"tooth": 0.0005}, teeth=(("", involute.tooth_outline(s, g)),),
                    at_radii=(("", involute.at_radius(s, g, ra)),), pointed=(("", tip),))
    words = texts(gear_sheet("g", ["tooth"], d, A3))
    assert "pointed tip: r = 26.99 mm" in words and "s_{a}" not in words
    # a ring: the construction by points runs off to the right, ρ off to the left
    ring = SpurGear(60, internal=True)
    r = involute.circles(s, ring)[0]
    d = GearDrawing(GearSet(s, (ring,)), {"tooth": 0.0005}, teeth=(("", involute.tooth_outline(s, ring)),),
                    at_radii=(("", involute.at_radius(s, ring, r)),))
    its = items(gear_sheet("g", ["tooth"], d, A3), "tooth")
    strings = [x for x in its if isinstance(x, Segment) and x.role == "construction" and not x.dashdot]
    assert strings and all(x.p0[0] > x.p1[0] for x in strings if math.dist(x.p0, x.p1) > 1.0)  # N right of K
    rho = next(x for x in its if isinstance(x, Label) and x.text == "ρ")
    assert rho.anchor[0] < 0.0
    low = GearSet(ToothSystem(0.004, ALPHA, 0.5), (SpurGear(19), SpurGear(42)), "external")
    m = construct_meshing(low)
    d = GearDrawing(low, {"zones": 0.00025}, mesh=m)
    assert m.eps_alpha < 1.0 and "ε_{α} < 1: not continuous" in texts(gear_sheet("g", ["zones"], d, A3))


def test_a_zero_addendum_is_not_dimensioned(tmp_path):
    """h*a = 0 (found by the mutation test on gear.root_circle_equals_base_circle): the tip circle is
    the reference circle, so the addendum's dimension has no length and is left out — not an arrow
    between one point and itself."""
    assert dimension((1.0, 2.0), (1.0, 2.0), "h_{a}") == []
    assert len(dimension((0.0, 0.0), (20.0, 0.0), "h_{a}")) == 3
    text = (SCENES / "gear.root_circle_equals_base_circle.toml").read_text(encoding="utf-8")
    p = tmp_path / "g.toml"
    p.write_text(text.replace("ha_star = 1", "ha_star = 0", 1), encoding="utf-8")
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "g.svg"))
    assert code == 0 and "Traceback" not in err
