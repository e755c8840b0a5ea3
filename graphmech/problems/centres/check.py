"""Checking an instant-centre scene given by its direct centres (``[centres]``).

The construction, as the book does it on the drawing (μl): the direct centres — each revolute
P_ij at its joint (a compound hinge: every two of its links), each pure rolling contact P_ij at
the point where the two wheels touch — then every other centre by Kennedy's theorem
(:func:`graphmech.methods.instant_centres.kennedy`, the linkage's own code), every ω from the
driver's by ``ω_j = ω_i·P_kiP_ij/P_kjP_ij`` (k the frame), and the ratio as the book writes it,
``ω_i/ω_j = P_jkP_ij / P_ikP_ij`` with signed lengths on the line of the three centres: P_ij
between P_ik and P_jk (it divides them internally) — the two turn in opposite senses; outside
— in the same sense. Three direct centres of three links that are not on one line contradict
Kennedy's theorem: the pairs lock the mechanism, and the scene is refused.

Checked against :mod:`graphmech.exact.rolling` (the pairs' velocity equations solved by least
squares), which shares nothing with the construction.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import combinations
from typing import TYPE_CHECKING, Any

from graphmech.errors import SceneError
from graphmech.exact.rolling import twists
from graphmech.methods.instant_centres import (
    Centre,
    InstantCentres,
    LinkMotion,
    centre_name,
    kennedy,
    motions_from,
    pair,
)
from graphmech.problems.centres.scene import CentresScene, parse_name
from graphmech.problems.judging import Row, Verdict, judge_value, measured_entries
from graphmech.scales import drawn_size_problem, format_scale, round_scale

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene

#: The mechanism's size on paper when graphmech chooses μl, mm.
DRAWN_MM = 150.0
#: A direct centre farther than this from the line of two others (relative to the size) breaks Kennedy.
LINE_REL = 1e-9


@dataclass
class CentresAnalysis:
    """The centres (drawing mm at μl), the check rows and the exact twists."""

    scene: Scene[CentresScene]
    ic: InstantCentres
    mu_l: float
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)
    stated: bool = False
    exact: dict[str, tuple[float, float, float]] = field(default_factory=dict)
    extra_measured: tuple[tuple[str, float], ...] = ()

    def scale_notes(self) -> list[str]:
        return [format_scale(k, v) + ("" if self.stated else " (chosen)") for k, v in self.scales.items()]

    def summary(self) -> dict[str, Any]:
        """The ``"instant_centres"`` section of ``check --json``: every centre (m) and each ω by the centres."""
        out: dict[str, Any] = {}
        for key in self.ic.order:
            c = self.ic.centres[key]
            d: dict[str, Any] = {"kind": c.kind, "via": list(c.via)}
            if c.point is not None:
                d.update(x=c.point[0] * self.mu_l, y=c.point[1] * self.mu_l)
            elif c.direction is not None:
                d["direction_deg"] = math.degrees(math.atan2(c.direction[1], c.direction[0])) % 180.0
            else:
                d["why"] = c.why
            out[centre_name(*key)] = d
        omegas = {k: m.omega for k, m in self.ic.motions.items() if k != self.ic.frame}
        return {"instant_centres": {"centres": out, "omega": omegas, "undetermined": dict(self.ic.undetermined)}}


def construct(scene: Scene[CentresScene]) -> tuple[InstantCentres, float, bool]:
    """The centres on the drawing at μl (stated, or chosen to draw the mechanism ~:data:`DRAWN_MM` across)."""
    d = scene.problem.drive
    xy = list(d.points.values()) + [c.at for c in d.contacts]
    xy += [(d.points[w.centre][0] + s * w.radius, d.points[w.centre][1] + s * w.radius)
           for w in d.wheels for s in (-1.0, 1.0)]
    size_m = max(max(p[0] for p in xy) - min(p[0] for p in xy), max(p[1] for p in xy) - min(p[1] for p in xy))
    if "l" in scene.scales:
        mu = float(scene.scales["l"])
        why = drawn_size_problem(size_m, mu)
        if why:
            raise SceneError([("scales", why)], scene.source)
    else:
        mu = round_scale(max(size_m, 1e-12) / DRAWN_MM)
    links = d.links()
    size = size_m / mu
    centres: dict[tuple[str, str], Centre] = {}
    order: list[tuple[str, str]] = []

    def direct(i: str, j: str, p: tuple[float, float], via: str) -> None:
        key = pair(links, i, j)
        if key in centres:
            raise SceneError([("centres", (f"{centre_name(*key)} is stated twice (links {i} and {j} are joined "
                                          "by two pairs)"))], scene.source)
        centres[key] = Centre(key, "direct", (p[0] / mu, p[1] / mu), None, (via,))
        order.append(key)

    for r in d.revolutes:
        for i, j in combinations(r.links, 2):
            direct(i, j, d.points[r.at], r.at)
    for c in d.contacts:
        direct(c.links[0], c.links[1], c.at, "rolling")
    _kennedy_holds(scene, links, centres, size)
    kennedy(links, centres, order, size)
    w = d.omega
    a = centres[pair(links, d.frame, d.driver)].point
    assert a is not None
    start = {d.frame: LinkMotion(d.frame, 0.0, (0.0, 0.0), ("frame",)),
             d.driver: LinkMotion(d.driver, w, (w * a[1], -w * a[0]), ("driver",))}
    motions, undetermined = motions_from(links, d.frame, centres, start, size)
    return InstantCentres(links, d.frame, centres, tuple(order), motions, undetermined, size), mu, "l" in scene.scales


def _kennedy_holds(scene: Scene[CentresScene], links: tuple[str, ...], centres: dict[tuple[str, str], Centre],
                   size: float) -> None:
    """Three direct centres of three links lie on one line, or the pairs lock the links."""
    for i, j, k in combinations(links, 3):
        keys = (pair(links, i, j), pair(links, j, k), pair(links, i, k))
        pts = [centres[x].point for x in keys if x in centres]
        if len(pts) < 3:
            continue
        (x1, y1), (x2, y2), (x3, y3) = (p for p in pts if p is not None)
        base = max(math.dist((x1, y1), (x3, y3)), math.dist((x1, y1), (x2, y2)), math.dist((x2, y2), (x3, y3)))
        if base == 0.0:
            continue
        off = abs((x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)) / base
        if off > LINE_REL * size:
            names = [centre_name(*x) for x in keys]
            raise SceneError([("centres", (f"{names[0]}, {names[1]} and {names[2]} are not on one line "
                                          f"({off * 1.0:.3g} mm off at μl): by Kennedy's theorem the pairs "
                                          f"lock links {i}, {j}, {k}"))], scene.source)


def ratio(ic: InstantCentres, i: str, j: str) -> tuple[float, float, float] | str:
    """ω_i/ω_j by the book's ratio: ``(P_jkP_ij, P_ikP_ij, ratio)`` (signed mm on their line, k the
    frame), or why it cannot be read (a centre undetermined or at infinity, a zero length)."""
    k = ic.frame
    cs = [ic.centre(i, j), ic.centre(j, k), ic.centre(i, k)]
    for c in cs:
        if c.point is None:
            return f"{centre_name(*c.links)} is " + ("at infinity" if c.at_infinity else "undetermined")
    pij, pjk, pik = (c.point for c in cs if c.point is not None)
    ux, uy = pij[0] - pik[0], pij[1] - pik[1]
    den = math.hypot(ux, uy)
    if den <= 1e-9 * ic.size:
        return f"{centre_name(*cs[0].links)} coincides with {centre_name(*cs[2].links)}: ω{j} = 0 there"
    ux, uy = ux / den, uy / den
    num = (pij[0] - pjk[0]) * ux + (pij[1] - pjk[1]) * uy
    return num, den, num / den


def _exact_centre(ex: dict[str, tuple[float, float, float]], a: str, b: str) -> tuple[float, float] | None:
    wa, ax, ay = ex[a]
    wb, bx, by = ex[b]
    dw = wa - wb
    return None if dw == 0.0 else (-(ay - by) / dw + 0.0, (ax - bx) / dw + 0.0)


def analyse_centres(scene: Scene[CentresScene], extra: tuple[tuple[str, float], ...] = ()) -> CentresAnalysis:
    """Construct the centres and build the check table of what ``find`` asks (everything when empty)."""
    from graphmech.errors import GraphmechError

    ic, mu, stated = construct(scene)
    an = CentresAnalysis(scene, ic, mu, scales={"l": mu}, stated=stated, extra_measured=tuple(extra))
    try:
        an.exact = twists(scene.problem.drive)
    except GraphmechError as e:
        raise SceneError([("centres", str(e))], scene.source) from None
    for j, why in ic.undetermined.items():
        an.warnings.append(f"ω{j} is undetermined: {why}")
    names = list(scene.find) or _defaults(ic, scene.problem)
    for k, name in enumerate(names):
        got = _row(an, name)
        if isinstance(got, str):
            raise SceneError([(f"find[{k}]" if scene.find else "centres", got)], scene.source)
        an.rows.extend(got)
    return an


def _defaults(ic: InstantCentres, p: CentresScene) -> list[str]:
    """Without ``find``: every centre, each ω, and the driver's ratio to every other moving link."""
    moving = [x for x in ic.links if x != ic.frame]
    return ([centre_name(*k) for k in ic.order if ic.centres[k].point is not None]
            + [f"omega_{x}_ic" for x in moving if x != p.drive.driver and x in ic.motions]
            + [f"ratio_{p.drive.driver}_{x}" for x in moving if x != p.drive.driver and x in ic.motions])


def _row(an: CentresAnalysis, name: str) -> list[Row] | str:
    ic, mu, ex = an.ic, an.mu_l, an.exact
    parsed = parse_name(name.partition("@")[0], ic.links)
    assert parsed is not None  # the reader refused other names
    kind, args = parsed
    if kind == "centre":
        coord, i, j = args
        c = ic.centre(i, j)
        e = _exact_centre(ex, i, j)
        if c.point is None or e is None:
            why = c.why or "at infinity"
            return f"{centre_name(i, j)}: {why} (no finite point to report)"
        out = []
        for axis, g, ev in (("x_", c.point[0], e[0]), ("y_", c.point[1], e[1])):
            if coord in ("", axis):
                out.append(Row(f"{axis}{centre_name(i, j)}", "m", g, mu, g * mu, ev,
                               abs(g * mu - ev) / max(ic.size * mu, 1e-300)))
        return out
    if kind == "omega":
        k = args[0]
        m = ic.motions.get(k)
        if m is None:
            return f"ω{k} is undetermined: {ic.undetermined.get(k, '')}"
        we = ex[k][0]
        return [Row(name, "rad/s", m.drawn, m.scale if m.scale is not None else 1.0, m.omega, we,
                    abs(m.omega - we) / max(abs(we), abs(an.scene.problem.drive.omega)))]
    i, j = args
    r = ratio(ic, i, j)
    if isinstance(r, str):
        return f"{name}: {r}"
    num, den, g = r
    re_ = ex[i][0] / ex[j][0] if ex[j][0] != 0.0 else math.inf
    if not math.isfinite(re_):
        return f"{name}: ω{j} = 0 exactly"
    return [Row(name, "", num, 1.0 / den, g, re_, abs(g - re_) / max(abs(re_), 1.0))]


def judge_centres(an: CentresAnalysis) -> list[Verdict]:
    """Hand values: a centre's coordinate within the drawing precision × μl, ω and a ratio within 0.1 %."""
    rows = {r.name: r for r in an.rows}
    out = []
    for key, name, value in measured_entries(an.scene, an.extra_measured):
        r = rows.get(name)
        if r is None:
            got = _row(an, name)
            if isinstance(got, str):
                raise SceneError([(key, got)], an.scene.source)
            r = next((x for x in got if x.name == name), None)
            if r is None:  # P12 as a measured name: it is two values
                raise SceneError([(key, f"{name} is a point: give x_{name} and y_{name}")], an.scene.source)
        drawn = r.drawn_mm if r.unit == "m" else None
        out.append(judge_value(name, value, r.graphical, drawn, r.scale, an.scene.precision_mm, r.unit))
    return out


def text_lines(an: CentresAnalysis) -> list[str]:
    """The centres and the book's ratios, under the text table."""
    ic = an.ic
    lines = []
    for key in ic.order:
        c = ic.centres[key]
        how = ("direct, " + ("rolling contact" if c.via == ("rolling",) else f"at {c.via[0]}")) \
            if c.kind == "direct" else (f"Kennedy, via links {', '.join(c.via)}" if c.kind == "kennedy" else c.why)
        where = "" if c.point is None else f" ({c.point[0] * an.mu_l * 1e3:.6g}, {c.point[1] * an.mu_l * 1e3:.6g}) mm"
        lines.append(f"{centre_name(*key)}{where}: {how}")
    for r in an.rows:
        if r.name.startswith("ratio_"):
            i, j = r.name[len("ratio_"):].split("_")
            k = ic.frame
            sense = "opposite senses" if r.graphical < 0 else "the same sense"
            lines.append(f"ω{i}/ω{j} = {centre_name(*pair(ic.links, j, k))}{centre_name(*pair(ic.links, i, j))} / "
                         f"{centre_name(*pair(ic.links, i, k))}{centre_name(*pair(ic.links, i, j))} = "
                         f"{r.graphical:.6g} ({sense})")
    return lines


def centres_steps(scene: Scene[CentresScene]) -> list[str]:
    """The construction protocol: the direct centres, Kennedy's lines, the ratios."""
    an = analyse_centres(scene)
    ic = an.ic
    out = [f"Number the links {', '.join(ic.links)} (the frame {ic.frame}) and put them on the polygon of links."]
    for key in ic.order:
        c = ic.centres[key]
        n = centre_name(*key)
        if c.kind == "direct":
            out.append(f"{n}: " + ("where the two wheels touch (pure rolling: no slip, the same velocity)"
                                   if c.via == ("rolling",) else f"the revolute {c.via[0]}") + "; a solid chord.")
        elif c.kind == "kennedy":
            k, m = c.via
            out.append(f"{n} by Kennedy's theorem: where the lines {centre_name(*pair(ic.links, key[0], k))}"
                       f"{centre_name(*pair(ic.links, k, key[1]))} and {centre_name(*pair(ic.links, key[0], m))}"
                       f"{centre_name(*pair(ic.links, m, key[1]))} meet; a dashed chord.")
        else:
            out.append(f"{n} is undetermined: {c.why}.")
    for i, j, k in combinations(ic.links, 3):  # the direct centres obey Kennedy: three of three links in line
        keys = (pair(ic.links, i, j), pair(ic.links, j, k), pair(ic.links, i, k))
        cs = [ic.centres[x] for x in keys]
        ps = [c.point for c in cs if c.kind == "direct" and c.point is not None]
        if len(ps) == 3 and min(math.dist(p, q) for p, q in combinations(ps, 2)) > 1e-9 * ic.size:
            out.append(f"Kennedy's theorem: {', '.join(centre_name(*x) for x in keys[:2])} and "
                       f"{centre_name(*keys[2])} lie on one line (checked).")
    out.extend(text_lines(an)[len(ic.order):])
    return out


__all__ = ["CentresAnalysis", "analyse_centres", "centres_steps", "construct", "judge_centres", "ratio",
           "text_lines"]
