"""`hikari render --formulas`: a workbook whose cells compute the assignment with spreadsheet
formulas. LibreOffice recalculates it (headless), and its 8-bit cells must be hikari's render;
changing n in the workbook's parameter cell must change the picture as the render with that n."""

import os
import re
import shutil
import subprocess
import zipfile

import numpy as np
import pytest

from conftest import CLI, scene_path

SOFFICE = shutil.which("soffice")
needs_soffice = pytest.mark.skipif(
    SOFFICE is None,
    reason="LibreOffice (soffice) is not installed; scripts/install-deps.sh --ci installs "
    "libreoffice-calc-nogui",
)

SIZE = ["--width", "20", "--height", "16"]

# LibreOffice keeps the cached results of an .xlsx unless told to recalculate on loading
# (Tools > Options > Calc > Formula: "Excel 2007 and newer: Always recalculate").
ALWAYS_RECALCULATE = """<?xml version="1.0" encoding="UTF-8"?>
<oor:items xmlns:oor="http://openoffice.org/2001/registry"
           xmlns:xs="http://www.w3.org/2001/XMLSchema"
           xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
<item oor:path="/org.openoffice.Office.Calc/Formula/Load">
<prop oor:name="OOXMLRecalcMode" oor:op="fuse"><value>0</value></prop></item>
</oor:items>
"""


def read_ppm(path):
    with open(path, "rb") as f:
        assert f.readline().strip() == b"P6"
        width, height = map(int, f.readline().split())
        assert int(f.readline()) == 255
        return np.frombuffer(f.read(), np.uint8).reshape(height, width, 3).astype(int)


def render_ppm(tmp_path, *args):
    out = tmp_path / "render.ppm"
    subprocess.run([CLI, "render", scene_path("assignment.json"), *SIZE, *args, "-o", str(out),
                    "-q"], check=True)
    return read_ppm(out)


def recalculated_sheets(tmp_path, workbooks):
    """Every sheet of each workbook after LibreOffice recalculated it (one LibreOffice run for
    all), as arrays of numbers: {workbook stem: {sheet: array}}."""
    profile = tmp_path / "profile"
    (profile / "user").mkdir(parents=True, exist_ok=True)
    (profile / "user" / "registrymodifications.xcu").write_text(ALWAYS_RECALCULATE)
    out = tmp_path / "csv"
    csv_all_sheets = "csv:Text - txt - csv (StarCalc):44,34,76,1,,0,false,true,false,false,false,-1"
    subprocess.run([SOFFICE, f"-env:UserInstallation={profile.as_uri()}", "--headless",
                    "--convert-to", csv_all_sheets, "--outdir", str(out),
                    *[str(w) for w in workbooks]],
                   check=True, capture_output=True, timeout=280)
    books = {}
    for workbook in workbooks:
        sheets = books.setdefault(workbook.stem, {})
        for name in os.listdir(out):
            if not name.startswith(workbook.stem + "-"):
                continue
            sheet = name[len(workbook.stem) + 1:-4]
            rows = [line.split(",") for line in (out / name).read_text().splitlines()]
            if sheet != "parameters":
                sheets[sheet] = np.array([[float(v) for v in row] for row in rows])
    return books


def read_workbook(path):
    with zipfile.ZipFile(path) as z:
        return {name: z.read(name) for name in z.namelist()}


def write_workbook(path, files):
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files.items():
            z.writestr(name, data)


def without_stored_results(source, target):
    """A copy of the workbook `source` whose formulas' stored results are all 0: whatever
    LibreOffice then shows, it computed."""
    files = read_workbook(source)
    for name in files:
        if name.startswith("xl/worksheets/sheet"):
            files[name] = re.sub(rb"(</f>)<v>[^<]*</v>", rb"\g<1><v>0</v>", files[name])
    write_workbook(target, files)


def stored_results(path, sheet_number, shape):
    """The results stored with the formulas of a sheet (sheetN.xml), row by row."""
    xml = read_workbook(path)[f"xl/worksheets/sheet{sheet_number}.xml"].decode()
    values = [float(v) for v in re.findall(r"</f><v>([^<]*)</v>", xml)]
    return np.array(values).reshape(shape)


def with_exponent(source, target, n):
    """A copy of the workbook `source` whose Phong exponent cell (the name shininess_n) holds n."""
    files = read_workbook(source)
    book = files["xl/workbook.xml"].decode()
    cell = re.search(r'<definedName name="shininess_n">parameters!\$([A-Z]+)\$(\d+)<', book)
    assert cell, "the workbook names its exponent cell shininess_n"
    ref = cell.group(1) + cell.group(2)
    sheet_name = "xl/worksheets/sheet2.xml"  # "parameters", the second sheet
    xml = files[sheet_name].decode()
    edited, count = re.subn(rf'(<c r="{ref}"[^>]*><v>)[^<]*(</v>)', rf"\g<1>{n}\g<2>", xml)
    assert count == 1
    files[sheet_name] = edited.encode()
    write_workbook(target, files)


def formula_workbook(tmp_path, encoding, *args):
    workbook = tmp_path / f"sphere-{encoding}.xlsx"
    subprocess.run([CLI, "render", scene_path("assignment.json"), *SIZE, "--formulas",
                    "--encoding", encoding, *args, "-o", str(workbook), "-q"], check=True)
    return workbook


def pixel_codes(sheets):
    return np.stack([sheets["red"], sheets["green"], sheets["blue"]], axis=-1)


@needs_soffice
def test_recalculated_cells_are_the_render_and_follow_n(tmp_path):
    # Both encodings with their stored results zeroed (whatever LibreOffice shows, it computed),
    # and the linear one with n changed from 40 to 5 in its parameter cell.
    books = []
    for encoding in ("linear", "srgb"):
        computed = tmp_path / f"computed-{encoding}.xlsx"
        without_stored_results(formula_workbook(tmp_path, encoding), computed)
        books.append(computed)
    n5 = tmp_path / "n5.xlsx"
    with_exponent(formula_workbook(tmp_path, "linear"), n5, 5)
    books.append(n5)
    sheets = recalculated_sheets(tmp_path, books)
    for encoding in ("linear", "srgb"):
        cells = pixel_codes(sheets[f"computed-{encoding}"])
        expected = render_ppm(tmp_path, "--encoding", encoding)
        assert cells.shape == expected.shape
        # Doubles in the spreadsheet, floats in hikari: a code may round the other way.
        assert np.abs(cells - expected).max() <= 1, encoding
        assert (cells != expected).mean() < 0.02, encoding
        # The picture covers the sphere exactly where the render does (not the background).
        on_sphere = sheets[f"computed-{encoding}"]["image"] >= 0
        assert on_sphere.sum() > 20
        assert np.all(np.any(expected[on_sphere] != expected[0, 0], axis=-1))
    cells = pixel_codes(sheets["n5"])
    expected = render_ppm(tmp_path, "--encoding", "linear", "--set", "materials.clay.shininess=5")
    assert np.abs(cells - expected).max() <= 1
    assert np.abs(cells - render_ppm(tmp_path, "--encoding", "linear")).max() > 10


def test_stored_results_are_the_render(tmp_path):
    """What a spreadsheet shows before it recalculates (LibreOffice's default) is the picture."""
    workbook = formula_workbook(tmp_path, "linear")
    expected = render_ppm(tmp_path, "--encoding", "linear")
    shape = expected.shape[:2]
    # Sheets 13, 14, 15: red, green, blue (after image, parameters, E_x..z, D, t, N_x..z,
    # cos_alpha, cos_gamma).
    stored = np.stack([stored_results(workbook, n, shape) for n in (13, 14, 15)], axis=-1)
    assert np.abs(stored - expected).max() <= 1


def test_scenes_it_cannot_express_are_refused(tmp_path):
    out = tmp_path / "w.xlsx"
    result = subprocess.run([CLI, "render", scene_path("whitted.json"), "--formulas", "-o",
                             str(out)], capture_output=True, text=True)
    assert result.returncode == 1
    assert "--formulas cannot express this scene" in result.stderr
    assert not out.exists()
    result = subprocess.run([CLI, "render", scene_path("assignment.json"), "--formulas", "-o",
                             str(tmp_path / "w.png")], capture_output=True, text=True)
    assert result.returncode == 2
    assert "spreadsheet" in result.stderr
