// What the browser tests share: a tiny static server on 127.0.0.1 (started and stopped by the test
// itself), Debian's Chromium driven by playwright-core with SwiftShader WebGL, a page opener that
// records console errors, page errors and failed requests, and pixel helpers.
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';

export const CHROMIUM = process.env.PENUMBRA_CHROMIUM || '/usr/bin/chromium';
// From ../shared/design/TOOLCHAIN.md: WebGL on SwiftShader, and no background networking (this
// machine cannot reach other hosts).
export const CHROMIUM_ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--use-angle=swiftshader',
  '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update',
  '--disable-sync',
];
// Every exercise's page, in the list's order: the X(name) lines of examples/exercises/list.h.
export const PAGES = [...readFileSync(new URL('../../examples/exercises/list.h', import.meta.url), 'utf8')
  .matchAll(/^ *X\(([a-z0-9_]+)\)/gm)].map((m) => m[1]);

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.css': 'text/css; charset=utf-8',
  '.wasm': 'application/wasm', '.png': 'image/png', '.json': 'application/json',
};

// Serves `root` on 127.0.0.1 at a free port, and each folder of `routes` ([[prefix, folder], ...],
// e.g. ['/three/', 'node_modules/three']) under its prefix. Returns {url, close()}.
export async function serve(root, routes = []) {
  const server = createServer(async (req, res) => {
    try {
      let rel = decodeURIComponent(new URL(req.url, 'http://x').pathname);
      let base = root;
      const route = routes.find(([prefix]) => rel.startsWith(prefix));
      if (route) [base, rel] = [route[1], rel.slice(route[0].length - 1)];
      const file = path.join(base, path.normalize(rel === '/' ? '/index.html' : rel));
      if (!file.startsWith(path.resolve(base))) throw new Error('outside the site');
      const s = await stat(file);
      if (!s.isFile()) throw new Error('not a file');
      const body = await readFile(file);
      res.writeHead(200, { 'Content-Type': TYPES[path.extname(file)] || 'application/octet-stream',
                           'Cache-Control': 'no-store' });
      res.end(body);
    } catch {
      res.writeHead(404, { 'Content-Type': 'text/plain' });
      res.end('not found');
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address();
  return { url: `http://127.0.0.1:${port}`, close: () => new Promise((r) => server.close(r)) };
}

export function siteDir() {
  const dir = process.env.PENUMBRA_SITE || path.resolve(path.dirname(new URL(import.meta.url).pathname), '../../build-web/site');
  // Each page has its own module (NAME.wasm); the first page's stands for them all.
  if (!existsSync(path.join(dir, `${PAGES[0]}.wasm`)))
    throw new Error(`${dir} has no ${PAGES[0]}.wasm: build the web preset first (cmake --preset web && cmake --build --preset web)`);
  return dir;
}

export async function launch() {
  return chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, headless: true });
}

// Opens `url` in a fresh page (1280x900 at a device pixel ratio of 1 unless `viewport` and `scale`
// say otherwise), waits for the module (window.penumbra.ready), fixes the canvas's backing store at
// 512x512 unless `fixedCanvas` is false, and returns {page, context, problems}: problems collects
// console errors, page errors and failed requests. `init`: a function run in the page before any
// of its scripts (page.addInitScript), e.g. to wrap WebGL calls.
export async function openPage(browser, url,
  { waitReady = true, init = null, fixedCanvas = true, viewport = { width: 1280, height: 900 }, scale = 1 } = {}) {
  const context = await browser.newContext({ viewport, deviceScaleFactor: scale });
  const page = await context.newPage();
  if (init) await page.addInitScript(init);
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()} (${r.failure()?.errorText})`));
  page.on('response', (r) => { if (r.status() >= 400) problems.push(`HTTP ${r.status()}: ${r.url()}`); });
  await page.goto(url, { waitUntil: 'load' });
  if (waitReady) {
    await page.evaluate(() => window.penumbra.ready);
    // The tests compare with 512x512 renders: the backing store is fixed there, not at the CSS
    // size x devicePixelRatio the page would use (tests/web/layout.mjs checks that).
    if (fixedCanvas) await page.evaluate(() => window.penumbra.setCanvasSize(512, 512));
  }
  return { page, context, problems };
}

// Waits until the page has drawn `n` more frames through its animation loop.
export async function waitFrames(page, n) {
  const start = await page.evaluate(() => window.penumbra.frameCount());
  await page.waitForFunction((target) => window.penumbra.frameCount() >= target, start + n, { timeout: 60000 });
}

// The canvas's pixels now: {width, height, data: Buffer RGBA top row first}.
export async function readPixels(page) {
  const px = await page.evaluate(() => window.penumbra.readPixelsBase64());
  if (!px) throw new Error('readPixels failed');
  return { width: px.width, height: px.height, data: Buffer.from(px.data, 'base64') };
}

// Fixes time at t (paused), draws a frame now and reads it back.
export async function frameAt(page, t) {
  return page.evaluate((time) => {
    window.penumbra.pause();
    window.penumbra.setTime(time);
    if (!window.penumbra.renderNow()) return null;
    return window.penumbra.readPixelsBase64();
  }, t).then((px) => {
    if (!px) throw new Error('renderNow/readPixels failed');
    return { width: px.width, height: px.height, data: Buffer.from(px.data, 'base64') };
  });
}

// Per-pixel comparison of two RGBA images of the same size (alpha ignored).
export function compare(a, b, threshold = 0) {
  if (a.width !== b.width || a.height !== b.height) throw new Error(`sizes differ: ${a.width}x${a.height} vs ${b.width}x${b.height}`);
  let differing = 0, sum = 0, max = 0;
  const n = a.width * a.height;
  const mask = new Uint8Array(n);
  for (let i = 0; i < n; ++i) {
    let d = 0;
    for (let c = 0; c < 3; ++c) d = Math.max(d, Math.abs(a.data[4 * i + c] - b.data[4 * i + c]));
    sum += d;
    if (d > max) max = d;
    if (d > threshold) { ++differing; mask[i] = 1; }
  }
  return { differing, fraction: differing / n, mean: sum / n, max, mask };
}

export function check(condition, message) {
  if (!condition) throw new Error(message);
}

// Waits until the page's URL holds its module's whole query. The URL follows a camera move 200 ms
// later, so after several moves it may hold an earlier one's query for a while.
export async function waitForUrlQuery(page) {
  await page.waitForFunction(() => {
    const q = window.penumbra.query();
    return location.search === (q ? '?' + q : '');
  }, null, { timeout: 5000 });
}

// The options `want` (name -> value) in the page's URL and its module's state, and again after a
// reload from that URL: what a student's link keeps.
export async function checkKeptOverReload(page, want) {
  await waitForUrlQuery(page);
  const params = new URL(page.url()).searchParams;
  for (const [k, v] of Object.entries(want)) check(params.get(k) === v, `URL ${page.url()}: ${k} is not ${v}`);
  let s = await page.evaluate(() => window.penumbra.state());
  for (const [k, v] of Object.entries(want)) check(s.options[k] === v, `module: ${k} = ${s.options[k]}, not ${v}`);
  await page.reload({ waitUntil: 'load' });
  await page.evaluate(() => window.penumbra.ready);
  s = await page.evaluate(() => window.penumbra.state());
  for (const [k, v] of Object.entries(want)) check(s.options[k] === v, `after reload ${k} = ${s.options[k]}, not ${v}`);
  return s;
}

// The page's pending GL errors (window.penumbra.glError until 0; at most 16).
export async function glErrors(page) {
  return page.evaluate(() => {
    const out = [];
    for (let e = window.penumbra.glError(), i = 0; e !== 0 && i < 16; e = window.penumbra.glError(), ++i) out.push(e);
    return out;
  });
}

// Fails the test if any of the pages has a GL error pending.
export async function checkNoGlErrors(...pages) {
  const errs = [];
  for (const p of pages) errs.push(...(await glErrors(p)));
  check(errs.length === 0, `glGetError: ${errs.map((e) => '0x' + e.toString(16)).join(', ')}`);
}

// The page's own loop with `options` set: its ms/frame, the median of the last 60 frames (each
// waited for). The loop must be running (window.penumbra.resume()).
export async function loopMs(page, options) {
  await setOptions(page, options);
  await waitFrames(page, 70);
  return (await page.evaluate(() => window.penumbra.state())).ms;
}

// Sets render options through the page's module (window.penumbra.setOption); fails the test on
// the first one the page refuses.
export async function setOptions(page, options) {
  const err = await page.evaluate((o) => {
    for (const [k, v] of Object.entries(o)) {
      const e = window.penumbra.setOption(k, v);
      if (e) return `${k}=${v}: ${e}`;
    }
    return '';
  }, options);
  check(err === '', `setOption ${err}`);
}

// Runs `body` with a browser and the served site (and `routes`, as serve's), closing both whatever
// happens; prints PASS or the failure and sets the exit status.
export async function runTest(name, body, routes = []) {
  const started = Date.now();
  let server, browser;
  try {
    server = await serve(siteDir(), routes);
    browser = await launch();
    await body({ server, browser });
    console.log(`PASS ${name} (${((Date.now() - started) / 1000).toFixed(1)} s)`);
  } catch (e) {
    console.error(`FAIL ${name}: ${e.stack || e}`);
    process.exitCode = 1;
  } finally {
    if (browser) await browser.close().catch(() => {});
    if (server) await server.close();
  }
}

// Writes pixels ({width, height, data}: RGBA rows, top first) as a PNG.
export function savePng(px, file) {
  const png = new PNG({ width: px.width, height: px.height });
  png.data = Buffer.from(px.data);
  writeFileSync(file, PNG.sync.write(png));
}

// The tints of --aov cascades: a cascade's (red, green, blue, yellow from near to far), a point
// light's cube face's (+x red, -x green, +y blue, -y yellow, +z magenta, -z cyan), by hue range.
export const CASCADE_TINTS = [['red', (h) => h <= 25 || h >= 335], ['green', (h) => h >= 90 && h <= 150],
                              ['blue', (h) => h >= 200 && h <= 260], ['yellow', (h) => h >= 40 && h <= 70]];
export const FACE_TINTS = CASCADE_TINTS.concat([['magenta', (h) => h >= 285 && h <= 320],
                                                ['cyan', (h) => h >= 170 && h <= 195]]);
// The share of the picture each tint holds, counted on saturated pixels by hue (as
// tests/desktop/check_cascades.py counts them).
export function tintShares(px, tints) {
  const count = Object.fromEntries(tints.map(([n]) => [n, 0]));
  const n = px.width * px.height;
  for (let i = 0; i < n; ++i) {
    const r = px.data[4 * i] / 255, g = px.data[4 * i + 1] / 255, b = px.data[4 * i + 2] / 255;
    const max = Math.max(r, g, b), min = Math.min(r, g, b);
    if (max < 0.15 || (max - min) / max < 0.3) continue;
    let h = max === r ? (g - b) / (max - min) : max === g ? 2 + (b - r) / (max - min) : 4 + (r - g) / (max - min);
    h = (h * 60 + 360) % 360;
    for (const [name, inside] of tints) if (inside(h)) { ++count[name]; break; }
  }
  for (const k of Object.keys(count)) count[k] /= n;
  return count;
}

// The page's WebGL context lost (WEBGL_lose_context) and restored: the status says each, the module
// knows, its second context draws the frame it drew before, pixel for pixel. Returns that frame.
export async function loseAndRestore(page) {
    const before = await frameAt(page, 0);
    await page.evaluate(() => {
      window.__lose = document.getElementById('canvas').getContext('webgl').getExtension('WEBGL_lose_context');
      window.__lose.loseContext();
    });
    await page.waitForFunction(() => /lost/i.test(document.getElementById('status').textContent), null, { timeout: 10000 });
    check((await page.evaluate(() => window.penumbra.state())).lost, 'the module does not know its context is lost');
    await page.evaluate(() => window.__lose.restoreContext());
    await page.waitForFunction(() => /restored/i.test(document.getElementById('status').textContent), null, { timeout: 10000 });
    const restored = await page.evaluate(() => window.penumbra.state());
    check(!restored.lost && restored.generation === 2, `after the restore: lost ${restored.lost}, generation ${restored.generation}`);
    const after = await frameAt(page, 0);
    const d = compare(before, after);
    check(d.differing === 0, `the frame after the restore differs from the one before in ${d.differing} pixels (max ${d.max})`);
    return after;
}

// The frame `penumbra render` (headless EGL) draws with `args`, written to `file` and read back
// as the pages' pixels are ({ width, height, data }, rows top first).
export function cliFrame(cli, args, file) {
  execFileSync(cli, ['render', ...args, '--out', file]);
  const png = PNG.sync.read(readFileSync(file));
  return { width: png.width, height: png.height, data: png.data };
}

// Each [name, args] of `runs`: the page's frame shot[name] against `frameOf(name, args, size)` (the
// CLI's), at most 0.5 % of the pixels more than 64 levels apart; the share printed.
export function checkMatchesCli(shot, runs, frameOf, outDir) {
  for (const [name, args] of runs) {
    const d = compare(shot[name], frameOf(name, args, shot[name]), 64);
    console.log(`${name} against penumbra render: ${(100 * d.fraction).toFixed(3)}% of the pixels differ by more than 64`);
    check(d.fraction <= 0.005, `${name}: the browser's frame differs from penumbra render's in ${(100 * d.fraction).toFixed(3)}% ` +
                               `(images in ${outDir})`);
  }
}
