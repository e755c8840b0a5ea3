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
the assemblies so found the one nearest the stated start is taken — at several positions, the
one nearest the previous position's, so that a cycle keeps its branch. This is a different route
from the construction's (Newton on the two loop equations from the start, or from the previous
position), so they check each other.

A leg may be a block on a frame guide (its pin slides along it: ``Triad.guides``): the scan then
runs over the first pivoted leg's angle, the next leg is closed as an RRR or an RRP dyad (circle
∩ circle, or circle ∩ the guide), and the last leg's residual is ``|X − O|² − l²`` or the pin's
signed distance from its guide.

Velocities and accelerations: differentiating the loops once and twice gives four real linear
equations in (ω2, ω3, ω4, ω5) and (α2, α3, α4, α5) — a slider leg's ṡ and s̈ along its guide in
place of its ω and α — with the same matrix, solved by numpy's LU.
The matrix is singular exactly where the group's position stops being locally unique (the
group's "dead centre"); its condition number past ``1/TANGENT_REL`` marks the position invalid.

Imports only numpy, math, the model and the tolerances — nothing of the construction.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphmech.mechanisms.linkage import Triad
from graphmech.tolerances import TANGENT_REL

__all__ = ["SCAN", "TriadSolution", "assemblies", "assemblies_at", "solve_triad"]

#: Samples of θ2 over a full turn in the root scan (per hand of the dyad C–D–F). Two roots
#: closer than 2π/SCAN may be missed; the group's assemblies are far apart in any drawable case.
SCAN = 2880
_BISECT = 80  # halvings: 2π/SCAN / 2^80 is below every double's spacing

_C = complex


def _dyad(zc: np.ndarray, zf: Any, a: float, l4: float, hand: Any) -> tuple[np.ndarray, np.ndarray]:
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


def _on_guide(zc: np.ndarray, q: complex, u: complex, a: float, hand: Any) -> tuple[np.ndarray, np.ndarray]:
    """D on circle(C, a) ∩ the line Q + t·u, ahead of (hand +1) or behind the foot of the
    perpendicular from C; and whether it exists."""
    along = ((zc - q) * u.conjugate()).real
    across = ((zc - q) * u.conjugate()).imag
    h2 = a * a - across * across
    ok = h2 >= -TANGENT_REL * a * a  # the circle just touching the guide (the leg's limit) still meets it
    return q + u * (along + hand * np.sqrt(np.where(ok, np.maximum(h2, 0.0), 0.0))), ok


def _legs(y: Triad) -> tuple[int, int, int]:
    """(scan, next, last): the scanned leg is the first pivoted one (its angle spans a full turn),
    the next is closed by a dyad (RRR, or RRP on a slider leg's guide), the last is the residual."""
    r = next(k for k in range(3) if not y.slides(k))
    d, e = (k for k in range(3) if k != r)
    return r, d, e


def _local(y: Triad) -> tuple[complex, complex, complex]:
    """The ternary link's joints in its own frame: C at 0, D at l_CD on +x, E to the hand's side."""
    a, _, c = y.ternary  # l_CD, l_DE, l_EC
    return 0j, _C(a, 0.0), c * _rot(y)


def _unit(y: Triad, k: int) -> complex:
    g = y.guides[k]
    assert g is not None
    return _C(*g.direction)


def _chain(y: Triad, zo: tuple[Any, Any, Any], th: np.ndarray, hand: Any
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(C, D, E, f, assembled) along the scanned leg's angle: f the last leg's residual —
    ``|X − O|² − l²`` on a pivoted leg, the signed distance from the guide on a slider leg."""
    r, d, e = _legs(y)
    loc = _local(y)
    z: list[np.ndarray] = [np.zeros_like(th, dtype=complex)] * 3
    z[r] = zo[r] + y.lengths[r] * np.exp(1j * th)
    rho = abs(loc[d] - loc[r])
    if y.slides(d):
        g = y.guides[d]
        assert g is not None
        z[d], ok = _on_guide(z[r], _C(*g.through), _unit(y, d), rho, hand)
    else:
        z[d], ok = _dyad(z[r], zo[d], rho, y.lengths[d], hand)
    z[e] = z[r] + (z[d] - z[r]) / rho * ((loc[e] - loc[r]) / ((loc[d] - loc[r]) / rho))
    if y.slides(e):
        g = y.guides[e]
        assert g is not None
        f = ((z[e] - _C(*g.through)) * _unit(y, e).conjugate()).imag
    else:
        f = np.abs(z[e] - zo[e]) ** 2 - y.lengths[e] ** 2
    return z[0], z[1], z[2], f, ok


def _rot(y: Triad) -> complex:
    """e^{±iγ}: CE is CD turned by the ternary link's angle γ at C, to the triangle's hand."""
    a, b, c = y.ternary  # CD, DE, EC
    cos_g = (a * a + c * c - b * b) / (2.0 * a * c)
    sin_g = math.sqrt(max(0.0, 1.0 - cos_g * cos_g))
    return _C(cos_g, y.hand * sin_g)


def _dyad_limits(y: Triad, zo: tuple[complex, complex, complex]) -> list[float]:
    """The scanned leg's angles where the next leg's dyad is at a limit: a pivoted next leg where
    |X_r − O_d| = ρ ± l_d (its two circles touch), a slider leg where X_r is ρ from the guide."""
    r, d, _ = _legs(y)
    loc = _local(y)
    rho, lr = abs(loc[d] - loc[r]), y.lengths[r]
    out: list[float] = []
    if y.slides(d):
        g = y.guides[d]
        assert g is not None
        u = _unit(y, d)
        c0 = ((zo[r] - _C(*g.through)) * u.conjugate()).imag  # the pivot's distance across the guide
        for target in (rho, -rho):  # lr·sin(θ − ∠u) = target − c0
            s_ = (target - c0) / lr if lr > 0.0 else 2.0
            if abs(s_) <= 1.0:
                base = math.atan2(u.imag, u.real)
                out += [(base + math.asin(s_)) % (2.0 * math.pi), (base + math.pi - math.asin(s_)) % (2.0 * math.pi)]
        return out
    od = zo[d] - zo[r]
    dist = abs(od)
    for radius in (rho + y.lengths[d], abs(rho - y.lengths[d])):
        cos_t = (lr * lr + dist * dist - radius * radius) / (2.0 * lr * dist) if dist > 0.0 and lr > 0.0 else 2.0
        if abs(cos_t) <= 1.0:
            t = math.acos(cos_t)
            out += [(math.atan2(od.imag, od.real) + s * t) % (2.0 * math.pi) for s in (1.0, -1.0)]
    return out


def assemblies(y: Triad, zb: complex, zf: complex, zg: complex) -> list[tuple[complex, complex, complex]]:
    """Every assembly (C, D, E) of the group with its outer joints at B, F, G (a slider leg's
    entry is not read: its guide stands in for it)."""
    return assemblies_at(y, np.array([zb]), np.array([zf]), np.array([zg]))[0]


def assemblies_at(y: Triad, zb: np.ndarray, zf: np.ndarray, zg: np.ndarray
                  ) -> list[list[tuple[complex, complex, complex]]]:
    """:func:`assemblies` at several positions (the outer joints as complex arrays): the scan one
    position at a time, every root of every position then narrowed together — one bisection over
    all of them, so a cycle costs the same 80 halvings as one position."""
    # Each root bracketed by the scan: its position, hand, ends and the residual at the low end
    where: list[tuple[int, float]] = []
    lo_, hi_, flo_ = [], [], []
    for i in range(zb.shape[0]):
        zo = (complex(zb[i]), complex(zf[i]), complex(zg[i]))
        # the scan's nodes, and the limits of the dyad that closes the next leg (where its two hands
        # meet): a root between the last node that assembles and such a limit has no sign change
        # between two assembled nodes
        grid = np.unique(np.concatenate([np.linspace(0.0, 2.0 * math.pi, SCAN + 1), _dyad_limits(y, zo)]))
        for hand in (1.0, -1.0):
            _, _, _, f, ok = _chain(y, zo, grid, hand)
            change = np.flatnonzero(ok[:-1] & ok[1:] & (np.sign(f[:-1]) != np.sign(f[1:])))
            where += [(i, hand)] * change.size
            lo_.append(grid[change])
            hi_.append(grid[change + 1])
            flo_.append(f[change])
    out: list[list[tuple[complex, complex, complex]]] = [[] for _ in range(zb.shape[0])]
    if not where:
        return out
    lo, hi, flo = np.concatenate(lo_), np.concatenate(hi_), np.concatenate(flo_)
    at = np.array([i for i, _ in where])
    zo_r = (zb[at], zf[at], zg[at])
    hand_r = np.array([h for _, h in where])
    going = np.ones(lo.shape, dtype=bool)  # the roots still being halved
    for _ in range(_BISECT):
        mid = 0.5 * (lo + hi)
        going &= (mid != lo) & (mid != hi)
        if not going.any():
            break
        _, _, _, fm, okm = _chain(y, zo_r, mid, hand_r)
        going &= okm
        low = going & (np.sign(fm) == np.sign(flo))
        lo, flo = np.where(low, mid, lo), np.where(low, fm, flo)
        hi = np.where(going & ~low, mid, hi)
    zc, zd, ze, _, _ = _chain(y, zo_r, 0.5 * (lo + hi), hand_r)
    for k, (i, _) in enumerate(where):
        out[i].append((complex(zc[k]), complex(zd[k]), complex(ze[k])))
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
        self.sign = np.zeros(n)  # the sign of the velocity equations' determinant: one per branch


def solve_triad(y: Triad, known: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]) -> TriadSolution:
    """The group at N positions, its outer joints' (z, v, a) given as complex arrays in ``known``
    (a slider leg's entry is not read: its guide is on the frame)."""
    n = np.asarray(known[y.known_outer[0]][0]).shape[0]
    zero = np.zeros(n, dtype=complex)
    zo, vo, ao = (np.array([zero if y.slides(j) else known[p][k] for j, p in enumerate(y.outer)]) for k in range(3))
    sol = TriadSolution(n)
    start = np.array([_C(*p) for p in y.start])
    side = 0.0  # the branch's sign of the determinant, from the first position solved
    for i, found in enumerate(assemblies_at(y, zo[0], zo[1], zo[2])):
        if not found:
            sol.assembled[i] = sol.valid[i] = False
            sol.reason[i] = f"class III group {y.name}: cannot be assembled"
            continue
        # the assembly nearest the last position's (the first: nearest the start) — the branch is
        # followed over a cycle
        best = min(found, key=lambda t: float(np.sum(np.abs(np.array(t) - start) ** 2)))
        start = np.array(best)
        sol.z[:, i] = best
        ok = _rates(y, sol, i, zo[:, i], vo[:, i], ao[:, i])
        if not ok:
            sol.valid[i] = False
            sol.reason[i] = f"class III group {y.name}: dead centre (its velocity equations are singular)"
        elif side and sol.sign[i] != side:
            # a branch never crosses a singular position, so its determinant keeps its sign: a flip
            # means the branch ended (the group locked) since the last position and the assembly found
            # is another one — not where the mechanism can be driven to
            sol.valid[i] = False
            sol.reason[i] = (f"class III group {y.name}: its branch ends before this position (the group locks "
                             "between the last position and this one)")
        elif ok:
            side = sol.sign[i]
    return sol


def _rates(y: Triad, sol: TriadSolution, i: int, zo: np.ndarray, vo: np.ndarray, ao: np.ndarray) -> bool:
    """ω and α of the legs and the ternary link from the differentiated loops; False at a singular
    position. A slider leg's unknown is its pin's speed ṡ (and s̈) along the guide instead of ω."""
    zc, zd, ze = sol.z[:, i]
    r2, r4, r5 = zc - zo[0], zd - zo[1], ze - zo[2]
    rd, re = zd - zc, ze - zc  # the ternary link's sides CD, CE
    # A leg's column: iω·r (pivoted: v_X = v_O + iω·r) or ṡ·u (a slider: v_X = ṡ·u on the frame)
    col = [_unit(y, k) if y.slides(k) else 1j * r for k, r in enumerate((r2, r4, r5))]
    # Loop k (k = F via D, G via E):  v_B + col0·q0 + iω3·r_k − colk·qk = v_k  (real and imaginary rows)
    cols = [(col[0], col[0]), (1j * rd, 1j * re), (-col[1], 0j), (0j, -col[2])]
    m = np.array([[c[0].real for c in cols], [c[0].imag for c in cols],
                  [c[1].real for c in cols], [c[1].imag for c in cols]])
    scale = np.array([abs(c) for c in (col[0], rd, col[1], col[2])])
    theta = [y.guides[k].angle if y.guides[k] is not None else np.angle(r)  # type: ignore[union-attr]
             for k, r in enumerate((r2, r4, r5))]
    sol.theta[:, i] = [theta[0], np.angle(rd), theta[1], theta[2]]
    sol.sign[i] = np.sign(np.linalg.det(m))
    if np.linalg.cond(m / scale) > 1.0 / TANGENT_REL:
        return False
    rhs_v = np.array([vo[1] - vo[0], vo[2] - vo[0]])
    w = np.linalg.solve(m, [rhs_v[0].real, rhs_v[0].imag, rhs_v[1].real, rhs_v[1].imag])
    leg_of = (0, None, 1, 2)  # the solution's rows: leg 0, the ternary link, leg 1, leg 2
    w2, w3, w4, w5 = (0.0 if k is not None and y.slides(k) else w[j] for j, k in enumerate(leg_of))
    # Twice: a_B + (iα2 − ω2²)·r2 + (iα3 − ω3²)·r_k − (iαk − ωk²)·rk = a_k (a slider leg: s̈·u, no ω²)
    c1 = ao[1] - ao[0] + w2 * w2 * r2 + w3 * w3 * rd - w4 * w4 * r4
    c2 = ao[2] - ao[0] + w2 * w2 * r2 + w3 * w3 * re - w5 * w5 * r5
    al = np.linalg.solve(m, [c1.real, c1.imag, c2.real, c2.imag])
    a2, a3 = al[0], al[1]
    sol.omega[:, i] = [w2, w3, w4, w5]
    sol.alpha[:, i] = [0.0 if k is not None and y.slides(k) else al[j] for j, k in enumerate(leg_of)]
    vc = vo[0] + col[0] * w[0] if y.slides(0) else vo[0] + 1j * w2 * r2
    ac = ao[0] + col[0] * a2 if y.slides(0) else ao[0] + (1j * a2 - w2 * w2) * r2
    sol.v[:, i] = [vc, vc + 1j * w3 * rd, vc + 1j * w3 * re]
    sol.a[:, i] = [ac, ac + (1j * a3 - w3 * w3) * rd, ac + (1j * a3 - w3 * w3) * re]
    return True
