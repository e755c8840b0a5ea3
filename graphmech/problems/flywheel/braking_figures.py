"""The run-down of a machine under a brake, drawn as a speed–time diagram ω(t).

Under a constant braking moment M_T the reduced link decelerates uniformly, ε = M_T/J, so ω(t)
is the straight line from ω0 on the ω axis to the stopping time t_stop = J·ω0/M_T on the t axis.
The diagram is drawn at μω ((rad/s)/mm) and μt (s/mm); the line's intercept on the t axis,
times μt, is the stopping time read off the drawing. A required stopping time is drawn as a thin
dashed ordinate, so a glance says whether the machine stops in time.
"""
from __future__ import annotations

from dataclasses import dataclass

from graphmech.drawing.lettering import LETTER, number, scale_text
from graphmech.drawing.primitives import Arrow, Label, Panel, Primitive, Segment
from graphmech.errors import OutOfDomain
from graphmech.problems.flywheel.figures import fly_word
from graphmech.scales import round_scale

#: The longest the t axis and the ω axis are drawn, mm (before rounding the scales up).
T_AXIS_MM, OMEGA_AXIS_MM = 160.0, 90.0
AXIS_OVERRUN = 8.0


@dataclass(frozen=True)
class Rundown:
    """The drawn run-down: scales and the drawn intercepts.

    Attributes
    ----------
    mu_t, mu_omega : float
        s/mm and (rad/s)/mm.
    omega0_mm, t_stop_mm : float
        The initial speed on the ω axis and the line's intercept on the t axis, drawing mm.
    """

    mu_t: float
    mu_omega: float
    omega0_mm: float
    t_stop_mm: float

    @property
    def t_stop(self) -> float:
        """The stopping time read off the drawing, s."""
        return self.t_stop_mm * self.mu_t


def draw_rundown(J: float, omega0: float, M_brake: float, t_limit: float | None = None) -> Rundown:
    """Lay off ω0 and the deceleration ε = M_T/J and intersect the line with the t axis.

    Examples
    --------
    ``fly.brake_time``: J = 0.5 kg·m², ω0 = 100 rad/s, M_T = 20 N·m, at most 3 s.

    >>> r = draw_rundown(0.5, 100.0, 20.0, 3.0)
    >>> r.mu_t, r.mu_omega, r.t_stop
    (0.02, 2.0, 2.5)
    """
    if not (J > 0.0 and omega0 > 0.0 and M_brake > 0.0):
        raise OutOfDomain("J, ω0 and the braking moment must all be > 0")
    eps = M_brake / J
    t_span = max(omega0 / eps, t_limit or 0.0)
    mu_t, mu_omega = round_scale(t_span / T_AXIS_MM), round_scale(omega0 / OMEGA_AXIS_MM)
    omega0_mm = omega0 / mu_omega
    slope = eps * mu_t / mu_omega  # drawing mm of ω lost per mm of t
    return Rundown(mu_t, mu_omega, omega0_mm, omega0_mm / slope)


def rundown_panel(J: float, omega0: float, M_brake: float, t_limit: float | None = None,
                  notation: str = "en") -> Panel:
    """The ω(t) diagram: axes, the run-down line (bold), ω0, t_stop and the required time;
    captions in ``notation``.

    >>> p = rundown_panel(0.5, 100.0, 20.0, 3.0)
    >>> p.name, p.notes[0], p.scales
    ('rundown', 'μ_{t} = 0.02 s/mm, μ_{ω} = 2 (rad/s)/mm', (('t', 0.02), ('omega', 2.0)))
    """
    r = draw_rundown(J, omega0, M_brake, t_limit)
    x_end = max(r.t_stop_mm, (t_limit or 0.0) / r.mu_t) + AXIS_OVERRUN
    n = (r.omega0_mm ** 2 + r.t_stop_mm ** 2) ** 0.5
    down_right = (r.t_stop_mm / n, -r.omega0_mm / n)  # along the run-down line, away from ω0
    items: list[Primitive] = [
        Arrow((0.0, 0.0), (x_end, 0.0), "label"),
        Arrow((0.0, 0.0), (0.0, r.omega0_mm + AXIS_OVERRUN), "label"),
        Segment((0.0, r.omega0_mm), (r.t_stop_mm, 0.0), "result"),
        Label("ω", (0.0, r.omega0_mm + AXIS_OVERRUN), ((0.0, -1.0),), LETTER),
        Label("t", (x_end, 0.0), ((-1.0, 0.0),), LETTER),
        Label("O", (0.0, 0.0), ((1.0, 0.0), (0.0, 1.0)), LETTER),
        Label("ω_{0}", (0.0, r.omega0_mm), ((0.0, -1.0), (0.0, 1.0), down_right), LETTER),
        Label("t_{stop}", (r.t_stop_mm, 0.0), ((-1.0, 0.0), (1.0, 0.0), (-down_right[0], -down_right[1])), LETTER),
    ]
    notes = [f"{scale_text('t', r.mu_t)}, {scale_text('omega', r.mu_omega)}",
             f"ε = M_{{T}}/J = {number(M_brake)}/{number(J)} = {number(M_brake / J)} rad/s^{{2}}; "
             f"t_{{stop}} = μ_{{t}}·⟨Ot_{{stop}}⟩ = {number(r.mu_t)}·{number(r.t_stop_mm)} = {number(r.t_stop)} s"]
    if t_limit is not None:
        x = t_limit / r.mu_t
        items += [Segment((x, 0.0), (x, r.omega0_mm), "construction", dashed=True),
                  Label(fly_word("t allowed", notation), (x, r.omega0_mm), ((0.0, -1.0),), LETTER)]
        verdict = fly_word("stops" if r.t_stop <= t_limit else "stops not", notation)
        notes.append(f"{fly_word('required', notation)} t ≤ {number(t_limit, 6)} s: {verdict}")  # as given
    return Panel("rundown", fly_word("rundown", notation), tuple(items), tuple(notes),
                 scales=(("t", r.mu_t), ("omega", r.mu_omega)))


__all__ = ["Rundown", "draw_rundown", "rundown_panel"]
