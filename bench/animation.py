#!/usr/bin/env python3
"""Issue 45's targets, timed as users run them (benchmarks, never tests):

  - a 120-frame 1280x720 zbuffer turntable of the bunny (default lights, shadow maps), PNG
    frames written: frames per second, from hikari's own summary line;
  - a path-traced animation's frames on 1 and 2 MPI ranks (one thread each): the speed-up;
  - one path-traced image on 1 and 2 MPI ranks (one thread each): the speed-up, and that the
    files are the same bytes.

Usage: bench/animation.py [--hikari build/hikari] [--runs 3] [--ranks 2]
Prints the median of each figure over the runs. The MPI lines need `mpirun` (openmpi-bin).
"""
import argparse
import filecmp
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def timed(command, env=None):
    start = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    seconds = time.perf_counter() - start
    if result.returncode != 0:
        sys.exit(f"failed ({result.returncode}): {' '.join(command)}\n{result.stderr}")
    return seconds, result.stderr


def mpirun(ranks):
    return ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--hikari", default=os.path.join(ROOT, "build", "hikari"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--ranks", type=int, default=2)
    args = parser.parse_args()
    hikari = args.hikari
    env = dict(os.environ, OMPI_MCA_btl="self,vader",
               OMPI_MCA_btl_vader_single_copy_mechanism="none")
    work = tempfile.mkdtemp(prefix="hikari-bench-")
    try:
        bunny = os.path.join(ROOT, "scenes", "models", "stanford-bunny.obj")
        fps = []
        for _ in range(args.runs):
            _, err = timed([hikari, "render", bunny, "-m", "zbuffer", "--turntable", "120",
                            "--width", "1280", "--height", "720", "--overwrite",
                            "-o", os.path.join(work, "bunny_%03d.png")])
            fps.append(float(re.search(r"([0-9.]+) frames/s", err).group(1)))
        print(f"zbuffer bunny turntable 120 x 1280x720 PNG: median {statistics.median(fps):.1f} "
              f"frames/s (target >= 25)")
        if not shutil.which("mpirun"):
            print("mpirun is not installed: MPI lines left out (apt-get install openmpi-bin)")
            return
        animation = os.path.join(ROOT, "scenes", "animation.json")
        frames = ["-m", "path", "--spp", "16", "--width", "320", "--height", "240",
                  "--threads", "1", "-q", "--frames", "0-11", "--overwrite"]
        one, many = [], []
        for _ in range(args.runs):
            one.append(timed([hikari, "render", animation, *frames,
                              "-o", os.path.join(work, "a1_%02d.png")], env)[0])
            many.append(timed([*mpirun(args.ranks), hikari, "render", animation, *frames,
                               "-o", os.path.join(work, "a2_%02d.png")], env)[0])
        print(f"path animation 12 frames, 1 thread per rank: 1 rank {statistics.median(one):.2f} s, "
              f"{args.ranks} ranks {statistics.median(many):.2f} s, speed-up "
              f"{statistics.median(one) / statistics.median(many):.2f}x (target >= 1.8x for 2)")
        glass = os.path.join(ROOT, "scenes", "cornell-glass.json")
        still = ["-m", "path", "--spp", "64", "--width", "320", "--height", "240",
                 "--threads", "1", "-q"]
        one, many = [], []
        for _ in range(args.runs):
            one.append(timed([hikari, "render", glass, *still,
                              "-o", os.path.join(work, "one.exr")], env)[0])
            many.append(timed([*mpirun(args.ranks), hikari, "render", glass, *still,
                               "-o", os.path.join(work, "many.exr")], env)[0])
        same = filecmp.cmp(os.path.join(work, "one.exr"), os.path.join(work, "many.exr"),
                           shallow=False)
        print(f"one path-traced image (cornell-glass, caustics) 320x240 64 spp: 1 rank "
              f"{statistics.median(one):.2f} s, {args.ranks} ranks {statistics.median(many):.2f} s, "
              f"speed-up {statistics.median(one) / statistics.median(many):.2f}x, "
              f"{'same bytes' if same else 'FILES DIFFER'}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
