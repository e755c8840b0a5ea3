"""Exact velocities of wheels in pure rolling contact, from the pairs' velocity equations.

Independent of the instant centres: each moving link's velocity field ``v(X) = v0 + ω k×X`` is
unknown (ω, v0x, v0y); every revolute and every rolling contact (no slip) says the two links'
velocities agree at its point, the frame is at rest and the driver turns at its ω. The linear
system is solved by least squares; a drive whose equations leave a link free, or admit no motion
with the driver's ω (the contacts lock it), is refused.
"""
from __future__ import annotations

import numpy as np

from graphmech.errors import OutOfDomain
from graphmech.mechanisms.rolling import RollingDrive

#: Residual of the velocity equations, relative to the driver's ω·size, above which they are inconsistent.
CONSISTENT_REL = 1e-9


def twists(drive: RollingDrive) -> dict[str, tuple[float, float, float]]:
    """Per link ``(ω, v0x, v0y)`` (rad/s, m/s): the velocity field ``v(X) = v0 + ω k×X`` (X in m).

    Raises
    ------
    OutOfDomain
        When the pairs do not determine every link's motion, or lock the driver.

    Examples
    --------
    A sun wheel 1 (r1 = 40 mm) about O, a planet 2 (r2 = 15 mm) rolling between it and the fixed
    ring 4 (R = 70 mm): ω2 = −ω1·r1/(2 r2).

    >>> from graphmech.mechanisms.rolling import Revolute, Rolling, RollingDrive
    >>> d = RollingDrive("4", "1", 10.0, {"O": (0.0, 0.0)}, (), (Revolute(("1", "4"), "O"),),
    ...                  (Rolling(("1", "2"), (0.04, 0.0)), Rolling(("2", "4"), (0.07, 0.0))))
    >>> round(twists(d)["2"][0], 12)
    -13.333333333333
    """
    links = [x for x in drive.links() if x != drive.frame]
    col = {x: 3 * k for k, x in enumerate(links)}
    rows: list[list[float]] = []
    rhs: list[float] = []
    pts = list(drive.points.values()) + [c.at for c in drive.contacts]
    size = max((max(abs(p[0]), abs(p[1])) for p in pts), default=1.0) or 1.0

    def agree(a: str, b: str, x: tuple[float, float]) -> None:
        for comp in (0, 1):  # v_a(X) − v_b(X) = 0, component by component
            row = [0.0] * (3 * len(links))
            for link, sign in ((a, 1.0), (b, -1.0)):
                if link == drive.frame:
                    continue
                c = col[link]
                row[c] += sign * (-x[1] if comp == 0 else x[0])  # ω k×X
                row[c + 1 + comp] += sign
            rows.append(row)
            rhs.append(0.0)

    for r in drive.revolutes:
        p = drive.points[r.at]
        for other in r.links[1:]:
            agree(r.links[0], other, p)
    for c in drive.contacts:
        agree(c.links[0], c.links[1], c.at)
    row = [0.0] * (3 * len(links))
    row[col[drive.driver]] = 1.0
    rows.append(row)
    rhs.append(drive.omega)
    a, b = np.array(rows), np.array(rhs)
    sol, _, rank, _ = np.linalg.lstsq(a, b, rcond=None)
    if rank < 3 * len(links):
        raise OutOfDomain(f"the pairs leave {3 * len(links) - rank} freedom(s) besides the driver's: "
                          "the motion is not determined")
    residual = float(np.max(np.abs(a @ sol - b)))
    if residual > CONSISTENT_REL * max(abs(drive.omega), 1e-300) * size:
        raise OutOfDomain("the pairs admit no motion with the driver turning: the contacts lock the drive")
    return {x: (float(sol[col[x]]), float(sol[col[x] + 1]), float(sol[col[x] + 2])) for x in links} | \
        {drive.frame: (0.0, 0.0, 0.0)}


__all__ = ["CONSISTENT_REL", "twists"]
