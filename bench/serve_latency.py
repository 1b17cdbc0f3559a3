#!/usr/bin/env python3
"""How long `hikari serve` takes to answer a camera drag (issue 43's targets): the first frame the
page shows after each camera move, per method, as the page asks for it (zbuffer: the full frame;
raytrace: the quarter-size pass; path: the quarter-size pass at 1 sample per pixel).

    bench/serve_latency.py [MODEL_OR_SCENE] [--size 1280x720] [--moves 20] [--threads N]

Starts build/hikari serve on loopback, orbits the camera in small steps (as a drag does) and
prints the median and 90th percentile of the request-to-last-byte time for each method. A
benchmark, never a test: nothing here asserts a time."""

import argparse
import json
import math
import os
import re
import signal
import statistics
import subprocess
import time
import urllib.request

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OPENER = urllib.request.build_opener(urllib.request.ProxyHandler({}))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene", nargs="?", default="scenes/models/stanford-bunny.obj")
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--moves", type=int, default=20)
    parser.add_argument("--hikari", default=os.path.join(ROOT, "build", "hikari"))
    args = parser.parse_args()
    width, height = map(int, args.size.split("x"))
    server = subprocess.Popen([args.hikari, "serve", args.scene, "--port", "0", "--root", ROOT],
                              cwd=ROOT, stdout=subprocess.PIPE, text=True)
    try:
        url = re.search(r"http://[\d.]+:\d+", server.stdout.readline()).group(0)
        with OPENER.open(f"{url}/api/scene?scene={args.scene}", timeout=600) as r:
            camera = json.load(r)["camera"]
        target = camera["look_at"]
        offset = [e - t for e, t in zip(camera["eye"], target)]
        radius = math.hypot(offset[0], offset[2])
        start = math.atan2(offset[0], offset[2])
        passes = {
            "zbuffer": {"width": width, "height": height},
            "raytrace": {"width": width >> 2, "height": height >> 2},
            "path": {"width": width >> 2, "height": height >> 2, "options": {"spp": 1}},
        }
        print(f"hikari serve {args.scene}, {width}x{height}, {args.moves} camera moves "
              f"(2 warm-up), {os.cpu_count()} cores")
        for method, frame in passes.items():
            times = []
            for move in range(args.moves + 2):
                angle = start + 0.05 * move
                eye = [target[0] + radius * math.sin(angle), camera["eye"][1],
                       target[2] + radius * math.cos(angle)]
                body = dict(frame, scene=args.scene, method=method, client="bench",
                            camera={"eye": eye, "look_at": target, "up": camera["up"],
                                    "fov_y": camera["fov_y"]})
                request = urllib.request.Request(f"{url}/api/render",
                                                 data=json.dumps(body).encode(), method="POST")
                began = time.perf_counter()
                with OPENER.open(request, timeout=600) as r:
                    r.read()
                    render = float(r.headers["X-Hikari-Seconds"])
                if move >= 2:
                    times.append((time.perf_counter() - began, render))
            total = sorted(t for t, _ in times)
            renders = sorted(r for _, r in times)
            print(f"  {method:9s} {frame['width']}x{frame['height']}: median "
                  f"{1000 * statistics.median(total):7.1f} ms, p90 "
                  f"{1000 * total[int(0.9 * (len(total) - 1))]:7.1f} ms "
                  f"(render {1000 * statistics.median(renders):.1f} ms)")
    finally:
        server.send_signal(signal.SIGINT)
        server.wait(timeout=30)


if __name__ == "__main__":
    main()
