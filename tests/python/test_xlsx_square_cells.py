"""The picture sheet of a workbook (`-o image.xlsx`, with and without --formulas) has square
cells in LibreOffice: its columns as wide as its rows are tall, as LibreOffice itself lays them
out (read back from its own OpenDocument conversion)."""

import re
import shutil
import subprocess
import zipfile

import pytest

from conftest import CLI, scene_path

SOFFICE = shutil.which("soffice")


def picture_cell_size(ods):
    """(column width, row height) in inches of the first sheet's first cell, as LibreOffice
    stored them."""
    with zipfile.ZipFile(ods) as z:
        xml = z.read("content.xml").decode()
    sizes = dict(re.findall(r'<style:style style:name="((?:co|ro)\d+)"[^>]*>\s*<style:table-'
                            r'(?:column|row)-properties[^>]*?style:(?:column-width|row-height)='
                            r'"([0-9.]+)in"', xml))
    sheet = re.search(r"<table:table .*?</table:table>", xml, re.S).group(0)
    column = re.search(r'<table:table-column table:style-name="(co\d+)"', sheet).group(1)
    row = re.search(r'<table:table-row table:style-name="(ro\d+)"', sheet).group(1)
    return float(sizes[column]), float(sizes[row])


@pytest.mark.skipif(SOFFICE is None, reason="LibreOffice (soffice) is not installed")
@pytest.mark.parametrize("formulas", [[], ["--formulas"]])
def test_picture_cells_are_square_in_libreoffice(tmp_path, formulas):
    workbook = tmp_path / "sphere.xlsx"
    subprocess.run([CLI, "render", scene_path("assignment.json"), "--width", "6", "--height",
                    "4", *formulas, "-o", str(workbook), "-q"], check=True)
    profile = tmp_path / "profile"
    subprocess.run([SOFFICE, f"-env:UserInstallation={profile.as_uri()}", "--headless",
                    "--convert-to", "ods", "--outdir", str(tmp_path), str(workbook)],
                   check=True, capture_output=True, timeout=280)
    width, height = picture_cell_size(tmp_path / "sphere.ods")
    # LibreOffice keeps 4 decimals of an inch; a fallback monospace font may differ from Courier
    # New's 0.6 em by 0.5%.
    assert width == pytest.approx(height, rel=0.01)
