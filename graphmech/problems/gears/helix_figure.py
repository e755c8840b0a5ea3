"""The panel "helix": the drawings of a helical, bevel or worm pair (孙桓 ch. 10, Figs. of the
developed reference cylinder, the normal section, the worm's thread and the bevel's back cone).

helical
    the development of gear 1's reference cylinder (a window a few pitches wide, B high, at the
    main μl): the tooth lines as straight lines at β, p_t along the circumference, p_n normal to
    them, s_t, B and the advance B·tan β dimensioned, β marked; the normal section's ellipse
    (semi-axes r/cos β, r) with its osculating circle at the pitch point and the construction of
    its centre; one turn of the helix developed (πd by the lead p_z, β and β_b); the transverse
    section's meshing (graphmech.problems.gears.figures' meshing panel on the m_t, α_t pair).
worm
    one turn of the worm's reference cylinder developed (πd₁ by the lead), the z₁ threads, p_x, p_z
    and the lead angle γ₁.
bevel
    the axial section: the axes at Σ, the pitch, tip and root cones, the teeth at the large end,
    the back cones with the virtual gears' radii r_v = r/cos δ, δ₁, δ₂ and R; the back cone
    developed: the virtual spur gears (Tredgold).

Every size fixed here is paper millimetres; each drawing states its own μl.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from graphmech.drawing.lettering import LETTER, number, scale_text
from graphmech.drawing.notation import word
from graphmech.drawing.primitives import (
    Circle,
    Label,
    Panel,
    Polyline,
    Primitive,
    Segment,
    Sheet,
    angle_arc,
)
from graphmech.problems.gears.figures import (
    GearDrawing,
    arc_points,
    dimension,
    meshing_items,
    mm_text,
    paper_label,
    to_paper,
)
from graphmech.scales import round_scale

if TYPE_CHECKING:
    from graphmech.methods.helix import (
        BevelConstruction,
        HelicalConstruction,
        WormConstruction,
    )
    from graphmech.problems.gears.spatial import SpatialAnalysis

XY = tuple[float, float]

#: The sheet's words: key → (English, 中文 (孙桓), русский).
WORDS: dict[str, tuple[str, str, str]] = {
    "development": ("Reference cylinder developed (gear 1)", "分度圆柱面展开图（齿轮1）",
                    "Развёртка делительного цилиндра (колесо 1)"),
    "section": ("Normal section: the virtual gear", "法面截面：当量齿轮", "Нормальное сечение: эквивалентное колесо"),
    "lead": ("One turn of the helix: the lead", "螺旋线展开一周：导程", "Виток винтовой линии: ход"),
    "transverse": ("Transverse section: ε_{α} on B_{1}B_{2}", "端面啮合：B_{1}B_{2} 上的 ε_{α}",
                   "Торцовое сечение: ε_{α} по B_{1}B_{2}"),
    "thread": ("Worm thread developed over πd_{1}", "蜗杆螺旋线沿 πd_{1} 展开", "Развёртка витка червяка по πd_{1}"),
    "cones": ("Bevel pair: pitch cones and back cones", "圆锥齿轮：分度圆锥与背锥", "Коническая пара: делительные и "
              "дополнительные конусы"),
    "virtual": ("Back cones developed: the virtual gears", "背锥展开：当量齿轮", "Развёртка дополнительных конусов: "
                "эквивалентные колёса"),
    "window": ("a window of πd_{1} = «w»", "πd_{1} = «w» 的一段", "часть πd_{1} = «w»"),
}
#: The secondary drawings' room, mm (the main drawing takes spatial.MAIN_SHARE of the page's width).
SIDE_ROOM = (80.0, 36.0)
#: Offsets of dimension lines from what they measure, mm.
DIM = 6.0


def _deg(v: float) -> str:
    return f"{number(math.degrees(v))}°"


def _scale_for(wide: float, tall: float, room: XY = SIDE_ROOM) -> float:
    return round_scale(max(wide / room[0], tall / room[1]))


def _lbl(text: str, at: XY, *avoid: XY, italic: bool = True) -> Label:
    return paper_label(text, at, avoid, LETTER, italic)


# ----------------------------------------------------------------------------- helical
def development_items(c: HelicalConstruction, mu: float) -> list[Primitive]:
    """The developed strip of gear 1's reference cylinder at μ (see the module's docstring)."""
    d = c.development
    pt, st, adv, B = d.pt / mu, d.st / mu, d.advance / mu, d.height / mu
    n = len(d.helices) - 1
    right = n * pt + adv
    items: list[Primitive] = [Segment((0.0, 0.0), (right, 0.0), "given"), Segment((0.0, B), (right, B), "given"),
                              Segment((0.0, 0.0), (0.0, B), "construction", dashdot=True)]
    for k in range(n + 1):
        x0 = k * pt
        items.append(Segment((x0, 0.0), (x0 + adv, B), "result"))
        if k < n:
            items.append(Segment((x0 + st, 0.0), (x0 + st + adv, B), "result"))
    # p_t and s_t along the circumference, below the strip
    # p_t along the top face (between the ends of two tooth lines), s_t along the bottom one
    items += dimension((2 * pt + adv, B + DIM), (3 * pt + adv, B + DIM), f"p_{{t}} = {mm_text(d.pt)}", (0.0, 1.0))
    items += [Segment((x + adv, B), (x + adv, B + DIM + 1.5), "label") for x in (2 * pt, 3 * pt)]
    items += dimension((0.0, -DIM), (st, -DIM), f"s_{{t}} = {mm_text(d.st)}", (0.0, -1.0))
    items += [Segment((x, 0.0), (x, -DIM - 1.5), "label") for x in (0.0, st)]
    # p_n normal to the tooth lines, from the middle of the third one
    u = (math.sin(d.beta), math.cos(d.beta))
    nrm = (math.cos(d.beta), -math.sin(d.beta))
    q0 = (pt + 0.5 * adv, 0.5 * B)
    pn = math.hypot(*d.Pn) / mu
    q1 = (q0[0] + pn * nrm[0], q0[1] + pn * nrm[1])
    items += dimension(q0, q1, f"p_{{n}} = {mm_text(math.hypot(*d.Pn))}", u)
    # B at the left, the advance B·tan β on top
    items += dimension((-DIM, 0.0), (-DIM, B), f"B = {mm_text(d.height)}", (-1.0, 0.0))
    if adv > 0.5:
        items += dimension((0.0, B + DIM), (adv, B + DIM), f"B·tan β = {mm_text(d.advance)}", (0.0, 1.0))
        items.append(Segment((adv, B), (adv, B + DIM + 1.5), "label"))
        items.append(Segment((0.0, B), (0.0, B + DIM + 1.5), "label"))
        arc = angle_arc((0.0, 0.0), (0.0, 1.0), u, 0.45 * B)
        if arc is not None:
            items.append(arc)
            mid = 0.5 * d.beta
            items.append(_lbl("β", (0.5 * B * math.sin(mid), 0.5 * B * math.cos(mid)), (0.0, -1.0), (-u[0], -u[1])))
    return items


def section_items(c: HelicalConstruction, mu: float) -> list[Primitive]:
    """Gear 1's normal section: the ellipse, the rectangle's construction of the centre of
    curvature K at the pitch point, the osculating circle ρ (dashed)."""
    s = c.sections[0]
    a, b, rho = s.a_e / mu, s.b_e / mu, s.rho / mu
    K = to_paper(s.K, mu)
    ell = tuple((a * math.cos(t), b * math.sin(t)) for t in (math.tau * k / 240 for k in range(241)))
    items: list[Primitive] = [
        Polyline(ell, "result"),
        Segment((-a - 4.0, 0.0), (a + 4.0, 0.0), "construction", dashdot=True),
        Segment((0.0, min(K[1], -b) - 4.0), (0.0, b + 4.0), "construction", dashdot=True),
        Polyline(((0.0, b), (a, b), (a, 0.0)), "construction", dashed=True),
        Segment((a, 0.0), (0.0, b), "construction"),
        Segment((a, b), K, "construction"),
        Circle(K, rho, "construction", dashed=True),
        Circle(K, 0.6, "result"),
        Circle((0.0, b), 0.6, "result"),
    ]
    items += dimension((0.0, -b - DIM), (a, -b - DIM), "r/cos β", (0.0, -1.0))
    items += [_lbl("K", K, (0.0, 1.0)), _lbl("C", (a, b), (-1.0, 0.0), (0.0, -1.0)),
              _lbl("P", (0.0, b), (0.0, -1.0), (1.0, 0.0)),
              _lbl(f"ρ = r/cos²β = {mm_text(s.rho)}", (-0.7 * rho, K[1] + 0.7 * rho), (1.0, -1.0), italic=False),
              _lbl("r", (-2.0, 0.5 * b), (0.0, 1.0), (0.0, -1.0))]
    return items


def lead_items(c: HelicalConstruction, mu: float) -> list[Primitive]:
    """One turn of gear 1's helix developed: πd by p_z, the helix at β to the axis; on the base
    cylinder (πd_b, dashed) at β_b."""
    assert c.leads is not None
    ld = c.leads[0]
    # drawn with the axis along x (the lead is longer than the circumference): πd up, p_z across
    w, wb, h = ld.pi_d / mu, ld.pi_db / mu, ld.pz / mu
    items: list[Primitive] = [Segment((0.0, 0.0), (0.0, w), "given"), Segment((0.0, w), (h, w), "given"),
                              Segment((0.0, 0.0), (h, 0.0), "construction", dashdot=True),
                              Segment((0.0, 0.0), (h, w), "result"), Segment((0.0, 0.0), (h, wb), "result", dashed=True),
                              Segment((h, wb), (h, w), "construction", dashed=True)]
    items += dimension((-DIM, 0.0), (-DIM, w), f"πd_{{1}} = {mm_text(ld.pi_d)}", (-1.0, 0.0))
    items += dimension((0.0, w + DIM), (h, w + DIM), f"p_{{z1}} = {mm_text(ld.pz)}", (0.0, 1.0))
    r = min(0.6 * h, 30.0)
    for end, rr, text in (((h, w), r, "β"), ((h, wb), 0.7 * r, "β_{b}")):
        arc = angle_arc((0.0, 0.0), (1.0, 0.0), end, rr)
        if arc is not None:
            items.append(arc)
            ang = math.atan2(end[1], end[0]) / 2.0
            items.append(_lbl(text, (1.1 * rr * math.cos(ang), 1.1 * rr * math.sin(ang)), (-1.0, 0.0)))
    return items


def helical_panels(an: SpatialAnalysis, notation: str) -> list[Panel]:
    c: HelicalConstruction = an.construction
    e = an.exact
    mu = an.scales["l"]
    d = c.development
    panels = [Panel("development", word("development", notation, WORDS), tuple(development_items(c, mu)),
                    (scale_text("l", mu) + "; " + word("window", notation, WORDS).replace("«w»", mm_text(d.width)),
                     f"β = {_deg(d.beta)}" + (f", ε_{{β}} = B·tan β/p_{{t}} = {number(c.eps_beta)}"
                                              if c.eps_beta is not None else "")),
                    0, (("l", mu),))]
    s = c.sections[0]
    mu_s = _scale_for(2.0 * s.a_e, s.b_e + 2.0 * s.rho)
    panels.append(Panel("section", word("section", notation, WORDS), tuple(section_items(c, mu_s)),
                        (scale_text("l", mu_s), f"z_{{v1}} = 2ρ/m_{{n}} = {number(c.sections[0].zv)}, "
                                                f"z_{{v2}} = {number(c.sections[1].zv)}"), 0, (("l", mu_s),)))
    if c.leads is not None:
        ld = c.leads[0]
        mu_l = _scale_for(ld.pz, ld.pi_d)
        panels.append(Panel("lead", word("lead", notation, WORDS), tuple(lead_items(c, mu_l)),
                            (scale_text("l", mu_l), f"β_{{b}} = {_deg(ld.beta_b)}, p_{{z2}} = {mm_text(c.leads[1].pz)}"),
                            1, (("l", mu_l),)))
    m = c.mesh
    assert m.O2 is not None
    r_a = [ri + an.gears.system.ha_star * an.gears.system.m for ri in (m.r_w1, m.r_w2 or 0.0)]
    mu_m = _scale_for(2.0 * max(r_a), m.a_w + r_a[0] + r_a[1], (120.0, 40.0))
    whole = m.B1B2 / mu_m >= 5.0
    if not whole:  # as the spur meshing panel does: a window about the line of action
        mu_m = round_scale(max(m.B1B2, m.pb) * 4.0 / 40.0)
    drawing = GearDrawing(gears=c.transverse, scales={"l": mu_m}, mesh=m, mesh_whole=whole)
    panels.append(Panel("transverse", word("transverse", notation, WORDS), tuple(meshing_items(drawing, m, notation)),
                        (scale_text("l", mu_m) + f"; m_{{t}} = p_{{t}}/π = {mm_text(d.mt)}, α_{{t}} = {_deg(d.alpha_t)}",
                         f"ε_{{α}} = B_{{1}}B_{{2}}/p_{{bt}} = {number(m.eps_alpha)}"
                         + (f", ε_{{γ}} = ε_{{α}} + ε_{{β}} = {number(e.eps_gamma)}" if e.eps_gamma is not None else "")),
                        1, (("l", mu_m),)))
    return panels


# ----------------------------------------------------------------------------- worm
def thread_items(c: WormConstruction, mu: float) -> list[Primitive]:
    """One turn of the worm's reference cylinder developed, its threads, p_x, p_z, γ₁."""
    w, px, pz = c.pi_d1 / mu, c.px / mu, c.pz1 / mu
    z1 = len(c.threads)
    h = pz + px
    items: list[Primitive] = [Segment((0.0, 0.0), (w, 0.0), "construction", dashdot=True),
                              Segment((0.0, h), (w, h), "construction", dashdot=True),
                              Segment((w, 0.0), (w, h), "given"), Segment((0.0, 0.0), (0.0, h), "given")]
    for k in range(-z1, z1 + 2):  # the threads wrapped round the cylinder, inside one turn  # every start, wrapped round the cylinder, inside the turn
        p0, p1 = (0.0, k * px), (w, pz + k * px)
        t0 = max(0.0, (0.0 - p0[1]) / (p1[1] - p0[1]))
        t1 = min(1.0, (h - p0[1]) / (p1[1] - p0[1]))
        if t1 - t0 > 1e-9:
            a = (p0[0] + t0 * (p1[0] - p0[0]), p0[1] + t0 * (p1[1] - p0[1]))
            b = (p0[0] + t1 * (p1[0] - p0[0]), p0[1] + t1 * (p1[1] - p0[1]))
            items.append(Segment(a, b, "result"))
    items += dimension((0.0, -DIM), (w, -DIM), f"πd_{{1}} = {mm_text(c.pi_d1)}", (0.0, -1.0))
    items += dimension((w + DIM, 0.0), (w + DIM, pz), f"p_{{z}} = z_{{1}}p_{{x}} = {mm_text(c.pz1)}", (1.0, 0.0))
    items += dimension((-DIM, 0.0), (-DIM, px), f"p_{{x}} = {mm_text(c.px)}", (-1.0, 0.0))
    r = min(0.3 * w, 30.0)
    arc = angle_arc((0.0, 0.0), (1.0, 0.0), c.T, r)
    if arc is not None:
        items.append(arc)
        # γ₁ inside its angle, beyond the arc where the wedge is a letter and a half high, and short of
        # where the next start wraps in (x = πd₁/z₁): at 1.1r the wedge of a small γ₁ was lower than the
        # letter and the label went across the thread, outside the angle
        tg = math.tan(c.gamma1)
        x = min(max(1.15 * r, 1.5 * LETTER / tg), 0.8 * w / z1) if tg > 0.0 else 1.15 * r
        items.append(_lbl("γ_{1}", (x, 0.5 * x * tg), (-1.0, 0.0)))
    return items


def worm_panels(an: SpatialAnalysis, notation: str) -> list[Panel]:
    c: WormConstruction = an.construction
    e = an.exact
    mu = an.scales["l"]
    z = an.gears.gears
    return [Panel("thread", word("thread", notation, WORDS), tuple(thread_items(c, mu)),
                  (scale_text("l", mu), f"z_{{1}} = {z[0].z}, q = d_{{1}}/m = {number(e.q)}, γ_{{1}} = β_{{2}} = "
                                        f"{_deg(c.gamma1)}",
                   f"d_{{1}} = {mm_text(e.d1)}, d_{{a1}} = {mm_text(e.da1)}, d_{{f1}} = {mm_text(e.df1)}; z_{{2}} = {z[1].z}, "
                   f"d_{{2}} = {mm_text(e.d2)}, d_{{a2}} = {mm_text(e.da2)}, d_{{f2}} = {mm_text(e.df2)}; a = {mm_text(e.a)}"),
                  0, (("l", mu),))]


# ----------------------------------------------------------------------------- bevel
def _mirror(p: XY, u: XY) -> XY:
    """p mirrored in the line through O along the unit u."""
    k = 2.0 * (p[0] * u[0] + p[1] * u[1])
    return (k * u[0] - p[0], k * u[1] - p[1])


def cone_items(c: BevelConstruction, face: float, mu: float) -> list[Primitive]:
    """The bevel pair's axial section at μ (see the module's docstring)."""
    u1, u2 = (1.0, 0.0), c.u2
    P, V1, V2 = to_paper(c.P, mu), to_paper(c.V1, mu), to_paper(c.V2, mu)
    A = [to_paper(a, mu) for a in c.A]
    F = [to_paper(f, mu) for f in c.F]
    k = max(0.0, (c.R - face) / c.R)
    reach = 1.15 * max(math.hypot(*V1), math.hypot(*V2), math.hypot(*A[0]), math.hypot(*A[1]))
    items: list[Primitive] = [Segment((0.0, 0.0), (reach * u1[0], reach * u1[1]), "construction", dashdot=True),
                              Segment((0.0, 0.0), (reach * u2[0], reach * u2[1]), "construction", dashdot=True)]
    for i, u in enumerate((u1, u2)):
        for mirrored in (False, True):
            f = (lambda p, uu=u: _mirror(p, uu)) if mirrored else (lambda p: p)
            a, fl, pp = f(A[i]), f(F[i]), f(P)
            tooth = (fl, a, (a[0] * k, a[1] * k), (fl[0] * k, fl[1] * k))
            items += [Polyline(tooth, "result", closed=True),
                      Segment((0.0, 0.0), pp, "construction", dashdot=True),
                      Segment((0.0, 0.0), (a[0] * k, a[1] * k), "construction"),
                      Segment((0.0, 0.0), (fl[0] * k, fl[1] * k), "construction")]
            V = f(V1 if i == 0 else V2)
            items.append(Segment(V, a, "construction"))
    items += [Circle(P, 0.6, "result"), Circle(V1, 0.6, "result"), Circle(V2, 0.6, "result"),
              _lbl("O", (0.0, 0.0), (1.0, 0.0), u2), _lbl("P", P, (-P[0], -P[1])),
              _lbl("O_{v1}", V1, (0.0, 1.0)), _lbl("O_{v2}", V2, (-u2[0], -u2[1]))]
    op = (P[0] / math.hypot(*P), P[1] / math.hypot(*P))
    side = (-op[1], op[0])
    off = (side[0] * 2.0 * DIM, side[1] * 2.0 * DIM)
    items += dimension((off[0], off[1]), (P[0] + off[0], P[1] + off[1]), f"R = {mm_text(c.R)}", side)
    for i, (u, text) in enumerate(((u1, "δ_{1}"), (u2, "δ_{2}"))):
        r = (0.3 + 0.08 * i) * math.hypot(*P)
        arc = angle_arc((0.0, 0.0), u, op, r)
        if arc is not None:
            items.append(arc)
            mid = arc.points[len(arc.points) // 2]
            items.append(_lbl(text, mid, (-mid[0], -mid[1])))
    items.append(_lbl(f"r_{{v1}} = {mm_text(c.r_v[0])}", ((P[0] + V1[0]) / 2.0, (P[1] + V1[1]) / 2.0), side, italic=False))
    items.append(_lbl(f"r_{{v2}} = {mm_text(c.r_v[1])}", ((P[0] + V2[0]) / 2.0, (P[1] + V2[1]) / 2.0), side, italic=False))
    return items


def virtual_items(c: BevelConstruction, mu: float) -> list[Primitive]:
    """The back cones developed: two pitch circles of radii r_v1, r_v2 touching at P."""
    r1, r2 = c.r_v[0] / mu, c.r_v[1] / mu
    o1, o2 = (0.0, 0.0), (0.0, r1 + r2)
    P = (0.0, r1)
    items: list[Primitive] = []
    for o, r in ((o1, r1), (o2, r2)):
        items.append(Polyline(arc_points(o, r, math.pi / 2.0 - 0.5 + (0.0 if o is o1 else math.pi),
                                         math.pi / 2.0 + 0.5 + (0.0 if o is o1 else math.pi)), "construction",
                              dashdot=True))
        items.append(Circle(o, 0.6, "result"))
    items += [Segment(o1, o2, "construction", dashdot=True), Circle(P, 0.6, "result"), _lbl("P", P, (0.0, 1.0), (0.0, -1.0)),
              _lbl("O_{v1}", o1, (0.0, 1.0)), _lbl("O_{v2}", o2, (0.0, -1.0))]
    items += dimension((-DIM, 0.0), (-DIM, r1), "r_{v1}", (-1.0, 0.0))
    items += dimension((-DIM, r1), (-DIM, r1 + r2), "r_{v2}", (-1.0, 0.0))
    return items


def bevel_panels(an: SpatialAnalysis, notation: str) -> list[Panel]:
    c: BevelConstruction = an.construction
    e = an.exact
    mu = an.scales["l"]
    sp = an.gears.spatial
    face = sp.face_width if sp is not None and sp.face_width is not None else c.R / 3.0
    sigma = sp.shaft_angle if sp is not None else 0.5 * math.pi
    panels = [Panel("cones", word("cones", notation, WORDS), tuple(cone_items(c, face, mu)),
                    (scale_text("l", mu), f"Σ = {_deg(sigma)}, δ_{{1}} = {_deg(c.delta[0])}, δ_{{2}} = {_deg(c.delta[1])}, "
                                          f"θ_{{a}} = {_deg(c.theta_a)}, θ_{{f}} = {_deg(c.theta_f)}",
                     f"d_{{a1}} = {mm_text(c.da[0])}, d_{{a2}} = {mm_text(c.da[1])}, d_{{f1}} = {mm_text(c.df[0])}, "
                     f"d_{{f2}} = {mm_text(c.df[1])}"), 0, (("l", mu),))]
    mu_v = _scale_for(2.0 * c.r_v[0] * math.sin(0.5), c.r_v[0] + c.r_v[1], (70.0, 110.0))
    panels.append(Panel("virtual", word("virtual", notation, WORDS), tuple(virtual_items(c, mu_v)),
                        (scale_text("l", mu_v), f"z_{{v1}} = z_{{1}}/cos δ_{{1}} = {number(e.zv[0])}, "
                                                f"z_{{v2}} = {number(e.zv[1])}"), 0, (("l", mu_v),)))
    return panels


def helix_sheet(an: SpatialAnalysis, page: tuple[float, float], footer: tuple[str, ...] = ()) -> Sheet:
    """The sheet of a helical, bevel or worm scene."""
    notation = an.scene.page.notation
    kind = an.gears.meshing
    panels = helical_panels(an, notation) if kind == "helical" else worm_panels(an, notation) if kind == "worm" \
        else bevel_panels(an, notation)
    return Sheet(an.scene.title, tuple(panels), page, footer)


__all__ = ["WORDS", "bevel_panels", "cone_items", "development_items", "helical_panels", "helix_sheet", "lead_items",
           "section_items", "thread_items", "virtual_items", "worm_panels"]
