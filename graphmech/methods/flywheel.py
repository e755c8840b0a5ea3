"""The flywheel designed graphically from the reduced moment Mп and the reduced inertia Jп.

The course project's steps, in the order the draftsman takes them (all on drawing millimetres;
a value is a drawn length times its scale μ):

1. choose the scales: μφ so the cycle spans about 150 mm, μM so Mп spans about 60 mm, the
   pole distance H, and μA = μT = μM·μφ·H (μφ in rad/mm); μJ so Jп spans about 60 mm;
2. lay off the ordinates Mп_k/μM at φ_k/μφ, the cycle closed by repeating position 1 at φ = Φ;
3. integrate Mп by chords with the pole P at distance H (:func:`integrate_by_chords`): the chord
   polygon is the work of the loads, Aп(φ);
4. the constant moment does the opposite work over a cycle: its work A_b(φ) is the straight line
   from the origin to −Aп(Φ); differentiate it by the ray from P parallel to it
   (:func:`differentiate_by_ray`): the ray cuts the moment axis at the constant moment's ordinate.
   With ``balance="driving"`` the given Mп are the loads and the constant is the driving moment
   Mд (> 0); with ``balance="resisting"`` Mп is the driving torque and the constant is the
   resistance Mс (< 0);
5. add the two works: ΔT_k = Aп_k + A_b,k (drawn at μT = μA), zero at position 1 and again at
   the end of the cycle;
6. the Wittenbauer diagram ΔT(Jп), its tangents at ψmax, ψmin, the segment kl on the ΔT axis
   and J_F = μT·kl/(ω_m²δ) (:mod:`graphmech.methods.wittenbauer`), if asked for;
7. the energy indicator: ΔW_max from the chain of excess and deficit areas and
   J_F′ = ΔW_max/(ω_m²δ) − J_mean, if asked for.

Everything is numpy and vectorised; N may be thousands of positions.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Literal, Mapping, Sequence, SupportsFloat

import numpy as np
from numpy.typing import ArrayLike

from graphmech.errors import OutOfDomain
from graphmech.methods.graphical_integration import Integration, differentiate_by_ray, integrate_by_chords
from graphmech.methods.wittenbauer import (EnergyIndicator, TangentForm, WittenbauerDiagram, energy_indicator,
                                           flywheel_inertia, tangent_slopes, wittenbauer)
from graphmech.scales import round_scale

Balance = Literal["driving", "resisting"]

#: The drawing sizes the scales are chosen for, mm: the cycle's length on the φ axis and the
#: height of the Mп, A and ΔT diagrams; the Jп axis's length.
CYCLE_MM, HEIGHT_MM, J_MM = 150.0, 60.0, 60.0
#: The pole distance taken when neither H nor μT is given, mm; if the work diagram would then be
#: higher than HEIGHT_MM, H is raised to the next multiple of H_STEP that fits.
H_STEP = 5.0
#: What ``need`` may ask for.
NEEDS = ("wittenbauer", "indicator")
#: Relative slack for a balancing moment of the wrong sign (rounding of a zero net work).
SIGN_SLACK = 1e-12


class WrongBalance(OutOfDomain):
    """The loads' work over a cycle has the sign the constant moment cannot balance (a ValueError).

    ``work`` is Aп(Φ), J: > 0 when the loads deliver work (no constant *driving* moment balances
    them), < 0 when a driving torque absorbs it (no constant *resistance* does)."""

    def __init__(self, message: str, work: float) -> None:
        super().__init__(message)
        self.work = work


@dataclass(frozen=True, eq=False)
class FlywheelDesign:
    """The graphical flywheel design: every construction (for drawing) and its results.

    Attributes
    ----------
    phi, J, M : ndarray, shape (N,)
        The positions φ_k (rad), Jп_k (kg·m²) and Mп_k (N·m) it was made from (M None when ΔT
        was given: :func:`design_from_energy`; so are the moment's construction and results).
    cycle, omega_m, delta : float
        Φ (rad), ω_m (rad/s), δ.
    balance, form : str
        Which moment is the constant one; the tangents' reading (see :func:`tangent_slopes`).
    scales : mapping
        ``"phi"`` rad/mm, ``"M"`` N·m/mm, ``"T"`` J/mm (= μA), ``"J"`` kg·m²/mm.
    H_mm : float
        The pole distance.
    sources : mapping
        How each scale and H was obtained: ``"given"``, ``"chosen"`` (round, to fit the
        drawing), ``"μM·μφ·H"``, ``"μT/(μM·μφ)"``, ``"default"``.
    x_mm : ndarray, shape (N+1,)
        The divisions' abscissae φ_k/μφ, φ = Φ last.
    moment : Integration
        The Mп diagram and its integration by chords: ``moment.x_mm`` (N+1 abscissae, φ = Φ
        last), ``moment.y_mm`` (Mп ordinates, position 1 repeated at the end), the mean
        ordinates, the pole, and the chord polygon ``moment.integral_mm`` = Aп at μT.
    work_mm : ndarray, shape (N+1,)
        Aп_k/μT (the same as ``moment.integral_mm``).
    balance_work_mm : ndarray, shape (N+1,)
        A_b: the straight line from the origin to −Aп(Φ), at the divisions.
    balancing_mm : float
        Where the ray from P parallel to A_b cuts the moment axis (mm at μM).
    energy_mm : ndarray, shape (N+1,)
        ΔT_k/μT = Aп_k + A_b,k, the end of the cycle (0) last.
    inertia_mm : ndarray, shape (N,)
        Jп_k/μJ.
    balancing_moment : float
        The constant moment, N·m (= ``balancing_mm``·μM): Mд > 0 or Mс < 0.
    dT : ndarray, shape (N,)
        ΔT_k, J.
    dT_max, dT_min : float
        The largest and smallest ΔT_k, J.
    energy_max_index, energy_min_index : int
        Where they are (0-based; position = index + 1).
    J_mean : float
        The mean of Jп over the cycle (chords, like Aп), kg·m².
    wittenbauer : WittenbauerDiagram or None
        If asked for.
    J_F : float or None
        μT·kl/(ω_m²δ), kg·m² (≤ 0: no flywheel needed).
    indicator : EnergyIndicator or None
        If asked for.
    DeltaW_max : float or None
        ΔW_max, J.
    J_F_indicator : float or None
        ΔW_max/(ω_m²δ) − J_mean, kg·m².
    """

    phi: np.ndarray
    J: np.ndarray
    M: np.ndarray | None
    cycle: float
    omega_m: float
    delta: float
    balance: Balance | None
    form: TangentForm
    scales: Mapping[str, float]
    H_mm: float | None
    sources: Mapping[str, str]
    x_mm: np.ndarray
    moment: Integration | None
    work_mm: np.ndarray | None
    balance_work_mm: np.ndarray | None
    balancing_mm: float | None
    energy_mm: np.ndarray
    inertia_mm: np.ndarray
    balancing_moment: float | None
    dT: np.ndarray
    dT_max: float
    dT_min: float
    energy_max_index: int
    energy_min_index: int
    J_mean: float
    wittenbauer: WittenbauerDiagram | None = None
    J_F: float | None = None
    indicator: EnergyIndicator | None = None
    DeltaW_max: float | None = None
    J_F_indicator: float | None = None

    @property
    def n(self) -> int:
        """The number of positions N."""
        return int(self.phi.size)


def _frozen(a: ArrayLike) -> np.ndarray:
    out = np.array(a, dtype=float)
    out.setflags(write=False)
    return out


def _positive(name: str, v: SupportsFloat | str) -> float:
    try:
        x = float(v)  # a caller without types may pass anything: float() refuses it below
    except (TypeError, ValueError):
        raise OutOfDomain(f"{name} must be a number, not {v!r}") from None
    if not (x > 0.0 and math.isfinite(x)):
        raise OutOfDomain(f"{name} must be positive and finite, not {v!r}")
    return x


def _inputs(phi: ArrayLike, J: ArrayLike, M: ArrayLike, cycle: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    p, j, m = (np.asarray(a, dtype=float) for a in (phi, J, M))
    problems = []
    if p.ndim != 1 or p.size < 2 or j.shape != p.shape or m.shape != p.shape:
        raise OutOfDomain(f"phi, J and M must be 1-D arrays of one length N ≥ 2, got shapes {p.shape}, {j.shape}, "
                         f"{m.shape}")
    if not (np.isfinite(p).all() and np.isfinite(j).all() and np.isfinite(m).all()):
        problems.append("phi, J and M must be finite")
    elif abs(p[0]) > 1e-12 * cycle:
        problems.append(f"φ is measured from position 1: phi[0] must be 0, not {float(p[0])!r}")
    elif not (np.all(np.diff(p) > 0.0) and p[-1] < cycle):
        problems.append("the positions must increase strictly within one cycle (0 ≤ φ < Φ)")
    if np.isfinite(j).all() and (j < 0.0).any():
        problems.append("a reduced moment of inertia cannot be negative")
    if problems:
        raise OutOfDomain("; ".join(problems))
    return p, j, m


def _chord_work(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Σ of the chords' rises with H = 1, in the units of x·y (the trapezoidal integral)."""
    return np.concatenate([[0.0], np.cumsum(0.5 * (y[:-1] + y[1:]) * np.diff(x))])


def _span(*arrays: ArrayLike) -> float:
    v = np.concatenate([np.ravel(np.asarray(a, dtype=float)) for a in arrays] + [np.zeros(1)])
    return float(v.max() - v.min())


def _choose_scales(phi_c: np.ndarray, J: np.ndarray, M_c: np.ndarray, omega_m: float,
                   given: Mapping[str, float], H_mm: float | None) -> tuple[dict[str, float], float, dict[str, str]]:
    """Round scales for what ``given`` lacks, and H (see :func:`design_flywheel`)."""
    bad = sorted(set(given) - {"phi", "M", "J", "T"})
    if bad:
        raise OutOfDomain(f"unknown scale(s) {', '.join(map(repr, bad))}; a flywheel uses phi, M, J, T")
    scales = {k: _positive(f"the scale μ{k}", v) for k, v in given.items()}
    sources = {k: "given" for k in scales}
    cycle = float(phi_c[-1])
    if "phi" not in scales:  # a round number of degrees per mm, as books write it
        scales["phi"] = math.radians(round_scale(math.degrees(cycle) / CYCLE_MM))
        sources["phi"] = "chosen"
    work = _chord_work(phi_c, M_c)  # Aп, J
    balance = -work[-1] * phi_c / cycle  # A_b, J
    if "M" not in scales:
        span = _span(M_c, [-work[-1] / cycle])
        scales["M"] = round_scale(span / HEIGHT_MM) if span > 0.0 else 1.0
        sources["M"] = "chosen"
    per_H = scales["M"] * scales["phi"]  # μT per mm of H
    if H_mm is not None:
        H = _positive("the pole distance H", H_mm)
        sources["H"] = "given"
        if "T" in scales and abs(scales["T"] - per_H * H) > 1e-9 * scales["T"]:
            raise OutOfDomain(f"μT = {scales['T']:g} J/mm contradicts μM·μφ·H = {per_H * H:g} J/mm")
    elif "T" in scales:
        H = scales["T"] / per_H
        sources["H"] = "μT/(μM·μφ)"
    else:
        need = max(_span(work, balance), _span(work + balance)) / (per_H * HEIGHT_MM)
        # the smallest round H that keeps A(φ) within the panel: the ΔT diagram as tall as it can be
        H = max(H_STEP, H_STEP * math.ceil(need / H_STEP - 1e-12))
        sources["H"] = "chosen"
    if "T" not in scales:
        scales["T"] = per_H * H
        sources["T"] = "μM·μφ·H"
    if "J" not in scales:
        jmax = float(J.max())  # the J axis starts at Jп = 0: k and l lie on it
        scales["J"] = round_scale(jmax / J_MM) if jmax > 0.0 else round_scale(2.0 * scales["T"] / omega_m ** 2)
        sources["J"] = "chosen"
    return scales, H, sources


def design_flywheel(phi: ArrayLike, J: ArrayLike, M: ArrayLike, *, cycle: float, omega_m: float, delta: float,
                    balance: Balance = "driving", form: TangentForm = "exact", H_mm: float | None = None,
                    scales: Mapping[str, float] | None = None,
                    need: Sequence[str] = ("wittenbauer",)) -> FlywheelDesign:
    """The whole graphical flywheel design from the reduced values at the positions.

    Parameters
    ----------
    phi : array_like, shape (N,)
        φ_k, rad from position 1 in the sense of rotation: 0 = φ₁ < φ₂ < … < Φ.
    J : array_like, shape (N,)
        Jп_k, kg·m² (≥ 0).
    M : array_like, shape (N,)
        Mп_k, N·m, signed by power (positive drives): with ``balance="driving"`` the loads'
        reduced moment, with ``"resisting"`` the driving torque.
    cycle : float
        Φ, rad (2π, or π for a torque repeating every half turn).
    omega_m : float
        Mean angular velocity ω_m, rad/s.
    delta : float
        The required coefficient of speed fluctuation δ.
    balance : "driving" or "resisting"
        Which moment is the constant one found from the balance of work.
    form : "exact" or "book"
        The Wittenbauer tangents' reading of ω_max, ω_min (:func:`tangent_slopes`).
    H_mm : float, optional
        The pole distance, mm. Without it: H = μT/(μM·μφ) if ``scales`` gives μT, else 40 mm
        (raised to a multiple of 10 mm if the work diagram would be over 60 mm high).
    scales : mapping, optional
        Any of ``"phi"`` (rad/mm), ``"M"`` (N·m/mm), ``"J"`` (kg·m²/mm), ``"T"`` (J/mm); the
        others are chosen round (:func:`graphmech.scales.round_scale`): μφ a round number of
        °/mm with the cycle about 150 mm long, μM with Mп and the constant moment spanning
        about 60 mm, μJ with Jп_max about 60 mm from the ΔT axis; μT = μM·μφ·H.
    need : sequence of str
        ``"wittenbauer"`` and/or ``"indicator"``: only those are computed.

    Raises
    ------
    ValueError
        Inconsistent or non-finite data, an unknown ``need`` or scale, μT contradicting
        μM·μφ·H, or a constant moment of the wrong sign (loads that drive the machine over a
        cycle cannot be balanced by a driving moment, nor a driving torque by a resistance).

    Examples
    --------
    Twelve positions of a machine with a sinusoidal load (mean −50 N·m) and constant Jп:

    >>> phi = np.arange(12) * np.pi / 6
    >>> d = design_flywheel(phi, np.full(12, 0.5), -50.0 + 100.0 * np.sin(phi), cycle=2 * np.pi,
    ...                     omega_m=100.0, delta=0.02, need=("wittenbauer", "indicator"))
    >>> round(d.balancing_moment, 9), d.H_mm, d.sources["H"]     # 40 mm would draw A(φ) over 60 mm high
    (50.0, 50.0, 'chosen')
    >>> round(d.J_F, 9) == round(d.J_F_indicator, 9)       # Jп constant: the two methods agree
    True
    """
    cycle = _positive("the cycle Φ", cycle)
    omega_m = _positive("ω_m", omega_m)
    delta = _positive("δ", delta)
    if balance not in ("driving", "resisting"):
        raise OutOfDomain(f"balance must be 'driving' or 'resisting', not {balance!r}")
    if form not in ("exact", "book"):
        raise OutOfDomain(f"form must be 'exact' or 'book', not {form!r}")
    need = tuple(need)
    bad = [x for x in need if x not in NEEDS]
    if bad:
        raise OutOfDomain(f"need may hold {' and '.join(NEEDS)}, not {', '.join(map(repr, bad))}")
    p, j, m = _inputs(phi, J, M, cycle)
    if "wittenbauer" in need:  # the tangents' δ range, before any drawing
        tangent_slopes(omega_m, delta, 1.0, 1.0, form)

    # 1. the scales
    phi_c = np.append(p, cycle)
    m_c = np.append(m, m[0])  # the cycle closed: position 1 again at φ = Φ
    mu, H, sources = _choose_scales(phi_c, j, m_c, omega_m, scales or {}, H_mm)

    # 2.–3. the Mп ordinates and their integration by chords: Aп
    x = phi_c / mu["phi"]
    integration = integrate_by_chords(x, m_c / mu["M"], H)
    work = integration.integral_mm

    # 4. the balancing work: the line from the origin to −Aп(Φ); its moment by the ray from P ∥ it
    end = -float(work[-1])
    balance_work = end * (x / x[-1])
    balancing_mm = differentiate_by_ray(float(x[-1]), end, H)
    moment = balancing_mm * mu["M"]
    slack = SIGN_SLACK * max(float(np.abs(m).max()), 1e-300)
    if balance == "driving" and moment < -slack:
        raise WrongBalance(f"the loads deliver work over the cycle (Aп(Φ) = {-end * mu['T']:.6g} J > 0): a constant "
                           "driving moment cannot balance them; check the signs of Mп or use balance='resisting'",
                           -end * mu["T"])
    if balance == "resisting" and moment > slack:
        raise WrongBalance(f"the driving torque absorbs work over the cycle (Aп(Φ) = {-end * mu['T']:.6g} J < 0): a "
                           "constant resistance cannot balance it; check the signs of Mп or use balance='driving'",
                           -end * mu["T"])

    # 5. ΔT = Aп + A_b
    energy = work + balance_work
    return _finish(p, j, m, energy, x, cycle=cycle, omega_m=omega_m, delta=delta, balance=balance, form=form,
                   mu=mu, H=H, sources=sources, need=need, integration=integration,
                   balance_work=balance_work, balancing_mm=float(balancing_mm), moment=float(moment))


def _finish(p: np.ndarray, j: np.ndarray, m: np.ndarray | None, energy: np.ndarray, x: np.ndarray, *,
            cycle: float, omega_m: float, delta: float, balance: Balance | None, form: TangentForm,
            mu: Mapping[str, float], H: float | None, sources: Mapping[str, str], need: Sequence[str],
            integration: Integration | None = None, balance_work: np.ndarray | None = None,
            balancing_mm: float | None = None, moment: float | None = None) -> FlywheelDesign:
    """Steps 5–7 from ΔT_k/μT (``energy``, N+1 with the cycle's end): its extremes, the Wittenbauer
    diagram and the energy indicator, as ``need`` asks."""
    dT = energy[:-1] * mu["T"]
    i_max, i_min = int(np.argmax(energy[:-1])), int(np.argmin(energy[:-1]))
    phi_c = np.append(p, cycle)
    j_mean = float(_chord_work(phi_c, np.append(j, j[0]))[-1] / cycle)
    inertia = j / mu["J"]

    # 6. the Wittenbauer diagram
    w = J_F = None
    if "wittenbauer" in need:
        w = wittenbauer(inertia, energy[:-1], *tangent_slopes(omega_m, delta, mu["J"], mu["T"], form))
        J_F = flywheel_inertia(w.kl_mm, mu["T"], omega_m, delta)

    # 7. the energy indicator
    ind = dW = J_F_ind = None
    if "indicator" in need:
        ind = energy_indicator(energy[:-1])
        dW = ind.dW_max_mm * mu["T"]
        J_F_ind = flywheel_inertia(ind.dW_max_mm, mu["T"], omega_m, delta) - j_mean

    return FlywheelDesign(
        phi=_frozen(p), J=_frozen(j), M=None if m is None else _frozen(m), cycle=cycle, omega_m=omega_m,
        delta=delta, balance=balance, form=form, scales=MappingProxyType(dict(mu)),
        H_mm=None if H is None else float(H), sources=MappingProxyType(dict(sources)), x_mm=_frozen(x),
        moment=integration, work_mm=None if integration is None else integration.integral_mm,
        balance_work_mm=None if balance_work is None else _frozen(balance_work), balancing_mm=balancing_mm,
        energy_mm=_frozen(energy), inertia_mm=_frozen(inertia), balancing_moment=moment, dT=_frozen(dT),
        dT_max=float(dT[i_max]), dT_min=float(dT[i_min]), energy_max_index=i_max, energy_min_index=i_min,
        J_mean=j_mean, wittenbauer=w, J_F=J_F, indicator=ind, DeltaW_max=dW, J_F_indicator=J_F_ind)


def design_from_energy(phi: ArrayLike, J: ArrayLike, dT: ArrayLike, *, cycle: float, omega_m: float,
                       delta: float, form: TangentForm = "exact", scales: Mapping[str, float] | None = None,
                       need: Sequence[str] = ("wittenbauer",)) -> FlywheelDesign:
    """The flywheel designed from ΔT_k given directly (a table of the increment of kinetic energy):
    steps 5–7 of :func:`design_flywheel`, with no moments, no integration and no pole.

    ``dT`` is ΔT_k, J, at the positions (ΔT_1 = 0 at φ = 0); the other parameters as for
    :func:`design_flywheel`. Of ``scales`` only ``"phi"``, ``"J"``, ``"T"`` apply; μT is chosen
    round with ΔT spanning about 60 mm when not given. The result's ``M``, ``moment``,
    ``work_mm``, ``balance_work_mm``, ``balancing_mm``, ``balancing_moment``, ``balance`` and
    ``H_mm`` are None.

    Examples
    --------
    >>> phi = np.arange(12) * np.pi / 6
    >>> d = design_from_energy(phi, np.full(12, 0.5), 100.0 * (1.0 - np.cos(phi)), cycle=2 * np.pi,
    ...                        omega_m=100.0, delta=0.02, need=("wittenbauer", "indicator"))
    >>> round(d.DeltaW_max, 9), d.scales["T"], d.moment is None
    (200.0, 5.0, True)
    >>> round(d.J_F_indicator, 9)                 # 200/(100²·0.02) − 0.5
    0.5
    """
    cycle = _positive("the cycle Φ", cycle)
    omega_m = _positive("ω_m", omega_m)
    delta = _positive("δ", delta)
    if form not in ("exact", "book"):
        raise OutOfDomain(f"form must be 'exact' or 'book', not {form!r}")
    need = tuple(need)
    bad = [x for x in need if x not in NEEDS]
    if bad:
        raise OutOfDomain(f"need may hold {' and '.join(NEEDS)}, not {', '.join(map(repr, bad))}")
    p, j, t = _inputs(phi, J, dT, cycle)
    if "wittenbauer" in need:
        tangent_slopes(omega_m, delta, 1.0, 1.0, form)
    given = dict(scales or {})
    bad = sorted(set(given) - {"phi", "J", "T"})
    if bad:
        raise OutOfDomain(f"scale(s) {', '.join(map(repr, bad))} do not apply: ΔT is given, nothing is integrated")
    mu = {k: _positive(f"the scale μ{k}", v) for k, v in given.items()}
    sources = {k: "given" for k in mu}
    if "phi" not in mu:
        mu["phi"] = math.radians(round_scale(math.degrees(cycle) / CYCLE_MM))
        sources["phi"] = "chosen"
    if "T" not in mu:
        span = _span(t)
        mu["T"] = round_scale(span / HEIGHT_MM) if span > 0.0 else 1.0
        sources["T"] = "chosen"
    if "J" not in mu:
        jmax = float(j.max())
        mu["J"] = round_scale(jmax / J_MM) if jmax > 0.0 else round_scale(2.0 * mu["T"] / omega_m ** 2)
        sources["J"] = "chosen"
    energy = np.append(t, 0.0) / mu["T"]  # the cycle closed: ΔT back to 0 at Φ
    x = np.append(p, cycle) / mu["phi"]
    return _finish(p, j, None, energy, x, cycle=cycle, omega_m=omega_m, delta=delta, balance=None, form=form,
                   mu=mu, H=None, sources=sources, need=need)


__all__ = ["FlywheelDesign", "NEEDS", "WrongBalance", "design_flywheel", "design_from_energy"]
