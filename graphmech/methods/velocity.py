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
from graphmech.mechanisms.linkage import PRP, Crank, Guide, LinkGuide, LinkPoint, RPP, RPR, RRP, RRR, SliderInput
from graphmech.methods import elements as E
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
                                              RPR: _rpr, RPP: _rpp, PRP: _prp, LinkPoint: _point}
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
    lr = E.line(b, PANEL, f"∥{Bp}·{X}@{lx}", K.line_parallel_to, (b.vel[X], E.direction(b, Bp, X)), f"through {lx} draw ∥ {Bp}{X}",
                  say=("par", Bp, X))
    img = E.image(b, PANEL, b.vel, xbar, label(xbar), K.intersect_lines, (lt, lr),
                 f"{lc} = (⟂{Bp}{X} through {lp}) ∩ (∥{Bp}{X} through {lx})", say=("meet",))
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
