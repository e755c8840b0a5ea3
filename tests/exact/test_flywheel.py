"""The exact reduced machine (exact/flywheel.py): reference problems, identities, conventions, errors."""
from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np
import pytest
from scipy.integrate import quad

from graphmech.problems.flywheel.bench import compressor_machine
from graphmech.exact.flywheel import ExactMachine, Extremes, table_line, table_value
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage, LinkPoint
from graphmech.mechanisms.machine import (
    CrankMoment,
    LinkMoment,
    Machine,
    Mass,
    SliderLoad,
    Table,
)

DEG = math.pi / 180.0
REL = 1e-9


def compressor() -> Machine:
    """fly.compressor_course_project, built here from its statement (not from the bench)."""
    e, lab, lbc = 0.010, 0.075, 0.300
    wm = 960 * math.pi / 30
    link = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", lab, wm),
                   (RRP("B", "C", ("2", "3"), lbc, Guide((0.0, e), 0.0), "forward"),),
                   (LinkPoint("S2", "2", ("B", "C"), 0.100, 0.0),), frame_link="4")
    area = math.pi * 0.12**2 / 4
    table = Table((0, .1, .2, .3, .4, .5, .6, .7, .8, .9, 1),
                  tuple(p * 1e6 * area for p in (0, .014, .032, .055, .087, .132, .201, .317, .5, .5, .5)))
    return Machine(link, start=math.asin(e / (lab + lbc)), cycle=2 * math.pi, omega_m=wm, delta=0.04,
                   masses=(Mass("1", "A", 0.0, 0.05), Mass("2", "S2", 3.0, 0.025), Mass("3", "C", 4.5, 0.0)),
                   loads=(SliderLoad("C", 0.0, -1, "forward", table),), balance="driving")


def ic_engine() -> Machine:
    """fly.ic_engine_flywheel: torque over half a turn (rise 20°, 200 N·m to 50°, fall to 180°)."""
    md = Table(tuple(np.radians([0.0, 20.0, 50.0, 180.0])), (0.0, 200.0, 200.0, 0.0))
    return Machine(None, 0.0, cycle=math.pi, omega_m=620 * math.pi / 30, delta=0.01,
                   loads=(CrankMoment(md),), balance="resisting")


@pytest.fixture(scope="module")
def comp() -> ExactMachine:
    return ExactMachine(compressor())


@pytest.fixture(scope="module")
def ref(problems) -> dict:
    return problems["fly.compressor_course_project"]["exact"]


def close(a, b, rel=REL, floor=0.0):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return bool(np.all(np.abs(a - b) <= rel * np.maximum(np.abs(b), floor)))


def test_bench_builds_the_same_compressor():
    assert compressor_machine() == compressor()


# --------------------------------------------------------------------------------------------
# fly.compressor_course_project


def test_compressor_stroke_and_dead_centres(comp, ref):
    st = comp.strokes[0]
    assert close(st.H, ref["stroke_H_m"], 1e-12)
    assert abs(st.phi_back / DEG - ref["phi_IDC_deg"]) < 1e-9  # the IDC, exactly where the statement puts it
    assert st.phi_front == 0.0  # position 1 is the ODC
    brk = comp.breaks()
    assert brk[0] == 0.0 and abs(brk[1] / DEG - ref["phi_IDC_deg"]) < 1e-9
    # the other breaks: s/H crosses the diagram's nodes 0.1 … 0.9 on the compression stroke
    s, _, _ = comp.slider_travel(0, brk[2:])
    assert np.allclose(s / st.H, np.arange(1, 10) / 10, rtol=0, atol=1e-14)


def test_compressor_reduced_inertia(comp, ref):
    assert close(comp.inertia(np.radians(ref["positions_phi_deg"])), ref["Jp_kgm2"])
    assert close(comp.inertia(np.radians(ref["phi_every10deg_deg"])), ref["Jp_every10deg_kgm2"])
    assert close(comp.mean_inertia(), ref["Jp_mean_kgm2"])
    je = comp.inertia_extremes()
    assert close([je.maximum, je.minimum], [ref["Jp_max_kgm2"], ref["Jp_min_kgm2"]])
    assert abs(je.phi_max / DEG - ref["phi_Jp_max_deg"]) < 1e-6
    assert abs(je.phi_min / DEG - ref["phi_Jp_min_deg"]) < 1e-6


def test_compressor_reduced_moment_and_energy(comp, ref):
    phi = np.radians(ref["phi_every10deg_deg"])
    scale = abs(ref["Mp_min_Nm"])
    assert close(comp.load_moment(phi), ref["Mp_every10deg_Nm"], floor=scale)
    assert close(comp.load_moment(np.radians(ref["positions_phi_deg"])), ref["Mp_Nm"], floor=scale)
    assert close(comp.balancing_moment(), ref["Md_Nm"], 1e-12)
    assert close(comp.energy(phi), ref["DeltaT_every10deg_J"], floor=ref["DeltaT_max_J"])
    assert close(comp.energy(np.radians(ref["positions_phi_deg"])), ref["DeltaT_J"], floor=ref["DeltaT_max_J"])


def test_compressor_energy_extremes(comp, ref):
    ex = comp.extremes()
    assert close([ex.maximum, ex.minimum], [ref["DeltaT_max_J"], ref["DeltaT_min_J"]])
    assert abs(ex.phi_max / DEG - ref["phi_DeltaT_max_deg"]) < 1e-6
    # problems.toml's angle of the minimum is 1.3e-6° early: there Mп + M_b = −1.2e-5 N·m, at ours
    # it is 0 to rounding (the minimum is flat: ΔT agrees to 2e-14 J either way).
    assert abs(ex.phi_min / DEG - ref["phi_DeltaT_min_deg"]) < 2e-6
    mb = comp.balancing_moment()
    assert abs(comp.load_moment(np.array([ex.phi_min]))[0] + mb) < 1e-9
    assert abs(comp.load_moment(np.array([ex.phi_max]))[0] + mb) < 1e-9
    ind = comp.indicator()
    assert close(ind.delta_W, ref["DeltaWmax_J"])
    assert close(ind.J_mean, ref["Jp_mean_kgm2"])
    assert close(ind.J_F, ref["JF_indicator_kgm2"])


def test_compressor_wittenbauer(comp, ref):
    ex = comp.wittenbauer("exact")
    assert close([ex.k, ex.l, ex.J_F], [ref["k_J"], ref["l_J"], ref["JF_kgm2"]])
    assert close([ex.omega_max, ex.omega_min],
                 [ref["omega_max_design_rad_s"], ref["omega_min_design_rad_s"]], 1e-14)
    assert abs(ex.phi_k / DEG - ref["phi_k_deg"]) < 1e-6
    assert abs(ex.phi_l / DEG - ref["phi_l_deg"]) < 1e-6
    bk = comp.wittenbauer("book")
    assert close([bk.k, bk.l, bk.J_F], [ref["k_book_J"], ref["l_book_J"], ref["JF_book_kgm2"]])
    assert abs(bk.phi_k / DEG - ref["phi_k_book_deg"]) < 1e-6
    assert abs(bk.phi_l / DEG - ref["phi_l_book_deg"]) < 1e-6


def test_compressor_flywheel_over_n_positions(comp, ref):
    """Tangents taken only over N positions (what a drawing with N positions can give)."""
    wm, de = compressor().omega_m, 0.04
    for n, jf in zip(ref["JF_byN_N"], ref["JF_byN_kgm2"]):
        phi = 2 * math.pi * np.arange(n) / n
        dt, j = comp.energy(phi), comp.inertia(phi)
        k = np.max(dt - 0.5 * (wm * (1 + de / 2)) ** 2 * j)
        l = np.min(dt - 0.5 * (wm * (1 - de / 2)) ** 2 * j)
        assert close((k - l) / (wm * wm * de), jf)


def test_compressor_energy_motion(comp, ref):
    jf = comp.wittenbauer("exact").J_F
    mo = comp.energy_motion(jf)
    assert close([mo.T0, mo.omega0, mo.omega_max, mo.omega_min],
                 [ref["T0_J"], ref["omega0_rad_s"], ref["omega_max_rad_s"], ref["omega_min_rad_s"]])
    assert abs(mo.delta - 0.04) < 1e-13  # the exact form gives back δ exactly
    # the speed extremes are the tangent points themselves (ω is extreme where the tangent touches)
    assert abs(mo.phi_omega_max / DEG - ref["phi_omega_max_deg"]) < 1e-6
    assert abs(mo.phi_omega_max / DEG - ref["phi_k_deg"]) < 1e-6
    assert abs(mo.phi_omega_min / DEG - ref["phi_l_deg"]) < 1e-6
    # problems.toml's phi_omega_min_deg is 1.0e-6° off its own phi_l_deg: the flat-minimum reading
    assert abs(mo.phi_omega_min / DEG - ref["phi_omega_min_deg"]) < 2e-6
    # the book's and the indicator's flywheels give other δ
    assert close(comp.energy_motion(comp.wittenbauer("book").J_F).delta, ref["delta_achieved_bookJF"])
    assert close(comp.energy_motion(comp.indicator().J_F).delta, ref["delta_achieved_indicatorJF"])


# --------------------------------------------------------------------------------------------
# fly.ic_engine_flywheel


def test_ic_engine(problems):
    ref = problems["fly.ic_engine_flywheel"]["exact"]
    em = ExactMachine(ic_engine())
    assert close(em.balancing_moment(), -ref["Mr_Nm"], 1e-14)  # resisting: negative by power
    assert np.allclose(em.breaks(), np.radians([0.0, 20.0, 50.0]), rtol=0, atol=1e-15)
    ex = em.extremes()
    assert abs(ex.phi_max / DEG - 625 / 6) < 1e-9 and abs(ex.phi_min / DEG - 35 / 3) < 1e-9
    assert abs(ex.phi_max / DEG - ref["phi_max_deg"]) < 1e-4  # the table rounds to 4 decimals
    ind = em.indicator()
    assert ind.J_mean == 0.0
    # problems.toml holds ΔW and J_F 3.9e-12 low; closed form: ΔW = 89.08451390387724 J
    assert close(ind.delta_W, ref["DeltaW_max_J"]) and abs(ind.delta_W - 89.08451390387724) < 1e-11
    assert close(ind.J_F, ref["JF_kgm2"])
    assert abs(ind.J_F - 2.003) > 0.1  # the book's 2.003 is an arithmetic slip
    w = em.wittenbauer()
    assert close(w.J_F, ind.J_F, 1e-13)  # Jп ≡ 0: the two methods are one
    mo = em.energy_motion(w.J_F)
    assert close(mo.omega_max * 30 / math.pi, ref["n_max_r_min"], 1e-13)
    assert abs(mo.delta - 0.01) < 1e-14


# --------------------------------------------------------------------------------------------
# Identities


def test_slope_and_energy_are_derivatives(comp):
    phi = np.radians(np.arange(3.0, 360.0, 7.0))
    h = 1e-5
    fd = (comp.inertia(phi + h) - comp.inertia(phi - h)) / (2 * h)
    assert np.allclose(comp.inertia_slope(phi), fd, rtol=0, atol=1e-10)
    fd = (comp.energy(phi + h) - comp.energy(phi - h)) / (2 * h)
    # away from breaks ΔT′ = Mп + M_b
    brk = comp.breaks()
    far = np.min(np.abs(phi[:, None] - brk[None, :]), axis=1) > 1e-3
    assert np.allclose((comp.load_moment(phi) + comp.balancing_moment())[far], fd[far], rtol=0, atol=1e-6)


def test_cycle_work_by_adaptive_quadrature(comp):
    brk = list(comp.breaks()) + [2 * math.pi]
    work = sum(quad(lambda x: float(comp.load_moment(np.array([x]))[0]), a, b, epsabs=1e-12, epsrel=1e-13)[0]
               for a, b in itertools.pairwise(brk))
    assert close(-work / (2 * math.pi), comp.balancing_moment(), 1e-11)


def test_energy_is_periodic(comp):
    assert comp.energy(np.array([0.0, 2 * math.pi]))[1] == 0.0
    phi = np.radians([17.0, 200.0, 300.0])
    assert np.allclose(comp.energy(phi + 2 * math.pi), comp.energy(phi), rtol=0, atol=1e-11)


def test_clockwise_mirror_image_is_the_same_machine(comp):
    """The compressor reflected in the x-axis turns CW: Jп, Mп, ΔT at φ are unchanged."""
    m = compressor()
    lk = m.linkage
    drv = lk.driver
    mirror = Linkage({"A": (0.0, 0.0)}, dataclasses.replace(drv, omega=-drv.omega),
                     (dataclasses.replace(lk.dyads[0], guide=Guide((0.0, -0.010), 0.0)),), lk.points,
                     frame_link="4")
    cw = ExactMachine(dataclasses.replace(m, linkage=mirror, start=-m.start))
    phi = np.radians(np.arange(0.0, 360.0, 10.0))
    assert np.allclose(cw.inertia(phi), comp.inertia(phi), rtol=1e-13, atol=0)
    assert np.allclose(cw.inertia_slope(phi), comp.inertia_slope(phi), rtol=0, atol=1e-13)
    assert np.allclose(cw.load_moment(phi), comp.load_moment(phi), rtol=0, atol=1e-10)
    assert np.allclose(cw.energy(phi), comp.energy(phi), rtol=0, atol=1e-10)


def test_link_moment_power():
    """A link moment's Mп is M·ω3/ω1 = M·dθ3/dφ (a finite difference of the rocker's angle)."""
    lk = Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("1", "A", "B", 0.06, 30.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.12, 0.09), "left"),), frame_link="4")
    md = Table((0.0, 2.0, 2.0, 2 * math.pi), (-6.0, -6.0, 2.0, 2.0))
    em = ExactMachine(Machine(lk, 0.3, 2 * math.pi, 30.0, 0.05, masses=(Mass("3", "D", 0.0, 0.004),),
                              loads=(LinkMoment("3", md),), balance="driving"))
    assert 2.0 in em.breaks().tolist()
    phi = np.radians(np.arange(5.0, 360.0, 10.0))
    h = 1e-6
    from graphmech.exact.linkage import solve
    th = [np.unwrap(solve(lk, 0.3 + phi + s * h).angle["3"]) for s in (1, -1)]
    dth = (th[0] - th[1]) / (2 * h)
    dth = (dth + np.pi / h) % (2 * np.pi / h) - np.pi / h  # the unwrap is per array, not across
    assert np.allclose(em.load_moment(phi), table_value(md, phi) * dth, rtol=0, atol=1e-7)
    assert np.allclose(em.inertia(phi), 0.004 * dth**2, rtol=1e-7, atol=0)


def test_tables():
    t = Table((0.0, 1.0, 1.0, 3.0), (0.0, 2.0, -1.0, 3.0))
    assert table_value(t, np.array([-1.0, 0.5, 1.0, 2.0, 5.0])).tolist() == [0.0, 1.0, -1.0, 1.0, 3.0]
    assert table_line(t, 0.999) == (0.0, 2.0) and table_line(t, 1.0) == (-3.0, 2.0)
    assert table_value(Table((0.5,), (7.0,)), np.array([0.0, 1.0])).tolist() == [7.0, 7.0]


def test_results_are_frozen(comp):
    ex = comp.extremes()
    assert isinstance(ex, Extremes)
    for obj in (ex, comp.wittenbauer(), comp.indicator(), comp.strokes[0]):
        with pytest.raises(dataclasses.FrozenInstanceError):
            obj.maximum = 0.0  # type: ignore[misc]


# --------------------------------------------------------------------------------------------
# Impossible inputs


def test_no_load_has_no_flywheel():
    em = ExactMachine(dataclasses.replace(compressor(), loads=()))
    assert em.inertia(np.array([0.0]))[0] > 0  # the inertia is still there
    with pytest.raises(ValueError, match=r"no work .*J_F is undefined"):
        em.balancing_moment()
    with pytest.raises(ValueError, match="no work"):
        em.wittenbauer()


def test_wrong_balance_sign():
    with pytest.raises(ValueError, match="cannot be driving"):
        ExactMachine(dataclasses.replace(ic_engine(), balance="driving")).balancing_moment()


def test_inconsistent_machines_are_refused_at_once():
    m = compressor()
    bad = dataclasses.replace(m, cycle=math.pi, masses=(Mass("7", "S9", 1.0),),
                              loads=(SliderLoad("X", 0.0, 2, "forward", m.loads[0].table),))
    with pytest.raises(ValueError) as err:
        ExactMachine(bad)
    keys = {k for k, _ in err.value.problems}
    assert keys == {"cycle"}  # names are checked against a linkage that can turn through Φ
    bad = dataclasses.replace(bad, cycle=2 * math.pi)
    with pytest.raises(ValueError) as err:
        ExactMachine(bad)
    assert {k for k, _ in err.value.problems} == {"masses[0].link", "masses[0].point", "loads[0].point",
                                                  "loads[0].sense"}
    with pytest.raises(ValueError, match="masses need a linkage"):
        ExactMachine(dataclasses.replace(ic_engine(), masses=(Mass("2", "S2", 1.0),)))


def test_linkage_that_does_not_assemble_names_the_angle():
    lk = Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("1", "A", "B", 0.08, 10.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.06, 0.05), "left"),), frame_link="4")
    m = Machine(lk, 0.0, 2 * math.pi, 10.0, 0.05, masses=(Mass("3", "D", 0.0, 0.01),))
    with pytest.raises(ValueError, match=r"cannot be solved at φ = [0-9.]+° from position 1"):
        ExactMachine(m)


# ---------------------------------------------------------------------------- Jп given as a table

def table_machine(cycle: float = 2 * math.pi) -> Machine:
    """The course project's 12 values of Jп (linear between them, closed at Φ) and a sinusoidal
    load table every 15°: no linkage, a driving constant moment."""
    jp = (0.6008325, 0.6018516, 0.6019891, 0.6017175, 0.6011137, 0.6005196,
          0.6, 0.6031759, 0.6045547, 0.6025725, 0.6009025, 0.6)
    step = cycle / 12
    jt = Table(tuple(k * step for k in range(13)), (*jp, jp[0]))
    xs = tuple(k * cycle / 24 for k in range(25))
    ms = tuple(-375.0 + 3450.0 * math.sin(x * 2 * math.pi / cycle - math.radians(30)) for x in xs)
    return Machine(None, 0.0, cycle, 28.0, 0.2, loads=(CrankMoment(Table(xs, ms)),), balance="driving",
                   inertia_table=jt)


def brute_force_wittenbauer(m: Machine, c_hi: float, c_lo: float, n: int = 400_001) -> tuple[float, float, float]:
    """k, l and the mean Jп by another route: the trapezoidal rule on a fine grid that holds every
    node of both tables (both are linear between nodes, so ΔT is exact up to the quadratic pieces)."""
    grid = np.union1d(np.linspace(0.0, m.cycle, n), np.concatenate([m.loads[0].table.x, m.inertia_table.x]))
    M = np.interp(grid, m.loads[0].table.x, m.loads[0].table.y)
    J = np.interp(grid, m.inertia_table.x, m.inertia_table.y)
    A = np.concatenate([[0.0], np.cumsum(0.5 * (M[1:] + M[:-1]) * np.diff(grid))])
    dT = A - A[-1] * grid / m.cycle
    J_mean = float(np.sum(0.5 * (J[1:] + J[:-1]) * np.diff(grid)) / m.cycle)
    return float(np.max(dT - c_hi * J)), float(np.min(dT - c_lo * J)), J_mean


def test_a_jp_table_is_linear_between_its_points_and_closed_at_the_cycle():
    m = table_machine()
    ex = ExactMachine(m)
    phi = np.array([0.0, math.radians(15), math.radians(345), 2 * math.pi - 1e-9])
    assert ex.inertia(phi) == pytest.approx([0.6008325, (0.6008325 + 0.6018516) / 2, (0.6 + 0.6008325) / 2,
                                             0.6008325], abs=1e-11)
    assert ex.inertia_slope(np.array([math.radians(15)]))[0] == pytest.approx(
        (0.6018516 - 0.6008325) / math.radians(30), rel=1e-12)
    hi = ex.inertia_extremes()
    assert (hi.maximum, math.degrees(hi.phi_max)) == pytest.approx((0.6045547, 240.0), rel=1e-12)
    assert hi.minimum == 0.6
    # every node of the Jп table is a break of the quadrature: the mean is the trapezoid's, exactly
    assert ex.mean_inertia() == pytest.approx(brute_force_wittenbauer(m, 0.0, 0.0, 13)[2], rel=1e-14)


@pytest.mark.parametrize("cycle", [2 * math.pi, 4 * math.pi])
def test_wittenbauer_of_tables_against_a_brute_force_and_the_tangency_condition(cycle):
    m = table_machine(cycle)
    ex = ExactMachine(m)
    t = ex.wittenbauer("book")
    c_hi, c_lo = t.omega_max ** 2 / 2, t.omega_min ** 2 / 2
    k, l_, _ = brute_force_wittenbauer(m, c_hi, c_lo)
    assert t.k == pytest.approx(k, rel=1e-7) and t.l == pytest.approx(l_, rel=1e-6)
    assert t.J_F == pytest.approx((k - l_) / (28.0 ** 2 * 0.2), rel=1e-7)
    # at the points of contact Mп + M_b − c·dJп/dφ changes sign from + to − (a maximum of ΔT − c·Jп) …
    mb = ex.balancing_moment()

    def slope(phi: float, c: float) -> float:
        return float(ex.load_moment(np.array([phi]))[0] + mb - c * ex.inertia_slope(np.array([phi]))[0])

    h = 1e-7
    assert slope(t.phi_k - h, c_hi) > 0 > slope(t.phi_k + h, c_hi)
    assert slope(t.phi_l - h, c_lo) < 0 < slope(t.phi_l + h, c_lo)  # … and from − to + at the minimum
    # over two turns the same tables stretched twice as long: the balancing moment is the same, ΔT doubles
    if cycle > 2 * math.pi:
        one = ExactMachine(table_machine())
        assert mb == pytest.approx(one.balancing_moment(), rel=1e-12) == 375.0
        assert ex.extremes().maximum == pytest.approx(2 * one.extremes().maximum, rel=1e-12)


def test_a_bad_jp_table_is_named():
    m = table_machine()
    bad = dataclasses.replace(m, inertia_table=Table((0.0, 1.0, 2 * math.pi), (0.6, -0.1, 0.6)))
    with pytest.raises(ValueError, match=r"inertia_table.y: Jп must be > 0"):
        ExactMachine(bad)
    bad = dataclasses.replace(m, inertia_table=Table((0.0, 1.0, 3.0), (0.6, 0.7, 0.6)))
    with pytest.raises(ValueError, match=r"inertia_table.x: φ must increase strictly from 0 to Φ"):
        ExactMachine(bad)


# ------------------------------------------------------------------------------------------
# ΔT given as a table (Machine.energy_table)


def test_a_table_of_the_compressors_delta_t_gives_its_flywheel_with_a_curved_jp() -> None:
    """The compressor's own ΔT every 5°, as a table, with its masses (Jп curved): the tangents touch
    between the table's points (brentq on the polygon's slope − c·dJп/dφ), the flywheel agrees with
    the one from the moments to the polygon's error, and the moments themselves are refused."""
    m = compressor()
    ex = ExactMachine(m)
    phi = np.radians(np.arange(0.0, 365.0, 5.0))
    dt = ex.energy(phi)
    dt[0] = dt[-1] = 0.0
    table = ExactMachine(dataclasses.replace(m, loads=(), energy_table=Table(tuple(phi), tuple(dt))))
    got, want = table.wittenbauer("exact"), ex.wittenbauer("exact")
    assert got.J_F == pytest.approx(want.J_F, rel=1e-4)
    assert got.J_F != pytest.approx(want.J_F, rel=1e-8)  # a polygon, not the curve
    for p in (got.phi_k, got.phi_l):  # not at a vertex: Jп's curvature moves the point of contact
        assert abs(math.remainder(p, math.radians(5.0))) > 1e-3
    assert table.energy(np.radians([10.0, 12.5]))[1] == pytest.approx(0.5 * (dt[2] + dt[3]), rel=1e-14)
    with pytest.raises(ValueError, match="cannot be split back"):
        table.balancing_moment()


def test_a_table_of_delta_t_with_loads_is_refused() -> None:
    m = compressor()
    t = Table((0.0, math.pi, 2 * math.pi), (0.0, 10.0, 0.0))
    with pytest.raises(ValueError, match="already holds the loads' work"):
        ExactMachine(dataclasses.replace(m, energy_table=t))
    with pytest.raises(ValueError, match="ΔT must be 0 at φ = 0 and at Φ"):
        ExactMachine(dataclasses.replace(m, loads=(), energy_table=Table((0.0, 2 * math.pi), (1.0, 1.0))))
