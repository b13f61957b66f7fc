// threejs_compare in the browser: a static server on 127.0.0.1 for penumbra's site, the three.js
// page (tests/threejs/compare.html + compare.js), three.js and the exported scenes; penumbra's
// W09P2c and the three.js page in headless Chromium: the visibility images of every configuration,
// then the interleaved timing rounds.
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import path from 'node:path';
import { launch } from '../../tests/web/harness.mjs';
import { OURS, PAGE_DEFAULTS, ROOT, SIZE, THREE_CONFIGS, log, median, oursOptions, tname, threeOptions } from './config.mjs';
import { savePng } from './images.mjs';

// A static server on 127.0.0.1 for the site (/), the three.js page (/compare/), three.js itself
// (/three/ = node_modules/three) and the exported scenes (/data/).
async function serve(routes) {
  const TYPES = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.mjs': 'text/javascript; charset=utf-8',
                  '.css': 'text/css; charset=utf-8', '.wasm': 'application/wasm', '.png': 'image/png',
                  '.json': 'application/json', '.gltf': 'model/gltf+json' };
  const server = createServer(async (req, res) => {
    try {
      const rel = decodeURIComponent(new URL(req.url, 'http://x').pathname);
      const [prefix, root] = routes.find(([p]) => rel.startsWith(p));
      const file = path.resolve(root, '.' + path.posix.normalize('/' + rel.slice(prefix.length)));
      if (!file.startsWith(path.resolve(root))) throw new Error('outside');
      if (!(await stat(file)).isFile()) throw new Error('not a file');
      const body = await readFile(file);
      res.writeHead(200, { 'Content-Type': TYPES[path.extname(file)] || 'application/octet-stream', 'Cache-Control': 'no-store' });
      res.end(body);
    } catch {
      res.writeHead(404, { 'Content-Type': 'text/plain' });
      res.end('not found');
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return { url: `http://127.0.0.1:${server.address().port}`, close: () => new Promise((r) => server.close(r)) };
}

async function openPage(browser, url, problems) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`${url}: console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`${url}: page error: ${e.message}`));
  page.on('response', (r) => { if (r.status() >= 400) problems.push(`${url}: HTTP ${r.status()}: ${r.url()}`); });
  await page.goto(url, { waitUntil: 'load' });
  return { page, context };
}

const oursUrl = (server, c, aov) =>
  `${server.url}/w09p2c.html?map-view=off&${new URLSearchParams(oursOptions(c))}&aov=${aov}`;

async function openOurs(browser, server, c, aov, problems) {
  const p = await openPage(browser, oursUrl(server, c, aov), problems);
  await p.page.evaluate(() => window.penumbra.ready);
  // The page sizes its canvas to the window (CSS size x devicePixelRatio): fixed at SIZE here, then
  // the size is known once the animation loop has drawn a frame at it.
  const n0 = await p.page.evaluate((n) => { window.penumbra.setCanvasSize(n, n); return window.penumbra.frameCount(); }, SIZE);
  await p.page.waitForFunction((n) => window.penumbra.frameCount() > n, n0, { timeout: 60000 });
  const s = await p.page.evaluate(() => window.penumbra.state());
  if (s.width !== SIZE || s.height !== SIZE) throw new Error(`penumbra's canvas is ${s.width}x${s.height}`);
  if (s.mapSize !== c.map) throw new Error(`penumbra's map is ${s.mapSize}, not ${c.map}`);
  for (const [k, v] of Object.entries(oursOptions(c)))
    if ((s.options[k] ?? PAGE_DEFAULTS[k]) !== v) throw new Error(`penumbra's page took ${k}=${s.options[k]} for ${v} (${s.status})`);
  return { ...p, state: s };
}

async function openThree(browser, server, problems) {
  const p = await openPage(browser, `${server.url}/compare/compare.html`, problems);
  await p.page.waitForFunction(() => window.compare !== undefined, null, { timeout: 60000 });
  return p;
}


// Renders every configuration's visibility image at every time (written to imgDir) and times
// their colour frames. Returns {images: id -> t -> png, ms: id -> [median of each round], ...}.
export async function measureInBrowser(o, site, dataDir, imgDir, frames, started) {
  const server = await serve([
    ['/three/', path.join(ROOT, 'node_modules/three')],
    ['/compare/', path.join(ROOT, 'tests/threejs')],
    ['/data/', dataDir],
    ['/', site],
  ]);
  const browser = await launch();
  const problems = [];
  const images = {};  // id -> t -> png path
  const ms = {};      // id -> [median of each round]
  let oursRenderer = '', threeInfo = null, frustum = null, threeSummary = null;
  try {
    // 3a. Visibility images.
    log('visibility images: penumbra (W09P2c)');
    for (const c of OURS) {
      const { page, context, state } = await openOurs(browser, server, c, 'visibility', problems);
      oursRenderer = state.renderer;
      images[c.id] = {};
      for (const t of o.times) {
        const px = await page.evaluate((time) => {
          window.penumbra.pause();
          window.penumbra.setTime(time);
          if (!window.penumbra.renderNow()) return null;
          return window.penumbra.readPixelsBase64();
        }, t);
        if (!px) throw new Error(`penumbra ${c.id} at t=${t}: no frame (${(await page.evaluate(() => window.penumbra.state())).status})`);
        const file = path.join(imgDir, `ours_${c.id}_t${tname(t)}.png`);
        savePng({ width: px.width, height: px.height, data: Buffer.from(px.data, 'base64') }, file);
        images[c.id][t] = file;
      }
      await context.close();
    }
    log('visibility images: three.js');
    for (const c of THREE_CONFIGS) {
      const { page, context } = await openThree(browser, server, problems);
      images[c.id] = {};
      for (const t of o.times) {
        const summary = await page.evaluate(([url, opts]) => window.compare.load(url, opts),
                                            [`/data/course_${tname(t)}.gltf`, threeOptions(c, 'phong')]);
        if (t === o.times[0] && !threeSummary) threeSummary = summary;
        if (Math.abs(t - 0.6) < 1e-9 || !frustum) frustum = { t, ...summary.frustum };
        const px = await page.evaluate(() => window.compare.renderVisibility());
        const file = path.join(imgDir, `${c.id}_t${tname(t)}.png`);
        savePng({ width: px.width, height: px.height, data: Buffer.from(px.data, 'base64') }, file);
        images[c.id][t] = file;
        if (c.id === 'three-pcf-matched' && Math.abs(t - (o.times.includes(0.6) ? 0.6 : o.times[0])) < 1e-9) {
          const col = await page.evaluate(() => window.compare.renderColor());
          savePng({ width: col.width, height: col.height, data: Buffer.from(col.data, 'base64') },
                  path.join(imgDir, `three_colour_t${tname(t)}.png`));
        }
      }
      threeInfo = await page.evaluate(() => window.compare.info());
      const err = await page.evaluate(() => window.compare.glError());
      if (err) problems.push(`three.js ${c.id}: GL error ${err}`);
      await context.close();
    }

    // 3b. Timing. One penumbra page and one three.js page, each switched from configuration to
    // configuration; penumbra's own animation loop is paused (Emscripten's Module.pauseMainLoop),
    // so nothing draws but the frames being timed. In each round, for each time, every
    // configuration in turn (penumbra's and three.js's interleaved): 3 warm-up frames, then the
    // frames t + k/60 back to back. A round's figure is the median over its frames, the reported
    // one the median of the rounds'; a ratio is the median of the rounds' ratios, so a disturbance
    // on the machine that lasts a round hits both sides of it alike.
    const timed = [
      ...OURS.map((c) => ({ id: c.id, kind: 'ours', c })),
      ...THREE_CONFIGS.map((c) => ({ id: c.id, kind: 'three', c, material: 'phong' })),
      ...THREE_CONFIGS.filter((c) => c.id.endsWith('default')).map((c) => ({ id: `${c.id}-standard`, kind: 'three', c, material: 'standard' })),
    ];
    const order = [];  // ours and three.js alternating
    const oursList = timed.filter((x) => x.kind === 'ours');
    const threeList = timed.filter((x) => x.kind === 'three');
    for (let i = 0; i < Math.max(oursList.length, threeList.length); ++i) {
      if (i < threeList.length) order.push(threeList[i]);
      if (i < oursList.length) order.push(oursList[i]);
    }
    for (const x of timed) ms[x.id] = [];
    const oursPage = await openOurs(browser, server, OURS[0], 'color', problems);
    await oursPage.page.evaluate(() => { window.penumbra.pause(); Module.pauseMainLoop(); });
    const idle0 = await oursPage.page.evaluate(() => window.penumbra.frameCount());
    await oursPage.page.waitForTimeout(300);
    if ((await oursPage.page.evaluate(() => window.penumbra.frameCount())) !== idle0)
      throw new Error("penumbra's animation loop still draws after Module.pauseMainLoop()");
    const threePage = await openThree(browser, server, problems);
    await threePage.page.evaluate(([url, opts]) => window.compare.load(url, opts),
                                  [`/data/course_${tname(o.times[0])}.gltf`, threeOptions(THREE_CONFIGS[0], 'phong')]);
    for (let r = 0; r < o.rounds; ++r) {
      const round = Object.fromEntries(timed.map((x) => [x.id, []]));
      for (const t of o.times) {
        for (const x of order) {
          if (x.kind === 'ours') {
            round[x.id].push(...await oursPage.page.evaluate(([opts, t0, n]) => {
              const p = window.penumbra;
              for (const [k, v] of Object.entries(opts)) {
                const err = p.setOption(k, v);
                if (err) throw new Error(`setOption ${k}=${v}: ${err}`);
              }
              const out = [];
              for (let k = -3; k < n; ++k) {
                p.setTime(t0 + Math.max(k, 0) / 60);  // the light and the teapot move: the map is redrawn
                const a = performance.now();
                if (!p.renderNow()) throw new Error('renderNow failed: ' + p.state().status);  // draws, then reads one pixel back
                const b = performance.now();
                if (k >= 0) out.push(b - a);
              }
              return out;
            }, [oursOptions(x.c), t, o.frames]));
          } else {
            round[x.id].push(...await threePage.page.evaluate(([opts, f]) => {
              window.compare.configure(opts);
              return window.compare.timeFrames(f, 3);
            }, [threeOptions(x.c, x.material), frames[t]]));
          }
        }
      }
      for (const x of timed) ms[x.id].push(median(round[x.id]));
      log(`timing round ${r + 1}/${o.rounds} done (${((Date.now() - started) / 1000).toFixed(0)} s)`);
    }
    const err = await threePage.page.evaluate(() => window.compare.glError());
    if (err) problems.push(`three.js timing: GL error ${err}`);
    await oursPage.context.close();
    await threePage.context.close();
  } finally {
    await browser.close().catch(() => {});
    await server.close();
  }
  return { images, ms, oursRenderer, threeInfo, frustum, threeSummary, problems };
}
