"""A compound gear train split into its basic trains and solved as the book does.

The split (孙桓 §11-5, "混合轮系的传动比"): find each carrier H; its planets and the central gears
they mesh make one planetary (a central gear fixed) or differential basic train; what is left —
gears on axes fixed in the frame — makes the ordinary chains. Then

* an ordinary chain gives i_1k = n₁/n_k = (−1)^m ∏z_driven/∏z_driving (the sign by (−1)^m for
  parallel axes, from the arrows for spatial meshes: each mesh's stated or resolved sign);
* a basic train of carrier H gives Willis' equation for its converted train (H held still):
  i^H_ab = (n_a − n_H)/(n_b − n_H) = ± ∏z_driven/∏z_driving along the planets from a to b;
* the basic trains are joined by their shared members (n₄ = n₅: two gears on one shaft; a ring
  gear cut on a carrier), the fixed members (n = 0) and the inputs, and solved together — the
  book's substitution: each ordinary chain gives its members' speeds from one of them, and what
  is left is Willis' equations in those few speeds.

The arithmetic is the book's fractions (:class:`fractions.Fraction`: a ratio of tooth numbers is
exact), so a cancelling result (the double-worm reducer's 1/99 − 101/10⁴) loses nothing. A second
planet identical to the first, or a second idler, repeats a ratio already found: its meshes are
redundant, counted once and said. This shares no code with :mod:`graphmech.exact.gear_train`,
which writes every mesh as one equation and eliminates them all at once.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from fractions import Fraction
from typing import Literal

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.mechanisms.gear_train import GearTrain

BasicKind = Literal["ordinary", "planetary", "differential"]
#: A speed as an affine form in the unknown speeds of the split (parameter → coefficient; ``1``: constant).
Form = dict[str, Fraction]
CONST = ""


@dataclass(frozen=True)
class Ratio:
    """One ratio of a basic train: i_ab (ordinary, carrier None) or i^H_ab, as a fraction and as the
    book writes it (``−z2·z3/(z1·z2')``)."""

    a: str
    b: str
    value: Fraction
    carrier: str | None
    driven: tuple[str, ...]
    driving: tuple[str, ...]

    @property
    def formula(self) -> str:
        """``−z2·z3/(z1·z2')`` (the sign, the driven gears over the driving)."""
        sign = "−" if self.value < 0 else "+" if self.carrier is not None else ""
        idlers = set(self.driven) & set(self.driving)  # an idler's z cancels
        num = "·".join(f"z{g}" for g in self.driven if g not in idlers) or "1"
        driving = [g for g in self.driving if g not in idlers]
        den = "·".join(f"z{g}" for g in driving) or "1"
        if len(driving) > 1:
            den = f"({den})"
        return f"{sign}{num}/{den}"

    @property
    def name(self) -> str:
        return f"i{self.a}{self.b}" if self.carrier is None else f"i^{self.carrier}_{self.a}{self.b}"

    def equation(self, names: Mapping[str, str] | None = None) -> str:
        """``i^H_13 = (n1 − nH)/(n3 − nH) = −z2·z3/(z1·z2') = −5``; ``names``: member → the gear
        name the book uses for it in this basic train (``n3'`` for member 3 in 3'-4-5)."""
        a, b = (names or {}).get(self.a, self.a), (names or {}).get(self.b, self.b)
        if self.carrier is None:
            lhs = f"i{a},{b} = n{a}/n{b}"
        else:
            h = self.carrier
            lhs = f"i^{h}_{a},{b} = (n{a} − n{h})/(n{b} − n{h})"
        return f"{lhs} = {self.formula} = {_frac(self.value)}"


def _frac(x: Fraction) -> str:
    """A fraction as the book prints a ratio: whole, or to 6 significant figures."""
    if x.denominator == 1:
        return str(x.numerator).replace("-", "−")
    return f"{float(x):.6g}".replace("-", "−")


@dataclass(frozen=True)
class BasicTrain:
    """One basic train of the split.

    kind : ``"ordinary"`` (every axis fixed), ``"planetary"`` (a central member fixed) or
        ``"differential"``. carrier : H (None for an ordinary chain). root : the member every
        ratio starts from. members : its members (the carrier last). planets, centrals : a
        carrier's planets and the members coaxial with it that they mesh. meshes : indices into
        the train's meshes. redundant : meshes that repeat a ratio already found (identical
        planets, a second idler). ratios : root → every other member (i^H_root,x or i_root,x).
        names : member → the gear the book names it by here. shown : the members whose ratio the
        book writes (a carrier's central members; a chain's ends and its members shared with
        other trains, inputs or fixed — not its idlers).
    """

    kind: BasicKind
    carrier: str | None
    root: str
    members: tuple[str, ...]
    planets: tuple[str, ...]
    centrals: tuple[str, ...]
    meshes: tuple[int, ...]
    redundant: int
    ratios: tuple[Ratio, ...]
    label: str
    names: Mapping[str, str] = field(default_factory=dict)
    shown: tuple[str, ...] = ()

    def ratio_to(self, member: str) -> Ratio:
        for r in self.ratios:
            if r.b == member:
                return r
        raise OutOfDomain(f"{member} is not in the basic train {self.label}")

    def equations(self) -> list[str]:
        """The book's equations of this train: Willis' between its central members (a planet's own
        relative speed comes after), or the chain's ratios."""
        return [r.equation(self.names) for r in self.ratios if r.b in self.shown]

    def as_dict(self) -> dict[str, object]:
        return {"kind": self.kind, "carrier": self.carrier, "label": self.label, "members": list(self.members),
                "planets": list(self.planets), "centrals": list(self.centrals), "meshes": list(self.meshes),
                "redundant_meshes": self.redundant, "equations": self.equations()}


@dataclass(frozen=True)
class Split:
    """The split of a train and, once solved, every member's speed.

    trains : the basic trains, planetary/differential first (by carrier), then the ordinary chains.
    links : the connecting conditions in words (``n4 = n5: gears 4 and 5 on member 4``).
    mobility : the train's degrees of freedom as the split counts them. redundant : meshes
        counted once (their ratios repeat others').
    """

    train: GearTrain
    trains: tuple[BasicTrain, ...]
    links: tuple[str, ...]
    mobility: int
    redundant: int
    forms: Mapping[str, Form] = field(default_factory=dict)
    equations: tuple[Form, ...] = ()

    def basic_train_of(self, carrier: str) -> tuple[BasicTrain, ...]:
        return tuple(t for t in self.trains if t.carrier == carrier)

    def converted_ratio(self, a: str, b: str, carrier: str) -> Fraction:
        """Willis' i^H_ab from the converted train's tooth numbers (a, b members or gears)."""
        ma, mb = self.train.member_of(a), self.train.member_of(b)
        for t in self.basic_train_of(carrier):
            if ma in t.members and mb in t.members and carrier not in (ma, mb):
                # ρ_x = (n_r − n_H)/(n_x − n_H) from the root r: (n_a − n_H)/(n_b − n_H) = ρ_b/ρ_a
                ra = Fraction(1) if ma == t.root else t.ratio_to(ma).value
                rb = Fraction(1) if mb == t.root else t.ratio_to(mb).value
                return rb / ra
        raise NoSolution(f"the converted train of carrier {carrier} does not relate {a} to {b}")


def _path_ratios(train: GearTrain, frame: str | None, meshes: Sequence[int], root: str
                 ) -> tuple[dict[str, tuple[Fraction, tuple[str, ...], tuple[str, ...]]], list[int], list[int]]:
    """From ``root`` along the meshes (a tree): member → ((n_root − n_F)/(n_x − n_F), driven, driving);
    the meshes off the tree that repeat a ratio (redundant) and those that contradict it."""
    ratio: dict[str, tuple[Fraction, tuple[str, ...], tuple[str, ...]]] = {root: (Fraction(1), (), ())}
    used: set[int] = set()
    frontier = [root]
    while frontier:
        x = frontier.pop(0)
        for k in meshes:
            if k in used:
                continue
            m = train.meshes[k]
            ga, gb = train.gear(m.a), train.gear(m.b)
            if x not in (ga.member, gb.member):
                continue
            # the driving gear on x's side, the driven on the other
            here, there = (ga, gb) if ga.member == x else (gb, ga)
            if there.member in ratio:
                continue
            used.add(k)
            r, dn, dg = ratio[x]
            ratio[there.member] = (r * m.relative_sign * Fraction(there.z, here.z), dn + (there.name,),
                                   dg + (here.name,))
            frontier.append(there.member)
    same: list[int] = []
    contra: list[int] = []
    for k in meshes:
        if k in used:
            continue
        m = train.meshes[k]
        ga, gb = train.gear(m.a), train.gear(m.b)
        # ω_a/ω_b (relative) = s·z_b/z_a, and ω_a/ω_b = ρ_b/ρ_a
        (same if ratio[gb.member][0] / ratio[ga.member][0] == m.relative_sign * Fraction(gb.z, ga.z)
         else contra).append(k)
    return ratio, same, contra


def _components(train: GearTrain, meshes: Sequence[int]) -> list[list[int]]:
    """The meshes grouped by the members they connect, in the train's order."""
    groups: list[tuple[set[str], list[int]]] = []
    for k in meshes:
        m = train.meshes[k]
        pair = {train.gear(m.a).member, train.gear(m.b).member}
        hit = [g for g in groups if g[0] & pair]
        members, ks = set(pair), [k]
        for g in hit:
            members |= g[0]
            ks += g[1]
            groups.remove(g)
        groups.append((members, sorted(ks)))
    return sorted((ks for _, ks in groups), key=lambda ks: ks[0])


def _label(train: GearTrain, meshes: Sequence[int], carrier: str | None) -> str:
    gears: list[str] = []
    for k in meshes:
        for g in (train.meshes[k].a, train.meshes[k].b):
            if g not in gears:
                gears.append(g)
    return "-".join(gears + ([carrier] if carrier is not None and carrier not in gears else []))


def split(train: GearTrain) -> Split:
    """The basic trains of ``train`` and how they join (not yet solved: :func:`solve`)."""
    order = {m.name: k for k, m in enumerate(train.members)}
    by_frame: dict[str | None, list[int]] = {}
    for k, m in enumerate(train.meshes):
        by_frame.setdefault(train.mesh_frame(m), []).append(k)
    basics: list[BasicTrain] = []
    loops: list[tuple[BasicTrain, int]] = []
    for h in train.carriers:
        for ks in _components(train, by_frame.get(h, [])):
            members = sorted({train.gear(g).member for k in ks for g in (train.meshes[k].a, train.meshes[k].b)},
                             key=order.__getitem__)
            planets = tuple(x for x in members if train.member(x).carrier == h)
            centrals = tuple(x for x in members if x not in planets)
            if not centrals:
                raise OutOfDomain(f"the planets of carrier {h} mesh no central gear: nothing turns them")
            root = centrals[0]
            ratio, same, contra = _path_ratios(train, h, ks, root)
            kind: BasicKind = "planetary" if any(c in train.fixed for c in centrals) else "differential"
            bt = BasicTrain(kind, h, root, (*centrals, *planets, h), planets, centrals, tuple(ks), len(same),
                            tuple(Ratio(root, x, r, h, dn, dg) for x, (r, dn, dg) in ratio.items() if x != root),
                            _label(train, ks, h))
            basics.append(bt)
            loops += [(bt, k) for k in contra]
    for ks in _components(train, by_frame.get(None, [])):
        members = sorted({train.gear(g).member for k in ks for g in (train.meshes[k].a, train.meshes[k].b)},
                         key=order.__getitem__)
        root = members[0]
        ratio, same, contra = _path_ratios(train, None, ks, root)
        bt = BasicTrain("ordinary", None, root, tuple(members), (), (), tuple(ks), len(same),
                        tuple(Ratio(root, x, r, None, dn, dg) for x, (r, dn, dg) in ratio.items() if x != root),
                        _label(train, ks, None))
        basics.append(bt)
        loops += [(bt, k) for k in contra]

    basics = [_with_names(train, b, basics) for b in basics]
    loops = [(_with_names(train, b, basics), k) for b, k in loops]
    # every member's speed from the unknowns: an ordinary chain's root speed gives its members'
    forms: dict[str, Form] = {}
    for bt in basics:
        if bt.carrier is None:
            forms[bt.root] = {bt.root: Fraction(1)}
            for r in bt.ratios:
                forms[r.b] = {bt.root: 1 / r.value}  # n_x = n_root/i_root,x
    for member in train.members:
        if member.carrier is None and member.name not in forms:
            forms[member.name] = {member.name: Fraction(1)}
    equations: list[Form] = []
    for bt in basics:
        if bt.carrier is None:
            continue
        nh = forms[bt.carrier]
        for r in bt.ratios:
            if r.b in bt.centrals:  # Willis: (n_r − n_H) − i^H_rb (n_b − n_H) = 0
                equations.append(_combine((1, forms[bt.root]), (-r.value, forms[r.b]), (r.value - 1, nh)))
    for bt, _k in loops:  # a loop whose ratios disagree holds its root to its frame (cannot turn)
        equations.append(_combine((1, forms[bt.root]), (-1, forms[bt.carrier] if bt.carrier else {})))
    equations += [dict(forms[f]) for f in train.fixed]
    unknowns = sorted({p for f in forms.values() for p in f}, key=order.__getitem__)
    rank = len(_reduce(equations, unknowns)[0])
    links = _links(train, basics)
    redundant = sum(b.redundant for b in basics)
    return Split(train, tuple(basics), tuple(links), len(unknowns) - rank, redundant, forms, tuple(equations))


def _with_names(train: GearTrain, bt: BasicTrain, basics: Sequence[BasicTrain]) -> BasicTrain:
    """``bt`` with the gear name of each member in its meshes and the members whose ratio is shown."""
    names: dict[str, str] = {}
    degree: dict[str, int] = {}
    for k in bt.meshes:
        for g in (train.meshes[k].a, train.meshes[k].b):
            member = train.gear(g).member
            names.setdefault(member, g)
            degree[member] = degree.get(member, 0) + 1
    if bt.carrier is not None:
        shown = bt.centrals
    else:
        others = {x for b in basics if b is not bt and b.label != bt.label for x in b.members}
        shown = tuple(x for x in bt.members
                      if x in others or x in train.fixed or x in train.inputs or degree.get(x, 0) == 1)
    return replace(bt, names=names, shown=tuple(x for x in shown if x != bt.root))


def _combine(*terms: tuple[Fraction | int, Form]) -> Form:
    out: Form = {}
    for c, f in terms:
        for p, v in f.items():
            out[p] = out.get(p, Fraction(0)) + c * v
    return {p: v for p, v in out.items() if v != 0}


def _reduce(rows: Sequence[Form], unknowns: Sequence[str]) -> tuple[dict[str, Form], bool]:
    """Substitution, one unknown after another (the rows' ``CONST`` entry is the right-hand side
    moved left): pivot → its row solved for it; and whether the rows agree."""
    done: dict[str, Form] = {}
    ok = True
    for row in rows:
        row = dict(row)
        for p, sol in done.items():  # put in what is known
            c = row.pop(p, None)
            if c:
                for q, v in sol.items():
                    row[q] = row.get(q, Fraction(0)) + c * v
        row = {q: v for q, v in row.items() if v != 0}
        free = [q for q in unknowns if q in row]
        if not free:
            ok = ok and not row.get(CONST)
            continue
        p = free[0]
        c = row.pop(p)
        sol = {q: -v / c for q, v in row.items()}  # p = −Σ(v/c)·q
        for q, s in done.items():
            d = s.pop(p, None)
            if d:
                for r, v in sol.items():
                    s[r] = s.get(r, Fraction(0)) + d * v
                done[q] = {r: v for r, v in s.items() if v != 0}
        done[p] = sol
    return done, ok


def _links(train: GearTrain, basics: Sequence[BasicTrain]) -> list[str]:
    """The connecting conditions: members in two basic trains (n4 = n5), carriers in another train."""
    out = []
    for m in train.members:
        where = [b for b in basics if m.name in b.members]
        if len(where) < 2:
            continue
        gears = []
        for b in where:
            for k in b.meshes:
                for g in (train.meshes[k].a, train.meshes[k].b):
                    if train.gear(g).member == m.name and g not in gears:
                        gears.append(g)
        roles = ", ".join(b.label for b in where)
        names = list(dict.fromkeys(gears + ([m.name] if any(b.carrier == m.name for b in where) else [])))
        same = " = ".join(f"n{g}" for g in names) if len(names) > 1 else f"n{m.name}"
        out.append(f"{same}: member {m.name} is in {roles}")
    return out


@dataclass(frozen=True)
class SplitSolution:
    """Every member's speed (the inputs' unit: rad/s or r/min alike), as fractions and floats."""

    split: Split
    exact_speeds: Mapping[str, Fraction]

    @property
    def speeds(self) -> dict[str, float]:
        return {k: float(v) for k, v in self.exact_speeds.items()}

    def speed(self, name: str) -> float:
        return float(self.exact_speeds[self.split.train.member_of(name)])


def solve(train: GearTrain, the_split: Split | None = None) -> SplitSolution:
    """Solve the basic trains together: the fixed members, the inputs, Willis' equations."""
    sp = the_split if the_split is not None else split(train)
    f = sp.mobility
    if len(train.inputs) != f:
        raise OutOfDomain(f"the split gives mobility {f} but {len(train.inputs)} "
                          f"input{'s' if len(train.inputs) != 1 else ''} {'are' if len(train.inputs) != 1 else 'is'}"
                          " given")
    order = {m.name: k for k, m in enumerate(train.members)}
    unknowns = sorted({p for fm in sp.forms.values() for p in fm}, key=order.__getitem__)
    base, _ = _reduce(sp.equations, unknowns)
    for name in train.inputs:
        form = _substitute(sp.forms[name], base)
        if not any(p != CONST for p in form):
            raise NoSolution(f"the train locks: its meshes{' and fixed members' if train.fixed else ''} hold {name} "
                             f"at rest{_lock_words(sp, name)}, so it cannot be driven")
    rows = list(sp.equations) + [_combine((1, sp.forms[k]), (-Fraction(w), {CONST: Fraction(1)}))
                                 for k, w in train.inputs.items()]
    done, ok = _reduce(rows, unknowns)
    if not ok or len(done) < len(unknowns):
        raise NoSolution(f"the inputs ({', '.join(train.inputs)}) do not fix every speed: one follows from the "
                         "others through the basic trains")
    speeds: dict[str, Fraction] = {}
    for m in train.members:
        if m.carrier is None:
            speeds[m.name] = _substitute(sp.forms[m.name], done).get(CONST, Fraction(0))
    for bt in sp.trains:  # a planet: n_p = n_H + (n_root − n_H)/i^H_root,p
        if bt.carrier is None:
            continue
        nh, nr = speeds[bt.carrier], speeds[bt.root]
        for r in bt.ratios:
            if r.b in bt.planets:
                speeds[r.b] = nh + (nr - nh) / r.value
    return SplitSolution(sp, speeds)


def _substitute(form: Form, known: Mapping[str, Form]) -> Form:
    out: Form = {}
    for p, c in form.items():
        for q, v in (known[p].items() if p in known else [(p, Fraction(1))]):
            out[q] = out.get(q, Fraction(0)) + c * v
    return {q: v for q, v in out.items() if v != 0}


def _lock_words(sp: Split, name: str) -> str:
    """``(i^H_1,3 = 1 with 3 fixed)`` when a converted ratio of 1 is why."""
    for bt in sp.trains:
        if bt.carrier is None or name not in bt.centrals:
            continue
        for c in bt.centrals:
            if c != name and c in sp.train.fixed and sp.converted_ratio(name, c, bt.carrier) == 1:
                return f" (the converted ratio i^{bt.carrier}_{name},{c} = 1 with {c} fixed)"
    return ""


__all__ = ["BasicTrain", "Ratio", "Split", "SplitSolution", "solve", "split"]
