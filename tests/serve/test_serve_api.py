"""`hikari serve`'s HTTP API on loopback, as the page and scripts use it (docs/serve.md): frames
equal `hikari render`'s files, bad requests get 400 with the command line's message, paths
outside --root 403, a client's newer request replaces its older one, many clients at once."""

import json
import os
import re
import shutil
import signal
import subprocess
import threading
import time
import urllib.error
import urllib.request

import pytest

SOURCE = os.environ.get("HIKARI_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CLI = os.environ.get("HIKARI_CLI", os.path.join(SOURCE, "build", "hikari"))
# Loopback never goes through a proxy.
OPENER = urllib.request.build_opener(urllib.request.ProxyHandler({}))


class Server:
    def __init__(self, *args, cwd=None):
        self.process = subprocess.Popen([CLI, "serve", "--port", "0", *args], cwd=cwd,
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                        text=True)
        line = self.process.stdout.readline()
        match = re.search(r"http://([\d.]+):(\d+)/", line)
        assert match, line + self.process.stderr.read()
        self.url = f"http://{match.group(1)}:{match.group(2)}"

    def get(self, path):
        return self.call(urllib.request.Request(self.url + path))

    def post(self, path, body):
        data = body if isinstance(body, (bytes, str)) else json.dumps(body)
        if isinstance(data, str):
            data = data.encode()
        return self.call(urllib.request.Request(self.url + path, data=data, method="POST"))

    @staticmethod
    def call(request):
        try:
            with OPENER.open(request, timeout=120) as r:
                return r.status, r.read(), dict(r.headers)
        except urllib.error.HTTPError as e:
            return e.code, e.read(), dict(e.headers)

    def stop(self):
        self.process.send_signal(signal.SIGINT)
        return self.process.wait(timeout=20)


@pytest.fixture(scope="module")
def server():
    s = Server("scenes/teapot.json", "--root", SOURCE, cwd=SOURCE)
    yield s
    s.stop()


def cli_file(tmp_path, suffix, *args):
    out = tmp_path / ("cli" + suffix)
    subprocess.run([CLI, "render", *args, "-o", str(out), "-q"], check=True, cwd=SOURCE)
    return out.read_bytes()


CAMERA = {"eye": [2.5, 1.2, 2.0], "look_at": [0, 0.4, 0], "up": [0, 1, 0], "fov_y": 40}
CAMERA_ARGS = ["--camera-from", "2.5,1.2,2", "--look-at", "0,0.4,0", "--set", "camera.fov_y=40"]


@pytest.mark.parametrize("method", ["zbuffer", "scanline", "depthsort", "wireframe"])
def test_raster_frames_are_the_command_lines_png_byte_for_byte(server, tmp_path, method):
    status, body, headers = server.post("/api/render", {
        "scene": "scenes/teapot.json", "method": method, "width": 96, "height": 72,
        "camera": CAMERA})
    assert status == 200 and headers["Content-Type"] == "image/png"
    assert headers["X-Hikari-Size"] == "96x72"
    expected = cli_file(tmp_path, ".png", "scenes/teapot.json", "-m", method, "--width", "96",
                        "--height", "72", *CAMERA_ARGS)
    assert body == expected


def test_the_depth_sort_steps_through_its_painting_order(server, tmp_path):
    # Fig 4.6 part-way: the server says how long the order is, and paint_steps = k paints the
    # first k polygons of it, as `hikari render -m depthsort --paint-steps k` does.
    def frame(options):
        status, body, headers = server.post("/api/render", {
            "scene": "scenes/teapot.json", "method": "depthsort", "width": 64, "height": 48,
            "camera": CAMERA, "options": options})
        assert status == 200, body
        return body, headers
    whole, headers = frame({})
    order = int(headers["X-Hikari-Paint-Order"])
    assert order > 100 and int(headers["X-Hikari-Splits"]) >= 0
    part, headers = frame({"paint_steps": order // 3})
    assert int(headers["X-Hikari-Paint-Order"]) == order
    assert part != whole
    assert part == cli_file(tmp_path, ".png", "scenes/teapot.json", "-m", "depthsort",
                            "--width", "64", "--height", "48", "--paint-steps",
                            str(order // 3), *CAMERA_ARGS)
    assert frame({"paint_steps": order})[0] == whole
    status, _, headers = server.post("/api/render", {
        "scene": "scenes/teapot.json", "method": "zbuffer", "width": 32, "height": 24})
    assert status == 200 and "X-Hikari-Paint-Order" not in headers


def test_float_frames_and_options_are_the_command_lines(server, tmp_path):
    status, body, headers = server.post("/api/render", {
        "method": "raytrace", "width": 64, "height": 48, "format": "pfm",
        "options": {"spp": 2, "max_depth": 3}})
    assert status == 200 and headers["Content-Type"] == "image/x-portable-floatmap"
    assert body == cli_file(tmp_path, ".pfm", "scenes/teapot.json", "--width", "64",
                            "--height", "48", "--spp", "2", "--max-depth", "3")


def test_aovs_exposure_and_the_default_scene(server, tmp_path):
    status, body, _ = server.post("/api/render", {
        "scene": "", "method": "zbuffer", "width": 40, "height": 40, "aov": "depth"})
    assert status == 200
    assert body == cli_file(tmp_path, ".png", "-m", "zbuffer", "--width", "40", "--aov", "depth")
    status, body, _ = server.post("/api/render", {
        "method": "zbuffer", "width": 40, "height": 30, "exposure": 1, "tonemap": "aces"})
    assert status == 200
    assert body == cli_file(tmp_path, "2.png", "scenes/teapot.json", "-m", "zbuffer", "--width",
                            "40", "--exposure", "1", "--tonemap", "aces")


def test_explain_is_the_command_lines(server):
    status, body, _ = server.post("/api/explain", {
        "method": "zbuffer", "width": 80, "height": 60, "pixel": [40, 35]})
    assert status == 200
    expected = subprocess.run([CLI, "explain", "scenes/teapot.json", "-m", "zbuffer", "--width",
                               "80", "--height", "60", "--pixel", "40,35"], cwd=SOURCE,
                              check=True, capture_output=True, text=True).stdout
    assert body.decode().strip() == expected.strip()
    status, body, _ = server.post("/api/explain", {"method": "scanline", "width": 80,
                                                   "height": 60})
    assert status == 400 and b"needs --row" in body


@pytest.mark.parametrize("body, status, message", [
    ('{"method": "nope"}', 400, "unknown method 'nope'"),
    ('{"width": 0}', 400, "width"),
    ('{"options": {"spp": 0}}', 400, "options.spp"),
    ('{"method": "zbuffer", "options": {"max_depth": 3}}', 400, "has no option 'max_depth'"),
    ('{"aov": "shadow"}', 400, "aov"),
    ('{"camera": {"eye": [0, 0, 0], "look_at": [0, 0, 0]}}', 400, "same point"),
    ('{"camera": {"eye": [0, 0, "x"]}}', 400, "camera.eye"),
    ('{"exposure": 1e9}', 400, "exposure"),
    ('{"format": "gif"}', 400, "format"),
    ('{"surprise": 1}', 400, "unknown key"),
    ('{"width": 65536, "height": 65536}', 400, "--max-memory"),
    ('{bad json', 400, "request:1:"),
    ('[1, 2]', 400, "expected a JSON object"),
    ('', 400, "request"),
    ('{"scene": "../CMakeLists.txt"}', 403, ".."),
    ('{"scene": "/etc/passwd"}', 403, "relative"),
    ('{"scene": "scenes/missing.json"}', 404, "no such file"),
    ('{"scene": "CMakeLists.txt"}', 400, "CMakeLists.txt"),
])
def test_bad_requests_are_refused_with_a_message(server, body, status, message):
    got, text, _ = server.post("/api/render", body)
    assert got == status, text
    assert message in text.decode()


def test_paths_are_confined_to_the_root(tmp_path):
    root = tmp_path / "root"
    (root / "sub").mkdir(parents=True)
    shutil.copy(os.path.join(SOURCE, "scenes", "assignment.json"), root / "sub" / "a.json")
    outside = tmp_path / "outside.json"
    shutil.copy(os.path.join(SOURCE, "scenes", "assignment.json"), outside)
    (root / "link.json").symlink_to(outside)
    (root / ".hidden").mkdir()
    shutil.copy(outside, root / ".hidden" / "h.json")
    s = Server("--root", str(root))
    try:
        status, body, _ = s.get("/api/scenes")
        assert status == 200 and json.loads(body)["scenes"] == ["sub/a.json"]
        assert s.post("/api/render", {"scene": "sub/a.json", "width": 8})[0] == 200
        assert s.post("/api/render", {"scene": "link.json", "width": 8})[0] == 403
        assert s.post("/api/render", {"scene": "sub/../../outside.json"})[0] == 403
        assert s.get("/api/scene?scene=%2Fetc%2Fpasswd")[0] == 403
        assert s.get("/api/nothing")[0] == 404
    finally:
        assert s.stop() == 130


def test_a_newer_request_of_the_same_client_replaces_the_older(server):
    results = {}

    def long_render():
        results["old"] = server.post("/api/render", {
            "client": "c1", "method": "path", "width": 64, "height": 48,
            "options": {"spp": 1 << 20}})

    thread = threading.Thread(target=long_render)
    thread.start()
    time.sleep(1.0)
    start = time.monotonic()
    new = server.post("/api/render", {"client": "c1", "method": "zbuffer", "width": 32})
    thread.join(timeout=60)
    assert not thread.is_alive()
    assert results["old"][0] == 409
    assert new[0] == 200
    assert time.monotonic() - start < 30


def test_twenty_clients_at_once_get_their_frames(server):
    statuses = []

    def client(k):
        statuses.append(server.post("/api/render", {
            "client": f"many-{k}", "method": ["zbuffer", "raytrace"][k % 2], "width": 24,
            "height": 18, "options": {}})[0])

    threads = [threading.Thread(target=client, args=(k,)) for k in range(20)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=120)
    assert statuses == [200] * 20


def test_the_page_the_registry_and_the_scene(server):
    status, page, headers = server.get("/")
    assert status == 200 and headers["Content-Type"].startswith("text/html")
    assert b"<canvas" in page and b"http://" not in page.replace(b"http://\" + ", b"")
    status, body, _ = server.get("/api/methods")
    names = [m["name"] for m in json.loads(body)]
    assert "zbuffer" in names and "raytrace" in names
    status, body, _ = server.get("/api/scene?scene=scenes/teapot.json")
    info = json.loads(body)
    assert status == 200 and info["triangles"] > 0 and len(info["camera"]["eye"]) == 3


def test_progress_events_stream(server):
    request = urllib.request.Request(server.url + "/api/progress?client=nobody")
    with OPENER.open(request, timeout=10) as r:
        assert r.headers["Content-Type"].startswith("text/event-stream")
        assert r.readline().decode().startswith("data: idle")


def test_progress_is_pushed_when_it_changes_and_idle_after(server):
    body = {"scene": "scenes/teapot.json", "client": "slow", "method": "path", "width": 160,
            "height": 120, "options": {"spp": 48}}
    request = urllib.request.Request(server.url + "/api/progress?client=slow")
    events = []
    with OPENER.open(request, timeout=120) as r:
        assert r.readline().decode().strip() == "data: idle"
        r.readline()
        render = threading.Thread(target=server.post, args=("/api/render", body))
        render.start()
        while not events or events[-1] != "data: idle":
            line = r.readline().decode().strip()
            if line:
                events.append(line)
        render.join()
    fractions = [float(e[6:]) for e in events[:-1]]
    assert fractions, events
    assert all(0 <= f <= 1 for f in fractions)
    assert all(a != b for a, b in zip(events, events[1:])), events


@pytest.mark.parametrize("scene", ["scenes/teapot.json", "scenes/models/BoxTextured.gltf", ""])
def test_the_scene_file_of_a_view_renders_that_view_from_any_folder(server, tmp_path, scene):
    view = {"scene": scene, "method": "zbuffer", "width": 80, "height": 60, "camera": CAMERA}
    status, body, headers = server.post("/api/scene-file", view)
    assert status == 200 and headers["Content-Type"] == "application/json", body
    document = json.loads(body)
    assert document["camera"]["width"] == 80 and document["camera"]["eye"] == [2.5, 1.2, 2.0]
    folder = tmp_path / "elsewhere"
    folder.mkdir()
    (folder / "view.json").write_bytes(body)
    out = folder / "view.png"
    subprocess.run([CLI, "render", "view.json", "-m", "zbuffer", "-o", str(out), "-q"],
                   check=True, cwd=folder)
    status, frame, _ = server.post("/api/render", view)
    assert status == 200
    assert out.read_bytes() == frame


def test_the_scene_file_of_a_bad_view_is_refused_with_the_reason(server):
    status, body, _ = server.post("/api/scene-file", {"camera": {"fov_y": 500}})
    assert status == 400 and b"camera.fov_y" in body, body
