"""Checking a flywheel scene: reduce, integrate, draw the Wittenbauer diagram, prove it by motion.

The counterpart of :mod:`graphmech.problems.linkage.check` for the flywheel problem. The course project's steps
are carried out as graphical constructions at the scene's N positions (Jп and Mп from the
velocity polygons, Aп by graphical integration, the balancing moment by graphical
differentiation, ΔT, the Wittenbauer diagram and its tangents, or the energy indicator) and
each result is set against its exact value: Jп and Mп agree to rounding; the integrals and
the flywheel differ by the discretisation error of N positions, which the table states and
``graphmech bench`` reports against N and run time. When the scene asks for it, the machine's
equation of motion is integrated with the flywheel just designed, and the achieved speed
fluctuation is compared with the energy equation's and with the required δ.

Only what the scene asks for is computed: a scene that wants J_F by the energy indicator does
not draw the Wittenbauer diagram, and none integrates the motion unless asked.
"""
from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING, Any, TypeVar, cast

import numpy as np

from graphmech.accuracy import DISCRETISATION, READING, estimate_from_three, relative
from graphmech.problems.judging import Row, Verdict, close_names, in_double_precision, judge_value, measured_entries
from graphmech.errors import DegenerateConstruction, SceneError
from graphmech.mechanisms.machine import Machine

if TYPE_CHECKING:
    from graphmech.exact.flywheel import ExactMachine
    from graphmech.problems.flywheel.scene import Braking
    from graphmech.problems.flywheel.scene import FlywheelScene
    from graphmech.problems.reader import Scene

T = TypeVar("T")

#: Quantities a flywheel scene can ask for: name → (unit, what it needs).
#: "design": the graphical construction; "wittenbauer"/"indicator": that method's diagram;
#: "motion": the equation of motion; "braking": the run-down.
QUANTITIES: dict[str, tuple[str, str]] = {
    "Jp": ("kg·m²", "reduction"), "Mp": ("N·m", "reduction"), "DeltaT": ("J", "design"),
    "A_p": ("J", "design"),
    "M_b": ("N·m", "design"), "Md": ("N·m", "design"), "Mr": ("N·m", "design"),
    "DeltaT_max": ("J", "design"), "DeltaT_min": ("J", "design"),
    "phi_DeltaT_max": ("deg", "design"), "phi_DeltaT_min": ("deg", "design"),
    "k": ("J", "wittenbauer"), "l": ("J", "wittenbauer"),
    "psi_max": ("deg", "wittenbauer"), "psi_min": ("deg", "wittenbauer"),
    "tan_psi_max": ("", "wittenbauer"), "tan_psi_min": ("", "wittenbauer"),
    "phi_max": ("deg", "wittenbauer"), "phi_min": ("deg", "wittenbauer"),
    "J_F": ("kg·m²", "flywheel"),
    "J_F_wittenbauer": ("kg·m²", "wittenbauer"), "J_F_indicator": ("kg·m²", "indicator"),
    "DeltaW_max": ("J", "indicator"), "J_mean": ("kg·m²", "indicator"),
    "omega_max": ("rad/s", "design"), "omega_min": ("rad/s", "design"),
    "n_max": ("rpm", "design"), "n_min": ("rpm", "design"),
    "omega_max_true": ("rad/s", "motion"), "omega_min_true": ("rad/s", "motion"),
    "phi_omega_max": ("deg", "motion"), "phi_omega_min": ("deg", "motion"),
    "delta_achieved": ("", "motion"), "omega_mean_time": ("rad/s", "motion"),
    "omega_s": ("rad/s", "motion"),
    "t_stop": ("s", "braking"),
}
#: Per-position quantities (named ``Jp@3``).
PER_POSITION = ("Jp", "Mp", "DeltaT", "A_p")
DEFAULT_FIND = ("M_b", "DeltaW_max", "J_F")
#: What needs the moments: refused when ΔT is given as a table ([flywheel.energy_increment]).
FROM_MOMENTS = ("Mp", "A_p", "M_b", "Md", "Mr")
#: Angles that say where in the cycle something happens: compared modulo the cycle Φ, their
#: relative error is the wrapped difference over Φ (an angle near 0° has no scale of its own).
POSITION_ANGLES = ("phi_DeltaT_max", "phi_DeltaT_min", "phi_omega_max", "phi_omega_min", "phi_max", "phi_min")
#: Angle between the two tangents below which a drawn pair cannot be told apart, degrees.
TANGENTS_APART_DEG = 0.1


@dataclass
class FlywheelAnalysis:
    scene: Scene[FlywheelScene]
    machine: Machine
    phi: np.ndarray
    labels: tuple[str, ...]
    reduction: Any = None
    design: Any = None
    exact: ExactMachine | None = None
    motion: Any = None  # TrueMotion (solve_ivp)
    motion_ref: Any = None  # the energy equation's motion with the same flywheel (or a tight reference)
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)
    stated: set[str] = field(default_factory=set)
    extra_measured: tuple[tuple[str, float], ...] = ()
    braking: Any = None
    rundown: Any = None  # the run-down diagram ω(t) as drawn (problems.flywheel.braking_figures.Rundown)
    #: Wall time spent integrating the equation of motion (every run: the scene's, its reference,
    #: the tighter one of the error estimate), s, and how many runs.
    motion_seconds: float = 0.0
    motion_runs: int = 0

    def scale_notes(self) -> list[str]:
        from graphmech.scales import format_scale

        out = []
        for k, v in self.scales.items():
            try:
                out.append(format_scale(k, v) + ("" if k in self.stated else " (chosen)"))
            except KeyError:
                out.append(f"μ{k} = {v:g}")
        return out

    def integrated(self, run: Callable[[], T]) -> T:
        """``run()``, one integration of the true motion, its wall time added to ``motion_seconds``."""
        t0 = time.perf_counter()
        try:
            return run()
        finally:
            self.motion_seconds += time.perf_counter() - t0
            self.motion_runs += 1

    def motion_summary(self) -> dict[str, Any]:
        """How the true motion was found: solver, tolerance, work done (for ``check --json``)."""
        mo = self.motion
        return {"solver": mo.solver, "rtol": mo.rtol, "atol": mo.atol, "J_F": mo.J_F, "cycles": mo.cycles,
                "steps_per_cycle": mo.steps, "nfev": mo.nfev, "njev": mo.njev, "period_s": mo.period,
                "omega_s": mo.omega_s, "delta_required": self.machine.delta}


    @cached_property
    def braking_inertia(self) -> float:
        """The inertia the brake stops, kg·m²: the constant one, plus the masses' reduced inertia
        averaged over a turn (a run-down lasts many turns, so the swing of Jп averages out)."""
        J = float(self.machine.inertia)
        if self.machine.masses:
            phi = np.linspace(0.0, self.machine.cycle, 720, endpoint=False)
            J = float(np.mean(_exact(self).inertia(phi)))
        return J

    def braking_summary(self) -> dict[str, Any]:
        """The run-down: stopping time against the required one (``ok`` None when none is required)."""
        limit = cast("Braking", self.scene.problem.braking).time_limit
        t = float(self.braking.t)
        return {"t_stop": t, "time_limit": limit, "ok": None if limit is None else bool(t <= limit)}


def split(name: str) -> tuple[str, str | None]:
    base, sep, at = name.partition("@")
    return base, (at if sep else None)


def _needs(scene: Scene[FlywheelScene], names: list[str]) -> set[str]:
    fw = scene.problem
    needs: set[str] = set()
    for n in names:
        base, _ = split(n)
        what = QUANTITIES[base][1]
        needs.add("flywheel:" + fw.method if what == "flywheel" else what)
    for panel in scene.show:
        if panel in ("wittenbauer", "indicator"):
            needs.add(panel)
        elif panel == "motion":  # ω(φ) of the true motion is drawn
            needs.add("motion")
        elif panel in ("moment", "work", "energy", "inertia"):
            needs.add("design")
    if fw.true_motion is not None:
        needs.add("motion")
    if "flywheel:wittenbauer" in needs:
        needs.add("wittenbauer")
    if "flywheel:indicator" in needs:
        needs.add("indicator")
    if "motion" in needs:
        needs.add(fw.method)
    if needs & {"wittenbauer", "indicator", "motion"}:
        needs.add("design")
    if "design" in needs:
        needs.add("reduction")
    return needs


def requested(scene: Scene[FlywheelScene], extra: tuple[tuple[str, float], ...] = ()) -> list[str]:
    """The quantity names the scene asks for, validated (problems raised as one SceneError)."""
    fw = scene.problem
    given_dT = fw.machine.energy_table is not None
    default = [x for x in DEFAULT_FIND if not (given_dT and x in FROM_MOMENTS)]
    names = list(scene.find) or ([] if fw.braking is not None and not fw.machine.loads and not given_dT
                                 else default)
    if fw.braking is not None and "t_stop" not in names:
        names.append("t_stop")
    problems = []
    n = fw.positions
    for key, name in [(f"find[{i}]", x) for i, x in enumerate(scene.find)] + \
            [(k, x) for k, x, _ in measured_entries(scene, extra) if x != "kl"]:
        base, at = split(name)
        if base not in QUANTITIES:
            problems.append((key, f"unknown flywheel quantity {base!r}{close_names(base, QUANTITIES)}"))
        elif base in PER_POSITION and (at is None or not at.isdigit() or not 1 <= int(at) <= n):
            problems.append((key, f"{base} is per position: write {base}@1 … {base}@{n}"))
        elif base not in PER_POSITION and at is not None:
            problems.append((key, f"{base} is one value for the cycle: write it without @{at}"))
        elif given_dT and (base in FROM_MOMENTS or QUANTITIES[base][1] == "motion"):
            problems.append((key, (f"{base} needs the moments: [flywheel.energy_increment] gives ΔT, which cannot "
                                   "be split back into its driving and resisting moments")))
        elif QUANTITIES[base][1] == "braking" and fw.braking is None:
            problems.append((key, "t_stop needs a [flywheel.braking] table"))
        elif QUANTITIES[base][1] == "motion" and fw.machine.loads == ():
            problems.append((key, f"{base} needs loads to move the machine"))
        elif base == "omega_s" and fw.machine.motor is None:
            problems.append((key, "omega_s is the motor's synchronous speed: it needs a [flywheel.motor] table"))
    if problems:
        raise SceneError(problems, scene.source)
    return names


def analyse_flywheel(scene: Scene[FlywheelScene], extra_measured: tuple[tuple[str, float], ...] = (), *,
                     estimates: bool = True) -> FlywheelAnalysis:
    """Carry out what the flywheel scene asks for and build its check table (with each row's own
    error estimate, which redoes the work at 2N and 4N positions: only a check needs it)."""
    with in_double_precision("the flywheel construction"):
        return _analyse(scene, extra_measured, estimates)


def _analyse(scene: Scene[FlywheelScene], extra: tuple[tuple[str, float], ...], estimates: bool) -> FlywheelAnalysis:
    fw = scene.problem
    machine: Machine = fw.machine
    names = requested(scene, extra)
    asked = names + [x for _, x, _ in measured_entries(scene, extra)]
    needs = _needs(scene, [x for x in asked if x != "kl"])  # kl, a drawn segment, is no quantity row
    if any(x == "kl" for x in asked):
        needs |= {"wittenbauer", "design", "reduction"}
    phi = np.asarray(machine.positions(fw.positions), dtype=float)
    an = FlywheelAnalysis(scene, machine, phi, tuple(str(k + 1) for k in range(fw.positions)))
    an.extra_measured = tuple(extra)
    if fw.braking is not None:
        _braking(an)
    if "reduction" in needs:
        _reduce(an)
    if "design" in needs:
        _design(an, needs)
    if "motion" in needs:
        _motion(an)
    for name in names:
        an.rows.append(_row(an, name))
    if estimates:
        _estimate(an, needs)
    return an


# ---------------------------------------------------------------------------- the steps


def _exact(an: FlywheelAnalysis) -> ExactMachine:
    if an.exact is None:
        from graphmech.exact.flywheel import ExactMachine

        try:
            an.exact = ExactMachine(an.machine)
        except SceneError as e:  # the exact machine names its own parts: say them as the scene's keys
            raise SceneError([_scene_key(k, why) for k, why in e.problems], an.scene.source) from None
        except ValueError as e:
            raise SceneError([("flywheel", str(e))], an.scene.source) from None
    return an.exact


def _scene_key(key: str, why: str) -> tuple[str, str]:
    """A problem the exact machine found (``loads[2]``, ``balance``, ``linkage``) under the scene's key."""
    if key.startswith("loads"):
        return "flywheel.load" + key[len("loads"):], why
    if key == "linkage":
        return "", f"the linkage {why}"
    return f"flywheel.{key}", why


def _reduce(an: FlywheelAnalysis) -> None:
    from graphmech.methods.reduction import reduce_to_crank

    scene, machine = an.scene, an.machine
    scales = {}
    if machine.linkage is not None:
        from graphmech.problems.linkage.check import choose_scales

        pos = np.array([machine.crank_angle(float(f)) for f in an.phi[:1]])
        lin, stated = choose_scales(_with_show(scene), machine.linkage, pos)
        scales = {"l": lin["l"], "v": lin["v"]}
        an.stated |= {k for k in ("l", "v") if k in stated}
    an.reduction = reduce_to_crank(machine, an.phi, scales)
    for k in sorted({k for k, _ in an.reduction.on_steps}):  # one rule at a jump, stated where it applies
        at = [i for kk, i in an.reduction.on_steps if kk == k]
        where = ", ".join(f"{i + 1} (φ = {math.degrees(an.phi[i]):.6g}°)" for i in at[:6]) + (" …" if len(at) > 6 else "")
        an.warnings.append(f"flywheel.load[{k}]: a step of its table falls on position{'s' if len(at) > 1 else ''} "
                           f"{where}: Mп there is the mean of both sides of the step")
    if not (np.isfinite(an.reduction.J).all() and np.isfinite(an.reduction.M).all()):  # ω1 of 1e-300 rad/s
        from graphmech.problems.judging import OUT_OF_RANGE

        raise DegenerateConstruction("the reduction to the crank", OUT_OF_RANGE)
    bad = np.flatnonzero(~an.reduction.valid)
    if bad.size:
        k = int(bad[0])
        raise DegenerateConstruction("the velocity polygon", an.reduction.reasons[k] or "impossible",
                                     f"position {k + 1} (φ = {math.degrees(an.phi[k]):.6g}°)")


def _with_show(scene: Scene[FlywheelScene]) -> Scene[FlywheelScene]:
    """The linkage scales are chosen as for a sheet showing the mechanism and its velocity polygon."""
    import dataclasses

    return dataclasses.replace(scene, show=("mechanism", "velocity"))


def _design(an: FlywheelAnalysis, needs: set[str]) -> None:
    from graphmech.methods.flywheel import design_from_energy

    fw, machine = an.scene.problem, an.machine
    scales = {k: float(v) for k, v in an.scene.scales.items() if k in ("phi", "M", "J", "T")}
    an.stated |= set(scales)
    want = tuple(x for x in ("wittenbauer", "indicator") if x in needs)
    r = an.reduction
    if machine.energy_table is not None:  # ΔT handed in: read off its table at the positions
        from graphmech.methods.reduction import table_at

        dT = table_at(machine.energy_table, np.mod(r.phi, machine.cycle))
        an.design = design_from_energy(r.phi, r.J, dT, cycle=machine.cycle, omega_m=machine.omega_m,
                                       delta=machine.delta, form=fw.tangents, scales=scales, need=want)
    else:
        _design_from_moments(an, scales, want)
    an.scales.update(getattr(an.design, "scales", {}))
    if "wittenbauer" in want:
        apart = float(getattr(an.design.wittenbauer, "angle_between_deg", 90.0))
        if apart < TANGENTS_APART_DEG:
            an.warnings.append(
                f"the tangents ψmax and ψmin differ by {apart:.2g}° (δ = {machine.delta:g}): a drawn pair cannot "
                "be told apart, and their intersection is ill-conditioned; k and l were found analytically "
                "(the extremes of ΔT − ω²·Jп/2 over the positions), not by intersecting drawn lines")


def _design_from_moments(an: FlywheelAnalysis, scales: dict[str, float], want: tuple[str, ...]) -> None:
    from graphmech.methods.flywheel import WrongBalance, design_flywheel

    fw, machine = an.scene.problem, an.machine
    r = an.reduction
    try:
        an.design = design_flywheel(r.phi, r.J, r.M, cycle=machine.cycle, omega_m=machine.omega_m,
                                    delta=machine.delta, balance=machine.balance, form=fw.tangents,
                                    H_mm=fw.pole_distance, scales=scales, need=want)
    except WrongBalance as e:
        raise SceneError([("flywheel.balance", _wrong_balance(machine.balance, e.work))], an.scene.source) from None


def _wrong_balance(balance: str, work: float) -> str:
    """Why the constant moment named by ``balance`` cannot balance the loads' work over a cycle."""
    if balance == "driving":
        return (f"the loads deliver {work:.6g} J over a cycle: a constant driving moment cannot balance them; "
                'check the signs of the loads or set balance = "resisting"')
    return (f"the driving torque absorbs {-work:.6g} J over a cycle: a constant resistance cannot balance it; "
            'check the signs of the loads or set balance = "driving"')


def _design_J_F(an: FlywheelAnalysis) -> float:
    d = an.design
    if an.scene.problem.method == "wittenbauer":
        return float(d.J_F)
    return float(d.J_F_indicator)


def _motion(an: FlywheelAnalysis) -> None:
    from graphmech.exact.true_motion import true_motion

    spec = an.scene.problem.true_motion
    solver = spec.solver if spec is not None else "Radau"
    rtol = spec.rtol if spec is not None else 1e-10
    ex = _exact(an)
    J_F = _design_J_F(an)
    if J_F <= 0.0:  # a flywheel of negative inertia cannot be fitted: run the machine as it is
        an.warnings.append(
            f"J_F = {J_F:.6g} kg·m² ≤ 0: the machine's own inertia already keeps δ within {an.machine.delta:g}, "
            "no flywheel is needed; the true motion is that of the machine without one")
        J_F = 0.0
    try:
        an.motion = an.integrated(lambda: true_motion(an.machine, ex, J_F, solver=solver, rtol=rtol))
        if an.machine.motor is None:
            an.motion_ref = ex.energy_motion(J_F)
        else:  # no closed form: a tighter run with another stiff solver is the reference
            other = "BDF" if solver == "Radau" else "Radau"
            an.motion_ref = an.integrated(
                lambda: true_motion(an.machine, ex, J_F, solver=other, rtol=max(rtol * 1e-2, 1e-13)))
    except ValueError as e:
        raise DegenerateConstruction("the true motion", str(e)) from None
    d = an.machine.delta
    got = an.motion.delta
    if got > d * (1 + 1e-3):
        an.warnings.append(
            f"the flywheel designed from {an.scene.problem.positions} positions (J_F = {J_F:.6g} kg·m²) gives "
            f"δ = {got:.6g} in the true motion, above the required {d:g} ({(got / d - 1) * 100:+.2f} %): "
            "use more positions")


def true_motion_curve(an: FlywheelAnalysis, samples: int) -> tuple[np.ndarray, np.ndarray]:
    """ω(φ) of the periodic true motion at ``samples`` equal steps of the cycle (both ends
    included), for drawing: stepped from the periodic ω(0) with the solver and tolerance the
    check used, through the same equation of motion."""
    from graphmech.exact.true_motion import integrate

    mo = an.motion
    phi = np.linspace(0.0, an.machine.cycle, samples)
    omega = np.empty(samples)
    omega[0] = mo.omega0
    ex = _exact(an)
    for i in range(1, samples):
        omega[i] = integrate(an.machine, ex, mo.J_F, (float(phi[i - 1]), float(phi[i])), float(omega[i - 1]),
                             solver=mo.solver, rtol=mo.rtol, atol=mo.atol).omega
    return phi, omega


def _braking(an: FlywheelAnalysis) -> None:
    from graphmech.exact.true_motion import T_STOP_MIN, braking_time

    fw = an.scene.problem
    from graphmech.problems.flywheel.braking_figures import draw_rundown

    b, w0 = cast("Braking", fw.braking), an.machine.omega_m  # asked only of a scene with [flywheel.braking]
    J = an.braking_inertia
    if not J > 0.0:
        raise SceneError([("flywheel.braking", "nothing to stop: the machine's reduced inertia is 0; give its "
                           "inertia (inertia_kgm2) or [[flywheel.mass]] with mass")], an.scene.source)
    t = J * w0 / b.moment
    if not (math.isfinite(t) and t >= T_STOP_MIN):  # J·ω0/M beyond double precision: no number to draw
        raise SceneError([(b.moment_path, f"the brake stops J = {J:.6g} kg·m² from ω = {w0:.6g} rad/s in "
                           f"J·ω/M = {t:.6g} s, beyond the range of numbers a run-down can be drawn at")],
                         an.scene.source)
    an.braking = braking_time(J, w0, b.moment)
    an.rundown = r = draw_rundown(J, w0, b.moment, b.time_limit)
    an.scales.update({"t": r.mu_t, "omega": r.mu_omega})
    prec = an.scene.precision_mm
    if r.t_stop_mm < prec:
        an.warnings.append(
            f"the run-down stops after {t:.6g} s, {r.t_stop_mm:.3g} mm on the t axis at μt = {r.mu_t:g} s/mm "
            f"(drawn to fit the required {b.time_limit:.6g} s): below the drawing's precision of {prec:g} mm, "
            "t_stop cannot be read off it")


# ---------------------------------------------------------------------------- rows


def _rel(g: float, e: float, scale: float) -> float:
    return abs(g - e) / max(abs(e), abs(scale) * 1e-3, 1e-300)


def _row(an: FlywheelAnalysis, name: str) -> Row:
    base, at = split(name)
    unit = QUANTITIES[base][0]
    g, e, drawn, scale, ill = quantity_values(an, base, None if at is None else int(at) - 1)
    rel = _rel(g, e, scale)
    if base in POSITION_ANGLES:  # where in the cycle: 0° and 353.47° are 6.53° apart, not 353.47°
        cycle = math.degrees(an.machine.cycle)
        rel = abs(_wrapped(an, base, g - e)) / cycle
    if unit == "J" and base != "t_stop":  # an energy near zero (ΔT_min) is judged against the cycle's swing of ΔT
        x = _exact(an).extremes()
        rel = abs(g - e) / max(abs(e), x.maximum - x.minimum, 1e-300)
    return Row(name, unit, drawn, scale, g, e, rel, ill)


def quantity_values(an: FlywheelAnalysis, base: str, i: int | None) -> tuple[float, float, float | None, float, bool]:
    """(graphical, exact, drawn mm or None, μ, ill-conditioned) of one quantity."""
    d, m = an.design, an.machine
    wm, delta = m.omega_m, m.delta
    if base == "t_stop":  # read off the run-down diagram ω(t): its intercept on the t axis × μt
        r = an.rundown
        return r.t_stop, an.braking.t, r.t_stop_mm, r.mu_t, False
    if base in ("Jp", "Mp"):
        ex = _exact(an)
        phi = an.phi[cast(int, i) : cast(int, i) + 1]  # a quantity at a position has one
        if base == "Jp":
            return float(an.reduction.J[i]), float(ex.inertia(phi)[0]), None, an.scales.get("v", 1.0), False
        return float(an.reduction.M[i]), float(ex.load_moment(phi, mean_at_steps=True)[0]), None, \
            an.scales.get("v", 1.0), False
    ex = _exact(an)
    mu_T = float(d.scales["T"]) if d is not None else 1.0
    if base in ("DeltaT", "A_p"):
        g = float(d.energy_mm[i] if base == "DeltaT" else cast(np.ndarray, d.work_mm)[i]) * mu_T
        e = float(ex.energy(an.phi[cast(int, i) : cast(int, i) + 1])[0])
        if base == "A_p":
            e -= ex.balancing_moment() * float(an.phi[i])
        return g, e, g / mu_T, mu_T, False
    if base in ("M_b", "Md", "Mr"):
        mu_M = float(d.scales["M"])
        return float(d.balancing_moment), float(ex.balancing_moment()), float(d.balancing_moment) / mu_M, mu_M, False
    if base in ("DeltaT_max", "DeltaT_min", "phi_DeltaT_max", "phi_DeltaT_min"):
        x = ex.extremes()
        top = base.endswith("max")
        kk = int(d.energy_max_index if top else d.energy_min_index)
        if base.startswith("phi"):
            return math.degrees(float(an.phi[kk])), math.degrees(x.phi_max if top else x.phi_min), None, 1.0, False
        g = float(d.energy_mm[kk]) * mu_T
        return g, float(x.maximum if top else x.minimum), g / mu_T, mu_T, False
    if base in ("k", "l", "psi_max", "psi_min", "tan_psi_max", "tan_psi_min", "phi_max", "phi_min",
                "J_F_wittenbauer") or (base == "J_F" and an.scene.problem.method == "wittenbauer"):
        w = d.wittenbauer
        t = ex.wittenbauer(an.scene.problem.tangents)
        ill = float(getattr(w, "angle_between_deg", 90.0)) < TANGENTS_APART_DEG
        if base in ("k", "l"):
            mm = float(w.k_mm if base == "k" else w.l_mm)
            return mm * mu_T, float(t.k if base == "k" else t.l), mm, mu_T, ill
        if base in ("phi_max", "phi_min"):  # ω_max, ω_min where the tangents touch the curve
            top = base == "phi_max"
            kk = int(w.k_index if top else w.l_index)
            return math.degrees(float(an.phi[kk])), math.degrees(t.phi_k if top else t.phi_l), None, 1.0, ill
        if base in ("psi_max", "psi_min", "tan_psi_max", "tan_psi_min"):
            top = base.endswith("max")
            tg = float(w.tan_psi_max if top else w.tan_psi_min)
            # the exact slope from ω_max, ω_min of the tangents (the same formula: no discretisation)
            c = (t.omega_max if top else t.omega_min) ** 2 / 2.0 * float(d.scales["J"]) / mu_T
            if base.startswith("tan"):
                return tg, c, None, 1.0, False
            return math.degrees(math.atan(tg)), math.degrees(math.atan(c)), None, 1.0, False
        return float(d.J_F), float(t.J_F), float(w.kl_mm), mu_T / (wm * wm * delta), False
    if base in ("J_F", "J_F_indicator", "DeltaW_max", "J_mean"):
        ind = ex.indicator()
        if base == "J_mean":
            return float(d.J_mean), float(ind.J_mean), None, 1.0, False
        if base == "DeltaW_max":  # measured on the indicator as drawn: at μT′ = μT/k when enlarged
            from graphmech.problems.flywheel.figures import energy_factor

            mu_ind = mu_T / energy_factor(d)
            return float(d.DeltaW_max), float(ind.delta_W), float(d.DeltaW_max) / mu_ind, mu_ind, False
        return float(d.J_F_indicator), float(ind.J_F), None, mu_T / (wm * wm * delta), False
    if base in ("omega_max", "omega_min", "n_max", "n_min"):
        hi = base.endswith("max")
        if an.scene.problem.tangents == "book":
            w = wm * math.sqrt(1 + delta if hi else 1 - delta)
        else:
            w = wm * (1 + delta / 2 if hi else 1 - delta / 2)
        if base.startswith("n"):
            w *= 30.0 / math.pi
        return w, w, None, 1.0, False
    mo, ref = an.motion, an.motion_ref
    if base in ("omega_max_true", "omega_min_true"):
        hi = base == "omega_max_true"
        return float(mo.omega_max if hi else mo.omega_min), float(ref.omega_max if hi else ref.omega_min), None, 1.0, False
    if base in ("phi_omega_max", "phi_omega_min"):
        hi = base == "phi_omega_max"
        return math.degrees(mo.phi_omega_max if hi else mo.phi_omega_min), \
            math.degrees(ref.phi_omega_max if hi else ref.phi_omega_min), \
            None, 1.0, False
    if base == "delta_achieved":
        return float(mo.delta), float(ref.delta), None, 1.0, False
    if base == "omega_mean_time":
        return float(mo.omega_time_mean), float(getattr(ref, "omega_time_mean", mo.omega_time_mean)), None, 1.0, False
    if base == "omega_s":
        return float(mo.omega_s), float(getattr(ref, "omega_s", mo.omega_s)), None, 1.0, False
    raise KeyError(base)  # requested() let through a name with no row: a bug of ours


# ---------------------------------------------------------------------------- how accurate

#: Values the construction gets exactly (but for round-off): read off the velocity polygons, or
#: a formula of the scene's data (ω_max of the tangents, ψ, the brake's run-down line).
CONSTRUCTED = ("Jp", "Mp", "omega_max", "omega_min", "n_max", "n_min", "psi_max", "psi_min", "tan_psi_max",
               "tan_psi_min", "omega_s", "t_stop")
#: Extremes over the N positions: their sampled value also misses the extreme between positions.
SAMPLED_EXTREMES = ("DeltaT_max", "DeltaT_min", "k", "l", "J_F", "J_F_wittenbauer", "J_F_indicator", "DeltaW_max")
#: The true motion's values: the ODE's own error, estimated by the same solve at a tighter rtol.
MOTION = ("omega_max_true", "omega_min_true", "phi_omega_max", "phi_omega_min", "delta_achieved",
          "omega_mean_time")


def _estimate(an: FlywheelAnalysis, needs: set[str]) -> None:
    """Each row's own error estimate (graphmech.accuracy), from the method, never the exact value.

    - N positions (chords, graphical integration, ΔT and everything drawn from it): the same
      pipeline at 2N and 4N, Richardson with the order observed on the three (the pipeline is
      second order, but a kink of Mп between positions lowers it). An extreme over the positions
      also misses the extreme between them, by a jump that is not smooth in N: that part is
      read off the parabola through the extreme position and its neighbours, and the estimate is
      the larger of the two.
    - The angle of an extreme is a reading at the positions: its error is its distance from the
      extreme that the pipeline at 2N places between its positions (the vertex of that parabola).
    - The true motion: the same solve at rtol/10.
    """
    rows = [(k, r) for k, r in enumerate(an.rows) if split(r.name)[0] not in CONSTRUCTED]
    if not rows:
        return
    n = an.scene.problem.positions
    basis = f"{n} positions"
    finer: dict[int, FlywheelAnalysis] = {}

    def at(factor: int) -> FlywheelAnalysis:
        if factor not in finer:
            finer[factor] = _with_positions(an, n * factor, needs)
        return finer[factor]

    motion_fine = None
    for k, r in rows:
        base, pos = split(r.name)
        i = None if pos is None else int(pos) - 1
        den = _denominator(an, r)
        if base in MOTION:
            if motion_fine is None:
                motion_fine = _tighter_motion(an)
            g, scale_down = motion_fine
            fine = _motion_value(g, base)
            err = abs(_wrapped(an, base, r.graphical - fine)) * scale_down
            an.rows[k] = r.estimated(DISCRETISATION, relative(err, den), f"{an.motion.solver} rtol {an.motion.rtol:g}")
            continue
        v2 = quantity_values(at(2), base, None if i is None else 2 * i)[0]
        polygon = an.machine.energy_table is not None  # ΔT a polygon: no parabola between positions
        if polygon and (base in POSITION_ANGLES or base in SAMPLED_EXTREMES):
            # its extremes lie at the table's points: what 2N and 4N positions reach that N missed
            v4 = quantity_values(at(4), base, None if i is None else 4 * i)[0]
            err = max(abs(_wrapped(an, base, r.graphical - v2)), abs(_wrapped(an, base, r.graphical - v4)))
            source, how = (READING, f"{basis}, read at a position") if base in POSITION_ANGLES else \
                (DISCRETISATION, basis)
            an.rows[k] = r.estimated(source, relative(err, den), how)
            continue
        if base in ("phi_DeltaT_max", "phi_DeltaT_min", "phi_max", "phi_min"):
            top = base.endswith("max")
            energy = base.startswith("phi_D")
            err = abs(_wrapped(an, base, r.graphical - _refined_angle(at(2), top, energy)))
            # next to a kink of Mп a parabola misplaces the extreme: where those at N and 2N disagree
            # (by over a factor 2 in the distance from the reading), the one at 4N decides
            if abs(_wrapped(an, base, r.graphical - _refined_angle(an, top, energy))) > 2.0 * err:
                err = abs(_wrapped(an, base, r.graphical - _refined_angle(at(4), top, energy)))
            an.rows[k] = r.estimated(READING, relative(err, den), f"{basis}, read at a position")
            continue
        v4 = quantity_values(at(4), base, None if i is None else 4 * i)[0]
        err = estimate_from_three(r.graphical, v2, v4)
        if base in SAMPLED_EXTREMES:  # the extreme between the positions, as N and 2N place it
            err = max(err, abs(_between_positions(an, base)),
                      abs(r.graphical - v2 - _between_positions(at(2), base)))
        an.rows[k] = r.estimated(DISCRETISATION, relative(err, den), basis)


def _with_positions(an: FlywheelAnalysis, n: int, needs: set[str]) -> FlywheelAnalysis:
    """The same graphical pipeline at n positions (its warnings dropped; the exact part shared)."""
    fine = FlywheelAnalysis(an.scene, an.machine, np.asarray(an.machine.positions(n), dtype=float),
                            tuple(str(k + 1) for k in range(n)), exact=an.exact)
    _reduce(fine)
    _design(fine, needs - {"motion"})
    return fine


def _denominator(an: FlywheelAnalysis, r: Row) -> float:
    """The row's rel_error denominator (so that the estimate compares with rel_error)."""
    base, _ = split(r.name)
    if base in POSITION_ANGLES:
        return math.degrees(an.machine.cycle)
    if r.unit == "J":
        x = _exact(an).extremes()
        return max(abs(r.exact), x.maximum - x.minimum, 1e-300)
    return max(abs(r.exact), abs(r.scale) * 1e-3, 1e-300)


def _wrapped(an: FlywheelAnalysis, base: str, d: float) -> float:
    """A difference of angles in the cycle taken the short way round; other differences as they are."""
    return math.remainder(d, math.degrees(an.machine.cycle)) if base in POSITION_ANGLES else d


def _vertex(y: np.ndarray, i: int) -> tuple[float, float]:
    """The parabola through y[i−1], y[i], y[i+1] (periodic): (its vertex's value − y[i], the
    vertex's offset from i in steps, within ±½)."""
    a, b, c = float(y[(i - 1) % y.size]), float(y[i]), float(y[(i + 1) % y.size])
    curv = a + c - 2.0 * b
    off = 0.5 if curv == 0.0 else min(0.5, max(-0.5, (a - c) / (2.0 * curv)))
    return 0.5 * (c - a) * off + 0.5 * curv * off * off, off


def _between_positions(an: FlywheelAnalysis, base: str) -> float:
    """How far the extreme(s) behind an extreme value lie beyond the positions' values (signed,
    in the row's unit), read off the parabola through the extreme position and its neighbours."""
    d, m = an.design, an.machine
    mu = float(d.scales["T"])
    T = np.asarray(d.energy_mm[:-1], dtype=float) * mu
    per_J_F = 1.0 / (m.omega_m ** 2 * m.delta)
    hi, lo = _vertex(T, int(d.energy_max_index))[0], _vertex(T, int(d.energy_min_index))[0]
    if base == "DeltaT_max":
        return hi
    if base == "DeltaT_min":
        return lo
    if base == "DeltaW_max":
        return hi - lo
    if base == "J_F_indicator" or (base == "J_F" and an.scene.problem.method == "indicator"):
        return (hi - lo) * per_J_F
    w = d.wittenbauer
    x, y = np.asarray(w.x_mm, dtype=float), np.asarray(w.y_mm, dtype=float)
    k = _vertex((y - x * w.tan_psi_max) * mu, int(w.k_index))[0]
    l_ = _vertex((y - x * w.tan_psi_min) * mu, int(w.l_index))[0]
    return {"k": k, "l": l_}.get(base, (k - l_) * per_J_F)


def _refined_angle(an: FlywheelAnalysis, top: bool, energy: bool = True) -> float:
    """Where the pipeline places the extreme of ΔT (``energy``), or the Wittenbauer tangent's point
    of contact (the extreme of ΔT − Jп·tan ψ: ω_max, ω_min), between its positions, degrees."""
    d = an.design
    if energy:
        T = np.asarray(d.energy_mm[:-1], dtype=float)
        i = int(d.energy_max_index if top else d.energy_min_index)
    else:
        w = d.wittenbauer
        T = np.asarray(w.y_mm, dtype=float) - np.asarray(w.x_mm, dtype=float) * (w.tan_psi_max if top else w.tan_psi_min)
        i = int(w.k_index if top else w.l_index)
    step = math.degrees(an.machine.cycle) / T.size
    return math.degrees(float(an.phi[i])) + _vertex(T, i)[1] * step


def _tighter_motion(an: FlywheelAnalysis) -> tuple[Any, float]:
    """The same solve at rtol/10 (or, at the tightest rtol already, at 10·rtol with its difference
    scaled down by 10: the error goes as rtol); and that scale. A tenth is enough to see the
    error of the scene's solve and costs about half of a hundredth."""
    from graphmech.exact.true_motion import true_motion
    from graphmech.problems.flywheel.scene import RTOL_MIN

    mo = an.motion
    rtol, down = (mo.rtol * 1e-1, 1.0) if mo.rtol * 1e-1 >= RTOL_MIN else (mo.rtol * 1e1, 1e-1)
    try:
        return an.integrated(lambda: true_motion(an.machine, _exact(an), mo.J_F, solver=mo.solver, rtol=rtol)), down
    except ValueError as e:
        raise DegenerateConstruction("the true motion", str(e)) from None


def _motion_value(mo: Any, base: str) -> float:
    return cast(float, {"omega_max_true": mo.omega_max, "omega_min_true": mo.omega_min,
            "phi_omega_max": math.degrees(mo.phi_omega_max), "phi_omega_min": math.degrees(mo.phi_omega_min),
            "delta_achieved": mo.delta, "omega_mean_time": mo.omega_time_mean}[base])


# ---------------------------------------------------------------------------- verdicts


def judge_flywheel(an: FlywheelAnalysis, precision_mm: float | None = None) -> list[Verdict]:
    """Hand values against what a perfect construction at the scene's N positions gives.

    A student's J_F drawn from 12 positions is judged against graphmech's J_F from the same 12
    positions (not the continuous value, which no 12-point drawing reaches); the tolerance is
    the drawing precision times that quantity's μ. ``kl`` is the drawn segment in mm.
    """
    prec = precision_mm if precision_mm is not None else an.scene.precision_mm
    out = []
    for _key, name, value in measured_entries(an.scene, an.extra_measured):
        if name == "kl":
            kl = float(an.design.wittenbauer.kl_mm)
            out.append(Verdict(name, value, kl, prec, abs(value - kl) <= prec, "mm"))
            continue
        base, at = split(name)
        g, _e, drawn, scale, _ = quantity_values(an, base, None if at is None else int(at) - 1)
        out.append(judge_value(name, value, g, drawn, scale, prec, QUANTITIES[base][0]))
    return out


__all__ = ["FlywheelAnalysis", "analyse_flywheel", "judge_flywheel", "QUANTITIES", "quantity_values", "requested"]
