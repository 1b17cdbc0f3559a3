#!/usr/bin/env python3
"""Runs every code cell of a Jupyter notebook in order, as a kernel would, with Debian's python3
and no Jupyter: the test suite runs docs/notebooks/lecture.ipynb this way so it never goes stale.

    python3 scripts/run-notebook.py NOTEBOOK            # run; exit 1 naming the failing cell
    python3 scripts/run-notebook.py NOTEBOOK --write    # run and save the outputs in the file

Cells run in the notebook's folder (Jupyter's working directory) in one namespace. What a cell
prints, what it passes to display(), and the value of its last expression become its outputs
(image/png where the value has _repr_png_, as Jupyter shows it, and text/plain).
"""

import argparse
import ast
import base64
import contextlib
import io
import json
import os
import sys
import traceback


def rich_output(value, count=None):
    """A display_data (or execute_result) output for `value`, as Jupyter would show it."""
    data = {"text/plain": repr(value)}
    show_png = getattr(value, "_repr_png_", None)
    if callable(show_png):
        png = show_png()
        if png:
            data["image/png"] = base64.b64encode(png).decode("ascii")
    if count is None:
        return {"output_type": "display_data", "data": data, "metadata": {}}
    return {"output_type": "execute_result", "execution_count": count, "data": data,
            "metadata": {}}


def run_cell(source, namespace, count):
    """Runs one cell; its outputs, in order. The last expression's value is shown, as in IPython."""
    outputs = []
    printed = io.StringIO()

    def flush_printed():
        text = printed.getvalue()
        if text:
            outputs.append({"output_type": "stream", "name": "stdout", "text": text})
            printed.seek(0)
            printed.truncate()

    def display(*values):
        flush_printed()
        outputs.extend(rich_output(v) for v in values)

    namespace["display"] = display
    tree = ast.parse(source)
    last = tree.body.pop() if tree.body and isinstance(tree.body[-1], ast.Expr) else None
    with contextlib.redirect_stdout(printed):
        exec(compile(tree, "<cell>", "exec"), namespace)
        value = eval(compile(ast.Expression(last.value), "<cell>", "eval"),
                     namespace) if last else None
    flush_printed()
    if value is not None:
        outputs.append(rich_output(value, count))
    return outputs


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("notebook")
    parser.add_argument("--write", action="store_true", help="save the outputs in the notebook")
    args = parser.parse_args()
    path = os.path.abspath(args.notebook)
    with open(path, encoding="utf-8") as f:
        notebook = json.load(f)
    os.chdir(os.path.dirname(path))
    namespace = {"__name__": "__main__"}
    count = 0
    for index, cell in enumerate(notebook["cells"]):
        if cell["cell_type"] != "code":
            continue
        count += 1
        source = "".join(cell["source"])
        try:
            outputs = run_cell(source, namespace, count)
        except Exception:  # noqa: BLE001 -- any failure of a cell fails the run, named
            print(f"{args.notebook}: code cell {count} (cell {index}) failed:\n{source}\n",
                  file=sys.stderr)
            traceback.print_exc()
            return 1
        cell["execution_count"] = count
        cell["outputs"] = outputs
    if args.write:
        with open(path, "w", encoding="utf-8") as f:
            json.dump(notebook, f, indent=1, ensure_ascii=False)
            f.write("\n")
    print(f"{args.notebook}: {count} code cells ran")
    return 0


if __name__ == "__main__":
    sys.exit(main())
