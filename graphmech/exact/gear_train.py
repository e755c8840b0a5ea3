"""A gear train's angular speeds from its meshing constraints, as one linear system.

The independent reference for the gear-train kind: no converted train is built and no compound
train split, and a spatial mesh's sense is found here from its geometry (the pitch points' velocity
vectors), not from the arrows the scene reader followed — every mesh is one equation in the
members' absolute speeds, written in the frame of the member carrying both axes (the frame, or the
planets' carrier H):

    z_a·(ω_a − ω_H) − s·z_b·(ω_b − ω_H) = 0,   s = −1 external, +1 internal, stated if spatial,

with ω = 0 for each fixed member and ω = the given value for each input. The coefficients are
whole numbers, so the system is eliminated in exact rationals (:class:`fractions.Fraction`; a
float input is a rational too): the rank is exact — a redundant mesh (the second and third of
identical planets) is counted once without a tolerance — and the speeds are the correctly rounded
values even where they cancel (the double-worm reducer's ω_H = ½(ω₂ + ω₄′) is 10⁻⁴ of its terms).

The mobility is the rank deficit of the constraints before the inputs (1: a planetary or ordinary
train, 2: a differential); a train given another number of inputs, or inputs that do not fix every
speed, is refused in one sentence, a locked train (its input held at rest by the meshes, as by a
converted ratio of 1 to a fixed central gear) said so.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.mechanisms.gear_train import AXES, HANDS, PARALLEL_SIGN, GearTrain, Mesh

#: One equation: coefficients by member index, and the right-hand side.
Row = tuple[dict[int, Fraction], Fraction]


def _cross(u: tuple[int, int, int], v: tuple[int, int, int]) -> tuple[int, int, int]:
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def mesh_sign(train: GearTrain, mesh: Mesh) -> int:
    """s of ω_a − ω_H = s·(z_b/z_a)(ω_b − ω_H), from the geometry where the train has it.

    The pitch point's velocity, per unit speed and radius: û × t on a gear (û its axis, t toward
    the pitch point); along −h·û on a worm's thread (h = +1 right hand), its axial lead z·p_x
    against the wheel's z·p_x per turn. The two agree at the pitch point, so s is the cosine of
    their directions. Parallel axes without ``towards``: the kind's sign, reversed when the axes
    are drawn opposite; a spatial mesh without geometry: the sign stated for it.
    """
    ua = AXES[train.member(train.gear(mesh.a).member).axis]
    ub = AXES[train.member(train.gear(mesh.b).member).axis]
    if mesh.towards is None:
        if mesh.kind in PARALLEL_SIGN:
            cos = sum(x * y for x, y in zip(ua, ub))
            if cos == 0:
                raise OutOfDomain(f"the {mesh.kind} mesh {mesh.a}–{mesh.b} joins axes that are not parallel")
            return PARALLEL_SIGN[mesh.kind] * cos
        return mesh.relative_sign
    ta, tb = AXES[mesh.towards[0]], AXES[mesh.towards[1]]
    if mesh.kind == "worm":
        h = HANDS[mesh.hand or "right"]
        va = (-h * ua[0], -h * ua[1], -h * ua[2])
    else:
        va = _cross(ua, ta)
    vb = _cross(ub, tb)
    cos = sum(x * y for x, y in zip(va, vb))
    if cos == 0 or _cross(va, vb) != (0, 0, 0):
        raise OutOfDomain(f"mesh {mesh.a}–{mesh.b}: its pitch points move across each other ({mesh.towards})")
    return 1 if cos > 0 else -1


def mesh_row(train: GearTrain, mesh: Mesh, index: Mapping[str, int]) -> dict[int, Fraction]:
    """z_a(ω_a − ω_H) − s·z_b(ω_b − ω_H) as coefficients (ω_H = 0 in the frame)."""
    ga, gb = train.gear(mesh.a), train.gear(mesh.b)
    s = mesh_sign(train, mesh)
    row: dict[int, Fraction] = {}

    def add(member: str, c: int) -> None:
        k = index[member]
        row[k] = row.get(k, Fraction(0)) + c

    add(ga.member, ga.z)
    add(gb.member, -s * gb.z)
    h = train.mesh_frame(mesh)
    if h is not None:
        add(h, -ga.z + s * gb.z)
    return {k: c for k, c in row.items() if c != 0}


def constraint_rows(train: GearTrain) -> list[Row]:
    """The meshes' equations, then ω = 0 for each fixed member (no inputs)."""
    index = {m.name: k for k, m in enumerate(train.members)}
    rows: list[Row] = [(mesh_row(train, mesh, index), Fraction(0)) for mesh in train.meshes]
    rows += [({index[f]: Fraction(1)}, Fraction(0)) for f in train.fixed]
    return rows


@dataclass(frozen=True)
class Reduced:
    """The reduced row echelon form of a system: pivot column → (its row's other entries, rhs)."""

    n: int
    pivots: dict[int, tuple[dict[int, Fraction], Fraction]]
    consistent: bool

    @property
    def rank(self) -> int:
        return len(self.pivots)

    def determined(self, k: int) -> Fraction | None:
        """ω_k when the system fixes it whatever the free unknowns, else None."""
        if k not in self.pivots:
            return None
        others, rhs = self.pivots[k]
        return rhs if not others else None


def reduce(rows: Sequence[Row], n: int) -> Reduced:
    """Gauss–Jordan elimination in exact rationals."""
    work = [(dict(c), r) for c, r in rows]
    pivots: dict[int, int] = {}  # column → row
    done: list[tuple[dict[int, Fraction], Fraction]] = []
    for coeffs, rhs in work:
        # eliminate the pivots found so far
        for col, i in pivots.items():
            c = coeffs.get(col)
            if c:
                pc, pr = done[i]
                for j, v in pc.items():
                    coeffs[j] = coeffs.get(j, Fraction(0)) - c * v
                rhs -= c * pr
        coeffs = {j: v for j, v in coeffs.items() if v != 0}
        if not coeffs:
            if rhs != 0:
                return Reduced(n, {}, False)
            continue
        col = min(coeffs)
        p = coeffs[col]
        coeffs = {j: v / p for j, v in coeffs.items()}
        rhs /= p
        # back-substitute into the rows already reduced
        for i, (oc, orhs) in enumerate(done):
            c = oc.get(col)
            if c:
                for j, v in coeffs.items():
                    oc[j] = oc.get(j, Fraction(0)) - c * v
                done[i] = ({j: v for j, v in oc.items() if v != 0}, orhs - c * rhs)
        pivots[col] = len(done)
        done.append((coeffs, rhs))
    return Reduced(n, {col: ({j: v for j, v in done[i][0].items() if j != col}, done[i][1])
                       for col, i in pivots.items()}, True)


def mobility(train: GearTrain) -> int:
    """The train's degrees of freedom: members − rank of the meshes and fixed members."""
    return len(train.members) - reduce(constraint_rows(train), len(train.members)).rank


def redundant(train: GearTrain) -> int:
    """The constraints that repeat others (identical planets beyond the first: counted once)."""
    rows = constraint_rows(train)
    return len(rows) - reduce(rows, len(train.members)).rank


@dataclass(frozen=True)
class TrainSolution:
    """Every member's ω (rad/s); a gear's name gives its member's speed."""

    train: GearTrain
    omega: Mapping[str, float]
    mobility: int
    redundant: int

    def speed(self, name: str) -> float:
        """ω of a member, or of the member carrying the gear ``name``."""
        return self.omega[self.train.member_of(name)]

    def ratio(self, a: str, b: str) -> float:
        """i_ab = ω_a/ω_b."""
        wb = self.speed(b)
        if wb == 0.0:
            raise NoSolution(f"i_{a}{b} has no value: {b} is at rest")
        return self.speed(a) / wb

    def converted_ratio(self, a: str, b: str, carrier: str) -> float:
        """Willis' i^H_ab = (ω_a − ω_H)/(ω_b − ω_H) from the speeds."""
        wh = self.speed(carrier)
        d = self.speed(b) - wh
        if d == 0.0:
            raise NoSolution(f"i^{carrier}_{a}{b} has no value here: {b} turns with the carrier {carrier}")
        return (self.speed(a) - wh) / d


def _plural(k: int, word: str) -> str:
    return f"{k} {word}" + ("" if k == 1 else "s")


def solve(train: GearTrain) -> TrainSolution:
    """Every member's speed from the meshes, the fixed members and the inputs."""
    names = [m.name for m in train.members]
    n = len(names)
    index = {name: k for k, name in enumerate(names)}
    rows = constraint_rows(train)
    base = reduce(rows, n)
    f = n - base.rank
    kind = {0: "it cannot move", 1: "one input drives it", 2: "a differential: two inputs drive it"}
    if len(train.inputs) != f:
        given = ", ".join(train.inputs) or "none"
        raise OutOfDomain(f"the train has mobility {f} ({kind.get(f, f'{f} inputs drive it')}) "
                          f"but {_plural(len(train.inputs), 'input')} {'is' if len(train.inputs) == 1 else 'are'} "
                          f"given ({given})")
    for name in train.inputs:
        if base.determined(index[name]) is not None:
            raise NoSolution(f"the train locks: the meshes{' and fixed members' if train.fixed else ''} hold "
                             f"{name} at rest{_lock_reason(train, name)}, so it cannot be driven")
    full = reduce(rows + [({index[k]: Fraction(1)}, Fraction(w)) for k, w in train.inputs.items()], n)
    if not full.consistent or full.rank < n:
        raise NoSolution(f"the inputs ({', '.join(train.inputs)}) do not fix every speed: "
                         "one of them follows from the others through the meshes")
    omega = {name: float(v) for name, k in index.items() if (v := full.determined(k)) is not None}
    return TrainSolution(train, omega, f, len(rows) - base.rank)


def converted_train_ratio(train: GearTrain, a: str, b: str, carrier: str) -> float:
    """Willis' i^H_ab of the converted train: the carrier held, the fixed members released.

    The converted train is the basic train of H: the meshes written in its frame (its planets with
    their central gears). Refused when it does not fix ω_a from ω_b (a or b outside that train).
    """
    index = {m.name: k for k, m in enumerate(train.members)}
    ma, mb = train.member_of(a), train.member_of(b)
    rows = [(mesh_row(train, mesh, index), Fraction(0)) for mesh in train.meshes if train.mesh_frame(mesh) == carrier]
    rows += [({index[carrier]: Fraction(1)}, Fraction(0)), ({index[mb]: Fraction(1)}, Fraction(1))]
    red = reduce(rows, len(index))
    v = red.determined(index[ma]) if red.consistent else None
    if v is None:
        raise NoSolution(f"the converted train of carrier {carrier} does not relate {a} to {b}")
    return float(v)


def _lock_reason(train: GearTrain, name: str) -> str:
    """The converted ratio of 1 that locks ``name``, when there is one to name."""
    for h in train.carriers:
        for f in train.fixed:
            if h in (f, name) or f == name:
                continue
            try:
                i = converted_train_ratio(train, name, f, h)
            except NoSolution:
                continue
            if i == 1.0:
                return f" (the converted ratio i^{h}_{name},{f} = 1 with {f} fixed)"
    return ""


def coaxial_tooth_number(*meshes: tuple[int | None, int | None, str]) -> int:
    """The missing tooth number that makes the meshes of one planet set coaxial.

    Each mesh is (z_central, z_planet, "external" | "internal"), all of one module, standard gears:
    the arm m(z_central ± z_planet)/2 is common to all — z₃ = z₁ + 2z₂ for a sun–planet–ring set,
    z₁ + z₂ = z₃ − z₂′ for a double planet with a ring. None marks the missing number; it may stand
    in several meshes when it is one gear's (the planet between a sun and a ring).
    """
    if len(meshes) < 2:
        raise OutOfDomain(f"the coaxial condition relates two meshes or more, not {len(meshes)}")
    arms: list[tuple[int, int]] = []  # the arm in module units as c + k·z
    for zc, zp, kind in meshes:
        if kind not in ("external", "internal"):
            raise OutOfDomain(f"a coaxial mesh is external or internal, not {kind!r}")
        sp = 1 if kind == "external" else -1
        c = (zc or 0) + sp * (zp or 0)
        k = (zc is None) + sp * (zp is None)
        arms.append((c, k))
    if all(k == 0 for _, k in arms):
        raise OutOfDomain("the coaxial condition needs the missing tooth number marked None")
    # two arms with different k give z; every other pair must agree with it
    (c0, k0), rest = arms[0], arms[1:]
    ks = [(c, k) for c, k in rest if k != k0]
    if not ks:
        raise OutOfDomain("the missing tooth number cancels from the coaxial condition")
    c1, k1 = ks[0]
    num, den = c1 - c0, k0 - k1
    if num % den:
        raise NoSolution(f"the coaxial condition gives z = {num}/{den}, not a whole number")
    z = num // den
    if len({c + k * z for c, k in arms}) != 1:
        raise NoSolution(f"the meshes are not coaxial for any z (arms {[c + k * z for c, k in arms]} in module units "
                         f"with z = {z})")
    if z < 1:
        raise NoSolution(f"the coaxial condition gives z = {z}: no such gear")
    return z
