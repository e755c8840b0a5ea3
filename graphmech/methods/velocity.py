"""The velocity polygon (速度多边形, план скоростей) at μv, pole p.

For each dyad the new image is the intersection of two lines through known images, each
line carrying one unknown of a vector equation, e.g. for an RRR dyad B–C–D

    v_C = v_B + v_CB (⟂ BC) = v_D + v_CD (⟂ DC):  c = (⟂BC through b) ∩ (⟂DC through d).

Points fixed on a link get their image by similarity (the velocity image, 速度影像).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING

from graphmech.geometry import kernels as K
from graphmech.mechanisms.linkage import PRP, Crank, Guide, LinkGuide, LinkPoint, RPP, RPR, RRP, RRR, SliderInput, Triad
from graphmech.methods import elements as E
from graphmech.methods.diagram import bar_direction
from graphmech.methods import measure
from graphmech.methods.linkage_construction import VELOCITY_POLE

if TYPE_CHECKING:
    from graphmech.geometry.kernels import Components, Ops
    from graphmech.methods.linkage_construction import LinkageConstruction
    from graphmech.mechanisms.linkage import Part

PANEL = "velocity"
POLE = VELOCITY_POLE  # pole p, named in linkage_construction: measure reads it too


def label(point: str) -> str:
    """The image letter of a point: B → b, C2 → c2."""
    return point.lower()


def add_pole(b: "LinkageConstruction") -> None:
    b.g.add(POLE, "point", lambda ops: (0.0, 0.0), (), role="result", text="pole p", panel=PANEL,
            label="p", say=("pole",))
    for name in b.linkage.frame_points:
        b.vel[name] = POLE  # fixed points have zero velocity: their image is the pole


def add(b: "LinkageConstruction", part: Part) -> None:
    build: dict[type, Callable[..., None]] = {Crank: _crank, SliderInput: _slider, RRR: _rrr, RRP: _rrp,
                                              RPR: _rpr, RPP: _rpp, PRP: _prp, LinkPoint: _point, Triad: _triad}
    build[type(part)](b, part)


def _img_label(b: "LinkageConstruction", point: str) -> str:
    return b.g.steps[b.vel[point]].label or "p"


def _crank(b: "LinkageConstruction", d: Crank) -> None:
    k = d.omega * b.mu_l / b.scales["v"]  # drawing mm of pb per drawing mm of AB

    def tip(ops: Ops, p: Components, a: Components, t: Components) -> Components:
        return (p[0] - k * (t[1] - a[1]), p[1] + k * (t[0] - a[0]))

    img = E.image(b, PANEL, b.vel, d.tip, label(d.tip), tip, (POLE, b.mech[d.pivot], b.mech[d.tip]),
                 f"p{label(d.tip)} ⟂ {d.pivot}{d.tip}, p{label(d.tip)} = ω{d.link}·l_{d.pivot}{d.tip}/μv", say=("crank", d.pivot, d.tip, d.link))
    E.vector(b, PANEL, POLE, img)
    measure.omega(b, d.link, d.pivot, d.tip)


def _slider(b: "LinkageConstruction", d: SliderInput) -> None:
    gx, gy = d.guide.direction
    k = d.velocity / b.scales["v"]
    img = E.image(b, PANEL, b.vel, d.point, label(d.point), lambda ops, p: (p[0] + k * gx, p[1] + k * gy), (POLE,),
                 f"p{label(d.point)} ∥ guide, p{label(d.point)} = v/μv", say=("slider", d.point))
    E.vector(b, PANEL, POLE, img)
    measure.zero_rate(b, d.link)


def _rrr(b: "LinkageConstruction", y: RRR) -> None:
    P, C, Q = y.p, y.c, y.q
    lp, lq, lc = _img_label(b, P), _img_label(b, Q), label(C)
    li = E.line(b, PANEL, f"⟂{P}·{C}@{lp}", K.line_perpendicular_to, (b.vel[P], E.direction(b, P, C)), f"through {lp} draw ⟂ {P}{C}",
                  say=("perp", P, C))
    lj = E.line(b, PANEL, f"⟂{Q}·{C}@{lq}", K.line_perpendicular_to, (b.vel[Q], E.direction(b, Q, C)), f"through {lq} draw ⟂ {Q}{C}",
                  say=("perp", Q, C))
    img = E.image(b, PANEL, b.vel, C, label(C), K.intersect_lines, (li, lj),
                 f"{lc} = (⟂{P}{C} through {lp}) ∩ (⟂{Q}{C} through {lq})", say=("meet",))
    b.g.extend_line(li, img)
    b.g.extend_line(lj, img)
    E.vector(b, PANEL, POLE, img)
    E.vector(b, PANEL, b.vel[P], img)
    E.vector(b, PANEL, b.vel[Q], img)
    measure.omega(b, y.links[0], P, C)
    measure.omega(b, y.links[1], Q, C)


def _rrp(b: "LinkageConstruction", y: RRP) -> None:
    # v_C = v_P + v_CP (⟂ PC) = v_C(guide) + v_rel (∥ guide): the guide's point at C has the image p
    # on the frame, c2 on a moving link (its velocity image)
    P, C = y.p, y.c
    lp, lc = _img_label(b, P), label(C)
    li = E.line(b, PANEL, f"⟂{P}·{C}@{lp}", K.line_perpendicular_to, (b.vel[P], E.direction(b, P, C)), f"through {lp} draw ⟂ {P}{C}",
                  say=("perp", P, C))
    lg = _along_guide(b, C, y.guide)
    through = _img_label(b, C + y.guide.link) if isinstance(y.guide, LinkGuide) else "p"
    img = E.image(b, PANEL, b.vel, C, label(C), K.intersect_lines, (li, lg),
                 f"{lc} = (⟂{P}{C} through {lp}) ∩ (∥ guide through {through})", say=("meet",))
    b.g.extend_line(li, img)
    b.g.extend_line(lg, img)
    E.vector(b, PANEL, POLE, img)
    E.vector(b, PANEL, b.vel[P], img)
    measure.omega(b, y.links[0], P, C)
    _slides(b, C, y.links[1], y.guide, img)


def _rpr(b: "LinkageConstruction", y: RPR) -> None:
    # v_X(bar) = v_(bar pivot) + v_X(bar),pivot (⟂ bar) = v_X(block) + v_rel (∥ bar)
    Bp, X = y.bar_pivot, y.block_pivot
    xbar, xblock = y.coincident
    b.vel[xblock] = b.vel[X]
    lp, lx, lc = _img_label(b, Bp), _img_label(b, X), label(xbar)
    lt = E.line(b, PANEL, f"⟂{Bp}·{X}@{lp}", K.line_perpendicular_to, (b.vel[Bp], E.direction(b, Bp, X)), f"through {lp} draw ⟂ {Bp}{X}",
                  say=("perp", Bp, X))
    first = Bp if y.offset == 0.0 else "F"  # an offset bar slides along its line FX, not OX
    along = first + X
    lr = E.line(b, PANEL, f"∥{first}·{X}@{lx}", K.line_parallel_to, (b.vel[X], bar_direction(b, y)),
                f"through {lx} draw ∥ {along}", say=("par", first, X))
    img = E.image(b, PANEL, b.vel, xbar, label(xbar), K.intersect_lines, (lt, lr),
                 f"{lc} = (⟂{Bp}{X} through {lp}) ∩ (∥{along} through {lx})", say=("meet",))
    b.g.extend_line(lt, img)
    b.g.extend_line(lr, img)
    E.vector(b, PANEL, POLE, img)
    E.vector(b, PANEL, b.vel[Bp], img)
    E.vector(b, PANEL, b.vel[X], img)
    measure.omega(b, y.bar_link, Bp, xbar)
    measure.same_rate(b, y.block_link, y.bar_link)
    b.coincident.append((xbar, xblock))


def _rpp(b: "LinkageConstruction", y: RPP) -> None:
    # v_P = v_P(slotted) + v_rel (∥ slot), v_P(slotted) = v_C (∥ guide): j translates.
    P, C = y.p, y.c
    gx, gy = y.guide.direction
    sx, sy = math.cos(y.slot_angle), math.sin(y.slot_angle)
    lp, lc = _img_label(b, P), label(C)
    lg = E.line(b, PANEL, f"∥guide{C}@p", lambda ops, t: K.line_fixed(ops, t, gx, gy), (POLE,),
               f"through p draw ∥ the guide of {C}", say=("guide", C))
    ls = E.line(b, PANEL, f"∥slot{C}@{lp}", lambda ops, t: K.line_fixed(ops, t, sx, sy), (b.vel[P],),
               f"through {lp} draw ∥ the slot", say=("slot", C))
    img = E.image(b, PANEL, b.vel, C, label(C), K.intersect_lines, (lg, ls),
                 f"{lc} = (∥ guide through p) ∩ (∥ slot through {lp})", say=("meet",))
    b.g.extend_line(lg, img)
    b.g.extend_line(ls, img)
    pblock, pslot = y.coincident
    b.vel[pblock] = b.vel[P]
    b.vel[pslot] = img
    E.vector(b, PANEL, POLE, img)
    E.vector(b, PANEL, img, b.vel[P])
    measure.zero_rate(b, y.links[0])
    measure.zero_rate(b, y.links[1])
    b.coincident.append((pblock, pslot))


def _along_guide(b: "LinkageConstruction", C: str, g: Guide | LinkGuide) -> str:
    """The line ∥ a guide that carries C's image: through p for a frame guide; for a guide on a
    moving link, through the image c1 of that link's point C1 at C (by the link's velocity image),
    since v_C = v_C1 + v_C2C1 (∥ the guide)."""
    if isinstance(g, Guide):
        gx, gy = g.direction
        return E.line(b, PANEL, f"∥guide{C}@p", lambda ops, t: K.line_fixed(ops, t, gx, gy), (POLE,),
                      f"through p draw ∥ the guide of {C}", say=("guide", C))
    U, V, on = g.through, g.towards, C + g.link
    img = E.image(b, PANEL, b.vel, on, label(on), K.similar_point,
                  (b.mech[U], b.mech[V], b.mech[on], b.vel[U], b.vel[V]),
                  f"{label(on)}: △{_img_label(b, U)}{_img_label(b, V)}{label(on)} ∼ △{U}{V}{on} (velocity image)",
                  say=("image", U, V, on))
    E.vector(b, PANEL, POLE, img)
    return E.line(b, PANEL, f"∥{U}·{V}@{label(on)}", K.line_parallel_to, (img, E.direction(b, U, V)),
                  f"through {label(on)} draw ∥ {U}{V}", say=("par", U, V))


def _slides(b: "LinkageConstruction", C: str, block: str, g: Guide | LinkGuide, img: str) -> None:
    """The block at C slides on g: on a moving link it turns with that link, and c1→c is the sliding
    velocity v_C2C1; on the frame it translates."""
    if isinstance(g, LinkGuide):
        on = C + g.link
        b.vel[C + block] = img
        E.vector(b, PANEL, b.vel[on], img)  # v_C2C1, the sliding velocity along the guide
        measure.same_rate(b, block, g.link)
        b.coincident.append((C + block, on))
    else:
        measure.zero_rate(b, block)


def _prp(b: "LinkageConstruction", y: PRP) -> None:
    # v_C = v_C1 + v_C2C1 (∥ guide 1) = v_C' + v_C3C' (∥ guide 2): C1 the guide link's point at C,
    # its image by the velocity image of that link; a frame guide's point is the pole.
    C = y.c
    lines = [_along_guide(b, C, g) for g in y.guides]
    img = E.image(b, PANEL, b.vel, C, label(C), K.intersect_lines, tuple(lines),
                  f"{label(C)} = the two lines ∥ the guides meet", say=("meet",))
    for ln in lines:
        b.g.extend_line(ln, img)
    E.vector(b, PANEL, POLE, img)
    for block, g in zip(y.links, y.guides):
        b.vel[C + block] = img
        _slides(b, C, block, g, img)


def _point(b: "LinkageConstruction", pt: LinkPoint) -> None:
    if len(pt.base) == 1:  # a translating link: every point has the same velocity
        b.vel[pt.name] = b.vel[pt.base[0]]
        return
    U, V = pt.base
    img = E.image(b, PANEL, b.vel, pt.name, label(pt.name), K.similar_point,
                 (b.mech[U], b.mech[V], b.mech[pt.name], b.vel[U], b.vel[V]),
                 f"{label(pt.name)}: △{label(U)}{label(V)}{label(pt.name)} ∼ △{U}{V}{pt.name} (velocity image)", say=("image", U, V, pt.name))
    E.vector(b, PANEL, POLE, img)
    E.vector(b, PANEL, b.vel[U], img, "construction", kind="segment")
    E.vector(b, PANEL, b.vel[V], img, "construction", kind="segment")


def assur_name(y: Triad) -> str:
    """The step (and ``b.mech`` key) of a class III group's special point S on the kinematic diagram."""
    return E.own("mechanism", f"S{''.join(y.inner)}")


def leg_line(b: LinkageConstruction, y: Triad, n: int) -> str:
    """Leg n's line on the kinematic diagram, on which Assur's point S may lie: its binary link
    extended, or on a slider leg the normal to the guide at its pin (the pin moves along the guide,
    so a point of the ternary link on that normal moves relative to the pin along the guide too)."""
    P, X = y.outer[n], y.inner[n]
    g = y.guides[n]
    if g is None:
        return b.g.add(f"m:{P}{X}-line", "line", K.line_parallel_to, (b.mech[P], E.direction(b, P, X)),
                       role="construction", text=f"extend {P}{X}", panel="mechanism")
    nx, ny = -g.direction[1], g.direction[0]
    return b.g.add(f"m:{X}-normal", "line", lambda ops, t: K.line_fixed(ops, t, nx, ny), (b.mech[X],),
                   role="construction", text=f"the normal to {X}'s guide at {X}", panel="mechanism")


def assur_point(b: "LinkageConstruction", y: Triad) -> str:
    """The special (Assur) point S of a class III group on the kinematic diagram: where the lines
    of two binary links meet (``y.assur``; a slider leg's line is the normal to its guide), a
    point of the ternary link. Made once, shared by both polygons."""
    i, j = y.assur
    (P, X), (Q, Z) = (y.outer[i], y.inner[i]), (y.outer[j], y.inner[j])
    name = assur_name(y)
    if b.g.has(name):
        return name
    li, lj = leg_line(b, y, i), leg_line(b, y, j)
    s = b.g.add(name, "point", K.intersect_lines, (li, lj), role="construction",
                text=f"S = {P}{X if P != X else '⊥'} ∩ {Q}{Z if Q != Z else '⊥'} (Assur's special point of the ternary link)",
                panel="mechanism",
                label="S", say=("assur", P, X, Q, Z))
    b.g.extend_line(li, b.mech[X], s)
    b.g.extend_line(lj, b.mech[Z], s)
    b.mech[name] = s  # drawn on the kinematic diagram by its step name (no point name is one)
    return s


def mech_direction(b: "LinkageConstruction", a: str, c: str, text: str) -> str:
    """The direction between two steps of the kinematic diagram (a point that is no named point: S)."""
    name = f"dir:{a}->{c}"
    if not b.g.has(name):
        b.g.add(name, "scalar", K.unit, (a, c), role="hidden", text=f"direction {text}", panel="mechanism")
    return name


def _leg_words(b: LinkageConstruction, y: Triad, n: int) -> str:
    """Leg n's line in the velocity polygon, in words: ⟂ its binary link, or ∥ its guide through p."""
    P, X = y.outer[n], y.inner[n]
    return f"∥ the guide of {X} through p" if y.slides(n) else f"⟂{P}{X} through {_img_label(b, P)}"


def _triad(b: "LinkageConstruction", y: Triad) -> None:
    # Assur's special point S (on BC and FD, a point of the ternary link): v_S = v_B + (⟂BC) = v_F + (⟂FD)
    C, D, Ec = y.inner
    i, j = y.assur
    k = 3 - i - j  # the third binary link
    S = assur_point(b, y)
    perp: dict[int, str] = {}
    for n in range(3):
        P, X = y.outer[n], y.inner[n]
        g = y.guides[n]
        if g is not None:  # a slider leg: v_X ∥ its guide, through p
            perp[n] = _along_guide(b, X, g)
            continue
        lp = _img_label(b, P)
        perp[n] = E.line(b, PANEL, f"⟂{P}·{X}@{lp}", K.line_perpendicular_to, (b.vel[P], E.direction(b, P, X)),
                         f"through {lp} draw ⟂ {P}{X}", say=("perp", P, X))
    tag = "s"
    s = b.g.add(E.own(PANEL, tag), "point", K.intersect_lines, (perp[i], perp[j]), role="construction",
                text=f"s = ({_leg_words(b, y, i)}) ∩ ({_leg_words(b, y, j)}) (S on both lines)",
                panel=PANEL, label=tag, say=("meet",))
    b.g.extend_line(perp[i], s)
    b.g.extend_line(perp[j], s)
    # The third joint X3 from S: v_X3 = v_S + (⟂ S X3) = v_outer + (⟂ outer X3)
    X3 = y.inner[k]
    ls = E.line(b, PANEL, f"⟂S·{X3}@s", K.line_perpendicular_to, (s, mech_direction(b, S, b.mech[X3], f"S{X3}")),
                f"through s draw ⟂ S{X3}", say=("perp", "S", X3))
    img3 = E.image(b, PANEL, b.vel, X3, label(X3), K.intersect_lines, (ls, perp[k]),
                   f"{label(X3)} = (⟂S{X3} through s) ∩ ({_leg_words(b, y, k)})", say=("meet",))
    b.g.extend_line(ls, s, img3)
    b.g.extend_line(perp[k], img3)
    # The other two joints by the velocity image of the ternary link: △s x3 x ∼ △S X3 X (they lie on
    # the lines ⟂ their binary links through the outer joints' images too: drawn through them)
    for n in (i, j):
        P, X = y.outer[n], y.inner[n]
        img = E.image(b, PANEL, b.vel, X, label(X), K.similar_point, (S, b.mech[X3], b.mech[X], s, img3),
                      f"{label(X)}: △s{label(X3)}{label(X)} ∼ △S{X3}{X} (velocity image)", say=("image", "S", X3, X))
        b.g.extend_line(perp[n], img)
    for n in range(3):
        P, X = y.outer[n], y.inner[n]
        E.vector(b, PANEL, POLE, b.vel[X])
        if y.slides(n):  # a block on a frame guide translates
            measure.zero_rate(b, y.links[n])
            continue
        E.vector(b, PANEL, b.vel[P], b.vel[X])
        measure.omega(b, y.links[n], P, X)
    for U, V in ((C, D), (D, Ec), (Ec, C)):  # the ternary link's velocity image
        E.vector(b, PANEL, b.vel[U], b.vel[V], "construction", kind="segment")
    measure.omega(b, y.links[3], C, D)
