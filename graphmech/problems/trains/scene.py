"""Read a gear-train scene (``[train]``) into a :class:`TrainScene`: the model
(:class:`graphmech.mechanisms.gear_train.GearTrain`, spatial meshes' senses resolved from the
arrows), and what the drawing needs (the module, each member's axis, the sides and ``towards`` of
the meshes). The keys: docs/scene-format.md, "Gear-train scenes".
"""
from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from graphmech.errors import GraphmechError, OutOfDomain
from graphmech.mechanisms.gear_train import (
    AXES,
    HANDS,
    MESH_KINDS,
    PARALLEL_SIGN,
    Gear,
    GearTrain,
    Member,
    Mesh,
)
from graphmech.methods.train_coaxial import ArmMesh, arms, solve_missing
from graphmech.methods.train_senses import bevel_sign, parallel_sign, worm_sign
from graphmech.methods.train_split import split
from graphmech.problems.trains.dynamics import check_dynamics, is_dynamics_name, read_dynamics
from graphmech.problems.reader import (
    MISSING,
    Reader,
    maybe,
    one_of,
    pole_distances,
    say,
    type_name,
)

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene
    from graphmech.problems.trains.dynamics import TrainDynamics

#: What a gear-train scene may show.
TRAIN_SHOW_CHOICES = ("schematic", "velocity")
#: A gear's or member's name: the book's, primes allowed (``2'``, ``H1``).
GEAR_NAME = re.compile(r"[0-9A-Za-z]{1,8}['′]{0,3}")
#: The largest tooth number (the gear kind's bound).
MAX_Z = 100_000
#: The module's sane range, m (the gear kind's).
MODULE_RANGE = (1e-6, 10.0)
#: The most values of a list input.
MAX_LIST = 100
#: The work limit: the most gears and meshes of one train (the book's largest has 12 gears). The
#: exact elimination and the split grow with the cube of the members, the sheet's labels faster:
#: 60 gears check in under a second and render in a few.
MAX_GEARS = 60
MAX_MESHES = 120
#: The largest input speed, rad/s: beyond it the reduced moments and the powers leave double
#: precision (ω², M·ω), and no machine turns so fast.
MAX_SPEED = 1e12
#: The slowest input speed that is not 0, rad/s: below it the speeds through a train of 10⁶ run
#: into the subnormal numbers, where a ratio keeps few digits.
MIN_SPEED = 1e-200
SPEED_UNITS = {"rpm": " r/min", "rad_s": " rad/s"}
#: A mobility in words.
MOBILITY_WORDS = {0: "it cannot move", 1: "planetary or ordinary: one input", 2: "a differential: two inputs"}


@dataclass(frozen=True)
class TrainScene:
    """A ``[train]`` table in SI.

    train : the model; its ``inputs`` hold the first value of each input (a list input's others
        are in ``input_values``), spatial meshes' ``sign`` resolved from ``towards`` and ``hand``.
    module : m in metres (1 mm when not stated: ``module_stated`` False, radii in module units).
    axes : member → its axis in the drawing (``"+x"`` … ``"-z"``), every member listed.
    sides : mesh index → +1 (b's axis above a's, the default) or −1 (below); parallel meshes only.
    towards : mesh index → the directions from a's and b's axes to the pitch point (spatial meshes
        that state them).
    hands : mesh index → ``"right"`` or ``"left"`` (worm meshes).
    coaxial : pairs of members the scene puts on one axis although no mesh says so.
    solved_z : gear → the tooth number solved from the coaxial condition (``"coaxial"`` in ``z``).
    input_values : member → every value of its input speed (rad/s); one value unless a list.
    stated_mobility : the ``mobility`` the scene expects (None: not stated).
    pole_distance : H of the velocity diagram's ω line in drawing mm (None: chosen).
    dynamics : the dynamics and efficiency tables (None: not posed; [train.dynamics] and
        [train.efficiency] are read by problems/trains/dynamics.py).
    coaxial_sets : gear of ``solved_z`` → the meshes that closed it, (z_central, z_planet, kind)
        with None for the missing number (what exact.gear_train.coaxial_tooth_number takes);
        coaxial_equations the book's equation for it (``z3 = z1 + 2·z2 = 74``).
    coaxial_notes : planet sets (or coaxial pairs) whose arms differ with one module, said.
    """

    train: GearTrain
    module: float = 1e-3
    module_stated: bool = False
    axes: Mapping[str, str] = field(default_factory=dict)
    sides: Mapping[int, int] = field(default_factory=dict)
    towards: Mapping[int, tuple[str, str]] = field(default_factory=dict)
    hands: Mapping[int, str] = field(default_factory=dict)
    coaxial: tuple[tuple[str, str], ...] = ()
    solved_z: Mapping[str, int] = field(default_factory=dict)
    input_values: Mapping[str, tuple[float, ...]] = field(default_factory=dict)
    stated_mobility: int | None = None
    pole_distance: float | None = None
    dynamics: TrainDynamics | None = None
    coaxial_notes: tuple[str, ...] = ()
    coaxial_sets: Mapping[str, tuple[tuple[int | None, int | None, str], ...]] = field(default_factory=dict)
    coaxial_equations: Mapping[str, str] = field(default_factory=dict)
    gear_modules: Mapping[str, float] = field(default_factory=dict)

    @property
    def parallel(self) -> bool:
        """Every axis drawn horizontal (±x) and no bevel or worm mesh: the velocity diagram applies."""
        return (all(a in ("+x", "-x") for a in self.axes.values())
                and all(m.kind in ("external", "internal") for m in self.train.meshes))


def parse_train_scene(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[TrainScene]:
    """The whole scene file, ``[train]`` and the common tables (docs/scene-format.md).

    Examples
    --------
    >>> from graphmech.scene import parse_scene
    >>> s = parse_scene({"train": {"z": {"1": 20, "2": 40}, "mesh": [{"gears": ["1", "2"]}],
    ...                            "input": [{"member": "1", "speed_rpm": 100}]}}, "t.toml")
    >>> s.kind, s.problem.train.meshes[0].relative_sign, s.show
    ('trains', -1, ('schematic', 'velocity'))
    """
    from graphmech.problems.reader import (
        Scene,
        raise_sorted,
        read_header,
        read_measured,
        read_scales,
        read_tail,
    )
    from graphmech.problems.trains.names import parse_name

    title, show, find = read_header(top, TRAIN_SHOW_CHOICES, ())
    scales = read_scales(top, entries=(("l", "length"), ("v", "velocity"), ("omega", "omega")))
    t = top.table_at("train", required=True)
    problem = None if t is None else _read_train(t)
    if problem is not None:
        count = max((len(v) for v in problem.input_values.values()), default=1)
        for i, name in enumerate(find):
            if is_dynamics_name(name):  # answered by [train.dynamics] / [train.efficiency] (their rows check it)
                if problem.dynamics is None:
                    top.problem(f"find[{i}]", f"{name} needs [train.dynamics] or [train.efficiency]")
                continue
            try:
                parse_name(name, problem.train, problem.solved_z, count)
            except GraphmechError as e:
                top.problem(f"find[{i}]", str(e))
        if not show and "show" not in data:
            show = TRAIN_SHOW_CHOICES if problem.parallel else ("schematic",)
    measured = read_measured(top, None, cam=False)
    precision, page = read_tail(top)
    if top.problems or problem is None:
        raise_sorted(top.problems, data, order, "train", source)
    return Scene(source=source, title=title, show=show, find=find, scales=scales, measured=measured,
                 precision_mm=precision, page=page, kind="trains", problem=problem)


def _name(r: Reader, value: object, path: str, what: str = "a gear name") -> str | None:
    """A gear's or member's name as the book writes it (``"2'"``, ``"H1"``)."""
    if isinstance(value, int) and not isinstance(value, bool) and 0 <= value < 10**8:
        return str(value)
    if isinstance(value, str) and GEAR_NAME.fullmatch(value):
        return value
    r.problem(path, f"must be {what} such as \"2\", \"2'\" or \"H\", not "
                    + (say(value) if isinstance(value, str) else type_name(value)))
    return None


def _read_train(t: Reader) -> TrainScene | None:
    bad = len(t.problems)
    zs: dict[str, int | None] = {}
    coax_z: list[str] = []
    zt = t.table_at("z", required=True, hint='a table of tooth numbers, z = { "1" = 20, "2" = 40 }')
    if zt is not None:
        for key, value in zt.table.items():
            zt.used.add(key)
            path = zt.at(key)
            if _name(zt, key, path) is None:
                continue
            if value == "coaxial":
                zs[key] = None
                coax_z.append(key)
            elif isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= MAX_Z:
                zt.problem(path, f"must be a whole number of teeth 1 … {MAX_Z} (a worm: its starts) or \"coaxial\", "
                                 f"not {say(value) if isinstance(value, str) else value if isinstance(value, (int, float)) and not isinstance(value, bool) else type_name(value)}")
            else:
                zs[key] = value
        if not zt.table:
            zt.problem(zt.path, "no gears: give each gear's tooth number")
        elif len(zt.table) > MAX_GEARS:
            zt.problem(zt.path, f"too many gears ({len(zt.table)} > {MAX_GEARS}, the work limit of a train)")
            return None
    module = 1e-3
    m = t.value("m", "length", required=False, positive=True)
    if m is not None and not MODULE_RANGE[0] <= m.si <= MODULE_RANGE[1]:
        t.problem(m.path, f"{m.text()} is no module (between {MODULE_RANGE[0] * 1e3:g} and {MODULE_RANGE[1] * 1e3:g} mm)")
    elif m is not None:
        module = m.si

    # members: declared ones, then every gear left as a member of its own name
    member_of: dict[str, str] = {}
    members: dict[str, tuple[str | None, str]] = {}  # name → (carrier, axis)
    carriers_at: dict[str, str] = {}
    for mr in t.tables_at("member"):
        name = _name(mr, mr.raw("name", required=True), mr.at("name"), "a member name")
        gears_v = mr.raw("gears")
        carrier = mr.raw("carrier")
        axis = mr.string("axis", choices=tuple(AXES), default="+x") or "+x"
        mr.finish()
        if name is None:
            continue
        if name in members:
            mr.problem(mr.at("name"), f"member {name} is declared twice")
            continue
        gear_list: list[str] = []
        if gears_v is MISSING:
            if name not in zs:
                mr.problem(mr.at("name"), f"no gear {name} in train.z: list the gears cut on it (gears = [...]), "
                                          "or gears = [] for a bare carrier")
                continue
            gear_list = [name]
        elif not isinstance(gears_v, list):
            mr.problem(mr.at("gears"), f"must be a list of gear names, not {type_name(gears_v)}")
            continue
        else:
            for i, g in enumerate(gears_v):
                gn = _name(mr, g, f"{mr.at('gears')}[{i}]")
                if gn is None:
                    continue
                if gn not in zs:
                    mr.problem(f"{mr.at('gears')}[{i}]", f"no gear {gn} in train.z" + maybe(gn, zs))
                elif gn in member_of:
                    mr.problem(f"{mr.at('gears')}[{i}]", f"gear {gn} is already on member {member_of[gn]}")
                else:
                    gear_list.append(gn)
        for g in gear_list:
            member_of[g] = name
        cname = None
        if carrier is not MISSING:
            cname = _name(mr, carrier, mr.at("carrier"), "a carrier's member name")
            if cname is not None:
                carriers_at[name] = mr.at("carrier")
        members[name] = (cname, axis)
    for g in zs:
        if g not in member_of:
            if g in members:
                t.problem(f"train.z.{g}" if not t.path else f"{t.path}.z.{g}",
                          f"gear {g} is on no member, and member {g} is declared without it: add it to its gears")
                continue
            member_of[g] = g
            members[g] = (None, "+x")
    for name, path in carriers_at.items():
        c = members[name][0]
        if c is not None and (c not in members or c == name):
            t.problem(path, f"{c!r} is not another member" + maybe(c, [k for k in members if k != name]))

    def member_name(value: object, path: str) -> str | None:
        n = _name(t, value, path, "a member or gear name")
        if n is None:
            return None
        if n in members:
            return n
        if n in member_of:
            return member_of[n]
        t.problem(path, f"no member or gear {n}" + maybe(n, [*members, *member_of]))
        return None

    fixed: list[str] = []
    fv = t.raw("fixed")
    if fv is not MISSING:
        if not isinstance(fv, list):
            t.problem(t.at("fixed"), f"must be a list of members, not {type_name(fv)}")
        else:
            for i, v in enumerate(fv):
                n = member_name(v, f"{t.at('fixed')}[{i}]")
                if n is not None and members[n][0] is not None:
                    t.problem(f"{t.at('fixed')}[{i}]", f"member {n} is a planet of {members[n][0]}: its axis moves "
                                                       "with the carrier, it cannot be held in the frame")
                elif n is not None and n in fixed:
                    t.problem(f"{t.at('fixed')}[{i}]", f"member {n} is listed twice")
                elif n is not None:
                    fixed.append(n)

    # meshes, their senses from the arrows
    meshes: list[Mesh] = []
    sides: dict[int, int] = {}
    towards_d: dict[int, tuple[str, str]] = {}
    hands: dict[int, str] = {}
    gear_modules: dict[str, float] = {}
    items = t.tables_at("mesh")
    if not items and (t.table.get("mesh", []) == []):
        t.problem(t.at("mesh"), "no [[train.mesh]]: a train needs its meshes")
    elif len(items) > MAX_MESHES:
        t.problem(t.at("mesh"), f"too many meshes ({len(items)} > {MAX_MESHES}, the work limit of a train)")
        return None
    if len(t.tables_at("member")) > MAX_GEARS:
        t.problem(t.at("member"), f"too many members ({len(t.tables_at('member'))} > {MAX_GEARS}, the work limit "
                                  "of a train)")
        return None
    meshed: dict[frozenset[str], int] = {}
    for k, mr in enumerate(items):
        pair = mr.raw("gears", required=True, hint='gears = ["1", "2"]')
        kind = mr.string("kind", choices=MESH_KINDS, default="external") or "external"
        hand = mr.string("hand", choices=tuple(HANDS))
        side = mr.string("side", choices=("above", "below"))
        tw = mr.raw("towards")
        sign = mr.raw("sign")
        mesh_m = mr.value("m", "length", required=False, positive=True)
        mr.finish()
        if pair is MISSING:
            continue
        if not isinstance(pair, list) or len(pair) != 2:
            mr.problem(mr.at("gears"), "must be [a, b]: a list of two gear names")
            continue
        ab = [_name(mr, g, f"{mr.at('gears')}[{i}]") for i, g in enumerate(pair)]
        if ab[0] is None or ab[1] is None:
            continue
        a, b = ab[0], ab[1]
        missing = [g for g in (a, b) if g not in zs]
        if missing:
            mr.problem(mr.at("gears"), f"no gear {missing[0]} in train.z" + maybe(missing[0], zs))
            continue
        if a not in member_of or b not in member_of:  # its gear is on no member: said at train.z
            continue
        if frozenset((a, b)) in meshed and a != b:  # two gears mesh once (identical planets are other gears)
            mr.problem(mr.at("gears"), f"gears {a} and {b} already mesh in {t.at('mesh')}[{meshed[frozenset((a, b))]}]")
            continue
        meshed[frozenset((a, b))] = k
        pa, pb = (members.get(member_of[g], (None, ""))[0] for g in (a, b))
        if pa is not None and pa == member_of[b] or pb is not None and pb == member_of[a]:
            planet, on = (a, b) if pa is not None and pa == member_of[b] else (b, a)
            mr.problem(mr.at("gears"), f"gear {on} is on {member_of[planet]}'s own carrier {member_of[on]}: a planet "
                                       "meshes a gear coaxial with its carrier, not one on its arm")
            continue
        spatial = kind in ("bevel", "worm")
        if hand is not None and kind != "worm":
            mr.problem(mr.at("hand"), f"a hand is a worm's: this mesh is {kind}")
        if side is not None and spatial:
            mr.problem(mr.at("side"), f"a side is for parallel axes; a {kind} pair gives towards")
        if not spatial and (tw is not MISSING or sign is not MISSING):
            key = "towards" if tw is not MISSING else "sign"
            mr.problem(mr.at(key), f"an {kind} mesh's sense comes from its kind: no {key}")
            continue
        if tw is not MISSING and sign is not MISSING:
            mr.problem(mr.at("sign"), "towards and sign together: the arrows give the sign (sign only where the "
                                      "figure is missing)")
            continue
        axis_a, axis_b = members[member_of[a]][1], members[member_of[b]][1]
        s: int | None = None
        try:
            if not spatial:
                s = parallel_sign(kind, axis_a, axis_b, a, b)
                s = None if s == PARALLEL_SIGN[kind] else s
                sides[k] = -1 if side == "below" else +1
            elif sign is not MISSING:
                if sign not in (1, -1) or isinstance(sign, bool):
                    mr.problem(mr.at("sign"), f"must be +1 or −1, not {say(sign) if isinstance(sign, str) else sign!r}")
                    continue
                s = int(sign)
            elif tw is MISSING:
                mr.problem(mr.at("towards"), f"missing: a {kind} mesh's sense comes from the arrows: towards = "
                                             "[from a's axis, from b's axis] (or sign = ±1 where the figure is missing)")
                continue
            else:
                if (not isinstance(tw, list) or len(tw) != 2
                        or not all(isinstance(x, str) and x in AXES for x in tw)):
                    mr.problem(mr.at("towards"), f"must be two directions from {one_of(AXES)}, as [\"-y\", \"+x\"]")
                    continue
                pair_t = (str(tw[0]), str(tw[1]))
                if kind == "worm" and hand is None:
                    mr.problem(mr.at("hand"), 'missing: a worm\'s sense needs its hand, "right" or "left"')
                    continue
                s = (bevel_sign(axis_a, axis_b, pair_t, a, b) if kind == "bevel"
                     else worm_sign(axis_a, axis_b, pair_t, hand or "right", a, b))
                towards_d[k] = pair_t
            if hand is not None:
                hands[k] = hand
        except OutOfDomain as e:
            mr.problem(mr.at("towards") if tw is not MISSING else mr.at("kind"), str(e))
            continue
        if mesh_m is not None:  # the stage's module: both gears cut with it
            if not MODULE_RANGE[0] <= mesh_m.si <= MODULE_RANGE[1]:
                mr.problem(mesh_m.path, f"{mesh_m.text()} is no module (between {MODULE_RANGE[0] * 1e3:g} and "
                                        f"{MODULE_RANGE[1] * 1e3:g} mm)")
                continue
            clash = [g for g in (a, b) if g in gear_modules and gear_modules[g] != mesh_m.si]
            if clash:
                mr.problem(mesh_m.path, f"gear {clash[0]} meshes elsewhere at m = {gear_modules[clash[0]] * 1e3:g} mm: "
                                        "a gear has one module")
                continue
            gear_modules.update({a: mesh_m.si, b: mesh_m.si})
        # the arrows' sign for the book's method; the geometry too, for the exact solution's own
        meshes.append(Mesh(a, b, kind, s, towards_d.get(k), hand))  # type: ignore[arg-type]  # one of MESH_KINDS

    # inputs
    inputs: dict[str, tuple[float, ...]] = {}
    listed = 0
    for ir in t.tables_at("input"):
        given_member = ir.raw("member", required=True)
        who = None if given_member is MISSING else member_name(given_member, ir.at("member"))
        given = ir.quantity("speed", "omega", required=True)
        ir.finish()
        if given is None:
            continue
        path = ir.at(given.key)
        values: list[float] | None
        if isinstance(given.value, list):
            listed += 1
            if listed > 1:
                ir.problem(path, "at most one input has a list of speeds")
                continue
            if not 1 <= len(given.value) <= MAX_LIST:
                ir.problem(path, f"a list of 1 … {MAX_LIST} speeds, not {len(given.value)}")
                continue
            xs = [ir.number(v, f"{path}[{i}]") for i, v in enumerate(given.value)]
            values = None if any(x is None for x in xs) else [given.si(x) for x in xs if x is not None]
        else:
            x = ir.number(given.value, path)
            values = None if x is None else [given.si(x)]
        if values is None or who is None:
            continue
        raw = given.value if isinstance(given.value, list) else [given.value]
        fast = next((i for i, v in enumerate(values) if not abs(v) <= MAX_SPEED), None)  # inf: an overflow of the unit
        if fast is not None:
            ir.problem(path + (f"[{fast}]" if isinstance(given.value, list) else ""),
                       f"{float(raw[fast]):g}{SPEED_UNITS.get(given.key.removeprefix('speed_'), '')} is faster than the work limit of {MAX_SPEED:g} rad/s (the powers and "
                       "reduced moments would leave double precision)")
            continue
        slow = next((i for i, v in enumerate(values) if 0.0 < abs(v) < MIN_SPEED), None)
        if slow is not None:
            ir.problem(path + (f"[{slow}]" if isinstance(given.value, list) else ""),
                       f"{float(raw[slow]):g}{SPEED_UNITS.get(given.key.removeprefix('speed_'), '')} is slower than "
                       f"{MIN_SPEED:g} rad/s: the train's speeds would underflow double precision (0 is at rest)")
            continue
        if members[who][0] is not None:
            ir.problem(ir.at("member"), f"member {who} is a planet of {members[who][0]}: drive its carrier or a "
                                        "central gear")
        elif who in inputs:
            ir.problem(ir.at("member"), f"member {who} is driven twice")
        elif who in fixed:
            ir.problem(ir.at("member"), f"member {who} is fixed (train.fixed): it cannot be driven")
        else:
            inputs[who] = tuple(values)

    stated = None
    mv = t.raw("mobility")
    if mv is not MISSING:
        if isinstance(mv, bool) or not isinstance(mv, int) or not 0 <= mv <= 10:
            t.problem(t.at("mobility"), "must be a whole number: 1 (planetary or ordinary) or 2 (a differential)")
        else:
            stated = mv
    coaxial: list[tuple[str, str]] = []
    cv = t.raw("coaxial")
    if cv is not MISSING:
        if not isinstance(cv, list):
            t.problem(t.at("coaxial"), 'must be a list of pairs of members, as [["1", "3"]]')
        else:
            for i, pv in enumerate(cv):
                if not isinstance(pv, list) or len(pv) != 2:
                    t.problem(f"{t.at('coaxial')}[{i}]", 'must be a pair of members, as ["1", "3"]')
                    continue
                got = [member_name(x, f"{t.at('coaxial')}[{i}][{j}]") for j, x in enumerate(pv)]
                if got[0] is not None and got[1] is not None:
                    if got[0] == got[1]:
                        t.problem(f"{t.at('coaxial')}[{i}]", f"a pair of two members, not {got[0]} twice")
                    elif {got[0], got[1]} in [set(c) for c in coaxial]:
                        t.problem(f"{t.at('coaxial')}[{i}]", f"{got[0]} and {got[1]} are listed twice")
                    else:
                        coaxial.append((got[0], got[1]))
    poles = pole_distances(t)
    dyn = read_dynamics(t)
    t.finish()
    if len(t.problems) > bad:
        return None

    # the model; the missing tooth numbers from the coaxial condition
    planet_of = {name: c for name, (c, _) in members.items()}
    solved: dict[str, int] = {}
    solved_sets: dict[str, tuple[tuple[int | None, int | None, str], ...]] = {}
    equations: dict[str, str] = {}
    for g in coax_z:
        sets = _arm_sets(g, meshes, member_of, planet_of, zs, coaxial)
        if not sets:
            t.problem(f"{t.at('z')}.{g}", f'"coaxial" needs a planet set to close: gear {g} meshes no planet'
                      + (" (or a coaxial pair's countershaft)" if coaxial else ""))
            continue
        stage_m = {gear_modules.get(a.central, module) for a in sets[0]}
        if len(stage_m) > 1:  # the book's z3 = z1 + 2·z2 is the arms' equality in one module
            t.problem(f"{t.at('z')}.{g}", f'"coaxial" solves with one module: the meshes of its planet set are cut '
                                          f"at {' and '.join(f'{x * 1e3:g} mm' for x in sorted(stage_m))}")
            continue
        try:
            solved[g], equations[g] = solve_missing(g, sets[0])
            solved_sets[g] = tuple((a.z_central, a.z_planet, a.kind) for a in sets[0])
        except GraphmechError as e:
            t.problem(f"{t.at('z')}.{g}", str(e))
    if len(t.problems) > bad:
        return None
    zfull = {g: (z if z is not None else solved[g]) for g, z in zs.items()}
    notes = [note for sets in _all_arm_sets(meshes, member_of, planet_of, zfull, coaxial)
             for note in _not_coaxial(sets, {g: gear_modules.get(g, module) for g in zfull}, module)]
    # the members in the order of their first gear in train.z (bare carriers last): the book's
    # basic trains start from the lowest-numbered gear whatever order the members were declared in
    first = {g: k for k, g in enumerate(zs)}
    rank = {n: min((first[g] for g, mm in member_of.items() if mm == n), default=len(first)) for n in members}
    members = dict(sorted(members.items(), key=lambda kv: rank[kv[0]]))
    try:
        train = GearTrain(tuple(Member(n, c, ax) for n, (c, ax) in members.items()),
                          tuple(Gear(g, z, member_of[g]) for g, z in zfull.items()), tuple(meshes), tuple(fixed),
                          {k: v[0] for k, v in inputs.items()})
        the_split = split(train)
    except GraphmechError as e:
        t.problem(t.path, str(e))
        return None
    f = the_split.mobility
    if stated is not None and stated != f:
        t.problem(t.at("mobility"), f"the meshes give mobility {f} ({MOBILITY_WORDS.get(f, f'{f} inputs')}), "
                                    f"not {stated}")
        return None
    if len(inputs) != f:
        given_n = len(inputs)
        t.problem(t.at("input"), f"the train has mobility {f} ({MOBILITY_WORDS.get(f, f'{f} inputs')}) but "
                                 f"{given_n} input{'' if given_n == 1 else 's'} {'is' if given_n == 1 else 'are'} given")
        return None
    if dyn is not None:
        check_dynamics(dyn, train, t.problems, t.path or "train")
        if len(t.problems) > bad:
            return None
    axes = {n: ax for n, (_, ax) in members.items()}
    return TrainScene(train, module, m is not None, axes, sides, towards_d, hands, tuple(coaxial), solved, inputs,
                      stated, None if poles is None else poles[0], dyn, tuple(notes), solved_sets, equations,
                      gear_modules)


def _all_arm_sets(meshes: Sequence[Mesh], member_of: Mapping[str, str], planet_of: Mapping[str, str | None],
                  zs: Mapping[str, int | None], coaxial: Sequence[tuple[str, str]]) -> list[list[ArmMesh]]:
    """The meshes that must share one arm: each planet's with its central gears, and each coaxial
    pair's with the countershaft between them (external and internal meshes only)."""
    out: list[list[ArmMesh]] = []
    parallel = [m for m in meshes if m.kind in ("external", "internal")]
    for p in dict.fromkeys(planet_of):
        if planet_of[p] is None:
            continue
        arms = []
        for m in parallel:
            ma, mb = member_of[m.a], member_of[m.b]
            if p in (ma, mb) and planet_of[mb if ma == p else ma] is None:
                pg, cg = (m.a, m.b) if ma == p else (m.b, m.a)
                arms.append(ArmMesh(cg, zs[cg], pg, zs[pg], m.kind))
        if len(arms) >= 2:
            out.append(arms)
    for x, y in coaxial:
        for w in dict.fromkeys(member_of.values()):
            if w in (x, y) or planet_of.get(w) is not None:
                continue
            legs = []
            for end in (x, y):
                leg = next((m for m in parallel if {member_of[m.a], member_of[m.b]} == {end, w}), None)
                if leg is not None:
                    wg, eg = (leg.a, leg.b) if member_of[leg.a] == w else (leg.b, leg.a)
                    legs.append(ArmMesh(eg, zs[eg], wg, zs[wg], leg.kind))
            if len(legs) == 2:
                out.append(legs)
    return out


def _arm_sets(gear: str, meshes: Sequence[Mesh], member_of: Mapping[str, str],
              planet_of: Mapping[str, str | None], zs: Mapping[str, int | None],
              coaxial: Sequence[tuple[str, str]]) -> list[list[ArmMesh]]:
    """The sets of :func:`_all_arm_sets` that hold ``gear``."""
    return [s for s in _all_arm_sets(meshes, member_of, planet_of, zs, coaxial)
            if any(gear in (a.central, a.planet) for a in s)]


def _not_coaxial(arm_set: Sequence[ArmMesh], module_of: Mapping[str, float], module: float) -> list[str]:
    """A line when the set's arms differ: in module units with one module (the book's modules then
    differ), in mm where the meshes state their modules."""
    values = arms(arm_set)
    ms = [module_of[a.central] for a in arm_set]
    if len(set(ms)) == 1 and ms[0] == module:
        if len(set(values)) == 1:
            return []
        said = ", ".join(f"{a.text()} = {float(v):g}" for a, v in zip(arm_set, values))
        return [f"not coaxial with one module: {said} module units (the gears' modules must differ)"]
    mm = [float(v) * m * 1e3 for v, m in zip(values, ms)]
    if max(mm) - min(mm) <= 1e-9 * max(mm):
        return []
    said = ", ".join(f"{a.text()}·m = {x:g} mm" for a, x in zip(arm_set, mm))
    return [f"not coaxial with the meshes' modules: {said}"]
