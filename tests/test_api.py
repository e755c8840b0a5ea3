"""The Python API: a scene as a Problem — check table, drawing, variants — agreeing with the command."""
from __future__ import annotations

import json
import sys

import pytest

import graphmech as gm
from graphmech.api import ROW_FIELDS, CheckTable, Drawing, Problem
from graphmech.errors import GraphmechError, SceneError
from tests.conftest import SCENES, run_cli

BLOCK = SCENES / "kin.oscillating_block.toml"


def test_the_package_exports_the_api_lazily():
    assert {"load", "loads", "from_dict", "Problem", "CheckTable", "Drawing"} <= set(dir(gm))
    assert gm.load is gm.api.load and gm.Problem is Problem
    with pytest.raises(AttributeError, match="no attribute 'nope'"):
        gm.nope  # noqa: B018


def test_check_rows_carry_the_fields_of_check_json():
    table = gm.load(BLOCK).check()
    code, out, _ = run_cli("check", str(BLOCK), "--json")
    assert code == 0 and json.loads(out) == table.to_dict() == json.loads(table.to_json())
    assert [r.name for r in table] == ["l_BC", "omega_2", "alpha_2", "v_C2C3", "a_k_C2C3", "v_D", "a_D", "v_E", "a_E"]
    assert set(ROW_FIELDS) == set(table.to_dict()["quantities"][0])
    row = table["v_E"]
    assert row is table[7] and row.graphical == pytest.approx(row.drawn_mm * row.scale, rel=1e-15)
    assert row.rel_error < 1e-9 and row.error_source == "construction"
    assert len(table) == 9 and table.ok and table.measured == ()
    with pytest.raises(KeyError, match="'v_Z': not in the check table"):
        table["v_Z"]


def test_the_text_table_is_what_check_prints():
    code, out, _ = run_cli("check", str(BLOCK))
    assert code == 0 and out == gm.load(BLOCK).check().text() + "\n" == str(gm.load(BLOCK).check()) + "\n"


def test_measured_values_are_judged_as_on_the_command_line():
    p = gm.load(BLOCK)
    exact = p.check()["v_E"].exact
    table = p.check(measured={"v_E": exact * 1.001, "omega_2": 99.0})
    assert [(v.name, v.ok) for v in table.measured] == [("v_E", True), ("omega_2", False)] and not table.ok
    # the command line's values are as written: the API judges strings so
    table = p.check(measured={"v_E": repr(exact * 1.001), "omega_2": "99"})
    assert [(v.name, v.ok, v.written) for v in table.measured] == [("v_E", True, repr(exact * 1.001)),
                                                                   ("omega_2", False, "99")]
    code, out, _ = run_cli("check", str(BLOCK), "--json", f"--measured=v_E={exact * 1.001!r},omega_2=99")
    assert code == 1 and json.loads(out)["measured"] == [v.as_dict() for v in table.measured]
    assert p.check([("v_E", exact)], precision=0.01).measured[0].tolerance < table.measured[0].tolerance
    for bad in ("fast", float("nan"), float("inf"), None, True):
        with pytest.raises(SceneError, match="measured.v_E: must be a finite number"):
            p.check(measured={"v_E": bad})
    with pytest.raises(TypeError, match="measured takes"):
        p.check(measured=["pe"])
    for precision in (-1, 0, float("nan"), 11):
        with pytest.raises(SceneError, match="precision: must be a number of mm above 0 and at most 10"):
            p.check(precision=precision)


@pytest.mark.parametrize("value", [float("nan"), float("inf")])
def test_a_measured_value_that_is_no_finite_number_is_refused(value):
    """A NaN was judged (ok=False) and then to_json raised ValueError."""
    with pytest.raises(SceneError) as e:
        gm.load(BLOCK).check(measured={"pe": value})
    assert str(e.value) == f"kin.oscillating_block.toml: measured.pe: must be a finite number, not {value!r}"


@pytest.mark.parametrize("measured", ["pe=34", [34.0], [("pe",)], 5])
def test_measured_in_another_shape_is_a_type_error_saying_the_shape(measured):
    with pytest.raises(TypeError, match=r'measured takes \{"pc": 40.5, …\} or \[\("pc", 40.5\), …\]'):
        gm.load(BLOCK).check(measured=measured)


@pytest.mark.parametrize("precision", [0, -1, float("nan"), 11])
def test_a_precision_the_command_would_refuse_is_refused(precision):
    """A negative or NaN tolerance was used as given (every verdict 'out of tolerance')."""
    with pytest.raises(SceneError, match="precision: must be a number of mm above 0 and at most 10"):
        gm.load(BLOCK).check(measured={"pe": 34.4}, precision=precision)
    with pytest.raises(TypeError, match="precision is a number of mm"):
        gm.load(BLOCK).check(precision="1")  # type: ignore[arg-type]


def test_to_pandas_is_a_data_frame_with_the_row_fields():
    pd = pytest.importorskip("pandas")  # a test dependency; graphmech itself never needs it
    frame = gm.load(BLOCK).check().to_pandas()
    assert isinstance(frame, pd.DataFrame) and list(frame.columns) == list(ROW_FIELDS) and len(frame) == 9
    assert frame.set_index("name").loc["v_E", "exact"] == gm.load(BLOCK).check()["v_E"].exact


def test_to_pandas_without_pandas_says_what_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas → ImportError
    with pytest.raises(GraphmechError, match="pip install pandas"):
        gm.load(BLOCK).check().to_pandas()


def test_the_drawing_is_the_commands_svg_and_jupyter_shows_it(tmp_path):
    drawing = gm.load(BLOCK).render()
    code, _, _ = run_cli("render", str(BLOCK), "-o", str(tmp_path / "cli.svg"))
    assert code == 0 and drawing.svg == (tmp_path / "cli.svg").read_text(encoding="utf-8")
    assert drawing._repr_svg_() == drawing.svg and isinstance(drawing, Drawing)
    assert drawing.save(tmp_path / "api.svg") == tmp_path / "api.svg"
    assert (tmp_path / "api.svg").read_bytes() == (tmp_path / "cli.svg").read_bytes()


def test_loads_and_from_dict_read_as_the_file_does():
    text = BLOCK.read_text(encoding="utf-8")
    a, b = gm.loads(text, "kin.oscillating_block.toml"), gm.load(BLOCK)
    assert a.render().svg == b.render().svg  # the same bytes, the same ids
    import tomllib

    c = gm.from_dict(tomllib.loads(text), "block.toml")
    assert c.check().to_dict() == b.check().to_dict() and c.name == "block" and c.kind == "linkage"
    assert repr(c) == "<graphmech.Problem 'block': linkage, " + repr(b.title) + ">"


def test_loads_takes_bytes_and_refuses_what_is_no_text():
    text = BLOCK.read_text(encoding="utf-8")
    assert gm.loads(text.encode("utf-8")).check().to_dict() == gm.loads(text).check().to_dict()
    with pytest.raises(TypeError, match="loads takes the TOML text"):
        gm.loads(None)  # type: ignore[arg-type]
    with pytest.raises(SceneError, match="line 2: not UTF-8 text"):  # a lone surrogate: not an encoder's crash
        gm.loads("# x\ntitle = '\ud800'\n")


def test_from_dict_refuses_keys_that_are_no_text_and_data_that_contains_itself():
    """Both reached the scene reader and crashed there (AttributeError)."""
    data = gm.load(BLOCK).data
    with pytest.raises(SceneError, match=r"^scene.toml: driver.5: a key must be text"):
        gm.from_dict({**data, "driver": {**data["driver"], 5: 1}})
    loop: dict = {**data, "point": [dict(data["point"][0])]}
    loop["point"][0]["self"] = loop["point"]
    with pytest.raises(SceneError, match=r"^scene.toml: point\[0\].self: contains itself"):
        gm.from_dict(loop)


def test_from_dict_copies_the_dict_it_is_given():
    data = {k: (dict(v) if isinstance(v, dict) else v) for k, v in gm.load(BLOCK).data.items()}
    p = gm.from_dict(data)
    data["driver"]["angle"] = 60
    assert p.data["driver"]["angle"] == 45 and p.replace({"driver.omega": 10}).data["driver"]["angle"] == 45


@pytest.mark.parametrize("changes", [None, "driver.angle=60", [("driver.angle", 60)], {1: 60}])
def test_replace_takes_a_mapping_of_key_paths(changes):
    with pytest.raises(TypeError, match="replace takes a mapping of key paths to values"):
        gm.load(BLOCK).replace(changes)


def test_bad_scenes_raise_the_one_line_message():
    with pytest.raises(SceneError, match=r"^x.toml: line 1: invalid TOML"):
        gm.loads("title = ", "x.toml")
    with pytest.raises(SceneError, match=r"^scene.toml: driver.length: missing"):
        gm.from_dict({"frame": {"A_mm": [0, 0]}, "driver": {"type": "crank", "link": "1", "pivot": "A",
                                                             "tip": "B", "angle_deg": 0, "omega_rad_s": 1}})
    with pytest.raises(SceneError, match="a scene must be a table"):
        gm.from_dict([1, 2])  # type: ignore[arg-type]
    with pytest.raises(SceneError, match="cannot read the file"):
        gm.load(SCENES / "no-such.toml")


def test_a_variant_is_checked_and_named_and_the_original_kept():
    p = gm.load(BLOCK)
    v = p.replace({"driver.angle": 60, "driver.omega": 20})
    assert v.name == "kin.oscillating_block-driver.angle=60-driver.omega=20" and p.name == "kin.oscillating_block"
    assert v.variant == {"driver.angle": 60, "driver.omega": 20} and p.variant == {}
    # ω2 scales with ω1 at the same position
    assert v.check()["omega_2"].exact == pytest.approx(2 * p.replace({"driver.angle": 60}).check()["omega_2"].exact)
    assert v.check().to_dict()["variant"] == {"driver.angle": 60, "driver.omega": 20}
    assert v.render().svg != p.render().svg and v.prefix != p.prefix
    assert p.check()["omega_2"].exact == gm.load(BLOCK).check()["omega_2"].exact
    with pytest.raises(SceneError, match="kin.oscillating_block.toml: driver.angel: not in the scene"):
        p.replace({"driver.angel": 3})
    with pytest.raises(SceneError, match="driver.angle_deg|driver.angle"):
        p.replace({"driver.angle": "north"})  # the reader judges the value as the file's own


def test_another_page_chooses_other_paper():
    p = gm.load(BLOCK).with_page("fit")
    assert p.scene.page.fit and 'width="297mm"' not in p.render().svg


def test_the_check_table_shows_in_jupyter_as_html_with_text_escaped():
    p = gm.loads(BLOCK.read_text(encoding="utf-8").replace('title = "Oscillating block', 'title = "<b>x</b>'))
    html = p.check(measured={"v_E": 1.0})._repr_html_()
    assert html.startswith("<table><caption>&lt;b&gt;x&lt;/b&gt;") and html.count("<tr>") == 1 + 9 + 1
    assert "OUT OF TOLERANCE" in html and isinstance(p.check(), CheckTable)


def test_steps_is_the_construction_protocol_with_the_tables_numbers():
    p = gm.load(BLOCK)
    lines = p.steps()
    assert lines[0].startswith("choose μl = 0.002 m/mm") and len(lines) > 20
    pe = p.check()["v_E"]
    assert f"measure pe = {pe.drawn_mm:.2f} mm: v_E = pe·μv = {pe.graphical:.4f} m/s" in lines
    code, out, _ = run_cli("steps", str(BLOCK))
    assert code == 0 and out.splitlines() == [f"{k}. {line}" for k, line in enumerate(lines, 1)]
    assert gm.load(BLOCK).replace({"driver.angle": 60}).steps()[0].endswith("φ₁ = 60°")


def test_the_drawing_saved_where_it_cannot_be_names_the_path_given(tmp_path):
    drawing = gm.load(BLOCK).render()
    with pytest.raises(FileNotFoundError) as e:  # it named the temporary file, ".x.svg.k2j4.tmp"
        drawing.save(tmp_path / "none" / "x.svg")
    assert (e.value.filename, e.value.strerror) == (str(tmp_path / "none" / "x.svg"), "folder does not exist")
    with pytest.raises(IsADirectoryError):
        drawing.save(tmp_path)
    assert list(tmp_path.iterdir()) == []


def test_the_drawing_saves_as_pdf_and_png_by_extension(tmp_path):
    import os

    from graphmech.render.chromium import find_chromium
    from tests.browser import no_browser

    if find_chromium() is None:
        no_browser("CI" in os.environ)
    from PIL import Image
    from pypdf import PdfReader

    drawing = gm.load(BLOCK).render()
    drawing.save(tmp_path / "a.pdf")
    drawing.save(tmp_path / "a.png", dpi=72)
    drawing.save(tmp_path / "b", format="png")
    box = PdfReader(tmp_path / "a.pdf").pages[0].mediabox
    assert (round(float(box.width) / 72 * 25.4, 1), round(float(box.height) / 72 * 25.4, 1)) == (297.0, 210.0)
    with Image.open(tmp_path / "a.png") as a, Image.open(tmp_path / "b") as b:
        assert a.size == (842, 595) and b.size == (round(297 / 25.4 * 150), round(210 / 25.4 * 150))
    with pytest.raises(GraphmechError, match="unknown format .jpg"):
        drawing.save(tmp_path / "a.jpg")
    assert not (tmp_path / "a.jpg").exists()


def test_wrong_python_types_are_told_plainly(tmp_path):
    p = gm.load(BLOCK)
    with pytest.raises(TypeError, match="loads takes the TOML text"):
        gm.loads({"title": "x"})  # type: ignore[arg-type]
    assert gm.loads(BLOCK.read_bytes(), "kin.oscillating_block.toml").render().svg == p.render().svg
    with pytest.raises(SceneError, match=r"^scene.toml: driver.1: a key must be text"):
        gm.from_dict({"driver": {1: 2}})
    with pytest.raises(SceneError, match=r"dyad\[0\].2: a key must be text"):
        gm.from_dict({"dyad": [{2: 3}]})
    for bad in ([("driver.angle", 3)], {3: 4}):
        with pytest.raises(TypeError, match="replace takes a mapping"):
            p.replace(bad)  # type: ignore[arg-type]
    assert p.replace({}).name == p.name
    with pytest.raises(FileNotFoundError, match="folder does not exist: .*nowhere/x.svg"):
        p.render().save(tmp_path / "nowhere" / "x.svg")
    assert list(tmp_path.iterdir()) == []
