// hikari serve's page in a real browser, as a student would use it: Debian's chromium, headless,
// driven by playwright-core. It loads the page, drags the camera, switches the method, turns on
// compare, clicks a pixel for explain, and checks the canvas against `hikari render` of the view
// the page reports. Exit 0: passed; 77: skipped (no chromium or no playwright-core: run
// `scripts/install-deps.sh --tests`); anything else: failed.
import { spawn, execFileSync } from "node:child_process";
import { existsSync, mkdtempSync, readFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { createRequire } from "node:module";

const source = process.env.HIKARI_SOURCE_DIR;
const cli = process.env.HIKARI_CLI;
const chromium = process.env.HIKARI_CHROMIUM || "/usr/bin/chromium";
const screenshot = process.env.HIKARI_SCREENSHOT;  // where to save a picture of the page
const skip = (why) => { console.log(`skipped: ${why}`); process.exit(77); };

if (!existsSync(chromium)) skip(`no ${chromium}`);
let playwright;
try {
  playwright = createRequire(join(source, "tests/browser/package.json"))("playwright-core");
} catch {
  skip("no playwright-core in tests/browser/node_modules (npm ci --prefix tests/browser)");
}

function check(condition, what) {
  if (!condition) throw new Error(`failed: ${what}`);
  console.log(`ok: ${what}`);
}

// The server, on any free port, serving the repository's scenes.
function startServer() {
  return new Promise((resolve, reject) => {
    const server = spawn(cli, ["serve", "scenes/teapot.json", "--port", "0"], { cwd: source });
    let out = "";
    server.stdout.on("data", (d) => {
      out += d;
      const m = out.match(/http:\/\/[\d.]+:\d+\//);
      if (m) resolve({ server, url: m[0] });
    });
    server.on("exit", (code) => reject(new Error(`hikari serve exited ${code}`)));
  });
}

// `hikari render` of the view the page reports, as 8-bit sRGB bytes (binary PPM).
function cliPixels(view, extra = []) {
  const out = join(mkdtempSync(join(tmpdir(), "hikari-")), "view.ppm");
  const c = view.camera;
  const args = ["render", view.scene || "", "-m", view.method, "--width", String(view.width),
                "--height", String(view.height), "--camera-from", c.eye.join(","),
                "--look-at", c.look_at.join(","), "--set", `camera.up=[${c.up.join(",")}]`,
                "--set", `camera.fov_y=${c.fov_y}`, ...extra, "-o", out, "-q"].filter((a) => a !== "");
  execFileSync(cli, args, { cwd: source });
  const bytes = readFileSync(out);
  // P6\n<w> <h>\n255\n then RGB
  let offset = 0, fields = [];
  while (fields.length < 4) {
    let end = offset;
    while (bytes[end] > 32) end++;
    fields.push(bytes.subarray(offset, end).toString());
    offset = end + 1;
  }
  return bytes.subarray(offset);
}

const { server, url } = await startServer();
const browser = await playwright.chromium.launch({ executablePath: chromium, headless: true,
                                                   args: ["--no-sandbox"] });
let failed = false;
try {
  const page = await browser.newPage({ viewport: { width: 1100, height: 700 } });
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  await page.goto(url);
  const settled = () => page.waitForFunction(() => window.hikariView.frames > 0 &&
                                             !window.hikariView.busy, null, { timeout: 120000 });
  await settled();
  check(await page.locator("#method option").count() >= 8, "every method of the registry is offered");

  // Raster method, a fixed size, then drag the camera: the frame is hikari render's.
  await page.selectOption("#size", "320x240");
  await page.selectOption("#method", "zbuffer");
  await settled();
  const before = await page.evaluate(() => JSON.stringify(window.hikariView.camera));
  const box = await page.locator("#frame").boundingBox();
  await page.mouse.move(box.x + 100, box.y + 100);
  await page.mouse.down();
  await page.mouse.move(box.x + 160, box.y + 120, { steps: 5 });
  await page.mouse.up();
  await page.waitForTimeout(200);
  await settled();
  const view = await page.evaluate(() => ({
    scene: window.hikariView.scene, method: window.hikariView.last.method,
    camera: window.hikariView.last.camera, width: window.hikariView.last.width,
    height: window.hikariView.last.height }));
  check(JSON.stringify(view.camera) !== before, "dragging orbits the camera");
  const canvas = await page.evaluate(() => {
    const c = document.getElementById("frame");
    const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    const rgb = [];
    for (let i = 0; i < d.length; i += 4) rgb.push(d[i], d[i + 1], d[i + 2]);
    return { width: c.width, height: c.height, rgb };
  });
  const expected = cliPixels(view);
  check(canvas.width === view.width && canvas.height === view.height, "the canvas has the reported size");
  let differ = 0;
  for (let i = 0; i < expected.length; ++i) if (expected[i] !== canvas.rgb[i]) differ++;
  check(differ === 0, `the canvas is hikari render's image of the reported view (${differ} values differ)`);

  // Compare with the ray tracer: the status line reports a PSNR.
  await page.check("#compare");
  await page.selectOption("#method2", "raytrace");
  await settled();
  const psnr = await page.evaluate(() => window.hikariView.psnr);
  check(psnr > 20 && psnr < 200, `compare zbuffer | raytrace gives a PSNR (${psnr && psnr.toFixed(1)} dB)`);
  check(await page.locator("#split").isVisible(), "the split line is shown");

  // Explain in place: click a pixel of the Z-buffer's half of the image.
  await page.mouse.click(box.x + 110, box.y + 130);
  await page.waitForFunction(() => document.getElementById("explain").textContent.length > 0);
  const explained = await page.textContent("#explain");
  check(explained.startsWith("Z-buffer (Alg 4.2) at pixel (110, 130)"), "clicking a pixel explains it");
  if (screenshot) await page.screenshot({ path: screenshot });
  await page.uncheck("#compare");

  // The depth sort's step-through (Fig 4.6): one polygon fewer paints the order but its last,
  // and the page's frame is hikari render's with that --paint-steps.
  await page.selectOption("#method", "depthsort");
  await settled();
  check(await page.locator("#steps").isVisible(), "the depth sort shows its painting-order slider");
  const order = await page.evaluate(() => window.hikariView.paintOrder);
  check(order > 1, `the server reports the painting order's length (${order})`);
  await page.click("#step-back");
  await page.waitForFunction((n) => window.hikariView.options.paint_steps === n - 1 &&
                             !window.hikariView.busy, order, { timeout: 120000 });
  check((await page.textContent("#step-text")).startsWith(`${order - 1} of ${order} polygons`),
        "the slider says how many polygons are painted");
  const stepped = await page.evaluate(() => window.hikariView.last);
  const steppedPixels = cliPixels(Object.assign({}, stepped, { scene: view.scene }),
                                  ["--paint-steps", String(order - 1)]);
  const shown = await page.evaluate(() => {
    const c = document.getElementById("frame");
    return Array.from(c.getContext("2d").getImageData(0, 0, c.width, c.height).data)
        .filter((_, i) => i % 4 !== 3);
  });
  let stepDiffer = 0;
  for (let i = 0; i < steppedPixels.length; ++i) if (steppedPixels[i] !== shown[i]) stepDiffer++;
  check(stepDiffer === 0, `the stepped frame is hikari render --paint-steps's (${stepDiffer} values differ)`);

  // Switch to the ray tracer: progressive passes end in a full frame.
  await page.selectOption("#method", "raytrace");
  await settled();
  check(await page.evaluate(() => window.hikariView.last.width) === 320, "raytrace refines to the full size");
  check(errors.length === 0, `no script errors (${errors.join("; ")})`);
} catch (e) {
  console.error(e.message);
  failed = true;
} finally {
  await browser.close();
  server.kill("SIGINT");
}
process.exit(failed ? 1 : 0);
