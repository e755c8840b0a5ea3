"""Checking the instant-centre method of a linkage scene against the exact kinematics.

A linkage scene asks for the instant centres with ``show = ["instant_centres"]`` (the centres,
the Kennedy lines and the polygon of links are drawn) and for values by name in ``find``:

``P13``             the centre: rows ``x_P13``, ``y_P13`` (m), or ``dir_P13`` (deg in [0, 180)) at infinity
``x_P13``, ``y_P13``, ``dir_P13``   one coordinate, or the direction of a centre at infinity
``omega_3_ic``      ω3 from the centres, ``ω3 = ω2·P12P23/P13P23`` (rad/s, + CCW)
``v_C_ic``          the speed of point C, ``|ω_k|·P1kC`` (m/s)
``v_min_BC_ic``     the least speed of the points of line BC (fixed on one link) (m/s) …
``s_min_BC_ic``     … and where that point E is: its signed distance from B along B→C (m)
``phi_v0_C``        the crank angles at which v_C = 0 (rows ``phi_v0_C_1``, ``phi_v0_C_2`` …, deg)

(``_ic`` tells these apart from the polygons' ``omega_3``, ``v_C``; ``@`` stays the position
suffix: ``omega_3_ic@165``.) Every value is compared with :mod:`graphmech.exact.linkage`, which
shares nothing with the construction: the exact centre P_ij is where the exact velocity fields
of links i and j agree, ``P = k × (v0_i − v0_j)/(ω_i − ω_j)`` (at infinity ⟂ ``v0_i − v0_j`` when
ω_i = ω_j); the exact zero-velocity angles are the roots of the exact ω_k(φ) or v(φ).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Callable, cast

import numpy as np

from graphmech import tolerances as T
from graphmech.errors import NotApplicable, OutOfDomain, SceneError
from graphmech.exact.linkage import Kinematics, solve as solve_exact
from graphmech.mechanisms.linkage import Crank, Linkage
from graphmech.methods.instant_centres import (InstantCentres, centre_name, common_link, instant_centres,
                                               instant_centres_batch,
                                               least_speed_on_line, pair, point_names, polygon_of_links,
                                               positions_mm, signed_rate, split_line)

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene

#: The ``show`` entry that draws the instant centres.
SHOW = "instant_centres"
#: Samples of the crank's turn searched for a vanishing velocity (then refined by Brent's method).
ZERO_SAMPLES = 720

_CENTRE = re.compile(r"(x_|y_|dir_)?P([0-9A-Za-z]+?)_?([0-9A-Za-z]+)")
_OMEGA = re.compile(r"omega_([0-9A-Za-z]{1,8})_ic")
_SPEED = re.compile(r"v_([A-Z]+[0-9]*['′]*)_ic")
_LEAST = re.compile(r"(v|s)_min_([A-Z][A-Z0-9'′]*)_ic")
_ZERO = re.compile(r"phi_v0_([A-Z]+[0-9]*['′]*)")
_ZERO_ROW = re.compile(r"phi_v0_([A-Z]+[0-9]*['′]*)_[0-9]+")  # one of its rows, as a measured name


def canonical(name: str) -> str:
    """``omega_3@ic`` (the alias) → ``omega_3_ic``; other names unchanged."""
    base, sep, rest = name.partition("@")
    if rest == "ic" or rest.startswith("ic@"):
        return base + "_ic" + rest[2:]
    return name


def claims(name: str) -> bool:
    """Whether a ``find`` name (with or without its ``@position``) is the instant-centre method's."""
    base = canonical(name).partition("@")[0]
    return any(p.fullmatch(base) for p in (_CENTRE, _OMEGA, _SPEED, _LEAST, _ZERO, _ZERO_ROW))


def asked(scene: Scene[object], extra_measured: tuple[tuple[str, float], ...] = ()) -> bool:
    """Whether the scene shows, finds or judges anything by instant centres."""
    return (SHOW in scene.show or any(claims(n) for n in scene.find)
            or any(claims(n) for n, _ in tuple(scene.measured) + tuple(extra_measured)))


@dataclass
class ICAnalysis:
    """Per position the centres (None where the position was not constructed) and the zero angles."""

    centres: list[InstantCentres | None]
    zeros: dict[str, list[float]] = field(default_factory=dict)  # point → crank angles (rad) with v = 0
    measured: dict[str, Any] = field(default_factory=dict)  # row name → Row, for judging [measured] values


# ---------------------------------------------------------------------------- the method at a position


def centres_at(an: Any, sol: Any) -> InstantCentres:
    return instant_centres(an.build.linkage, positions_mm(an.build, sol), mu_l=an.scales["l"])


# ---------------------------------------------------------------------------- exact counterparts


def _twist(linkage: Linkage, kin: Kinematics, link: str, i: int) -> tuple[float, float, float]:
    """Exact (ω, v0x, v0y): the link's velocity field ``v(X) = v0 + ω k×X`` (SI) at position i."""
    if link == linkage.frame_link:
        return 0.0, 0.0, 0.0
    w = float(kin.omega[link][i])
    x, y = kin.point[linkage.links()[link][0]][i]
    vx, vy = kin.vel[linkage.links()[link][0]][i]
    return w, float(vx + w * y), float(vy - w * x)


def exact_centre(linkage: Linkage, kin: Kinematics, a: str, b: str, i: int,
                 at_rest: float = 0.0) -> tuple[str, tuple[float, float]]:
    """``("point", (x, y))`` m, or ``("direction", (dx, dy))`` at infinity, or ``("none", …)``
    where links a and b are at relative rest: their relative speed nowhere exceeds ``at_rest``
    (m/s) over the mechanism's size (the centre of a motion that is not there is undefined)."""
    wa, ax, ay = _twist(linkage, kin, a, i)
    wb, bx, by = _twist(linkage, kin, b, i)
    dw, dvx, dvy = wa - wb, ax - bx, ay - by
    n = math.hypot(dvx, dvy)
    if relative_speed(linkage, kin, a, b, i) <= at_rest:
        return "none", (0.0, 0.0)
    if dw != 0.0:
        return "point", (-dvy / dw + 0.0, dvx / dw + 0.0)
    return "direction", (-dvy / n, dvx / n)


def relative_speed(linkage: Linkage, kin: Kinematics, a: str, b: str, i: int) -> float:
    """How fast links a and b move relative to each other: ``|ω_a − ω_b|·size + |v0_a − v0_b|`` (m/s)."""
    wa, ax, ay = _twist(linkage, kin, a, i)
    wb, bx, by = _twist(linkage, kin, b, i)
    size = max(float(np.hypot(*p[i])) for p in kin.point.values()) + 1e-300
    return abs(wa - wb) * size + math.hypot(ax - bx, ay - by)


def _carrier(linkage: Linkage, ic: InstantCentres, x: str) -> str | None:
    """A link carrying point x whose motion the centres determine (the frame for a frame point)."""
    if x in linkage.frame_points:
        return linkage.frame_link
    for lid, pts in linkage.links().items():
        if x in pts and lid in ic.motions:
            return lid
    return None


# ---------------------------------------------------------------------------- rows


def add_rows(an: Any) -> ICAnalysis:
    """Compute the centres at every constructed position; append the asked rows and warnings to ``an``."""
    from graphmech.problems.judging import measured_entries, split_name
    from graphmech.problems.linkage.sizes import position_text

    scene, linkage = an.scene, an.build.linkage
    ica = ICAnalysis([centres_at(an, s) if s is not None else None for s in an.solutions])
    links = polygon_of_links(linkage)
    names = point_names(linkage)
    problems: list[tuple[str, str]] = []
    requests = [(f"find[{k}]", raw, False) for k, raw in enumerate(scene.find)]
    requests += [(key, raw, True) for key, raw, _ in measured_entries(scene, an.extra_measured)]
    found: list[Any] = []
    for key, raw, judged in requests:
        base, at = split_name(canonical(raw))
        if not claims(base):
            continue
        m_row = _ZERO_ROW.fullmatch(base)
        if m_row:
            if not judged:
                problems.append((key, f"find phi_v0_{m_row.group(1)}: its rows are numbered {base[:-2]}_1 …"))
                continue
            base = f"phi_v0_{m_row.group(1)}"
        rows: list[Any] = []
        _collect(an, ica, key, base, at, rows, problems, links, names)
        if judged:  # kept apart, for judge(); only what find asks for goes into the table
            ica.measured.update({r.name: r for r in rows})
        else:
            found += rows
    if problems:
        raise SceneError(problems, scene.source)
    an.rows.extend(found)
    _say_undetermined(an, ica, position_text)
    return ica


def _collect(an: Any, ica: ICAnalysis, key: str, base: str, at: str | None, rows: list[Any],
             problems: list[tuple[str, str]], links: tuple[str, ...], names: set[str]) -> None:
    """Append the rows of one instant-centre name (at one position or at every position)."""
    from graphmech.problems.judging import Row
    from graphmech.problems.linkage.sizes import characteristic, position_text

    build, linkage = an.build, an.build.linkage
    multi = len(an.labels) > 1

    def rel(g: float, e: float, unit: str) -> float:
        if unit == "deg":  # a direction: modulo 180°
            return abs((g - e + 90.0) % 180.0 - 90.0) / 180.0
        return abs(g - e) / max(abs(e), characteristic(linkage, unit, an.size))

    def ill(ic: InstantCentres, sol: Any, keys: list[tuple[str, str]]) -> bool:
        return (any(ic.centres[k].cond > T.COND_WARN for k in keys)
                or any(c > T.COND_WARN for c in sol.conds.values()))

    mu = an.scales["l"]
    ox, oy = build.origin
    lid: str | None
    m_zero = _ZERO.fullmatch(base)
    if m_zero:
        if at is not None:
            problems.append((key, f"{base} is found over the whole turn of the crank: drop '@{at}'"))
            return
        x = m_zero.group(1)
        try:
            rows += _zero_rows(an, ica, x, key)
        except ValueError as e:
            problems.append((key, str(e)))
        return
    if at is not None and at not in an.labels:
        problems.append((key, f"no position {at!r} (positions: {', '.join(an.labels)})"))
        return
    spec = _parse(base, linkage, links, names)
    if isinstance(spec, str):
        problems.append((key, spec))
        return
    for i in ([an.labels.index(at)] if at is not None else range(len(an.labels))):
        ic, sol = ica.centres[i], an.solutions[i]
        if ic is None or not an.exact.valid[i]:
            continue
        where = position_text(build, an.labels[i])
        suffix = f"@{an.labels[i]}" if multi else ""
        kind = spec[0]
        if kind == "centre":
            _, coord, a, b = spec
            c = ic.centre(a, b)
            nm = centre_name(*c.links)
            if not c.known:
                an.warnings.append(f"{where}: {nm} cannot be determined — {c.why}")
                continue
            v_char = characteristic(linkage, "m/s", an.size)
            if c.kind == "direct" and c.point is not None:  # a joint: where the exact solution puts it
                ek, ev = "point", tuple(float(t) for t in an.exact.point[c.via[0]][i])
                shaky = False
            else:
                ek, ev = exact_centre(linkage, an.exact, a, b, i, 1e-9 * v_char)
                # the exact centre divides by the links' relative motion: near relative rest it
                # carries EPS·v/relative of error (COND_SAFETY as for an intersection)
                shaky = ek != "none" and relative_speed(linkage, an.exact, a, b, i) < \
                    T.COND_SAFETY * T.EPS / T.REL_AGREEMENT * v_char
            if ek == "none":
                an.warnings.append(f"{where}: links {a} and {b} are at relative rest, so the exact {nm} is "
                                   "undefined; the construction's is not checked")
                continue
            if c.at_infinity:
                if coord in ("x_", "y_"):
                    an.warnings.append(f"{where}: {nm} is at infinity (direction "
                                       f"{_deg(c.direction):.6g}°): it has no {coord[0]} coordinate")
                    continue
                g = _deg(c.direction)
                exact_v = _deg(cast("tuple[float, float]", ev))  # a huge exact point lies in (nearly) the same direction
                rows.append(Row(f"dir_{nm}{suffix}", "deg", None, 1.0, g, exact_v, rel(g, exact_v, "deg"),
                                ill(ic, sol, [c.links]) or shaky))
                continue
            if coord == "dir_":
                an.warnings.append(f"{where}: {nm} is a finite point, not a direction: ask for x_{nm}, y_{nm}")
                continue
            for axis, n in (("x", 0), ("y", 1)):
                if coord in ("", f"{axis}_"):
                    drawn = cast("tuple[float, float]", c.point)[n] + (ox, oy)[n] / mu
                    g = drawn * mu
                    exact_v = ev[n] if ek == "point" else math.copysign(math.inf, 1.0)
                    if not math.isfinite(exact_v):
                        an.warnings.append(f"{where}: the exact {nm} is at infinity; the construction "
                                           f"put it at {g:.6g} m (ill-conditioned)")
                        continue
                    rows.append(Row(f"{axis}_{nm}{suffix}", "m", drawn, mu, g, exact_v, rel(g, exact_v, "m"),
                                    ill(ic, sol, [c.links]) or shaky))
        elif kind == "omega":
            lid = spec[1]
            if lid not in ic.motions:
                an.warnings.append(f"{where}: ω{lid} cannot be found from the centres — {ic.undetermined[lid]}")
                continue
            mo = ic.motions[lid]
            exact_v = float(an.exact.omega[lid][i]) if lid != linkage.frame_link else 0.0
            drawn, scale = (mo.drawn, mo.scale) if mo.drawn is not None else (None, 1.0)
            g = mo.omega if drawn is None else drawn * cast(float, scale)  # measured: both given
            keys = [ic.absolute(lid).links] + ([pair(links, mo.found[0], lid)] if len(mo.found) == 4 else [])
            rows.append(Row(f"omega_{lid}_ic{suffix}", "rad/s", drawn, cast(float, scale) if drawn is not None else 1.0, g, exact_v,
                            rel(g, exact_v, "rad/s"), ill(ic, sol, keys)))
        elif kind == "speed":
            x = spec[1]
            lid = _carrier(linkage, ic, x)
            if lid is None:
                an.warnings.append(f"{where}: v_{x} cannot be found from the centres — the motion of every "
                                   "link carrying it is undetermined")
                continue
            mo = ic.motions[lid]
            p = positions_mm(build, sol)[x]
            p1 = ic.absolute(lid)
            if p1.point is not None:  # |v| = |ω|·P1kX
                drawn = math.dist(p1.point, p)
                scale = abs(mo.omega) * mu
            else:  # a translating link: the velocity found at its common centre
                drawn, scale = math.hypot(*mo.velocity(p)), mu
            g = drawn * scale
            exact_v = float(np.hypot(*an.exact.vel[x][i]))
            rows.append(Row(f"v_{x}_ic{suffix}", "m/s", drawn, scale, g, exact_v, rel(g, exact_v, "m/s"),
                            ill(ic, sol, [p1.links])))
        elif kind == "least":
            _, what, a, b, lid = spec
            pos = positions_mm(build, sol)
            found = least_speed_on_line(ic, lid, pos[a], pos[b])
            if isinstance(found, str):
                an.warnings.append(f"{where}: no single point of {a}{b} with the least speed — {found}")
                continue
            s_mm, dist_mm, _ = found
            e_s, e_v = _exact_least(linkage, an.exact, lid, a, b, i)
            if what == "v":
                drawn, scale = dist_mm, abs(ic.motions[lid].omega) * mu
                g = drawn * scale
                rows.append(Row(f"v_min_{a}{b}_ic{suffix}", "m/s", drawn, scale, g, e_v, rel(g, e_v, "m/s"),
                                ill(ic, sol, [ic.absolute(lid).links])))
            else:
                g = s_mm * mu
                rows.append(Row(f"s_min_{a}{b}_ic{suffix}", "m", s_mm, mu, g, e_s, rel(g, e_s, "m"),
                                ill(ic, sol, [ic.absolute(lid).links])))


def summary(an: Any) -> list[dict[str, Any]]:
    """The ``"instant_centres"`` section of ``check --json``: per constructed position every centre
    (``x``, ``y`` in m; or ``direction_deg`` at infinity; or why it is undetermined, with the
    links whose Kennedy lines found it) and each link's ω from them (rad/s)."""
    mu = an.scales["l"]
    ox, oy = an.build.origin
    out = []
    for i, ic in enumerate(an.instant_centres.centres):
        if ic is None:
            continue
        centres = []
        for key in ic.order:
            c = ic.centres[key]
            row: dict[str, Any] = {"name": centre_name(*key), "kind": c.kind}
            if c.point is not None:
                row.update(x=c.point[0] * mu + ox, y=c.point[1] * mu + oy)
            elif c.direction is not None:
                row["direction_deg"] = _deg(c.direction)
            else:
                row["why"] = c.why
            if c.kind == "kennedy":
                row["via"] = list(c.via)
            centres.append(row)
        out.append({"position": an.labels[i], "centres": centres,
                    "omega": {k: m.omega for k, m in ic.motions.items() if k != ic.frame},
                    "undetermined": dict(ic.undetermined)})
    return out


def _say_undetermined(an: Any, ica: ICAnalysis, position_text: Any) -> None:
    """Warn about every centre and every link motion the construction cannot determine."""
    build = an.build
    for i, ic in enumerate(ica.centres):
        if ic is None:
            continue
        where = position_text(build, an.labels[i])
        for c in ic.centres.values():
            if not c.known:
                an.warnings.append(f"{where}: {centre_name(*c.links)} cannot be determined — {c.why}")
        for lid, why in ic.undetermined.items():
            an.warnings.append(f"{where}: the motion of link {lid} cannot be found from the centres — {why}")
    an.warnings[:] = list(dict.fromkeys(an.warnings))


def _not_judged(base: str, name: str, ica: ICAnalysis | None) -> str:
    """Why a measured instant-centre value has no row to be judged against."""
    if _CENTRE.fullmatch(base) and not base.startswith(("x_", "y_", "dir_")):
        return f"a centre is read as its coordinates: x_{base}, y_{base} (m), or dir_{base} (deg) at infinity"
    if _ZERO.fullmatch(base):
        return f"name one of the angles: {base}_1, {base}_2 …"
    if _ZERO_ROW.fullmatch(base) and ica is not None:
        stem = base.rpartition("_")[0]
        found = sorted(k for k in ica.measured if k.startswith(stem + "_"))
        return f"{name}: v = 0 at {len(found)} crank angle(s) only ({', '.join(found) or 'none'})"
    return f"{name} cannot be judged here (undetermined, at infinity or not constructed)"


def judge(an: Any, precision_mm: float) -> tuple[list[Any], list[tuple[str, str]]]:
    """Verdicts on the measured instant-centre values, within the drawing precision.

    A length read on the diagram (a coordinate, a distance, a speed ``|ω|·r``, a ratio's
    numerator) is good to ``precision_mm × μ``; a crank angle to the angle the precision
    subtends at the crank's length; a direction to the angle it subtends over the mechanism.
    """
    from graphmech.problems.judging import Verdict, measured_entries, split_name
    from graphmech.problems.linkage.sizes import characteristic

    ica: ICAnalysis | None = an.instant_centres
    out, problems = [], []
    size_mm = an.size / an.scales["l"]
    for key, name, value in measured_entries(an.scene, an.extra_measured):
        if not claims(name):
            continue
        name = canonical(name)
        base, at = split_name(name)
        if at is None and len(an.labels) > 1 and not base.startswith("phi_v0_"):
            problems.append((key, f"the scene has {len(an.labels)} positions: name one, e.g. {base}@{an.labels[0]}"))
            continue
        row = None if ica is None else ica.measured.get(name if len(an.labels) > 1 else base)
        if row is None:
            problems.append((key, _not_judged(base, name, ica)))
            continue
        if row.unit == "deg":
            crank = getattr(an.build.linkage.driver, "length", an.size) / an.scales["l"]
            arm = crank if base.startswith("phi_v0_") else size_mm
            tol = math.degrees(precision_mm / max(arm, precision_mm))
        elif row.drawn_mm is not None:
            tol = precision_mm * abs(row.scale)
        else:
            tol = precision_mm / size_mm * max(abs(row.exact), characteristic(an.build.linkage, row.unit, an.size))
        e = row.exact
        ok = abs(value - e) <= tol + 1e-12 * abs(e)
        if row.unit == "deg":
            period = 360.0 if base.startswith("phi_v0_") else 180.0
            ok = abs((value - e + period / 2) % period - period / 2) <= tol
        out.append(Verdict(name, value, e, tol, ok, row.unit))
    return out, problems


def _deg(d: tuple[float, float] | None) -> float:
    """A direction's angle in [0, 180) degrees (a line's direction has no sense)."""
    assert d is not None
    a = math.degrees(math.atan2(d[1], d[0])) % 180.0
    return 0.0 if a >= 180.0 else a + 0.0


def _exact_least(linkage: Linkage, kin: Kinematics, lid: str, a: str, b: str, i: int) -> tuple[float, float]:
    """Exact (s, v_min): the foot of the ⟂ from the exact P1k on line AB, and |ω|·distance."""
    w, vx, vy = _twist(linkage, kin, lid, i)
    pa, pb = kin.point[a][i], kin.point[b][i]
    u = (pb - pa) / np.hypot(*(pb - pa))
    if w == 0.0:
        return math.nan, math.hypot(vx, vy)
    p1 = np.array([-vy / w, vx / w])
    r = p1 - pa
    return float(r @ u), float(abs(w) * abs(r[0] * u[1] - r[1] * u[0]))


def _parse(base: str, linkage: Linkage, links: tuple[str, ...], names: set[str]) -> tuple[str, ...] | str:
    """A name → what to compute, or the reason it names nothing."""
    m = _CENTRE.fullmatch(base)
    if m:
        coord, raw = m.group(1) or "", base[len(m.group(1) or "") + 1:]
        for k in range(1, len(raw)):
            a, b = raw[:k].rstrip("_"), raw[k:].lstrip("_")
            if a in links and b in links and a != b:
                return ("centre", coord, a, b)
        return f"{base!r} names no instant centre (links: {', '.join(links)}; e.g. {centre_name(*links[:2])})"
    m = _OMEGA.fullmatch(base)
    if m:
        if m.group(1) not in links:
            return f"no link {m.group(1)!r} (links: {', '.join(links)})"
        if m.group(1) == linkage.frame_link:
            return f"link {m.group(1)} is the frame: it does not turn"
        return ("omega", m.group(1))
    m = _SPEED.fullmatch(base)
    if m:
        if m.group(1) not in names:
            return f"no point {m.group(1)!r} in the linkage"
        if m.group(1) in linkage.frame_points:  # no moving link carries it (was an internal error)
            return f"{m.group(1)} is a point of the frame: its velocity is always 0"
        return ("speed", m.group(1))
    m = _LEAST.fullmatch(base)
    if m:
        ab = split_line(m.group(2), names)
        if ab is None:
            return f"{m.group(2)!r} is not two points of the linkage (write v_min_BC_ic for line BC)"
        if ab[0] == ab[1]:
            return f"{m.group(2)!r} is one point twice: name a line by two points (v_min_BC_ic for line BC)"
        lid = common_link(linkage, *ab)
        if lid is None:
            return f"{ab[0]} and {ab[1]} are not points of one moving link"
        return ("least", m.group(1), ab[0], ab[1], lid)
    return f"unknown instant-centre quantity {base!r}"


# ---------------------------------------------------------------------------- v = 0 over the turn


def _zero_rows(an: Any, ica: ICAnalysis, x: str, key: str) -> list[Any]:
    """Crank angles at which v_X = 0: by the centres (sampled, refined by Brent), and exactly."""
    from graphmech.problems.judging import Row

    linkage = an.build.linkage
    if not isinstance(linkage.driver, Crank):
        raise NotApplicable("crank angles with a vanishing velocity need a crank as the driver")
    if linkage.driver.omega == 0.0:  # every angle would be a root: nothing to single out
        raise NotApplicable(f"the crank stands still (ω = 0): v_{x} is zero at every crank angle")
    if not abs(linkage.driver.omega) * an.size > 1e-250:  # ω = 5e-324: every velocity underflows to 0
        raise OutOfDomain(f"ω = {linkage.driver.omega:g} rad/s makes every velocity underflow double precision; "
                         f"the angles where v_{x} vanishes do not depend on ω: give ω = 1")
    kind, lid, u = signed_rate(linkage, x)
    plan, build = an.plan, an.build
    mu = an.scales["l"]
    grid = np.linspace(0.0, 2.0 * math.pi, ZERO_SAMPLES + 1)

    def by_centres(phi: float) -> float:
        try:
            sol = plan.solve({build.param: float(phi)})
        except Exception:  # not constructible here: no sign
            return math.nan
        ic = centres_at(an, sol)
        if lid not in ic.motions:
            return math.nan
        mo = ic.motions[lid]
        if kind == "omega":
            return mo.omega
        assert u is not None
        return cast(float, (mo.v0[0] * u[0] + mo.v0[1] * u[1]) * mu)

    batch = plan.evaluate_batch({build.param: grid})
    # the sampled turn as arrays: the same numbers as instant_centres position by position
    idx = np.flatnonzero(batch.valid)
    pos: dict[str, tuple[Any, Any]] = {}
    for name, slot in build.mech.items():
        if slot in batch.values:
            cx, cy = (c if np.ndim(c) == 0 else np.asarray(c)[idx] for c in batch.values[slot])
            pos[name] = (cx, cy)
    cb = instant_centres_batch(linkage, pos, len(idx), mu_l=mu)
    if kind == "omega":
        rate = cb.omega[lid]
    else:
        assert u is not None
        rate = (cb.v0[lid][:, 0] * u[0] + cb.v0[lid][:, 1] * u[1]) * mu
    values = np.full(len(grid), math.nan)
    values[idx] = np.where(cb.determined[lid], rate, math.nan)
    if not np.any(np.nan_to_num(values)):  # a point at rest (on the frame): no angles to single out
        raise NotApplicable(f"v_{x} is zero at every crank angle: it has no crank angles of its own where it vanishes")
    graphical = _roots(grid, values, by_centres)

    kin = solve_exact(linkage, grid)
    if kind == "omega":
        ex = np.where(kin.valid, kin.omega[lid], np.nan)
    else:
        assert u is not None
        ex = np.where(kin.valid, kin.vel[x][:, 0] * u[0] + kin.vel[x][:, 1] * u[1], np.nan)

    def exact_at(phi: float) -> float:
        k1 = solve_exact(linkage, np.array([phi]))
        if not k1.valid[0]:
            return math.nan
        return float(k1.omega[lid][0]) if kind == "omega" else float(k1.vel[x][0] @ np.array(u))

    exact = _roots(grid, ex, exact_at)
    ica.zeros[x] = graphical
    if not graphical and not exact:
        an.warnings.append(f"v_{x} does not vanish over the crank's turn")
        return []
    rows = []
    for n, g in enumerate(graphical, 1):
        e = min(exact, key=lambda t: abs((t - g + math.pi) % (2 * math.pi) - math.pi)) if exact else math.nan
        if not math.isfinite(e):
            continue
        gd, ed = math.degrees(g) % 360.0, math.degrees(e) % 360.0
        err = abs((gd - ed + 180.0) % 360.0 - 180.0) / 360.0
        rows.append(Row(f"phi_v0_{x}_{n}", "deg", None, 1.0, gd, ed, err))
    if len(exact) != len(graphical):
        an.warnings.append(f"v_{x} vanishes at {len(exact)} crank angles exactly but at {len(graphical)} by the "
                           "centres (a root at a dead centre or in a gap of assembly)")
    return rows


def _roots(grid: np.ndarray, values: np.ndarray, f: Callable[[float], float]) -> list[float]:
    """Sign changes of ``values`` between neighbouring finite samples, refined by Brent's method.

    A sign change across an infinite rate (a dead centre) is not a zero: it is kept only if
    ``|f|`` at the refined point is small compared with the rate's size.
    """
    from graphmech.roots import brentq

    finite = values[np.isfinite(values)]
    size = float(np.max(np.abs(finite))) if finite.size else 0.0
    out: list[float] = []
    for k in range(len(grid) - 1):
        a, b = values[k], values[k + 1]
        if not (math.isfinite(a) and math.isfinite(b)):
            continue
        if a == 0.0:
            root = float(grid[k])
        elif a * b < 0.0:
            try:
                root = brentq(f, float(grid[k]), float(grid[k + 1]), xtol=1e-14, rtol=4 * T.EPS, maxiter=200)
            except (ValueError, ArithmeticError):  # f undefined inside the bracket (a dead centre), no convergence
                continue
        else:
            continue
        if abs(f(root)) <= 1e-6 * max(size, 1e-300):
            r = root % (2.0 * math.pi)
            if not out or abs(r - out[-1]) > 1e-9:
                out.append(r)
    return out


__all__ = ["SHOW", "ICAnalysis", "add_rows", "asked", "canonical", "claims", "exact_centre", "judge", "positions_mm",
           "summary"]
