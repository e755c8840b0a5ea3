"""The command line: exit codes, one-line errors, atomic output, determinism, lazy imports."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from graphmech.drawing.lettering import plain
from tests.conftest import (
    ROOT,
    SCENES,
    assert_refused,
    check_json,
    fourbar_scene,
    run_cli,
    values,
)

STATED = "[scales]\nl_m_per_mm = 0.002\nv_m_s_per_mm = 0.01\na_m_s2_per_mm = 0.1"


def scene(tmp_path, scales: str = STATED, l2: float = 120, name: str = "s.toml"):
    p = tmp_path / name
    p.write_text(fourbar_scene(scales=scales, b=l2, title="Four-bar"), encoding="utf-8")
    return p


def test_render_is_byte_identical_and_parses(tmp_path):
    p = scene(tmp_path)
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    assert run_cli("render", str(p), "-o", str(a))[0] == 0
    assert run_cli("render", str(p), "-o", str(b))[0] == 0
    assert a.read_bytes() == b.read_bytes()
    root = ET.fromstring(a.read_text(encoding="utf-8"))
    text = " ".join("".join(t.itertext()) for t in root.iter() if t.tag.endswith("}text"))
    # the drawn characters (sub- and superscripts are tspans: plain() reads the marks alike)
    assert all(plain(n) in text for n in ("μl = 0.002 m/mm", "μv = 0.01 (m/s)/mm", "μa = 0.1 (m/s²)/mm"))


def test_measured_values_and_segments(tmp_path):
    p = scene(tmp_path)
    # v_C = 0.40098 m/s; pc = 40.098 mm at μv = 0.01
    code, out, err = run_cli("check", str(p), "--json", "--measured", "v_C=0.401,pc=40.3")
    doc = json.loads(out)
    assert code == 0
    assert [m["ok"] for m in doc["measured"]] == [True, True]
    code, out, _ = run_cli("check", str(p), "--json", "--measured", "pc=41")
    assert code == 1 and json.loads(out)["measured"][0]["ok"] is False
    assert json.loads(out)["measured"][0]["expected"] == pytest.approx(40.0984583710757, rel=1e-9)
    # a tighter precision turns a pass into a fail
    assert run_cli("check", str(p), "--measured", "pc=40.3", "--precision", "0.1")[0] == 1


def test_drawn_length_refused_when_the_scene_left_mu_to_graphmech(tmp_path):
    p = scene(tmp_path, scales="")
    code, out, err = run_cli("check", str(p), "--measured", "pc=40")
    assert code == 2 and err.count("\n") == 1
    assert "μv" in err and "pc" in err
    # but a value is fine
    assert run_cli("check", str(p), "--measured", "v_C=0.4")[0] == 0


def test_chosen_scales_are_round_and_written(tmp_path):
    doc = check_json(scene(tmp_path, scales=""))
    for k, mu in doc["scales"].items():
        mant = mu / 10 ** __import__("math").floor(__import__("math").log10(mu))
        assert round(mant, 9) in (1.0, 2.0, 2.5, 5.0), (k, mu)


def test_cannot_be_assembled_is_one_line_and_writes_nothing(tmp_path):
    p = scene(tmp_path, l2=10)
    out = tmp_path / "out.svg"
    out.write_text("keep me")
    code, o, err = run_cli("render", str(p), "-o", str(out))
    assert code == 2
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "s.toml" in err and "cannot be assembled" in err and "φ₁ = 165°" in err
    assert out.read_text() == "keep me"
    assert [x.name for x in tmp_path.iterdir() if x.name.startswith(".")] == []


@pytest.mark.parametrize("bad, where", [
    ('lengths = [-120, 90]', "dyad[0].lengths[0]"),
    ('lengths = [120, inf]', "dyad[0].lengths[1]"),
    ('lengths = [120, 90]\nbogus = 1', "dyad[0].bogus"),
])
def test_bad_input_names_file_and_key(tmp_path, bad, where):
    p = tmp_path / "bad.toml"
    p.write_text(fourbar_scene(scales=STATED, title="Four-bar").replace("lengths = [120, 90]", bad), encoding="utf-8")
    code, out, err = run_cli("check", str(p))
    assert code == 2 and out == ""
    assert err.startswith(f"bad.toml: {where}:") and err.count("\n") == 1


def test_unknown_find_name_suggests(tmp_path):
    p = tmp_path / "f.toml"
    p.write_text(fourbar_scene(scales=STATED, title="Four-bar").replace('"omega_2"]', '"omega2"]'), encoding="utf-8")
    code, _, err = run_cli("check", str(p))
    assert code == 2 and "find[1]" in err and "omega_2" in err


def test_markup_in_the_title_is_escaped(tmp_path):
    p = tmp_path / "x.toml"
    p.write_text(fourbar_scene(scales=STATED, title="Four-bar").replace(
        'title = "Four-bar"', 'title = "</text><script>alert(1)</script>&\\u0001"'), encoding="utf-8")
    out = tmp_path / "x.svg"
    assert run_cli("render", str(p), "-o", str(out))[0] == 0
    svg = out.read_text(encoding="utf-8")
    root = ET.fromstring(svg)
    assert not [e for e in root.iter() if e.tag.endswith("script")]
    assert "<script>" not in svg and "&lt;script&gt;" in svg and "\x01" not in svg


def test_only_what_is_asked_is_built(tmp_path):
    p = tmp_path / "v.toml"
    p.write_text(fourbar_scene(scales=STATED, title="Four-bar").replace(
        'show = ["mechanism", "velocity", "acceleration"]', 'show = ["mechanism"]'), encoding="utf-8")
    from graphmech.problems.linkage.check import analyse
    from graphmech.scene import load_scene

    an = analyse(load_scene(p))
    panels = {s.panel for s in an.plan.steps}
    assert "acceleration" not in panels  # v_C and ω2 need no acceleration polygon
    assert not any(s.name.startswith("m:a_") for s in an.plan.steps)
    out = tmp_path / "v.svg"
    run_cli("render", str(p), "-o", str(out))
    svg = out.read_text(encoding="utf-8")
    assert "Velocity polygon" not in svg and "Kinematic diagram" in svg


# Python source that makes matplotlib and svgwrite unimportable, as in an install without the
# plots extra (svgwrite is no dependency at all): the dependencies by need.
BLOCK = (
    "import sys\n"
    "class Block:\n"
    "    def find_spec(self, name, path=None, target=None):\n"
    "        if name.split('.')[0] in ('matplotlib', 'svgwrite'):\n"
    "            raise ModuleNotFoundError(f'No module named {name!r} (blocked)', name=name)\n"
    "sys.meta_path.insert(0, Block())\n"
)


def _python(code: str, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", BLOCK + code, *args], cwd=ROOT, capture_output=True, text=True)


def test_render_and_check_need_neither_matplotlib_nor_svgwrite(tmp_path):
    """With both unimportable: the zh figure is the committed one byte for byte, the check runs,
    and neither was even tried."""
    code = ("from graphmech.cli import main\n"
            f"rc = main(['check', r'{SCENES / 'linkage.slider_crank_offset.toml'}', '--json'])\n"
            f"rc += main(['render', r'{SCENES / 'kin.oscillating_block-zh.toml'}', '-o', r'{tmp_path / 'o.svg'}'])\n"
            "print(sorted(m for m in sys.modules if m.split('.')[0] in ('matplotlib', 'svgwrite')))\n"
            "sys.exit(rc)")
    r = _python(code)
    assert r.returncode == 0, r.stderr
    *table, written, imported = r.stdout.splitlines()
    assert (written, imported) == (str(tmp_path / "o.svg"), "[]")
    assert json.loads("\n".join(table))["quantities"][0]["name"] == "theta_2@50"
    assert (tmp_path / "o.svg").read_bytes() == (ROOT / "figures" / "kin.oscillating_block-zh.svg").read_bytes()


def test_help_and_the_cli_module_do_not_import_numpy():
    """`graphmech --help` (and --version) need no numpy: it is imported in main() once a command runs."""
    code = ("import graphmech.cli\n"
            "assert 'numpy' not in sys.modules, 'numpy imported by graphmech.cli'\n"
            "try:\n"
            "    graphmech.cli.main(sys.argv[1:])\n"
            "except SystemExit as e:\n"
            "    print('exit', e.code, 'numpy' in sys.modules)\n")
    for argv in (["--help"], ["render", "--help"], ["--version"]):
        r = _python(code, *argv)
        assert r.returncode == 0 and r.stderr == "", r.stderr
        assert r.stdout.splitlines()[-1] == "exit 0 False", (argv, r.stdout)


def test_bench_plots_without_matplotlib_keep_the_results_and_exit_2(tmp_path):
    """The plots are asked for but cannot be drawn: the results are printed and bench.json written,
    then one line says what to install, exit 2 — a requested output is missing, so a script must
    not carry on as if it were there, and -q (which silences warnings) must not hide it."""
    record = {"method": "m", "case": "c", "n": 10, "seconds": 1e-3, "max_rel_error": 1e-9}
    doc = {"records": [record], "notes": ["a note"]}
    code = ("import graphmech.bench\n"
            f"graphmech.bench.run_bench = lambda quick=False, explicit=False: {doc!r}\n"
            "from graphmech.cli import main\n"
            f"sys.exit(main(['bench', '--quick', '-o', r'{tmp_path / 'b'}']))")
    r = _python(code)
    assert r.returncode == 2
    assert r.stderr == 'graphmech: the log-log plots need matplotlib: pip install "graphmech[plots]"\n'
    assert "max rel error 1.0e-09" in r.stdout and r.stdout.endswith("a note\n")
    assert json.loads((tmp_path / "b" / "bench.json").read_text(encoding="utf-8")) == doc
    assert sorted(p.name for p in (tmp_path / "b").iterdir()) == ["bench.json"]


def test_python_dash_m_runs():
    r = subprocess.run([sys.executable, "-m", "graphmech", "check", str(SCENES / "linkage.slider_fixed_angle_guide.toml"),
                        "--json"], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0
    assert values(json.loads(r.stdout))["v_C"]["graphical"] == pytest.approx(-1.195433962877246, rel=1e-9)


NUMBER = __import__("re").compile(r"-?\d+\.?\d*(?:e-?\d+)?")


def _shape_and_numbers(svg: str) -> tuple[list, list[float]]:
    """The element tree's tags/attribute names/texts with every number pulled out."""
    root = ET.fromstring(svg)
    shape, numbers = [], []
    for e in root.iter():
        attrs = sorted((k, NUMBER.sub("#", v)) for k, v in e.attrib.items() if k != "id")
        shape.append((e.tag, attrs, NUMBER.sub("#", e.text or "")))
        for k, v in sorted(e.attrib.items()):
            if k != "id":
                numbers += [float(x) for x in NUMBER.findall(v)]
    return shape, numbers


def test_figures_match_their_scenes_within_tolerance():
    """figures/*.svg are what their scenes render now: same elements, numbers within 1e-3 mm.

    Compared parsed, not byte for byte, so another platform's last-digit rounding passes.
    """
    from graphmech.scene import render_scene

    for s in sorted(SCENES.glob("*.toml")):
        svg, _ = render_scene(s)
        committed = (ROOT / "figures" / f"{s.stem}.svg").read_text(encoding="utf-8")
        shape_a, nums_a = _shape_and_numbers(svg)
        shape_b, nums_b = _shape_and_numbers(committed)
        assert shape_a == shape_b, s.stem
        assert len(nums_a) == len(nums_b)
        assert max((abs(a - b) for a, b in zip(nums_a, nums_b)), default=0.0) <= 1.5e-3, s.stem


def test_output_through_a_symlink_keeps_the_link_and_normal_permissions(tmp_path):
    import os

    target = tmp_path / "target.svg"
    target.write_text("old")
    link = tmp_path / "link.svg"
    link.symlink_to(target)
    assert run_cli("render", str(SCENES / "kin.oscillating_block.toml"), "-o", str(link))[0] == 0
    assert link.is_symlink() and target.read_text().startswith("<svg")
    fresh = tmp_path / "fresh.svg"
    old = os.umask(0o022)
    try:
        assert run_cli("render", str(SCENES / "kin.oscillating_block.toml"), "-o", str(fresh))[0] == 0
    finally:
        os.umask(old)
    assert fresh.stat().st_mode & 0o777 == 0o644


def test_output_that_cannot_be_written_is_one_line(tmp_path):
    code, out, err = run_cli("render", str(SCENES / "kin.oscillating_block.toml"), "-o", str(tmp_path))
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err
    code, out, err = run_cli("render", str(SCENES / "kin.oscillating_block.toml"), "-o", str(tmp_path / "no" / "x.svg"))
    assert code == 2 and "does not exist" in err


def test_ambiguous_or_degenerate_segment_names_are_refused(tmp_path):
    p = scene(tmp_path)
    code, _, err = run_cli("check", str(p), "--measured", "n'c'=30")
    assert code == 2 and "n2'c'" in err and "n3'c'" in err  # two normal components end at c′
    code, _, err = run_cli("check", str(p), "--measured", "pp=0")
    assert code == 2 and "two different ends" in err
    code, out, _ = run_cli("check", str(p), "--json", "--measured", "n2'c'=35.7")
    assert json.loads(out)["measured"][0]["expected"] == pytest.approx(35.699499, rel=1e-6)


def test_render_refuses_more_positions_than_fit_but_check_takes_them(tmp_path):
    p = tmp_path / "many.toml"
    p.write_text(fourbar_scene(scales=STATED, title="Four-bar").replace("angle = 165", "angle = {start = 0, stop = 360, step = 30}"),
                 encoding="utf-8")
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "many.svg"))
    assert code == 2 and "12 positions do not fit" in err and err.count("\n") == 1
    assert not (tmp_path / "many.svg").exists()
    doc = check_json(p)
    assert len(doc["quantities"]) == 24 and all(q["rel_error"] < 1e-12 for q in doc["quantities"])


def test_two_positions_stand_in_two_rows(tmp_path):
    from graphmech.scene import render_scene

    svg, warnings = render_scene(SCENES / "linkage.slider_crank_offset.toml")
    assert not [w for w in warnings if "page" in w]
    root = ET.fromstring(svg)
    captions = [(float(t.get("y")), "".join(t.itertext())) for t in root.iter() if t.tag.endswith("}text")
                and t.text and t.text.startswith(("Kinematic", "Velocity", "Acceleration"))]
    ys = {round(y, 3) for y, _ in captions}
    assert len(captions) == 6 and len(ys) == 2  # three panels a row, one row per position
    assert {t for y, t in captions if round(y, 3) == min(ys)} == {plain(c) for c in (
        "Kinematic diagram, φ₁ = 50°", "Velocity polygon, φ₁ = 50°", "Acceleration polygon, φ₁ = 50°")}


def test_precision_on_the_command_line_reaches_every_kind_of_scene():
    """--precision widens the tolerance of a force scene's measured reaction too (it once read the scene's only)."""
    scene = SCENES / "force.sixbar_kinetostatic.toml"
    r12 = values(check_json(scene))["R_12"]
    off = r12["graphical"] + 0.8 * r12["scale"]  # 0.8 mm of the polygon off at μF
    code, out, _ = run_cli("check", str(scene), "--json", "--measured", f"R_12={off}")
    assert code == 1 and json.loads(out)["measured"][0]["tolerance"] == pytest.approx(0.5 * r12["scale"])
    code, out, _ = run_cli("check", str(scene), "--json", "--measured", f"R_12={off}", "--precision", "1")
    verdict = json.loads(out)["measured"][0]
    assert code == 0 and verdict["ok"] and verdict["tolerance"] == pytest.approx(1.0 * r12["scale"])


# ---------------------------------------------------------------------------- one line, naming the file


def test_a_control_character_in_a_measured_name_stays_on_one_line():
    scene = SCENES / "fly.ic_engine_flywheel.toml"
    err = assert_refused(run_cli("check", str(scene), "--measured", "J_F\nX\x1b[31m=3"),
                         "fly.ic_engine_flywheel.toml", "--measured")
    assert "J_F\\nX\\x1b[31m" in err


def test_a_problem_found_below_the_scene_reader_names_the_scene_file(tmp_path):
    """The exact machine raises with the section it knows ("machine"); the message still starts
    with the scene file and keeps the section and key."""
    text = (SCENES / "fly.ic_engine_flywheel.toml").read_text(encoding="utf-8")
    scene = tmp_path / "no-work.toml"
    scene.write_text(text.replace("moment_Nm = [0, 200, 200, 0]", "moment_Nm = [0, 0, 0, 0]"), encoding="utf-8")
    for argv in (("check", str(scene)), ("render", str(scene), "-o", str(tmp_path / "x.svg"))):
        assert_refused(run_cli(*argv), "no-work.toml", "machine: loads: the loads do no work")
    assert not (tmp_path / "x.svg").exists()


def test_warnings_name_the_scene_file_and_numpy_says_nothing(tmp_path):
    text = (SCENES / "cam.law_maxima-cosine.toml").read_text(encoding="utf-8")
    scene = tmp_path / "soft.toml"
    scene.write_text(text, encoding="utf-8")
    code, out, err = run_cli("check", str(scene))
    assert code == 0 and err
    assert all(line.startswith("soft.toml: warning: ") for line in err.splitlines())


def test_numpy_warnings_never_reach_stderr(tmp_path):
    """A flat-face cam on a base circle of 1e-300 mm divides by zero inside numpy (ten
    RuntimeWarnings when run bare); the command says only its own one-line warnings."""
    doc = (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8")
    block = doc.split('title = "Flat-face follower, cosine rise, 3-4-5 return"', 1)[1].split("```", 1)[0]
    scene = tmp_path / "flat.toml"
    scene.write_text('title = "flat"' + block.replace("base_radius = 40", "base_radius = 1e-300"), encoding="utf-8")
    for argv in (("check", str(scene)), ("render", str(scene), "-o", str(tmp_path / "f.svg"))):
        code, out, err = run_cli(*argv)
        assert code in (0, 2), err
        assert "RuntimeWarning" not in err and "encountered" not in err
        lines = err.splitlines()
        assert all(ln.startswith("flat.toml: ") for ln in lines) and (code == 0 or len(lines) == 1), err


def test_check_json_is_the_same_whatever_the_hash_seed():
    """A stated set of scales once came out in a set's order (PYTHONHASHSEED): the cam's μ listed
    l, φ, s in one run and s, l, φ in the next. Two seeds, the same bytes."""
    scene = SCENES / "cam.oscillating_roller.toml"
    outs = [subprocess.run([sys.executable, "-m", "graphmech", "check", str(scene), "--json"], cwd=ROOT,
                           capture_output=True, text=True, env={**os.environ, "PYTHONHASHSEED": seed}).stdout
            for seed in ("1", "2", "3")]
    assert outs[0] and outs[0] == outs[1] == outs[2]
    assert list(json.loads(outs[0])["scales"])[:3] == ["l", "s", "phi"]


def test_page_on_the_command_line_is_read_with_the_scene(tmp_path):
    """--page replaces [page] size before the scene is read: a reader that refuses a sheet too
    small for its positions sees the paper given on the command line."""
    p = tmp_path / "three.toml"
    p.write_text(fourbar_scene(scales=STATED, title="Four-bar").replace("angle = 165", "angle = [30, 90, 165]"),
                 encoding="utf-8")
    assert_refused(run_cli("render", str(p), "-o", str(tmp_path / "a4.svg")), "three.toml", "3 positions do not fit")
    assert run_cli("render", str(p), "--page", "A3", "-o", str(tmp_path / "a3.svg"))[0] == 0
    root = ET.fromstring((tmp_path / "a3.svg").read_text(encoding="utf-8"))
    assert (root.get("width"), root.get("height")) == ("420mm", "297mm")
    assert run_cli("render", str(p), "--page", "a2", "-o", str(tmp_path / "a2.svg"))[0] == 0  # any case
    assert ET.fromstring((tmp_path / "a2.svg").read_text(encoding="utf-8")).get("width") == "594mm"


def test_a_fit_page_is_cropped_to_the_drawing(tmp_path):
    out = tmp_path / "fit.svg"
    assert run_cli("render", str(SCENES / "thread.m20_lead_angles-fine.toml"), "--page", "fit", "-o", str(out))[0] == 0
    root = ET.fromstring(out.read_text(encoding="utf-8"))
    w, h = (float(root.get(k).removesuffix("mm")) for k in ("width", "height"))
    assert w < 297.0 and h < 210.0 and w * h < 0.5 * 297.0 * 210.0  # the scene's A4 was mostly empty
    again = tmp_path / "again.svg"
    assert run_cli("render", str(SCENES / "thread.m20_lead_angles-fine.toml"), "--page", "fit", "-o", str(again))[0] == 0
    assert out.read_bytes() == again.read_bytes()


def test_page_on_the_command_line_reaches_check(tmp_path):
    p = scene(tmp_path, scales="")  # graphmech chooses μ for the page
    small, large = check_json(p, "--page", "A4"), check_json(p, "--page", "A1")
    assert small["scales"]["l"] > large["scales"]["l"]  # more paper, a larger drawing
    assert check_json(p) == small  # the scene's own page is A4


@pytest.mark.parametrize("command", ["render", "check"])
def test_an_unknown_page_is_one_line(tmp_path, capsys, command):
    from graphmech.cli import main

    with pytest.raises(SystemExit) as stop:  # argparse's own exit, as for any bad option
        main([command, str(scene(tmp_path)), "--page", "A5"])
    out, err = capsys.readouterr()
    assert stop.value.code == 2 and out == "" and err.count("\n") == 1
    assert "--page" in err and "unknown paper 'A5'" in err
    assert "A4, A4-portrait, A3, A3-portrait, A2, A2-portrait, A1, A1-portrait, fit" in err


def test_steps_prints_the_numbered_construction_protocol():
    code, out, err = run_cli("steps", str(SCENES / "kin.oscillating_block.toml"))
    lines = out.splitlines()
    assert code == 0 and err == "" and len(lines) == 31
    assert [line.split(". ", 1)[0] for line in lines] == [str(k) for k in range(1, 32)]
    assert lines[9] == "10. through b draw a line ⟂ BC"
    assert lines[-1] == "31. measure p′e′ = 56.68 mm: a_E = p′e′·μa = 2.834 m/s²"


def test_steps_of_a_kind_without_a_protocol_is_refused_in_one_line(monkeypatch):
    import dataclasses

    from graphmech.problems import KINDS

    monkeypatch.setitem(KINDS, "cycle", dataclasses.replace(KINDS["cycle"], steps=None))  # a kind to come
    err = assert_refused(run_cli("steps", str(SCENES / "linkage.slider_crank_offset-cycle.toml")),
                         "linkage.slider_crank_offset-cycle.toml", "no construction protocol for a cycle scene yet")
    assert "linkage" in err and "flywheel" in err and "forces" in err


def test_help_points_to_the_installed_scene_format_and_lists_the_exit_codes(capsys):
    import pytest as _pytest

    from graphmech.packaged import docs

    for argv in (["--help"], ["render", "--help"], ["batch", "--help"]):
        with _pytest.raises(SystemExit) as e:
            from graphmech.cli import main

            main(argv)
        out = capsys.readouterr().out
        assert e.value.code == 0
        assert str(docs().joinpath("scene-format.md")) in out and docs().joinpath("scene-format.md").is_file()
        assert "exit status:" in out and "  2  bad input" in out and "  1  a measured value" in out
    with _pytest.raises(SystemExit):
        main(["render", "--help"])
    assert "--set KEY=V1[,V2…]" in capsys.readouterr().out
