"""How big a linkage is, for judging its quantities: its typical length and speeds (the
denominators of relative errors, so that a zero exact value does not blow them up), how far from
the origin it lies (digits its coordinates keep), and how a position is named (φ₁ = 30°).

Shared by the linkage's check and the checks built on it (instant centres, full cycle, forces).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from graphmech import tolerances as T
from graphmech.drawing.lettering import number, subscript
from graphmech.errors import SceneError
from graphmech.exact.linkage import Kinematics
from graphmech.mechanisms.linkage import Crank, Guide, Linkage
from graphmech.methods.linkage_construction import LinkageConstruction

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene


def position_text(build: LinkageConstruction, label: str) -> str:
    driver = build.linkage.driver
    sub = subscript(driver.link)
    return f"φ{sub} = {label}°" if isinstance(driver, Crank) else f"s{sub} = {label}"


def drawn_position_text(build: LinkageConstruction, label: str) -> str:
    """A position as a drawing letters it: ``φ_{1} = 26.38°`` (4 significant figures, a true
    minus); the check's :func:`position_text` keeps the scene's own digits."""
    driver = build.linkage.driver
    try:
        value = number(float(label))
    except ValueError:  # a label that is not a number is drawn as given
        value = label
    sym = "φ" if isinstance(driver, Crank) else "s"
    return f"{sym}_{{{driver.link}}} = {value}" + ("°" if isinstance(driver, Crank) else "")


def mechanism_size(linkage: Linkage, kin: Kinematics | None = None) -> float:
    """A length typical of the mechanism: the diagonal of the box its points sweep (m).

    Falls back on the links' and frame's own sizes where no solution is at hand.
    """
    if kin is not None and kin.valid.any():
        pts = np.concatenate([p[kin.valid] for p in kin.point.values()])
        size = float(np.hypot(*(pts.max(axis=0) - pts.min(axis=0))))
        if size > 0.0:
            return size
    sizes = [abs(v) for y in linkage.dyads for v in (getattr(y, "lengths", None) or (getattr(y, "length", 0.0),))]
    frame = list(linkage.frame_points.values())
    sizes += [math.dist(a, b) for a in frame for b in frame]
    if isinstance(linkage.driver, Crank):
        sizes.append(linkage.driver.length)
    return max(sizes + [0.0]) or 1.0


def offset_ratio(linkage: Linkage, size: float) -> float:
    """How many times its own size the mechanism's given coordinates lie from the origin."""
    coords = [abs(c) for p in linkage.frame_points.values() for c in p]
    d = linkage.driver
    guides = [getattr(d, "guide", None)] + [g for y in linkage.dyads for g in (getattr(y, "guide", None),
                                                                            *getattr(y, "guides", ()))]
    coords += [abs(c) for g in guides if isinstance(g, Guide) for c in g.through]  # a link's guide: its points
    return max(coords + [0.0]) / size


def refuse_far_from_origin(scene: Scene[object], linkage: Linkage, size: float) -> None:
    """Refuse a mechanism so far from the origin that its coordinates keep no digit of its
    geometry (a guide through x = 1e300 m): nothing can be drawn or solved there (the friction
    iteration of a force scene ran for minutes on it)."""
    ratio = offset_ratio(linkage, size)
    if T.EPS * ratio > 0.1:
        raise SceneError([("frame", f"the mechanism lies {ratio:.2g} times its own size from the origin: its "
                                    "coordinates keep no digit of its geometry; move the origin to a frame pivot")],
                         scene.source)


def offset_warning(linkage: Linkage, size: float) -> str:
    """Coordinates far from the origin, compared with the mechanism's size, carry few digits of it."""
    ratio = offset_ratio(linkage, size)
    if T.COND_SAFETY * T.EPS * ratio <= T.REL_AGREEMENT:
        return ""
    return (f"the mechanism lies {ratio:.2g} times its own size from the origin: its coordinates keep "
            f"only about {max(0.0, -math.log10(T.EPS * ratio)):.0f} significant digits of its geometry, "
            "so no value can be checked to 1e-9; move the origin to a frame pivot")


def characteristic(linkage: Linkage, unit: str, size: float | None = None) -> float:
    """The size of a quantity of this unit in this linkage (ω1·l_AB for velocities, …).

    The relative error divides by max(|exact|, this), so a zero exact value does not blow it
    up. ``size`` is the mechanism's typical length (:func:`mechanism_size`).
    """
    L = size if size is not None else mechanism_size(linkage)
    d = linkage.driver
    if isinstance(d, Crank):
        w = abs(d.omega) + math.sqrt(abs(d.epsilon))
        alpha = d.omega ** 2 + abs(d.epsilon)
        v, a = w * d.length, alpha * d.length
    else:
        v = abs(d.velocity) + math.sqrt(abs(d.acceleration) * L)
        a = abs(d.acceleration) + d.velocity ** 2 / L
        w, alpha = v / L, a / L
    chars = {"m/s": v, "m/s²": a, "rad/s": w, "rad/s²": alpha, "m": L, "deg": 360.0}
    return max(chars.get(unit, 1.0), 1e-300)
