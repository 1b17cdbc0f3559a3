#!/usr/bin/env python3
"""How sampled area-light shadows converge to the analytic ones (docs/lights.md).

Renders scenes/soft-shadow.json with `--shadows analytic` (exact: the scene has no highlights)
and with `--light-samples N` for N = 1, 2, 4, ..., 1024, measures the RMS error of each against
the analytic image, fits the slope of log(error) against log(N), and plots both with gnuplot
into docs/images/light-samples-convergence.png. Run from the repository root after building
(`build/hikari`); needs gnuplot (Debian: gnuplot-nox) for the plot, nothing for the numbers."""
import math
import os
import struct
import subprocess
import sys
import tempfile

HIKARI = os.environ.get("HIKARI", "build/hikari")
SCENE = "scenes/soft-shadow.json"
PLOT = "docs/images/light-samples-convergence.png"


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        channels = 3 if kind == b"PF" else 1
        fmt = ("<" if scale < 0 else ">") + "f" * (width * height * channels)
        return struct.unpack(fmt, f.read(4 * width * height * channels))


def render(args, out):
    subprocess.run([HIKARI, "render", SCENE, "-q", "-o", out] + args, check=True)
    return read_pfm(out)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        reference = render(["--shadows", "analytic"], os.path.join(tmp, "ref.pfm"))
        rows = []
        n = 1
        while n <= 1024:
            image = render(["--light-samples", str(n)], os.path.join(tmp, f"s{n}.pfm"))
            mse = sum((a - b) ** 2 for a, b in zip(image, reference)) / len(reference)
            rows.append((n, math.sqrt(mse)))
            n *= 2
    xs = [math.log(n) for n, _ in rows]
    ys = [math.log(e) for _, e in rows]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    for n, e in rows:
        print(f"{n:5d} samples: RMS error {e:.6f}")
    print(f"slope of log(error) over log(samples): {slope:.3f}")
    data = "\n".join(f"{n} {e}" for n, e in rows)
    first = rows[0][1]
    script = f"""
set terminal pngcairo size 720,480 font ",11"
set output "{PLOT}"
set logscale x 2
set logscale y 10
set format y "10^{{%L}}"
set xlabel "--light-samples N (per area light per shaded point)"
set ylabel "RMS error against --shadows analytic"
set title "Stratified area-light sampling converges to the analytic soft shadow (slope {slope:.2f})"
set key top right
set grid
plot "-" using 1:2 with linespoints lw 2 pt 7 title "measured (scenes/soft-shadow.json)", \\
     {first}*x**-0.5 with lines dt 2 title "N^{{-1/2}} (independent samples)", \\
     {first}*x**-0.75 with lines dt 3 title "N^{{-3/4}} (stratified, shadow edges crossing the strata)"
{data}
e
"""
    try:
        subprocess.run(["gnuplot"], input=script.encode(), check=True)
        print(f"wrote {PLOT}")
    except FileNotFoundError:
        print("gnuplot not found: no plot written", file=sys.stderr)


if __name__ == "__main__":
    main()
