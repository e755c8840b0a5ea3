"""Exact kinematics of a class III Assur group (RRR-III) by elimination and a linear solve.

The group: a ternary link carrying C, D, E, joined by binary links to known points B (B–C),
F (F–D), G (G–E). Its two vector loops, with complex numbers (a link of length l at angle θ is
``l·e^{iθ}``),

    B + l2·e^{iθ2} + l_CD·e^{iθ3} = F + l4·e^{iθ4},
    B + l2·e^{iθ2} + l_CE·e^{i(θ3 ± γ)} = G + l5·e^{iθ5}      (γ the ternary link's angle at C),

have no closed-form solution. Here they are *eliminated* to one equation in θ2: for a given θ2,
C is known, D is the closed-form RRR dyad C–D–F (either hand), E follows rigidly, and the
residual ``f(θ2) = |E − G|² − l5²`` must vanish. Every root is found by a scan of θ2 over the
full turn (both hands of the dyad), each sign change narrowed by bisection to the last bit; of
the assemblies so found the one nearest the stated start is taken. This is a different route
from the construction's (Newton on the two loop equations from the start), so they check each
other.

Velocities and accelerations: differentiating the loops once and twice gives four real linear
equations in (ω2, ω3, ω4, ω5) and (α2, α3, α4, α5) with the same matrix, solved by numpy's LU.
The matrix is singular exactly where the group's position stops being locally unique (the
group's "dead centre"); its condition number past ``1/TANGENT_REL`` marks the position invalid.

Imports only numpy, math, the model and the tolerances — nothing of the construction.
"""
from __future__ import annotations

import math

import numpy as np

from graphmech.mechanisms.linkage import Triad
from graphmech.tolerances import TANGENT_REL

__all__ = ["SCAN", "TriadSolution", "assemblies", "solve_triad"]

#: Samples of θ2 over a full turn in the root scan (per hand of the dyad C–D–F). Two roots
#: closer than 2π/SCAN may be missed; the group's assemblies are far apart in any drawable case.
SCAN = 2880
_BISECT = 80  # halvings: 2π/SCAN / 2^80 is below every double's spacing

_C = complex


def _dyad(zc: np.ndarray, zf: complex, a: float, l4: float, hand: float) -> tuple[np.ndarray, np.ndarray]:
    """D on circle(C, a) ∩ circle(F, l4), to the ``hand`` side of C→F; and whether it exists."""
    cf = zf - zc
    d = np.abs(cf)
    d = np.where(d == 0.0, 1.0, d)
    x = (a * a - l4 * l4 + d * d) / (2.0 * d)
    h2 = a * a - x * x
    ok = h2 >= -TANGENT_REL * a * a  # the two circles just touching (the dyad's limit) still meet
    h = np.sqrt(np.where(ok, np.maximum(h2, 0.0), 0.0))
    u = cf / d
    return zc + u * (x + 1j * hand * h), ok


def _chain(y: Triad, zb: complex, zf: complex, zg: complex, th2: np.ndarray, hand: float
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(C, D, E, f, assembled) along θ2: f = |E − G|² − l5²."""
    l2, l4, l5 = y.lengths
    a, _, c = y.ternary  # l_CD, l_DE, l_EC
    zc = zb + l2 * np.exp(1j * th2)
    zd, ok = _dyad(zc, zf, a, l4, hand)
    ze = zc + (zd - zc) / a * c * _rot(y)
    f = np.abs(ze - zg) ** 2 - l5 * l5
    return zc, zd, ze, f, ok


def _rot(y: Triad) -> complex:
    """e^{±iγ}: CE is CD turned by the ternary link's angle γ at C, to the triangle's hand."""
    a, b, c = y.ternary  # CD, DE, EC
    cos_g = (a * a + c * c - b * b) / (2.0 * a * c)
    sin_g = math.sqrt(max(0.0, 1.0 - cos_g * cos_g))
    return _C(cos_g, y.hand * sin_g)


def assemblies(y: Triad, zb: complex, zf: complex, zg: complex) -> list[tuple[complex, complex, complex]]:
    """Every assembly (C, D, E) of the group with its outer joints at B, F, G."""
    out: list[tuple[complex, complex, complex]] = []
    # the scan's nodes, and the limits of the dyad C–D–F (|CF| = l_CD ± l4, where its two hands
    # meet): a root between the last node that assembles and such a limit has no sign change
    # between two assembled nodes
    l2, l4 = y.lengths[0], y.lengths[1]
    a = y.ternary[0]
    bf = zf - zb
    d = abs(bf)
    limits = []
    for r in (a + l4, abs(a - l4)):
        cos_t = (l2 * l2 + d * d - r * r) / (2.0 * l2 * d) if d > 0.0 else 2.0
        if abs(cos_t) <= 1.0:
            t = math.acos(cos_t)
            limits += [(math.atan2(bf.imag, bf.real) + s * t) % (2.0 * math.pi) for s in (1.0, -1.0)]
    grid = np.unique(np.concatenate([np.linspace(0.0, 2.0 * math.pi, SCAN + 1), limits]))
    for hand in (1.0, -1.0):
        _, _, _, f, ok = _chain(y, zb, zf, zg, grid, hand)
        change = ok[:-1] & ok[1:] & (np.sign(f[:-1]) != np.sign(f[1:]))
        for k in np.flatnonzero(change):
            lo, hi, flo = grid[k], grid[k + 1], f[k]
            for _ in range(_BISECT):
                mid = 0.5 * (lo + hi)
                if mid in (lo, hi):
                    break
                _, _, _, fm, okm = _chain(y, zb, zf, zg, np.array([mid]), hand)
                if not okm[0]:
                    break
                if np.sign(fm[0]) == np.sign(flo):
                    lo, flo = mid, fm[0]
                else:
                    hi = mid
            zc, zd, ze, _, _ = _chain(y, zb, zf, zg, np.array([0.5 * (lo + hi)]), hand)
            out.append((complex(zc[0]), complex(zd[0]), complex(ze[0])))
    return out


class TriadSolution:
    """The group at N positions: joints (z, v, a) as complex arrays, links' θ, ω, α, validity."""

    def __init__(self, n: int) -> None:
        self.z = np.zeros((3, n), dtype=complex)
        self.v = np.zeros((3, n), dtype=complex)
        self.a = np.zeros((3, n), dtype=complex)
        self.theta = np.zeros((4, n))
        self.omega = np.zeros((4, n))
        self.alpha = np.zeros((4, n))
        self.assembled = np.ones(n, dtype=bool)
        self.valid = np.ones(n, dtype=bool)
        self.reason = [""] * n


def solve_triad(y: Triad, known: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]) -> TriadSolution:
    """The group at N positions, its outer joints' (z, v, a) given as complex arrays in ``known``."""
    zo, vo, ao = (np.array([known[p][k] for p in y.outer]) for k in range(3))
    n = zo.shape[1]
    sol = TriadSolution(n)
    start = np.array([_C(*p) for p in y.start])
    for i in range(n):
        found = assemblies(y, complex(zo[0, i]), complex(zo[1, i]), complex(zo[2, i]))
        if not found:
            sol.assembled[i] = sol.valid[i] = False
            sol.reason[i] = f"class III group {y.name}: cannot be assembled"
            continue
        best = min(found, key=lambda t: float(np.sum(np.abs(np.array(t) - start) ** 2)))
        sol.z[:, i] = best
        ok = _rates(y, sol, i, zo[:, i], vo[:, i], ao[:, i])
        if not ok:
            sol.valid[i] = False
            sol.reason[i] = f"class III group {y.name}: dead centre (its velocity equations are singular)"
    return sol


def _rates(y: Triad, sol: TriadSolution, i: int, zo: np.ndarray, vo: np.ndarray, ao: np.ndarray) -> bool:
    """ω and α of links 2, 3, 4, 5 from the differentiated loops; False at a singular position."""
    zc, zd, ze = sol.z[:, i]
    zb, zf, zg = zo
    r2, r4, r5 = zc - zb, zd - zf, ze - zg
    rd, re = zd - zc, ze - zc  # the ternary link's sides CD, CE
    # Loop k (k = F via D, G via E):  v_B + iω2·r2 + iω3·r_k − iωk·rk = v_k  (real and imaginary rows)
    cols = [(1j * r2, 1j * r2), (1j * rd, 1j * re), (-1j * r4, 0j), (0j, -1j * r5)]
    m = np.array([[c[0].real for c in cols], [c[0].imag for c in cols],
                  [c[1].real for c in cols], [c[1].imag for c in cols]])
    scale = np.array([abs(r2), abs(rd), abs(r4), abs(r5)])
    if np.linalg.cond(m / scale) > 1.0 / TANGENT_REL:
        sol.theta[:, i] = [np.angle(r2), np.angle(rd), np.angle(r4), np.angle(r5)]
        return False
    rhs_v = np.array([vo[1] - vo[0], vo[2] - vo[0]])
    w = np.linalg.solve(m, [rhs_v[0].real, rhs_v[0].imag, rhs_v[1].real, rhs_v[1].imag])
    w2, w3, w4, w5 = w
    # Twice: a_B + (iα2 − ω2²)·r2 + (iα3 − ω3²)·r_k − (iαk − ωk²)·rk = a_k
    c1 = ao[1] - ao[0] + w2 * w2 * r2 + w3 * w3 * rd - w4 * w4 * r4
    c2 = ao[2] - ao[0] + w2 * w2 * r2 + w3 * w3 * re - w5 * w5 * r5
    al = np.linalg.solve(m, [c1.real, c1.imag, c2.real, c2.imag])
    a2, a3, _, _ = al
    sol.theta[:, i] = [np.angle(r2), np.angle(rd), np.angle(r4), np.angle(r5)]
    sol.omega[:, i] = w
    sol.alpha[:, i] = al
    vc = vo[0] + 1j * w2 * r2
    ac = ao[0] + (1j * a2 - w2 * w2) * r2
    sol.v[:, i] = [vc, vc + 1j * w3 * rd, vc + 1j * w3 * re]
    sol.a[:, i] = [ac, ac + (1j * a3 - w3 * w3) * rd, ac + (1j * a3 - w3 * w3) * re]
    return True
