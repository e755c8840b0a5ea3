"""Wheels in pure rolling contact (摩擦轮, a friction planetary drive): the model of a mechanism
given by its links and their *direct* instant centres — revolutes at named points, rolling
contacts where two links' wheels touch.

A pure rolling contact is a direct instant centre: the two links have the same velocity at the
contact point. Its place follows from the wheels: two circles touching outside (|C1C2| = r1 + r2)
or one inside a ring (|C1C2| = R − r, the ring's working surface inside). Everything in SI (m,
rad/s); nothing here draws or checks.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

XY = tuple[float, float]

#: Two wheels touch when their gap is below this fraction of the larger radius (data given to a few decimals).
TOUCH_REL = 1e-6


@dataclass(frozen=True)
class Wheel:
    """A circular profile of one link: its centre (a point name) and radius (m); ``internal`` for a
    ring whose working surface is its inside (a planet rolls in it)."""

    link: str
    centre: str
    radius: float
    internal: bool = False


@dataclass(frozen=True)
class Revolute:
    """A revolute at point ``at`` joining ``links`` (more than two: a compound hinge)."""

    links: tuple[str, ...]
    at: str


@dataclass(frozen=True)
class Rolling:
    """Pure rolling between the wheels of two links; ``at`` the contact point, m (found from the wheels)."""

    links: tuple[str, str]
    at: XY


@dataclass(frozen=True)
class RollingDrive:
    """The mechanism: the frame, the driving link and its ω (rad/s, + CCW), the named points (m),
    the wheels, revolutes and rolling contacts."""

    frame: str
    driver: str
    omega: float
    points: Mapping[str, XY]
    wheels: tuple[Wheel, ...]
    revolutes: tuple[Revolute, ...]
    contacts: tuple[Rolling, ...]

    def links(self) -> tuple[str, ...]:
        """Every link, the frame included, in the book's order (numbers ascending)."""
        ids = {self.frame, self.driver}
        ids.update(x for r in self.revolutes for x in r.links)
        ids.update(x for c in self.contacts for x in c.links)
        return tuple(sorted(ids, key=lambda s: (0, int(s)) if s.isdigit() else (1, s)))

    def wheel(self, link: str) -> Wheel | None:
        return next((w for w in self.wheels if w.link == link), None)


def contact(a: Wheel, ca: XY, b: Wheel, cb: XY) -> XY | str:
    """Where wheels ``a`` (centre at ``ca``) and ``b`` touch, or why they do not.

    Outside each other: the point at r_a from C_a towards C_b (|C_aC_b| = r_a + r_b); one a ring
    (``internal``): the point at R from the ring's centre through the other's (|C_aC_b| = R − r).

    >>> contact(Wheel("1", "O", 0.04), (0.0, 0.0), Wheel("2", "C", 0.015), (0.055, 0.0))
    (0.04, 0.0)
    >>> contact(Wheel("4", "O", 0.07, True), (0.0, 0.0), Wheel("2", "C", 0.015), (0.0, 0.055))
    (0.0, 0.07)
    >>> contact(Wheel("1", "O", 0.04), (0.0, 0.0), Wheel("2", "C", 0.015), (0.06, 0.0))
    'the wheels do not touch: |OC| = 60 mm, r1 + r2 = 55 mm'
    """
    if a.internal and b.internal:
        return "two rings cannot roll on each other (both internal)"
    d = math.dist(ca, cb)
    tol = TOUCH_REL * max(a.radius, b.radius)
    names = f"|{a.centre}{b.centre}|"
    if a.internal or b.internal:
        ring, rc, other, oc = (a, ca, b, cb) if a.internal else (b, cb, a, ca)
        need, how = ring.radius - other.radius, f"R{ring.link} − r{other.link}"
        if need <= tol:
            return f"wheel {other.link} (r = {other.radius * 1e3:g} mm) does not fit inside ring {ring.link} " \
                   f"(R = {ring.radius * 1e3:g} mm)"
    else:
        need, how = a.radius + b.radius, f"r{a.link} + r{b.link}"
    if abs(d - need) > tol:
        return f"the wheels do not touch: {names} = {d * 1e3:.6g} mm, {how} = {need * 1e3:.6g} mm"
    if a.internal or b.internal:
        ux, uy = (oc[0] - rc[0]) / d, (oc[1] - rc[1]) / d
        return (rc[0] + ring.radius * ux, rc[1] + ring.radius * uy)
    ux, uy = (cb[0] - ca[0]) / d, (cb[1] - ca[1]) / d
    return (ca[0] + a.radius * ux, ca[1] + a.radius * uy)


def on_wheel(w: Wheel, c: XY, p: XY) -> bool:
    """Whether point ``p`` lies on wheel ``w``'s circle (centre at ``c``)."""
    return abs(math.dist(c, p) - w.radius) <= TOUCH_REL * max(w.radius, math.dist(c, p))


__all__ = ["TOUCH_REL", "Revolute", "Rolling", "RollingDrive", "Wheel", "contact", "on_wheel"]
