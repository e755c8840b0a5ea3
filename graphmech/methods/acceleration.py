"""The acceleration polygon (加速度多边形, план ускорений) at μa, pole p′.

Normal components are laid off from the ω read off the velocity polygon; the tangential
component's direction is known, its size is not, so it is a line; two such lines meet at the
new image. For an RRR dyad B–C–D

    a_C = a_B + a^n_CB (C→B, ω2²·l_BC) + a^t_CB (⟂ BC) = a_D + a^n_CD + a^t_CD,

and for coincident points on a sliding pair the Coriolis component a^k = 2ω×v_rel is laid off
(v_rel turned 90° in the sense of ω) and the relative acceleration runs ∥ the bar.
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
from graphmech.methods.linkage_construction import ACCELERATION_POLE
from graphmech.methods.quantities import Quantity

if TYPE_CHECKING:
    from graphmech.geometry.kernels import Components, Ops
    from graphmech.methods.linkage_construction import LinkageConstruction
    from graphmech.mechanisms.linkage import Part

PANEL = "acceleration"
POLE = ACCELERATION_POLE  # pole p′, named in linkage_construction: measure reads it too


def label(point: str) -> str:
    """The image letter of a point: B → b', C2 → c2'."""
    return point.lower() + "'"


def add_pole(b: "LinkageConstruction") -> None:
    b.g.add(POLE, "point", lambda ops: (0.0, 0.0), (), role="result", text="pole p′", panel=PANEL,
            label="p'", say=("pole",))
    for name in b.linkage.frame_points:
        b.acc[name] = POLE


def add(b: "LinkageConstruction", part: Part) -> None:
    build: dict[type, Callable[..., None]] = {Crank: _crank, SliderInput: _slider, RRR: _rrr, RRP: _rrp,
                                              RPR: _rpr, RPP: _rpp, PRP: _prp, LinkPoint: _point, Triad: _triad}
    build[type(part)](b, part)


def _lbl(b: "LinkageConstruction", slot: str) -> str:
    return b.g.steps[slot].label or ""


def _normal(b: "LinkageConstruction", link: str, X: str, Y: str) -> str:
    """Lay off a^n_XY = ω²·l_XY (from X towards Y) from Y's image: the point n′ of ``link``.

    X moves relative to Y on ``link``; the component points from X to Y.
    """
    k = b.mu_l / b.scales["a"]
    tag = f"n{link}'"
    while b.g.has(E.own(PANEL, tag)):
        tag += "'"

    def kern(ops: Ops, start: Components, x: Components, y: Components, om: Components) -> Components:
        w2 = (om[0] * om[1]) ** 2
        return (start[0] + w2 * k * (y[0] - x[0]), start[1] + w2 * k * (y[1] - x[1]))

    n = b.g.add(E.own(PANEL, tag), "point", kern, (b.acc[Y], b.mech[X], b.mech[Y], b.omega[link]),
                role="construction", panel=PANEL, label=tag,
                text=f"lay off {_lbl(b, b.acc[Y])}{tag} = ω{link}²·l_{X}{Y}/μa ∥ {X}{Y}", say=("normal", link, X, Y))
    E.vector(b, PANEL, b.acc[Y], n, "construction")
    measure.component(b, f"a_{X}{Y}_n", b.acc[Y], n, ("normal", X, Y, link))
    return n


def _tangential_line(b: "LinkageConstruction", n: str, X: str, Y: str) -> str:
    return E.line(b, PANEL, f"⟂{Y}·{X}@{_lbl(b, n)}",
                 K.line_perpendicular_to, (n, E.direction(b, Y, X)), f"through {_lbl(b, n)} draw ⟂ {Y}{X} (a^t_{X}{Y})",
                  say=("perp", Y, X, f"a^t_{X}{Y}"))


def _close(b: "LinkageConstruction", link: str, X: str, Y: str, n: str, img: str) -> None:
    """Draw and measure the tangential component n→img and read α of the link from it."""
    E.vector(b, PANEL, n, img, "construction")
    measure.component(b, f"a_{X}{Y}_t", n, img, ("tangential", X, Y, link))
    measure.alpha(b, link, Y, X, n, img)


def _crank(b: "LinkageConstruction", d: Crank) -> None:
    k = b.mu_l / b.scales["a"]
    A, B = d.pivot, d.tip
    w2, eps = d.omega ** 2, d.epsilon

    def tip(ops: Ops, p: Components, a: Components, t: Components) -> Components:
        # a_B = ω²·(A − B) + ε·(B − A) turned 90° CCW
        rx, ry = t[0] - a[0], t[1] - a[1]
        return (p[0] + k * (-w2 * rx - eps * ry), p[1] + k * (-w2 * ry + eps * rx))

    img = E.image(b, PANEL, b.acc, B, label(B), tip, (POLE, b.mech[A], b.mech[B]),
                 f"p′{label(B)} = a_{B}: ω{d.link}²·l_{A}{B}/μa ∥ {B}{A} + ε{d.link}·l_{A}{B}/μa ⟂ {A}{B}", say=("crank", d.pivot, d.tip, d.link))
    E.vector(b, PANEL, POLE, img)
    if eps != 0.0:
        n = _normal(b, d.link, B, A)
        _close(b, d.link, B, A, n, img)
    else:
        measure.component(b, f"a_{B}{A}_n", POLE, img, ("normal", B, A, d.link))
        measure.component(b, f"a_{B}{A}_t", img, img, ("tangential", B, A, d.link))
        measure.alpha(b, d.link, A, B, img, img)
    for c in ("n", "t"):  # the book also writes a^n_B, a^t_B for a crank's tip
        q = b.quantities[f"a_{B}{A}_{c}"]
        b.quantity(Quantity(f"a_{B}_{c}", q.unit, q.slot, q.exact, q.panel, q.segment))


def _slider(b: "LinkageConstruction", d: SliderInput) -> None:
    gx, gy = d.guide.direction
    k = d.acceleration / b.scales["a"]
    img = E.image(b, PANEL, b.acc, d.point, label(d.point), lambda ops, p: (p[0] + k * gx, p[1] + k * gy), (POLE,),
                 f"p′{label(d.point)} ∥ guide, = a/μa", say=("slider", d.point))
    E.vector(b, PANEL, POLE, img)


def _rrr(b: "LinkageConstruction", y: RRR) -> None:
    P, C, Q = y.p, y.c, y.q
    i, j = y.links
    ni = _normal(b, i, C, P)
    nj = _normal(b, j, C, Q)
    li = _tangential_line(b, ni, C, P)
    lj = _tangential_line(b, nj, C, Q)
    img = E.image(b, PANEL, b.acc, C, label(C), K.intersect_lines, (li, lj),
                 f"{label(C)} = (⟂{P}{C} through {_lbl(b, ni)}) ∩ (⟂{Q}{C} through {_lbl(b, nj)})", say=("meet",))
    b.g.extend_line(li, img)
    b.g.extend_line(lj, img)
    E.vector(b, PANEL, POLE, img)
    _close(b, i, C, P, ni, img)
    _close(b, j, C, Q, nj, img)


def _rrp(b: "LinkageConstruction", y: RRP) -> None:
    # a_C = a_P + a^n_CP + a^t_CP (⟂ PC) = a_C(guide) + a^k + a^r (∥ guide); on the frame only a^r, from p′
    P, C = y.p, y.c
    n = _normal(b, y.links[0], C, P)
    lt = _tangential_line(b, n, C, P)
    lg, kp = _along_guide(b, C, y.links[1], y.guide)
    img = E.image(b, PANEL, b.acc, C, label(C), K.intersect_lines, (lt, lg),
                 f"{label(C)} = (⟂{P}{C} through {_lbl(b, n)}) ∩ (∥ guide through {_lbl(b, kp) if kp else 'p′'})",
                  say=("meet",))
    b.g.extend_line(lt, img)
    b.g.extend_line(lg, img)
    E.vector(b, PANEL, POLE, img)
    _close(b, y.links[0], C, P, n, img)
    _slides(b, C, y.links[1], y.guide, kp, img)


def _coriolis(b: "LinkageConstruction", start: str, link: str, x: str, y: str) -> tuple[str, str]:
    """Lay off a^k_XY = 2ω×v_XY from ``start`` (Y's image): the point k′; X slides on ``link``'s
    guide, Y is the guide's point; v_XY is turned 90° in the sense of ω. Returns (k′'s label, step)."""
    kk = 2.0 * b.scales["v"] / b.scales["a"]

    def coriolis(ops: Ops, s: Components, vx: Components, vy: Components, om: Components) -> Components:
        w = om[0] * om[1]
        rx, ry = vx[0] - vy[0], vx[1] - vy[1]
        return (s[0] - kk * w * ry, s[1] + kk * w * rx)

    ktag = "k'"
    while b.g.has(E.own(PANEL, ktag)):
        ktag += "'"
    k = b.g.add(E.own(PANEL, ktag), "point", coriolis, (start, b.vel[x], b.vel[y], b.omega[link]),
                role="construction", panel=PANEL, label=ktag,
                text=f"lay off {_lbl(b, start)}{ktag} = 2ω{link}·v_{x}{y}/μa (Coriolis)",
                say=("coriolis", link, x, y))
    E.vector(b, PANEL, start, k, "construction")
    return ktag, k


def _rpr(b: "LinkageConstruction", y: RPR) -> None:
    # a_X(bar) = a_pivot + a^n + a^t (⟂ bar) = a_X(block) + a^k + a^r (∥ bar)
    Bp, X = y.bar_pivot, y.block_pivot
    xbar, xblock = y.coincident
    bar = y.bar_link
    b.acc[xblock] = b.acc[X]
    n = _normal(b, bar, xbar, Bp)
    lt = _tangential_line(b, n, xbar, Bp)

    ktag, k = _coriolis(b, b.acc[X], bar, xbar, xblock)
    first = Bp if y.offset == 0.0 else "F"  # an offset bar slides along its line FX, not OX
    along = first + X
    lr = E.line(b, PANEL, f"∥{first}·{X}@{ktag}", K.line_parallel_to, (k, bar_direction(b, y)),
                f"through {ktag} draw ∥ {along} (a^r_{xbar}{xblock})", say=("par", first, X, f"a^r_{xbar}{xblock}"))
    img = E.image(b, PANEL, b.acc, xbar, label(xbar), K.intersect_lines, (lt, lr),
                 f"{label(xbar)} = (⟂{Bp}{X} through {_lbl(b, n)}) ∩ (∥{along} through {ktag})", say=("meet",))
    b.g.extend_line(lt, img)
    b.g.extend_line(lr, img)
    E.vector(b, PANEL, POLE, img)
    E.vector(b, PANEL, k, img, "construction")
    _close(b, bar, xbar, Bp, n, img)
    b.alpha[y.block_link] = b.alpha[bar]
    q = b.quantities[f"alpha_{bar}"]
    b.quantity(Quantity(f"alpha_{y.block_link}", q.unit, q.slot, ("alpha", y.block_link), q.panel, q.segment))
    measure.component(b, f"a_k_{xbar}{xblock}", b.acc[X], k, ("coriolis", xbar, xblock, bar))
    measure.component(b, f"a_r_{xbar}{xblock}", k, img, ("rel_slide_a", xbar, xblock, bar))


def _rpp(b: "LinkageConstruction", y: RPP) -> None:
    P, C = y.p, y.c
    gx, gy = y.guide.direction
    sx, sy = math.cos(y.slot_angle), math.sin(y.slot_angle)
    lg = E.line(b, PANEL, f"∥guide{C}@p'", lambda ops, t: K.line_fixed(ops, t, gx, gy), (POLE,),
               f"through p′ draw ∥ the guide of {C}", say=("guide", C))
    ls = E.line(b, PANEL, f"∥slot{C}@{_lbl(b, b.acc[P])}", lambda ops, t: K.line_fixed(ops, t, sx, sy), (b.acc[P],),
               f"through {_lbl(b, b.acc[P])} draw ∥ the slot", say=("slot", C))
    img = E.image(b, PANEL, b.acc, C, label(C), K.intersect_lines, (lg, ls),
                 f"{label(C)} = (∥ guide through p′) ∩ (∥ slot through {_lbl(b, b.acc[P])})", say=("meet",))
    b.g.extend_line(lg, img)
    b.g.extend_line(ls, img)
    pblock, pslot = y.coincident
    b.acc[pblock] = b.acc[P]
    b.acc[pslot] = img
    E.vector(b, PANEL, POLE, img)
    E.vector(b, PANEL, img, b.acc[P], "construction")


def _along_guide(b: "LinkageConstruction", C: str, block: str, g: Guide | LinkGuide) -> tuple[str, str | None]:
    """The line ∥ a guide that carries C's image, and the Coriolis point k′ it starts from (None on
    the frame: the line runs through p′). On a moving link: c1′ by the link's acceleration image,
    then a^k_C2C1 = 2ω×v_C2C1 laid off from it as its own side c1′k′, then the line ∥ the guide
    through k′ (a^r_C2C1)."""
    if isinstance(g, Guide):
        gx, gy = g.direction
        return E.line(b, PANEL, f"∥guide{C}@p'", lambda ops, t: K.line_fixed(ops, t, gx, gy), (POLE,),
                      f"through p′ draw ∥ the guide of {C}", say=("guide", C)), None
    U, V, on = g.through, g.towards, C + g.link
    img = E.image(b, PANEL, b.acc, on, label(on), K.similar_point,
                  (b.mech[U], b.mech[V], b.mech[on], b.acc[U], b.acc[V]),
                  f"{label(on)}: △{_lbl(b, b.acc[U])}{_lbl(b, b.acc[V])}{label(on)} ∼ △{U}{V}{on} "
                  "(acceleration image)", say=("image", U, V, on))
    E.vector(b, PANEL, POLE, img)
    ktag, kp = _coriolis(b, img, g.link, C + block, on)
    measure.component(b, f"a_k_{C}{block}{on}", img, kp, ("coriolis", C + block, on, g.link))
    line = E.line(b, PANEL, f"∥{U}·{V}@{ktag}", K.line_parallel_to, (kp, E.direction(b, U, V)),
                  f"through {ktag} draw ∥ {U}{V} (a^r_{C}{block}{on})", say=("par", U, V, f"a^r_{C}{block}{on}"))
    return line, kp


def _slides(b: "LinkageConstruction", C: str, block: str, g: Guide | LinkGuide, kp: str | None, img: str) -> None:
    """The block at C slides on g: on a moving link the side k′c′ is a^r_C2C1, and the block turns
    (α) with that link."""
    if not isinstance(g, LinkGuide) or kp is None:
        return
    on = C + g.link
    b.acc[C + block] = img
    E.vector(b, PANEL, kp, img, "construction")
    measure.component(b, f"a_r_{C}{block}{on}", kp, img, ("rel_slide_a", C + block, on, g.link))
    if g.link in b.alpha:
        b.alpha[block] = b.alpha[g.link]
        q = b.quantities[f"alpha_{g.link}"]
        b.quantity(Quantity(f"alpha_{block}", q.unit, q.slot, ("alpha", block), q.panel, q.segment))


def _prp(b: "LinkageConstruction", y: PRP) -> None:
    # a_C = a_C1 + a^k_C2C1 (2ω1×v_C2C1) + a^r_C2C1 (∥ guide 1) = … the same along guide 2;
    # a frame guide has no Coriolis term: the line ∥ it runs through p′.
    C = y.c
    found = [_along_guide(b, C, block, g) for block, g in zip(y.links, y.guides)]
    lines = tuple(line for line, _ in found)
    img = E.image(b, PANEL, b.acc, C, label(C), K.intersect_lines, lines,
                  f"{label(C)} = the two lines ∥ the guides meet", say=("meet",))
    for ln in lines:
        b.g.extend_line(ln, img)
    E.vector(b, PANEL, POLE, img)
    for (_, kp), block, g in zip(found, y.links, y.guides):
        b.acc[C + block] = img
        _slides(b, C, block, g, kp, img)


def _point(b: "LinkageConstruction", pt: LinkPoint) -> None:
    if len(pt.base) == 1:
        b.acc[pt.name] = b.acc[pt.base[0]]
        return
    U, V = pt.base
    img = E.image(b, PANEL, b.acc, pt.name, label(pt.name), K.similar_point,
                 (b.mech[U], b.mech[V], b.mech[pt.name], b.acc[U], b.acc[V]),
                 f"{label(pt.name)}: △{label(U)}{label(V)}{label(pt.name)} ∼ △{U}{V}{pt.name} (acceleration image)", say=("image", U, V, pt.name))
    E.vector(b, PANEL, POLE, img)
    E.vector(b, PANEL, b.acc[U], img, "construction", kind="segment")
    E.vector(b, PANEL, b.acc[V], img, "construction", kind="segment")


def _lay_normal(b: "LinkageConstruction", start: str, link: str, X: str, Y: str, tag: str, text: str,
                names: tuple[str, str]) -> str:
    """Lay off ω_link²·|XY|/μa from ``start`` in the sense X→Y (X, Y steps of the kinematic diagram,
    ``names`` their letters): a normal component of a point that is no named point (Assur's S)."""
    k = b.mu_l / b.scales["a"]

    def kern(ops: Ops, s: Components, x: Components, y: Components, om: Components) -> Components:
        w2 = (om[0] * om[1]) ** 2
        return (s[0] + w2 * k * (y[0] - x[0]), s[1] + w2 * k * (y[1] - x[1]))

    while b.g.has(E.own(PANEL, tag)):
        tag += "'"
    n = b.g.add(E.own(PANEL, tag), "point", kern, (start, X, Y, b.omega[link]), role="construction", panel=PANEL,
                label=tag, text=text, say=("normal", link, *names))
    E.vector(b, PANEL, start, n, "construction")
    return n


def _triad(b: "LinkageConstruction", y: Triad) -> None:
    # a_S = a_P + aⁿ_XP + aⁿ_SX + (⟂ PX) for both binary links whose lines meet at S (S on PX, so
    # both tangential terms are ⟂ PX); then the third joint from S, the other two from it. On a
    # slider leg (S on the normal to the guide at its pin X): a_S = a_X (∥ guide) + aⁿ_SX + a^t_SX
    # (∥ guide too), so the line is ∥ the guide through p′ + aⁿ_SX.
    from graphmech.methods.velocity import assur_point, mech_direction

    i, j = y.assur
    k = 3 - i - j
    t = y.links[3]
    S = assur_point(b, y)
    normal = {n: POLE if y.slides(n) else _normal(b, y.links[n], y.inner[n], y.outer[n]) for n in range(3)}
    tline = {n: _along_guide(b, y.inner[n], y.links[n], y.guides[n])[0] if y.slides(n)  # type: ignore[arg-type]
             else _tangential_line(b, normal[n], y.inner[n], y.outer[n]) for n in range(3)}
    via: dict[int, str] = {}
    for n in (i, j):
        X = y.inner[n]
        ns = _lay_normal(b, normal[n], t, S, b.mech[X], f"σ{n + 1}'",
                         f"lay off ω{t}²·l_S{X}/μa ∥ S{X} (aⁿ of S about {X})", ("S", X))
        g = y.guides[n]
        if g is not None:
            gx, gy = g.direction
            via[n] = E.line(b, PANEL, f"∥guide{X}@S{n}", lambda ops, p, gx=gx, gy=gy: K.line_fixed(ops, p, gx, gy),
                            (ns,), f"through it draw ∥ the guide of {X} (a^t_S{X} + a_{X})", say=("guide", X))
            continue
        via[n] = E.line(b, PANEL, f"⟂{y.outer[n]}·{X}@S{n}", K.line_perpendicular_to,
                        (ns, E.direction(b, y.outer[n], X)), f"through it draw ⟂ {y.outer[n]}{X} (a^t_S{X} + a^t_{X}{y.outer[n]})",
                        say=("perp", y.outer[n], X, f"a^t_S{X}"))
    s = b.g.add(E.own(PANEL, "s'"), "point", K.intersect_lines, (via[i], via[j]), role="construction",
                text="s′ = the two lines ⟂ to the binary links through S meet", panel=PANEL, label="s'", say=("meet",))
    b.g.extend_line(via[i], s)
    b.g.extend_line(via[j], s)
    P3, X3 = y.outer[k], y.inner[k]
    n3 = _lay_normal(b, s, t, b.mech[X3], S, f"n{t}'", f"lay off ω{t}²·l_{X3}S/μa ∥ {X3}S (aⁿ_{X3}S)", (X3, "S"))
    ls = E.line(b, PANEL, f"⟂S·{X3}@{n3}", K.line_perpendicular_to, (n3, mech_direction(b, S, b.mech[X3], f"S{X3}")),
                f"through it draw ⟂ S{X3} (a^t_{X3}S)", say=("perp", "S", X3, f"a^t_{X3}S"))
    third = f"∥ the guide of {X3} through p′" if y.slides(k) else f"⟂{P3}{X3} through {_lbl(b, normal[k])}"
    img3 = E.image(b, PANEL, b.acc, X3, label(X3), K.intersect_lines, (ls, tline[k]),
                   f"{label(X3)} = (⟂S{X3}) ∩ ({third})", say=("meet",))
    b.g.extend_line(ls, img3)
    b.g.extend_line(tline[k], img3)
    E.vector(b, PANEL, POLE, img3)
    if not y.slides(k):
        _close(b, y.links[k], X3, P3, normal[k], img3)
    # The other two joints by the acceleration image △s′x3′x′ ∼ △S X3 X; their tangential lines
    # ⟂ the binary links pass through them, and α of each link is read there.
    for n in (i, j):
        P, X = y.outer[n], y.inner[n]
        img = E.image(b, PANEL, b.acc, X, label(X), K.similar_point, (S, b.mech[X3], b.mech[X], s, img3),
                      f"{label(X)}: △s′{label(X3)}{label(X)} ∼ △S{X3}{X} (acceleration image)",
                      say=("image", "S", X3, X))
        b.g.extend_line(tline[n], img)
        E.vector(b, PANEL, POLE, img)
        if not y.slides(n):
            _close(b, y.links[n], X, P, normal[n], img)
        if n == i:  # α of the ternary link from a^t_{X X3} (one is enough)
            nt = _normal(b, t, X, X3)
            _close(b, t, X, X3, nt, img)
    C, D, Ec = y.inner
    for U, V in ((C, D), (D, Ec), (Ec, C)):  # the ternary link's acceleration image
        E.vector(b, PANEL, b.acc[U], b.acc[V], "construction", kind="segment")
