"""The cam-inversion benchmark: its records, its exact reference, its plots (speed is measured there, not here)."""
from __future__ import annotations

import dataclasses
import json
import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from graphmech.problems.cam.bench import CAM_DIVISIONS, cam_cases
from graphmech.accuracy import convergence_order
from graphmech.exact.cam import working_profile as exact_working_profile
from tests.conftest import ROOT, SCENES

REQUIRED = {"method", "case", "n", "seconds", "max_rel_error"}
CASES = ("offset-roller-e+10", "oscillating-roller", "flat-face-translating")

#: Where the drawn roller profile stops converging (see ``bench._cam_notes``), relative to the
#: largest profile radius. offset-roller: shapely draws the roller's arc round the pitch curve's
#: concave corner at 0° with 32 segments per quarter circle — a chord error of at most about
#: r_r·(1 − cos 1.5°) = 3.4 µm for r_r = 10 mm, /35.4 mm ≈ 9.7e-5; oscillating-roller: shapely's
#: buffer thins the offset's vertices to a spacing of about 1 % of r_r. The flat face has no floor.
FLOOR = {"offset-roller-e+10": 6.0e-6, "oscillating-roller": 3.0e-6, "flat-face-translating": 0.0}
#: Smallest radius of curvature read off the drawing at 3600 divisions, relative error (measured
#: 3.5e-4, 1.9e-3, 5.7e-6).
RHO_3600 = {"offset-roller-e+10": 5e-4, "oscillating-roller": 2.5e-3, "flat-face-translating": 1e-5}
#: Measured at 3600 divisions: 4.8e-6, 2.2e-6, 4.5e-7 (the rollers' floor: shapely's buffer thins
#: the offset's vertices to about 1 % of r_r).
BOUND_3600 = {"offset-roller-e+10": 6.0e-6, "oscillating-roller": 3.0e-6, "flat-face-translating": 1.0e-6}


@pytest.fixture(scope="module")
def bench(quick_bench) -> tuple[dict, Path]:
    code, text, err, out = quick_bench
    assert code == 0, err
    return json.loads(text), out


def _cam(doc: dict, case: str) -> list[dict]:
    return sorted((r for r in doc["records"] if r["method"] == "cam-inversion" and r["case"] == case),
                  key=lambda r: r["n"])


def test_cam_records_have_the_schema_and_every_n(bench):
    doc, out = bench
    saved = json.loads((out / "bench.json").read_text())
    assert saved["records"] == doc["records"]
    for case in CASES:
        rs = _cam(doc, case)
        assert [r["n"] for r in rs] == list(CAM_DIVISIONS)
        for r in rs:
            assert REQUIRED <= set(r)
            assert r["method"] == "cam-inversion" and r["case"] == case
            assert math.isfinite(r["seconds"]) and r["seconds"] > 0.0
            assert 0.0 < r["max_rel_error"] < 0.1
            assert r["max_rel_error_smooth"] <= r["max_rel_error"]
            assert r["undercut_agrees"] and not r["undercut"]
    assert any("3600 divisions" in n and "target < 50 ms" in n for n in doc["notes"])
    assert sum("cam inversion" in n and "order" in n for n in doc["notes"]) == len(CASES)


@pytest.mark.parametrize("case", CASES)
def test_profile_error_falls_as_n_squared_down_to_the_drawing_floor(bench, case):
    rs = _cam(bench[0], case)
    err = [r["max_rel_error"] for r in rs]
    for (a, b) in zip(err, err[1:]):
        if a > FLOOR[case]:  # above the floor every finer drawing is better
            assert b < a
    assert all(e <= max(FLOOR[case], err[0]) for e in err)
    assert err[-1] <= BOUND_3600[case]
    # second order while the method's error dominates: ×4 per halving of the step
    o = convergence_order(rs)
    assert o["asymptotic"] > 1.9 and o["n_to"] >= 360
    # away from the pitch curve's corners it keeps falling to the buffer's vertex spacing
    smooth = convergence_order(rs, "max_rel_error_smooth")
    assert smooth["asymptotic"] > 1.9 and smooth["n_to"] >= 1440
    assert rs[-1]["max_rel_error_smooth"] <= 6e-6


def test_the_roller_arc_round_a_concave_corner_is_drawn_as_finely_as_the_divisions(bench):
    # quad_segs grows with n: the corner at 0° no longer puts a 9e-5 floor under the profile
    last = _cam(bench[0], "offset-roller-e+10")[-1]
    assert last["max_rel_error"] < 1e-5
    assert last["max_rel_error_smooth"] <= last["max_rel_error"]


def test_flat_face_is_second_order_throughout(bench):
    rs = _cam(bench[0], "flat-face-translating")
    o = convergence_order(rs)
    assert o["n_to"] == 3600 and 1.9 < o["overall"] < 2.1


@pytest.mark.parametrize("case", CASES)
def test_readings_off_the_drawing_converge(bench, case):
    rs = _cam(bench[0], case)
    alpha = [r["alpha_max_error_deg"] for r in rs]
    rho = [r["rho_min_rel_error"] for r in rs]
    # the extremes sit at joints of the law (a kink of α, a jump of s″), where a chord or a circle
    # through neighbouring divisions averages the two sides: first order there
    assert alpha[-1] <= 0.01 and rho[-1] <= RHO_3600[case]
    assert alpha[-1] <= alpha[0] and rho[-1] < rho[0] / 10


@pytest.mark.parametrize("sense, e", [("pos", 0.01), ("neg", -0.01)])
def test_exact_reference_profile_matches_the_book(problems, sense, e):
    """The reference the drawing is measured against: polar radii of the roller's envelope (with
    the arc round the concave corner at 0°) and the vertex where the offsets cross at 150°."""
    import shapely

    from graphmech.exact.cam import profile

    ex = problems["cam.offset_roller_translating"]["exact"]
    cam = cam_cases()["offset-roller-e+10"]
    cam = dataclasses.replace(cam, follower=dataclasses.replace(cam.follower, offset=e))
    pts, ang = exact_working_profile(cam)
    assert len(pts) == len(ang) >= 20000
    ring = shapely.LinearRing(pts)
    assert ring.is_simple
    radii = []
    for th in np.radians(np.arange(0.0, 360.0, 15.0)):
        hit = shapely.get_coordinates(shapely.LineString([(0, 0), (0.1 * math.cos(th), 0.1 * math.sin(th))])
                                      .intersection(ring))
        assert len(hit) == 1
        radii.append(float(np.hypot(*hit[0])) * 1e3)
    np.testing.assert_allclose(radii, ex[f"actual_polar_R_mm_{sense}_theta0to345step15"], atol=0.5e-4 + 1e-9)
    q = np.asarray(ex[f"actual_vertex_at_150_xy_mm_{sense}"]) / 1e3
    k = int(np.argmin(np.hypot(*(pts - q).T)))
    assert np.max(np.abs(pts[k] - q)) <= 0.5e-7 + 1e-12
    pitch = profile(cam, [math.radians(150.0)]).pitch[0]
    gap_mm = (float(np.hypot(*(pts[k] - pitch))) - 0.01) * 1e3
    # pts[k] is the densely drawn profile's point nearest the vertex, not the corner itself: 1e-6 mm
    assert gap_mm == pytest.approx(ex[f"roller_gap_at_150_mm_{sense}"], abs=1e-6)


def test_plots_are_written_parse_and_are_deterministic(bench, tmp_path):
    from graphmech.render.plots import error_time_plots

    doc, out = bench
    methods = dict.fromkeys(r["method"] for r in doc["records"])
    for m in methods:
        svg = out / f"{m}.svg"
        assert svg.is_file()
        root = ET.parse(svg).getroot()
        assert root.tag.endswith("svg")
    cam_svg = (out / "cam-inversion.svg").read_text(encoding="utf-8")
    assert "<dc:date>" not in cam_svg  # no date in the metadata
    # the same records give the same bytes: twice over, and the same as `graphmech bench -o` wrote
    saved = [r for r in json.loads((out / "bench.json").read_text())["records"] if r["method"] == "cam-inversion"]
    a, b = tmp_path / "a", tmp_path / "b"
    a.mkdir()
    b.mkdir()
    pa, pb = error_time_plots(saved, a), error_time_plots(saved, b)
    assert [p.name for p in pa] == [p.name for p in pb] == ["cam-inversion.svg"]
    for x, y in zip(pa, pb):
        assert x.read_bytes() == y.read_bytes() == (out / x.name).read_bytes()


def test_plots_only_module_imports_matplotlib():
    pattern = re.compile(r"^\s*(import|from)\s+matplotlib", re.M)
    offenders = [p.relative_to(ROOT).as_posix() for p in (ROOT / "graphmech").rglob("*.py")
                 if pattern.search(p.read_text(encoding="utf-8"))]
    assert offenders == ["graphmech/render/plots.py"]


def test_check_on_a_linkage_scene_never_imports_matplotlib():
    code = ("import sys; from graphmech.cli import main; import graphmech.render.plots, graphmech.bench; "
            f"rc = main(['check', r'{SCENES / 'kin.oscillating_block.toml'}']); "
            "assert not any(m.split('.')[0] == 'matplotlib' for m in sys.modules), 'matplotlib imported'; "
            "sys.exit(rc)")
    r = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert "matplotlib imported" not in r.stderr
