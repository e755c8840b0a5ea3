"""The exact disc-cam profile by the analytic (envelope) method.

This is the independent reference for the graphical inversion (反转法) in
``graphmech.methods``: the same cam is worked out here in closed form, vectorised over the cam
angle, and the pressure angle and the radius of curvature come from exact derivatives of the
motion law instead of from chords and three-point circles read off a drawing.

Nothing here is taken from ``graphmech.construction``, ``graphmech.methods`` or
``graphmech.geometry``: a check that reuses what it checks proves nothing. The module imports
only numpy, scipy, the cam model, the motion laws and the tolerances.

Notes
-----
**Frames.** The *follower frame* is the fixed frame in which the follower is drawn at δ = 0
(the model's conventions: O at the origin, a translating follower moving along +y with its axis
at x = e; an oscillating follower pivoted at A = (a, 0)). Its contact point (knife tip, roller
centre; for a flat face the face's reference point on the axis) is **B(δ)** there. Turning the
cam by rot·δ (rot = +1 CCW, −1 CW) is, by inversion, the same as keeping the cam still and
turning the follower by −rot·δ, so the pitch curve in the *cam frame* is

    P(δ) = R(−rot·δ) · B(δ),      R(θ) = [[cos θ, −sin θ], [sin θ, cos θ]].

With J the quarter turn (J·(x, y) = (−y, x), J² = −1) and dR(−rot·δ)/dδ = −rot·J·R(−rot·δ),
differentiating gives, with ′ = d/dδ,

    P′   = R·T,   T  = B′ − rot·J·B
    P″   = R·Q,   Q  = B″ − 2·rot·J·B′ − B
    P‴   = R·(Q′ − rot·J·Q),   Q′ = B‴ − 2·rot·J·B″ − B′.

Dot and cross products do not change under the rotation R, so every scalar below is computed
from T, Q, … in the follower frame and only the points are turned into the cam frame.

**Follower point.** Translating, knife or roller: B = (e, s0 + s), s0 = √(r0² − e²), so
B′ = (0, s′), B″ = (0, s″), B‴ = (0, s‴). With T = (rot·(s0 + s), s′ − rot·e) the textbook
formula falls out (see *pressure angle*). Translating flat face ⟂ its axis: B = (e, r0 + s)
(r0 is the profile's own base radius). Oscillating: ψ = ψ0 + φ, ψ0 = ∠OAB at the start from
cos ψ0 = (a² + l² − r0²)/(2al); B = A + l·u(ψ), u = (−cos ψ, σ·sin ψ), u_ψ = (sin ψ, σ·cos ψ),
u_ψψ = −u; σ = rot for ``sense = "opposite"`` (for a CCW cam B lies above OA and the rocker
turns clockwise, against the cam, while ψ grows during the rise) and σ = −rot for ``"same"``.
Then B′ = l·u_ψ·φ′, B″ = l·(u_ψ·φ″ − u·φ′²), B‴ = l·(u_ψ·(φ‴ − φ′³) − 3·u·φ′·φ″).

**Pressure angle.** α is the angle between the contact normal (⟂ the pitch curve, i.e. ⟂ T in
the follower frame) and the direction m in which the follower point can move: m = (0, 1) for a
translating follower, m = u_ψ (⟂ the arm) for a rocker. So sin α ∝ |T·m| and cos α ∝ |T × m|:

    α = atan2(|T·m|, |T × m|) ∈ [0, π/2].

For a translating knife or roller T·m = s′ − rot·e and T × m = rot·(s0 + s), i.e.
tan α = |s′ − rot·e| / (s0 + s): for a CCW cam an axis to the right of O (e > 0) lowers the
pressure angle of the rise (s′ > 0) and raises that of the return. A flat face ⟂ its axis has
its normal along the axis: α ≡ 0. The signed α_s = atan((T·m)/(T × m)) is smooth inside each
piece of the law; its extrema (dα_s/dδ = (f′g − fg′)/(f² + g²), f = T·m, g = T × m,
f′ = T′·m + T·m′, g′ = T′ × m + T × m′, T′ = B″ − rot·J·B′, m′ = −u·φ′ for a rocker) are the
only interior candidates for the largest |α|.

**Curvature.** The pitch point runs round O against the cam (clockwise for a CCW cam), so a
convex arc turns to the right for rot = +1. The signed radius, > 0 where the centre of curvature
lies inside the cam, is therefore

    ρ = −rot·|P′|³ / (P′ × P″) = −rot·|T|³ / (T × Q),

and for the search for its smallest positive value, with c = 1/ρ,
c′ = −rot·[(T × P‴)/|T|³ − 3·(T × Q)(T·Q)/|T|⁵].

**Working profile.** Knife edge: the pitch curve. Roller: the inner envelope of the roller
circles, P + r_r·n, n = −rot·J·P′/|P′| the inward unit normal; its radius of curvature is
ρ − r_r (meaningful where ρ > r_r on convex arcs; ρ ≤ r_r is undercut). Flat face: the face
lines {X: n·X = r0 + s}, n = R(−rot·δ)(0, 1); their envelope also satisfies n′·X = s′ with
n′ = −rot·J·n, which in the follower frame is the point (rot·s′, r0 + s) — the contact lies
s′ along the face from the foot of the perpendicular from O. Differentiating once more gives
P′ = R·(rot·(r0 + s + s″), 0) while the normal turns at unit rate, so ρ = r0 + s + s″.

**Oscillating flat face.** The face is the straight line through the pivot A along the rocker,
direction u(ψ) as for the arm above (the arm length is not used). It starts tangent to the base
circle, so its distance a·sin ψ0 from O is r0: ψ0 = asin(r0/a), r0 < a, on the side ``sense``
gives (as for the roller's B), and it turns by φ(δ) in the same sense as the roller's arm would.
Its reference ("pitch") point B is the foot of the perpendicular from O on the face,
B = A + a·cos ψ·u = (a/2)·(1 − cos 2ψ, σ·sin 2ψ), on the circle with diameter OA. In the cam
frame the faces are X = A(δ) + t·u(δ); their envelope touches face δ where (A′ + t·u′) ∥ u,

    t = (A′ × u)/(u × u′) = a·cos ψ / q,    q = 1 + k·φ′,  k = rot·σ = +1 "opposite", −1 "same"

(A′ × u = −rot·a·cos ψ and u × u′ = −rot − σ·φ′, the rotation R dropping out of the crosses):
the contact lies a·cos ψ·(1/q − 1) along the face from the foot B. The face line has normal
angle θ with θ′ = −rot·q and support p = a·sin ψ (its distance from O), so the envelope's
signed radius of curvature (> 0 convex; the support-function form of the parametric
−rot·|C′|³/(C′ × C″)) is ρ = p + d²p/dθ² = p + (p″·q − k·p′·φ″)/q³, with p′ = a·cos ψ·φ′,
p″ = a·(cos ψ·φ″ − sin ψ·φ′²). ρ ≤ 0 is a cusp of the profile (``undercut``); where q → 0 the
contact runs off along the face, which (like the face's finite length) is not modelled. The
pressure angle is 0: the point of the face in contact moves about A, ⟂ the face, i.e. along
the contact normal.

**Joints.** A motion law is smooth only between its joints: the segment boundaries
(``breakpoints``) and the laws' own knots where s′ or s″ jumps (``impacts``, e.g. the parabolic
law's middle); at a joint ``displacement`` returns the right-hand limit. Every search below works
piece by piece, evaluating a piece's left end as the right-hand limit and its right end just
below the joint (the left-hand limit), so a slope break is never smoothed over.

Examples
--------
The offset roller cam of the reference problems (e = 10 mm, r0 = 30 mm, r_r = 10 mm, h = 16 mm;
uniform rise 150°, dwell 30°, parabolic return 120°, dwell 60°, cam CCW):

>>> import math
>>> from graphmech.mechanisms.cam import DiscCam, MotionProgram, Segment, TranslatingFollower
>>> program = MotionProgram(0.016, (
...     Segment("rise", math.radians(150), "uniform"), Segment("dwell", math.radians(30)),
...     Segment("return", math.radians(120), "parabolic"), Segment("dwell", math.radians(60))))
>>> cam = DiscCam(0.030, TranslatingFollower(0.010, "roller", 0.010), program)
>>> alpha, where = max_pressure_angle(cam)
>>> round(math.degrees(alpha), 6), round(math.degrees(where), 6)
(34.864526, 240.0)
>>> rho, where = min_convex_rho_pitch(cam)
>>> round(rho * 1e3, 6), round(math.degrees(where), 6)
(29.407675, 0.0)
>>> undercut(cam)[0].startswith("the pitch curve has a convex corner at δ = 150.000°")
True
"""
from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Literal, cast

import numpy as np
from numpy.typing import ArrayLike

from graphmech.errors import NoSolution, NotApplicable, OutOfDomain, WrongKind
from graphmech.minimum import fminbound  # scipy's bounded search without loading scipy.optimize
from graphmech.roots import brentq, newton  # scipy.optimize's work without loading it (0.3 s)
from graphmech.mechanisms.cam import DiscCam, OscillatingFollower, TranslatingFollower
from graphmech.mechanisms.motion import breakpoints, displacement, impacts
from graphmech.tolerances import EPS, TANGENT_REL

__all__ = [
    "CamProfile",
    "initial_rocker_angle",
    "max_pressure_angle",
    "min_base_radius",
    "min_convex_rho_pitch",
    "profile",
    "undercut",
]

_TWO_PI = 2.0 * math.pi

#: Samples per smooth piece of the law when bracketing extrema (then refined by brentq).
_SAMPLES = 257

#: Joints closer than this (rad) are one joint (the same angle computed two ways).
_JOINT_TOL = 1e-12

#: How far below a joint its left-hand limit is taken, rad: beyond the motion law's snapping of
#: angles to a joint (8 ulp of 2π), so that the left-hand value is really the left one.
_LEFT = 32.0 * float(np.spacing(_TWO_PI))

#: Candidate base radii tried (geometrically spaced) before refining the smallest good one.
_R0_SCAN = 40

Where = Literal["rise", "return", "all"]


@dataclass(frozen=True)
class CamProfile:
    """The exact profile of a disc cam at N cam angles (cam frame, m, rad). Arrays are read-only.

    Attributes
    ----------
    delta : (N,) ndarray
        Cam angles, rad.
    pitch : (N, 2) ndarray
        Pitch curve: roller centre, knife tip, or for a flat face the face's reference point on
        the follower's axis (oscillating: the foot of the perpendicular from O on the face); m,
        cam frame.
    actual : (N, 2) ndarray
        Working profile: the pitch curve for a knife edge; for a roller the inner envelope,
        pitch + r_r·(inward unit normal); for a flat face the envelope of the face lines (the
        contact points).
    pressure_angle : (N,) ndarray
        |α| in [0, π/2], rad: the angle between the contact normal and the direction in which
        the follower point moves (0 for a flat face ⟂ its axis).
    rho_pitch : (N,) ndarray
        Signed radius of curvature of the pitch curve, m: > 0 convex (centre of curvature inside
        the cam), < 0 concave, ±inf at an inflection.
    rho_actual : (N,) ndarray
        The same for the working profile: ρ_pitch for a knife edge, ρ_pitch − r_r for a roller,
        r0 + s + s″ for a translating flat face, p + (p″·q − k·p′·φ″)/q³ for an oscillating one
        (module Notes).

    At a joint of the motion law every quantity is the right-hand limit (δ → joint⁺). Where the
    follower's velocity jumps the pitch curve has a corner. At a concave one (velocity rises) a
    roller rests on an arc of its own circle: the working profile there is that arc, between the
    points given at joint⁻ and joint⁺. At a convex one (velocity drops) the inner offsets of the
    two sides cross at the profile's vertex and their stretches beyond it are not part of the cam;
    ``undercut`` reports such corners.
    """

    delta: np.ndarray
    pitch: np.ndarray
    actual: np.ndarray
    pressure_angle: np.ndarray
    rho_pitch: np.ndarray
    rho_actual: np.ndarray

    def __post_init__(self) -> None:
        for field in dataclasses.fields(self):
            getattr(self, field.name).setflags(write=False)


# --------------------------------------------------------------------------------------------
# Small vector helpers on (..., 2) arrays


def _vec(x: np.ndarray | float, y: np.ndarray | float) -> np.ndarray:
    x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
    return np.stack([x, y], axis=-1)


def _dot(u: np.ndarray, w: np.ndarray) -> np.ndarray:
    return cast(np.ndarray, u[..., 0] * w[..., 0] + u[..., 1] * w[..., 1])


def _cross(u: np.ndarray, w: np.ndarray) -> np.ndarray:
    return cast(np.ndarray, u[..., 0] * w[..., 1] - u[..., 1] * w[..., 0])


def _quarter(u: np.ndarray) -> np.ndarray:
    """J·u: u turned a quarter turn counter-clockwise."""
    return _vec(-u[..., 1], u[..., 0])


def _turn(u: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """R(angle)·u, row by row."""
    c, s = np.cos(angle), np.sin(angle)
    return _vec(c * u[..., 0] - s * u[..., 1], s * u[..., 0] + c * u[..., 1])


# --------------------------------------------------------------------------------------------
# The follower point and the inverted path, with derivatives


@dataclass(frozen=True)
class _Path:
    """Everything at N cam angles, in the follower frame (see the module Notes)."""

    delta: np.ndarray
    s: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]  # s, s′, s″, s‴ (m or rad)
    B: np.ndarray
    T: np.ndarray  # P′ turned back
    T1: np.ndarray  # T′
    Q: np.ndarray  # P″ turned back
    P3: np.ndarray  # P‴ turned back
    m: np.ndarray  # direction of the follower point's motion (unit)
    m1: np.ndarray  # m′


def _check_rotation(cam: DiscCam) -> float:
    if cam.rotation not in (1, -1):
        raise OutOfDomain(f"cam rotation must be +1 (CCW) or -1 (CW), not {cam.rotation!r}")
    if not cam.base_radius > 0.0:
        raise OutOfDomain(f"the base radius must be > 0, not {cam.base_radius!r} m")
    return float(cam.rotation)


def initial_rocker_angle(cam: DiscCam) -> float:
    """The oscillating follower's start angle ψ0 = ∠OAB with B on the base circle, rad.

    Notes
    -----
    Triangle OAB with |OA| = a, |AB| = l, |OB| = r0: cos ψ0 = (a² + l² − r0²)/(2al). A flat face
    is the line through A along the rocker, tangent to the base circle at the start: its distance
    a·sin ψ0 from O is r0, so ψ0 = asin(r0/a) (needs r0 < a; the arm length is not used).

    Examples
    --------
    >>> from graphmech.mechanisms.cam import DiscCam, MotionProgram, OscillatingFollower, Segment
    >>> program = MotionProgram(math.radians(25), (Segment("rise", math.pi, "cosine"),
    ...                                            Segment("return", math.pi, "sine")))
    >>> cam = DiscCam(0.025, OscillatingFollower(0.055, 0.050, "roller", 0.008), program)
    >>> round(math.degrees(initial_rocker_angle(cam)), 10)
    27.0122939589
    """
    f = cam.follower
    if not isinstance(f, OscillatingFollower):
        raise WrongKind("the rocker angle belongs to an oscillating follower")
    if f.contact == "flat":
        a, r0 = f.pivot_distance, cam.base_radius
        if not a > 0.0:
            raise OutOfDomain(f"the pivot distance must be > 0, not {a!r} m")
        if not 0.0 < r0 < a:
            raise OutOfDomain(
                f"a flat face through the pivot can touch the base circle only if r0 < a "
                f"(r0 = {r0 * 1e3:g} mm, a = {a * 1e3:g} mm)")
        return math.asin(r0 / a)
    a, l, r0 = f.pivot_distance, f.arm, cam.base_radius
    if not (a > 0.0 and l > 0.0):
        raise OutOfDomain(f"pivot distance and arm must be > 0 (a = {a!r} m, l = {l!r} m)")
    c = (a * a + l * l - r0 * r0) / (2.0 * a * l)
    if not -1.0 < c < 1.0:
        raise OutOfDomain(
            f"the arm cannot reach the base circle: need |a − l| < r0 < a + l "
            f"(a = {a * 1e3:g} mm, l = {l * 1e3:g} mm, r0 = {r0 * 1e3:g} mm)")
    return math.acos(c)


def _path(cam: DiscCam, delta: np.ndarray) -> _Path:
    rot = _check_rotation(cam)
    f = cam.follower
    s0, s1, s2, s3 = (np.asarray(displacement(cam.program, delta, k), dtype=float) for k in range(4))
    s = (s0, s1, s2, s3)
    zero = np.zeros_like(s0)
    if isinstance(f, TranslatingFollower):
        e, r0 = f.offset, cam.base_radius
        if f.contact == "flat":
            y0 = r0
        else:
            if abs(e) >= r0:
                raise OutOfDomain(
                    f"the offset must be smaller than the base radius: |e| = {abs(e) * 1e3:g} mm "
                    f"≥ r0 = {r0 * 1e3:g} mm")
            y0 = math.sqrt(r0 * r0 - e * e)
        B = _vec(e + zero, y0 + s0)
        B1, B2, B3 = _vec(zero, s1), _vec(zero, s2), _vec(zero, s3)
        m, m1 = _vec(zero, 1.0), _vec(zero, zero)
    elif isinstance(f, OscillatingFollower):
        psi0 = initial_rocker_angle(cam)
        sigma = rot * (1.0 if f.sense == "opposite" else -1.0)
        psi = psi0 + s0
        u = _vec(-np.cos(psi), sigma * np.sin(psi))
        up = _vec(np.sin(psi), sigma * np.cos(psi))  # du/dψ, ⟂ the arm
        a = f.pivot_distance
        if f.contact == "flat":
            # the foot of the perpendicular from O on the face: B = A + a·cos ψ·u
            # = (a/2)·(1 − cos 2ψ, σ·sin 2ψ), on the circle with diameter OA
            v = _vec(np.sin(2.0 * psi), sigma * np.cos(2.0 * psi))  # dB/dψ = a·v
            w = _vec(np.cos(2.0 * psi), -sigma * np.sin(2.0 * psi))  # dv/dψ = 2·w, dw/dψ = −2·v
            B = 0.5 * a * _vec(1.0 - np.cos(2.0 * psi), sigma * np.sin(2.0 * psi))
            B1 = a * v * s1[..., None]
            B2 = a * (v * s2[..., None] + 2.0 * w * (s1 * s1)[..., None])
            B3 = a * (v * (s3 - 4.0 * s1**3)[..., None] + 6.0 * w * (s1 * s2)[..., None])
        else:
            l = f.arm
            B = _vec(a, 0.0) + l * u
            B1 = l * up * s1[..., None]
            B2 = l * (up * s2[..., None] - u * (s1 * s1)[..., None])
            B3 = l * (up * (s3 - s1**3)[..., None] - u * (3.0 * s1 * s2)[..., None])
        m, m1 = up, -u * s1[..., None]
    else:  # pragma: no cover - the model has only these two
        raise WrongKind(f"unknown follower {f!r}")
    JB, JB1, JB2 = _quarter(B), _quarter(B1), _quarter(B2)
    T = B1 - rot * JB
    T1 = B2 - rot * JB1
    Q = B2 - 2.0 * rot * JB1 - B
    Q1 = B3 - 2.0 * rot * JB2 - B1
    P3 = Q1 - rot * _quarter(Q)
    return _Path(delta, s, B, T, T1, Q, P3, m, m1)


def _flat(cam: DiscCam) -> bool:
    return cam.follower.contact == "flat"


def _rocker_face(cam: DiscCam, p: _Path) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """An oscillating flat face: (contact point in the follower frame, ρ of the envelope, dρ/dδ).

    See the module Notes (*Oscillating flat face*): t = a·cos ψ/q, q = 1 + k·φ′,
    ρ = p + (p″·q − k·p′·φ″)/q³ with p = a·sin ψ.
    """
    f = cast(OscillatingFollower, cam.follower)  # a rocker's face: called for an oscillating follower
    a = f.pivot_distance
    k = 1.0 if f.sense == "opposite" else -1.0
    sigma = float(cam.rotation) * k
    s0, s1, s2, s3 = p.s
    psi = initial_rocker_angle(cam) + s0
    c, sn = np.cos(psi), np.sin(psi)
    q = 1.0 + k * s1
    with np.errstate(divide="ignore", invalid="ignore"):
        t = a * c / q
        contact = _vec(a - t * c, sigma * t * sn)
        p0 = a * sn
        p1 = a * c * s1
        p2 = a * (c * s2 - sn * s1 * s1)
        p3 = a * (c * (s3 - s1**3) - 3.0 * sn * s1 * s2)
        num = p2 * q - k * p1 * s2
        rho = p0 + num / q**3
        num1 = p3 * q - k * p1 * s3
        rho1 = p1 + (num1 * q - 3.0 * k * num * s2) / q**4
    return contact, rho, rho1


def _alpha(cam: DiscCam, p: _Path) -> tuple[np.ndarray, np.ndarray]:
    """(|α|, dα_s/dδ) — see the module Notes."""
    if _flat(cam):
        z = np.zeros_like(p.delta)
        return z, z
    f, g = _dot(p.T, p.m), _cross(p.T, p.m)
    f1 = _dot(p.T1, p.m) + _dot(p.T, p.m1)
    g1 = _cross(p.T1, p.m) + _cross(p.T, p.m1)
    return np.arctan2(np.abs(f), np.abs(g)), (f1 * g - f * g1) / (f * f + g * g)


def _convexity(cam: DiscCam, p: _Path) -> tuple[np.ndarray, np.ndarray]:
    """(c, dc/dδ), c = 1/ρ of the pitch curve, > 0 convex."""
    rot = float(cam.rotation)
    speed = np.hypot(p.T[..., 0], p.T[..., 1])
    tq = _cross(p.T, p.Q)
    c = -rot * tq / speed**3
    dc = -rot * (_cross(p.T, p.P3) / speed**3 - 3.0 * tq * _dot(p.T, p.Q) / speed**5)
    return c, dc


# --------------------------------------------------------------------------------------------
# The profile


def profile(cam: DiscCam, delta: ArrayLike) -> CamProfile:
    """The exact pitch curve, working profile, pressure angle and curvature at cam angles δ.

    Parameters
    ----------
    cam : DiscCam
        The cam, its follower and motion program (SI units).
    delta : array_like, shape (N,)
        Cam angles, rad (taken mod 2π by the motion law; right-hand limits at its joints).

    Returns
    -------
    CamProfile
        Points in the cam frame (m), pressure angles (rad), signed radii of curvature (m).

    Raises
    ------
    ValueError
        An offset not smaller than r0, an arm that cannot reach the base circle, an oscillating
        flat face with r0 ≥ a, a rotation other than ±1.
    SceneError
        An invalid motion program (from ``graphmech.mechanisms.motion``; also a ValueError).

    Notes
    -----
    P = R(−rot·δ)·B(δ) (inversion); the roller's working profile P + r_r·n with the inward unit
    normal n = −rot·J·P′/|P′|; the flat face's contact point (rot·s′, r0 + s) turned by −rot·δ;
    α = atan2(|T·m|, |T × m|); ρ = −rot·|T|³/(T × Q); an oscillating flat face's contact at
    t = a·cos ψ/(1 + k·φ′) along the face from A. The derivations are in the module Notes.

    Examples
    --------
    A centred knife edge traces the base circle during the near dwell (s = 0), where its pressure
    angle is 0:

    >>> from graphmech.mechanisms.cam import DiscCam, MotionProgram, Segment, TranslatingFollower
    >>> quarter = math.pi / 2
    >>> program = MotionProgram(0.016, (Segment("rise", quarter, "cosine"), Segment("dwell", quarter),
    ...                                 Segment("return", quarter, "cosine"), Segment("dwell", quarter)))
    >>> p = profile(DiscCam(0.03, TranslatingFollower(), program), [1.75 * math.pi])
    >>> p.pitch.round(6).tolist(), p.rho_pitch.round(12).tolist(), p.pressure_angle.tolist()
    ([[-0.021213, 0.021213]], [0.03], [0.0])
    """
    d = np.asarray(delta, dtype=float)
    if d.ndim != 1:
        raise OutOfDomain(f"delta must be a 1-D array of cam angles, not shape {d.shape}")
    rot = _check_rotation(cam)
    p = _path(cam, d)
    turn = -rot * d
    pitch = _turn(p.B, turn)
    alpha, _ = _alpha(cam, p)
    c, _ = _convexity(cam, p)
    with np.errstate(divide="ignore"):
        rho = 1.0 / c
    f = cam.follower
    if f.contact == "roller":
        t = p.T / np.hypot(p.T[..., 0], p.T[..., 1])[..., None]
        inward = -rot * _quarter(t)
        actual = pitch + f.roller_radius * _turn(inward, turn)
        rho_actual = rho - f.roller_radius
    elif f.contact == "flat" and isinstance(f, OscillatingFollower):
        contact, rho_actual, _ = _rocker_face(cam, p)
        actual = _turn(contact, turn)
    elif f.contact == "flat":
        s, s1, s2, _ = p.s
        actual = _turn(_vec(rot * s1, cam.base_radius + s), turn)
        rho_actual = cam.base_radius + s + s2
    else:
        actual = pitch.copy()
        rho_actual = rho.copy()
    return CamProfile(d.copy(), pitch, actual, alpha, rho, rho_actual)


# --------------------------------------------------------------------------------------------
# Extrema, piece by piece


def _segments(cam: DiscCam) -> list[tuple[str, float, float]]:
    out: list[tuple[str, float, float]] = []
    start = 0.0
    for seg in cam.program.segments:
        out.append((seg.kind, start, start + seg.angle))
        start += seg.angle
    if abs(start - _TWO_PI) > 1e-9:
        raise OutOfDomain(f"the program's segments add up to {math.degrees(start):.6f}°, not 360°")
    return out


def _pieces(cam: DiscCam, where: str) -> list[tuple[float, float]]:
    """The smooth pieces [joint, next joint) of the law lying in segments of kind ``where``."""
    if where not in ("rise", "return", "all"):
        raise OutOfDomain(f'where must be "rise", "return" or "all", not {where!r}')
    segs = _segments(cam)
    joints = [a for _, a, _ in segs] + [float(x) % _TWO_PI for x in np.atleast_1d(breakpoints(cam.program))]
    joints += [imp.angle % _TWO_PI for imp in impacts(cam.program)]  # the laws' own jumps too
    joints = sorted(joints)
    clusters: list[list[float]] = []
    for j in joints:
        if clusters and j - clusters[-1][-1] <= _JOINT_TOL:
            clusters[-1].append(j)
        else:
            clusters.append([j])
    if len(clusters) > 1 and clusters[0][0] + _TWO_PI - clusters[-1][-1] <= _JOINT_TOL:
        clusters[0] = clusters[0] + [c - _TWO_PI for c in clusters.pop()]
    pieces = []
    for i, cl in enumerate(clusters):
        nxt = clusters[(i + 1) % len(clusters)]
        lo, hi = max(cl), min(nxt) + (_TWO_PI if i + 1 == len(clusters) else 0.0)
        mid = (0.5 * (lo + hi)) % _TWO_PI
        kind = next(k for k, a, b in segs if a <= mid < b)
        if where == "all" or kind == where:
            pieces.append((lo, hi))
    if not pieces:
        raise NotApplicable(f"the program has no {where} segment")
    return pieces


def _maximise(
    pieces: list[tuple[float, float]],
    fn: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]],
) -> tuple[float, float]:
    """Largest value of fn(δ)[0] over the pieces and where (rad in [0, 2π)).

    ``fn`` returns (value, derivative of a smooth quantity whose extrema are the value's only
    interior candidates). Each piece is sampled (its left end as the right-hand limit, its right
    end as the left-hand limit), each sign change of the derivative refined by brentq.
    """
    grids: list[np.ndarray] = []
    for lo, hi in pieces:
        grids.append(np.linspace(lo, hi - _LEFT, _SAMPLES))
    values, derivs = fn(np.concatenate(grids))
    cand_values: list[float] = []
    cand_at: list[float] = []
    roots: list[float] = []
    for k, ((lo, hi), x) in enumerate(zip(pieces, grids)):
        v = values[k * _SAMPLES:(k + 1) * _SAMPLES]
        dv = derivs[k * _SAMPLES:(k + 1) * _SAMPLES]
        cand_values += [float(v[0]), float(v[-1])]
        cand_at += [lo, hi]
        flat = np.flatnonzero(dv == 0.0)  # stationary samples (a dwell: all of them)
        cand_values += v[flat].tolist()
        cand_at += x[flat].tolist()
        for i in np.flatnonzero(np.sign(dv[:-1]) * np.sign(dv[1:]) < 0):
            roots.append(brentq(lambda t: float(fn(np.array([t]))[1][0]), float(x[i]), float(x[i + 1]),
                                xtol=1e-15, rtol=4.0 * EPS))
    if roots:
        cand_values += fn(np.array(roots))[0].tolist()
        cand_at += roots
    ok = np.isfinite(cand_values)
    if not ok.any():
        raise NoSolution("no finite value to maximise")
    order = np.argsort(np.asarray(cand_at) % _TWO_PI, kind="stable")  # ties: the first angle wins
    best_i = int(order[np.argmax(np.where(ok, cand_values, -np.inf)[order])])
    best, at = cand_values[best_i], cand_at[best_i]
    at = at % _TWO_PI
    return best, (0.0 if at >= _TWO_PI else at)


def max_pressure_angle(cam: DiscCam, where: Where = "all") -> tuple[float, float]:
    """The largest pressure angle over the rise, the return or the whole cycle, and where.

    Parameters
    ----------
    cam : DiscCam
    where : {"rise", "return", "all"}
        Which segments to search (``"all"`` includes the dwells, where an offset follower still
        has tan α = |e|/(s0 + s)).

    Returns
    -------
    (alpha_max, delta) : tuple of float
        |α| in rad and the cam angle in [0, 2π) rad. A maximum at a joint is reported at the
        joint, whichever side's limit it is.

    Notes
    -----
    The law is smooth between its joints, so |α| peaks at a piece's end (one-sided limits) or at
    an interior extremum of the signed α_s, where dα_s/dδ = (f′g − fg′)/(f² + g²) = 0 (module
    Notes). Each piece is sampled densely and each sign change of dα_s/dδ solved by brentq to
    machine precision.

    Examples
    --------
    >>> from graphmech.mechanisms.cam import DiscCam, MotionProgram, Segment, TranslatingFollower
    >>> program = MotionProgram(0.016, (Segment("rise", math.pi, "cosine"), Segment("return", math.pi, "cosine")))
    >>> alpha, at = max_pressure_angle(DiscCam(0.04, TranslatingFollower(), program), "rise")
    >>> round(math.degrees(alpha), 6), 0 < at < math.pi
    (9.594068, True)
    """
    pieces = _pieces(cam, where)
    if _flat(cam):
        return 0.0, pieces[0][0] % _TWO_PI
    best, at = _maximise(pieces, lambda d: _alpha(cam, _path(cam, d)))
    # Where α passes 90° the signed α_s jumps from +90° to −90° and no sign change of its
    # derivative marks the peak: a dense look at |α| itself catches it, then a bounded search.
    for lo, hi in pieces:
        d = np.linspace(lo, hi, 4097)[:-1]  # the piece's own values: its end belongs to the next one
        a = profile(cam, d % _TWO_PI).pressure_angle
        k = int(np.argmax(a))
        if a[k] > best + 1e-12:
            h = (hi - lo) / 4096
            x, fun = fminbound(lambda t: -float(profile(cam, np.array([t % _TWO_PI])).pressure_angle[0]),
                               max(lo, d[k] - h), min(hi, d[k] + h), xatol=1e-12)
            cand, cand_at = (-fun, x) if -fun > a[k] else (float(a[k]), float(d[k]))
            if cand > best:
                best, at = cand, cand_at % _TWO_PI
    return best, at


def min_convex_rho_pitch(cam: DiscCam) -> tuple[float, float]:
    """The smallest positive (convex) radius of curvature of the pitch curve, m, and where, rad.

    Corners of the pitch curve (velocity jumps of the law) are not counted: each smooth piece is
    searched with its one-sided limits; ``undercut`` reports convex corners separately.

    Notes
    -----
    The largest c = 1/ρ = −rot·(T × Q)/|T|³ over the smooth pieces; interior candidates where
    dc/dδ = −rot·[(T × P‴)/|T|³ − 3·(T × Q)(T·Q)/|T|⁵] = 0, refined by brentq.

    Raises
    ------
    ArithmeticError
        The pitch curve has no convex arc (impossible for a closed curve round O).

    Examples
    --------
    A centred knife edge, 16 mm cosine rise and return over 180° each, r0 = 30 mm: the pitch curve
    is sharpest a little before mid-rise (at the top, 180°, ρ = 46²/(46 + 8) ≈ 39.19 mm):

    >>> from graphmech.mechanisms.cam import DiscCam, MotionProgram, Segment, TranslatingFollower
    >>> program = MotionProgram(0.016, (Segment("rise", math.pi, "cosine"), Segment("return", math.pi, "cosine")))
    >>> rho, at = min_convex_rho_pitch(DiscCam(0.03, TranslatingFollower(), program))
    >>> round(rho * 1e3, 6), round(math.degrees(at), 6)
    (37.148351, 77.846803)
    """
    c, at = _maximise(_pieces(cam, "all"), lambda d: _convexity(cam, _path(cam, d)))
    if not c > 0.0:
        raise NoSolution("the pitch curve has no convex arc")
    return 1.0 / c, at


def _corners(cam: DiscCam) -> list[tuple[float, float]]:
    """Convex corners of the pitch curve: (δ, turning angle, rad) where the tangent jumps."""
    rot = float(cam.rotation)
    starts = np.array([imp.angle % _TWO_PI for imp in impacts(cam.program) if imp.kind == "rigid"])
    if starts.size == 0:
        return []
    left = _path(cam, np.where(starts > 0.0, starts, _TWO_PI) - _LEFT)
    right = _path(cam, starts)
    turn = np.arctan2(-rot * _cross(left.T, right.T), _dot(left.T, right.T))
    return [(float(d), float(t)) for d, t in zip(starts, turn) if t > 1e-9]


def _deg(x: float) -> str:
    return f"{math.degrees(x):.3f}°"


def undercut(cam: DiscCam) -> list[str]:
    """Plain-language findings on whether the working profile can be cut and followed.

    Returns
    -------
    list of str
        Empty when the profile is fine. Roller: r_r ≥ the smallest convex radius of curvature of
        the pitch curve (the inner envelope folds over itself, 根切), and convex corners of the
        pitch curve (a velocity drop of the law), where a roller of any radius leaves the profile
        for a moment. Flat face: r0 + s + s″ ≤ 0 somewhere (the face lines' envelope folds), and
        velocity drops at joints (s″ → −∞); an oscillating flat face: the envelope's radius of
        curvature ≤ 0 (a cusp; the contact leaving a finite face is not modelled). A knife edge
        has no finding.

    Notes
    -----
    Roller: the working profile's radius is ρ − r_r on a convex arc, so it vanishes (a cusp) when
    r_r = ρ_min; "just touching" counts (relative slack ``TANGENT_REL``). Flat face: its radius is
    r0 + s + s″ (module Notes); the smallest value is found like the other extrema, with s′ + s‴ as
    its derivative. A jump of s′ down by Δ at a joint is an impulse −Δ·δ(δ − δ_j) in s″.

    Examples
    --------
    >>> from graphmech.mechanisms.cam import DiscCam, MotionProgram, Segment, TranslatingFollower
    >>> third = math.pi / 3
    >>> program = MotionProgram(0.016, (Segment("rise", third, "cosine"), Segment("dwell", third),
    ...                                 Segment("return", math.pi / 2, "cosine"),
    ...                                 Segment("dwell", 5 * math.pi / 6)))
    >>> undercut(DiscCam(0.04, TranslatingFollower(0.0, "roller", 0.010), program))
    []
    >>> undercut(DiscCam(0.03, TranslatingFollower(0.0, "flat"), program))
    ['the flat face undercuts: r0 + s + s″ = -26.000 mm < 0 at δ = 60.000°; the base radius must exceed 56.000 mm']
    """
    f = cam.follower
    found: list[str] = []
    if f.contact == "roller":
        rho, at = min_convex_rho_pitch(cam)
        if f.roller_radius >= rho * (1.0 - TANGENT_REL):
            found.append(
                f"the roller undercuts: r_r = {f.roller_radius * 1e3:.4f} mm ≥ ρ_min = {rho * 1e3:.4f} mm "
                f"(smallest convex radius of curvature of the pitch curve) at δ = {_deg(at)}; use a "
                f"smaller roller or a larger base circle")
        for at, turn in _corners(cam):
            found.append(
                f"the pitch curve has a convex corner at δ = {_deg(at)} (the follower's velocity drops "
                f"there; the tangent turns {_deg(turn)}): the roller loses contact with the profile's "
                f"vertex for a moment")
    elif f.contact == "flat" and isinstance(f, OscillatingFollower):
        def negative_rho(d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            _, rho, rho1 = _rocker_face(cam, _path(cam, d))
            return -rho, -rho1

        worst, at = _maximise(_pieces(cam, "all"), negative_rho)
        if -worst <= cam.base_radius * TANGENT_REL:
            found.append(
                f"the flat face's profile has a cusp: the envelope of the face lines has radius of "
                f"curvature ρ = {-worst * 1e3:.3f} mm ≤ 0 at δ = {_deg(at)}; use a larger base circle "
                f"or a gentler motion law")
        for at, _ in _corners(cam):
            found.append(
                f"the follower's angular velocity drops at δ = {_deg(at)} (φ″ → −∞): the flat face "
                f"cannot follow there")
    elif f.contact == "flat":
        r0 = cam.base_radius

        def negative_rho(d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            p = _path(cam, d)
            return -(r0 + p.s[0] + p.s[2]), -(p.s[1] + p.s[3])

        worst, at = _maximise(_pieces(cam, "all"), negative_rho)
        if -worst <= r0 * TANGENT_REL:
            found.append(
                f"the flat face undercuts: r0 + s + s″ = {-worst * 1e3:.3f} mm < 0 at δ = {_deg(at)}; "
                f"the base radius must exceed {(r0 + worst) * 1e3:.3f} mm")
        for at, _ in _corners(cam):
            found.append(
                f"the follower's velocity drops at δ = {_deg(at)} (s″ → −∞): the flat face cannot "
                f"follow there")
    return found


# --------------------------------------------------------------------------------------------
# Sizing


def min_base_radius(cam: DiscCam, alpha_permissible: float) -> float:
    """The smallest base radius r0 whose largest pressure angle (all segments) stays ≤ [α].

    Parameters
    ----------
    cam : DiscCam
        Everything but its ``base_radius`` is kept.
    alpha_permissible : float
        [α], rad, in (0, π/2).

    Returns
    -------
    float
        r0, m, with max |α| = [α] (to brentq's precision) unless [α] already holds at the smallest
        geometrically possible r0.

    Raises
    ------
    ValueError
        [α] outside (0, π/2); a flat face ⟂ its axis (α ≡ 0: size it by r0 + s + s″ > 0 instead);
        no r0 up to 100 × the stroke (translating) or up to a + l (oscillating) is good enough.

    Notes
    -----
    F(r0) = α_max(r0) − [α]. For a translating follower tan α = |s′ − rot·e|/(√(r0² − e²) + s)
    falls as r0 grows, so F falls monotonically from +∞ at r0 = |e|; for a rocker F need not be
    monotone. Either way F is sampled on a geometric grid from the smallest possible r0 (|e|, or
    |a − l| for a rocker) upward, and the first sign change is solved by brentq.

    Examples
    --------
    >>> from graphmech.mechanisms.cam import DiscCam, MotionProgram, Segment, TranslatingFollower
    >>> program = MotionProgram(0.016, (Segment("rise", math.pi, "cosine"), Segment("return", math.pi, "cosine")))
    >>> cam = DiscCam(0.04, TranslatingFollower(), program)
    >>> r0 = min_base_radius(cam, math.radians(30))
    >>> alpha, _ = max_pressure_angle(dataclasses.replace(cam, base_radius=r0))
    >>> round(r0 * 1e3, 4), round(math.degrees(alpha), 9)
    (8.0, 30.0)
    """
    if not 0.0 < alpha_permissible < 0.5 * math.pi:
        raise OutOfDomain(f"[α] must lie in (0°, 90°), not {math.degrees(alpha_permissible):g}°")
    if _flat(cam):
        raise NotApplicable(
            "a flat face ⟂ its axis has pressure angle 0 at any base radius; size r0 by "
            "r0 + s + s″ > 0 (see undercut) instead")
    f = cam.follower
    if isinstance(f, TranslatingFollower):
        h = abs(cam.program.stroke)
        lo = max(abs(f.offset) * (1.0 + 1e-9), 1e-6 * h)
        hi = 100.0 * h
        limit = f"100 × the stroke = {hi * 1e3:g} mm"
    else:
        a, l = f.pivot_distance, f.arm
        lo, hi = abs(a - l) * (1.0 + 1e-9) + 1e-12 * (a + l), (a + l) * (1.0 - 1e-9)
        limit = f"a + l = {(a + l) * 1e3:g} mm (the arm's reach)"
    if not hi > lo:
        raise OutOfDomain(f"no base radius is possible below {limit}")

    def excess(r0: float) -> float:
        return max_pressure_angle(dataclasses.replace(cam, base_radius=r0))[0] - alpha_permissible

    radii = np.geomspace(lo, hi, _R0_SCAN)
    prev = None
    for r0 in radii:
        fr = excess(float(r0))
        if fr <= 0.0:
            if prev is None:
                return float(r0)
            return float(brentq(excess, prev, float(r0), xtol=1e-15, rtol=4.0 * EPS))
        prev = float(r0)
    raise OutOfDomain(
        f"no base radius up to {limit} keeps the pressure angle ≤ [α] = "
        f"{math.degrees(alpha_permissible):g}° (it is still "
        f"{math.degrees(excess(hi) + alpha_permissible):.3f}° there)")


# ------------------------------------------------------------------ the working profile as one closed curve

#: A hair to the left of a corner, for its left-hand limit.
_LEFT = 32.0 * float(np.spacing(math.tau))


def _actual(cam: DiscCam, delta: Any) -> np.ndarray:
    return profile(cam, np.atleast_1d(np.asarray(delta, dtype=float)) % math.tau).actual


def _central_jacobian(f: Callable[[np.ndarray], np.ndarray], h: float = 1e-7) -> Callable[[np.ndarray], np.ndarray]:
    """The Jacobian of the smooth map f: R² → R² by central differences of step h."""
    def jac(z: np.ndarray) -> np.ndarray:
        dx, dy = np.array([h, 0.0]), np.array([0.0, h])
        return np.column_stack([(f(z + dx) - f(z - dx)) / (2.0 * h), (f(z + dy) - f(z - dy)) / (2.0 * h)])

    return jac


def _convex_vertex(cam: DiscCam, c: float, w: float) -> tuple[float, float]:
    """Where the inner offsets of the two sides of a convex corner at ``c`` cross: (δ1 < c, δ2 ≥ c)
    with actual(δ1⁻ side) = actual(δ2⁺ side), to machine precision."""
    import shapely

    dl = c - np.linspace(_LEFT, w, 4001)
    dr = c + np.linspace(0.0, w, 4001)
    al, ar = _actual(cam, dl), _actual(cam, dr)
    x = shapely.LineString(al).intersection(shapely.LineString(ar))
    if x.geom_type != "Point":
        raise NoSolution(f"the roller's offsets at the corner δ = {math.degrees(c):.6g}° do not cross once")
    q = np.asarray(x.coords[0])
    guess = [dl[np.argmin(np.hypot(*(al - q).T))], dr[np.argmin(np.hypot(*(ar - q).T))]]

    def apart(t: np.ndarray) -> np.ndarray:  # the two sides' offsets, each kept to its own side
        gap: np.ndarray = _actual(cam, [min(t[0], c - _LEFT)])[0] - _actual(cam, [max(t[1], c)])[0]
        return gap

    z, _ = newton(apart, _central_jacobian(apart), np.array([float(guess[0]), float(guess[1])]), maxiter=50)
    d1, d2 = float(z[0]), float(z[1])
    gap = float(np.hypot(*(_actual(cam, [d1])[0] - _actual(cam, [d2])[0])))
    if not (c - w < d1 < c <= d2 < c + w) or gap > 1e-12 * cam.base_radius:
        raise NoSolution(f"the profile's vertex at δ = {math.degrees(c):.6g}° was not found")
    return d1, d2


def working_profile(cam: DiscCam, samples: int = 20_000) -> tuple[np.ndarray, np.ndarray]:
    """The exact working profile as ``samples``-odd points in order round the cam, and their cam angles.

    Knife edge and flat face: ``exact.cam.profile`` at evenly spaced angles (a flat face cannot
    follow a velocity jump, so its program must have none). Roller: the inner envelope between
    the pitch curve's corners; at a concave corner (the velocity rises) the roller rests on the
    corner and the profile is the arc of radius r_r round it, between the two sides' normals; at
    a convex corner (the velocity drops) the two sides' offsets cross at the profile's vertex and
    are cut there (found by solving actual(δ1) = actual(δ2) to machine precision) — their
    stretches beyond it are not part of the cam. Raises if the result crosses itself (an undercut
    profile folds over itself, and this is not its boundary).
    """
    f = cam.follower
    corners = np.array(sorted({i.angle % math.tau for i in impacts(cam.program) if i.kind == "rigid"}))
    if f.contact == "flat" and corners.size:
        raise NotApplicable("a flat face cannot follow a velocity jump: no working profile to compare with")
    if f.contact != "roller" or corners.size == 0:
        d = np.union1d(np.linspace(0.0, math.tau, samples, endpoint=False), corners)
        pts, ang = _actual(cam, d), d
    else:
        rot, r_r = float(cam.rotation), f.roller_radius
        cs = [float(c) for c in corners]
        m = len(cs)
        gaps = [((cs[(i + 1) % m] - cs[i]) % math.tau) or math.tau for i in range(m)]
        cut: dict[int, tuple[float, float]] = {}
        arcs: dict[int, np.ndarray] = {}
        for i, c in enumerate(cs):
            both = profile(cam, np.array([(c - _LEFT) % math.tau, c]))  # left, right limits
            nl, nr = (both.actual - both.pitch) / r_r
            tl = rot * np.array([-nl[1], nl[0]])  # the direction of travel on the left (n = −rot·J·t)
            if float(np.dot(nr - nl, tl)) >= 0.0:  # concave: the normals open, the roller turns on the corner
                a0 = math.atan2(nl[1], nl[0])
                da = (math.atan2(nr[1], nr[0]) - a0 + math.pi) % math.tau - math.pi
                k = max(8, math.ceil(abs(da) / math.tau * samples))
                t = a0 + da * np.linspace(0.0, 1.0, k + 1)[1:-1]
                arcs[i] = both.pitch[1] + r_r * np.column_stack([np.cos(t), np.sin(t)])
            else:  # convex: the offsets cross
                w = min(math.radians(30.0), 0.45 * gaps[i - 1], 0.45 * gaps[i])
                cut[i] = _convex_vertex(cam, c, w)
        parts, angs = [], []
        for i, c in enumerate(cs):
            j = (i + 1) % m
            lo = cut[i][1] if i in cut else c
            hi = (cut[j][0] if j in cut else cs[j] - _LEFT) + (math.tau if j == 0 else 0.0)
            k = max(16, math.ceil((hi - lo) / math.tau * samples))
            d = np.linspace(lo, hi, k + 1)
            if j in cut:
                d = d[:-1]  # the vertex is the next stretch's first point
            parts.append(_actual(cam, d))
            angs.append(d % math.tau)
            if j in arcs:
                parts.append(arcs[j])
                angs.append(np.full(len(arcs[j]), cs[j]))
        pts, ang = np.concatenate(parts), np.concatenate(angs)
    import shapely

    if not shapely.LinearRing(pts).is_simple:  # an offset beyond a vertex, or an undercut's loop
        raise NoSolution("the exact working profile crosses itself: the envelope folds over (undercut)")
    return pts, ang


def min_rho_actual(cam: DiscCam, samples: int = 20_000) -> tuple[float, float]:
    """The smallest radius of curvature of the working profile (for a flat face r0 + s + s″), m,
    and where, rad: a dense look, then a bounded search round the smallest sample."""
    d = np.linspace(0.0, math.tau, samples, endpoint=False)
    rho = profile(cam, d).rho_actual
    k = int(np.argmin(rho))
    h = math.tau / samples
    x, fun = fminbound(lambda t: float(profile(cam, [t % math.tau]).rho_actual[0]), d[k] - h, d[k] + h, xatol=1e-13)
    if fun < rho[k]:
        return fun, x % math.tau
    return float(rho[k]), float(d[k])
