#!/usr/bin/env node
// three.js side by side (issue 4, item 5): the course scene, exported by `penumbra export` at fixed
// times, rendered by three.js (GLTFLoader, WebGL 2; tests/threejs/compare.html) and by penumbra's
// own web build (W09P2c, WebGL 1; build-web/site) in the same headless Chromium, at the same canvas
// size and shadow-map size; both visibility images scored against the same Embree ground truth
// (`penumbra truth --score`), both timed the same way (median ms/frame, each frame followed by a
// one-pixel readback). Prints a Markdown table and writes docs/threejs.md.
//
// It builds nothing: it needs build/penumbra (export, truth, render), build-web/site and
// node_modules (npm ci: playwright-core, pngjs, three).
//
// usage: node tools/threejs_compare.mjs [--times 0,0.6,2.25,7] [--frames 30] [--rounds 5]
//          [--out-dir out/threejs] [--doc docs/threejs.md | --no-doc] [--cli build/penumbra]
//          [--quick] [--check] [--from-json out/threejs/results.json]
//   --quick   t = 0.6 only, 5 frames, 1 round, no doc (what the web.threejs test runs)
//   --check   exit 1 unless every output is well formed: scores in range, every visibility image
//             neither all lit nor all dark, the exported camera scoring as penumbra's own, three.js's
//             matched BasicShadowMap within 1 % of the pixels of penumbra's hard filter (never a timing)
//   --from-json  measure nothing: print the table and write the doc again from an earlier run
import { createServer } from 'node:http';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { readFile, stat } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { PNG } from 'pngjs';
import { launch, siteDir, CHROMIUM } from '../tests/web/harness.mjs';

const ROOT = path.resolve(path.dirname(new URL(import.meta.url).pathname), '..');
const SIZE = 512;
const MAP = 1024;

// ---- options ------------------------------------------------------------------------------------
function usage(message) {
  console.error(`threejs_compare: ${message} (see --help)`);
  process.exit(2);
}

function parseArgs(argv) {
  const o = { times: [0, 0.6, 2.25, 7], frames: 30, rounds: 5, outDir: path.join(ROOT, 'out/threejs'),
              doc: path.join(ROOT, 'docs/threejs.md'), cli: path.join(ROOT, 'build/penumbra'), check: false, quick: false };
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    const next = () => {
      if (i + 1 >= argv.length) usage(`${a} needs a value`);
      return argv[++i];
    };
    if (a === '--times') o.times = next().split(',').map(Number);
    else if (a === '--frames') o.frames = Number(next());
    else if (a === '--rounds') o.rounds = Number(next());
    else if (a === '--out-dir') o.outDir = path.resolve(next());
    else if (a === '--doc') o.doc = path.resolve(next());
    else if (a === '--no-doc') o.doc = null;
    else if (a === '--cli') o.cli = path.resolve(next());
    else if (a === '--check') o.check = true;
    else if (a === '--from-json') o.fromJson = path.resolve(next());
    else if (a === '--quick') { o.quick = true; o.times = [0.6]; o.frames = 5; o.rounds = 1; o.doc = null; }
    else if (a === '-h' || a === '--help') {
      const lines = readFileSync(new URL(import.meta.url), 'utf8').split('\n').slice(1);
      const end = lines.findIndex((l) => !l.startsWith('//'));
      console.log(lines.slice(0, end).map((l) => l.slice(3)).join('\n'));
      process.exit(0);
    } else usage(`unknown option ${a}`);
  }
  if (!o.times.length || o.times.some((t) => !Number.isFinite(t))) usage('--times: numbers, comma-separated');
  if (!(o.frames >= 1) || !(o.rounds >= 1)) usage('--frames and --rounds must be >= 1');
  return o;
}

// ---- what is compared -----------------------------------------------------------------------------
// penumbra's W09P2c page: every encoding, hard and 4x4 PCF, the encoding's default bias.
const OURS = [
  { id: 'rgba-hard', label: 'rgba hard', encoding: 'rgba', filter: 'hard' },
  { id: 'rgba-pcf4x4', label: 'rgba pcf4x4', encoding: 'rgba', filter: 'pcf4x4' },
  { id: 'depthtex-hard', label: 'depthtex hard', encoding: 'depthtex', filter: 'hard' },
  { id: 'depthtex-pcf4x4', label: 'depthtex pcf4x4', encoding: 'depthtex', filter: 'pcf4x4' },
  { id: 'r8-hard', label: 'r8 hard', encoding: 'r8', filter: 'hard' },
  { id: 'r8-pcf4x4', label: 'r8 pcf4x4', encoding: 'r8', filter: 'pcf4x4' },
];
// penumbra's default bias of rgba and depthtex (README: 0.0015, in window depth units), which
// three.js applies with the opposite sign (shadowCoord.z += bias; lit where z <= depth).
const OUR_BIAS = 0.0015;
// three.js: BasicShadowMap and PCFShadowMap, each at three.js's defaults (bias 0, normalBias 0, the
// back faces into the map: shadowSide = the opposite of the material's side), with penumbra's bias
// alone, and matched (penumbra's bias, both faces into the map as penumbra draws them).
const THREE_CONFIGS = [
  { id: 'three-basic-default', label: 'three.js BasicShadowMap, defaults', type: 'basic', bias: 0, shadowSide: 'default', vs: 'rgba-hard' },
  { id: 'three-basic-bias', label: 'three.js BasicShadowMap, bias -0.0015', type: 'basic', bias: -OUR_BIAS, shadowSide: 'default', vs: 'rgba-hard' },
  { id: 'three-basic-matched', label: 'three.js BasicShadowMap, matched', type: 'basic', bias: -OUR_BIAS, shadowSide: 'double', vs: 'rgba-hard' },
  { id: 'three-pcf-default', label: 'three.js PCFShadowMap, defaults', type: 'pcf', bias: 0, shadowSide: 'default', vs: 'rgba-pcf4x4' },
  { id: 'three-pcf-bias', label: 'three.js PCFShadowMap, bias -0.0015', type: 'pcf', bias: -OUR_BIAS, shadowSide: 'default', vs: 'rgba-pcf4x4' },
  { id: 'three-pcf-matched', label: 'three.js PCFShadowMap, matched', type: 'pcf', bias: -OUR_BIAS, shadowSide: 'double', vs: 'rgba-pcf4x4' },
];
const threeOptions = (c, material) => ({ shadowType: c.type, bias: c.bias, normalBias: 0, shadowSide: c.shadowSide,
                                         material, mapSize: MAP, radius: 1 });

// ---- helpers --------------------------------------------------------------------------------------
const median = (v) => {
  if (!v.length) return NaN;
  const s = [...v].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
};
const mean = (v) => v.reduce((a, b) => a + b, 0) / v.length;
const tname = (t) => t.toFixed(2);
const log = (s) => process.stderr.write(`threejs_compare: ${s}\n`);

function savePng(px, file) {
  const png = new PNG({ width: px.width, height: px.height });
  png.data = Buffer.from(px.data);
  writeFileSync(file, PNG.sync.write(png));
}

// Lit, dark and in-between pixels of a visibility image (red channel, 255 lit).
function histogram(px) {
  let lit = 0, dark = 0, grey = 0;
  for (let i = 0; i < px.width * px.height; ++i) {
    const v = px.data[4 * i];
    if (v >= 250) ++lit; else if (v <= 5) ++dark; else ++grey;
  }
  return { lit, dark, grey, n: px.width * px.height };
}

// Two visibility images (red channel): the fraction of pixels more than 8 levels apart, the mean |difference|.
function imageDiff(fileA, fileB) {
  const a = PNG.sync.read(readFileSync(fileA));
  const b = PNG.sync.read(readFileSync(fileB));
  let differing = 0, sum = 0;
  const n = a.width * a.height;
  for (let i = 0; i < n; ++i) {
    const d = Math.abs(a.data[4 * i] - b.data[4 * i]);
    sum += d;
    if (d > 8) ++differing;
  }
  return { differing, fraction: differing / n, meanLevels: sum / n };
}

function run(cli, args) {
  return execFileSync(cli, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

// `penumbra truth --score`: "score of X: valid N px, false shadow A %, false lit B %, error C %, mean abs error D %"
function score(o, t, png) {
  const dir = path.join(o.outDir, 'truth', `t${tname(t)}`);
  const out = run(o.cli, ['truth', '--scene', 'teapot', '--time', String(t), '--size', `${SIZE}x${SIZE}`, '--out-dir', dir,
                          '--score', png]);
  const m = /valid (\d+) px, false shadow ([\d.]+) %, false lit ([\d.]+) %, error ([\d.]+) %, mean abs error ([\d.]+) %/.exec(out);
  if (!m) throw new Error(`cannot read the score of ${png} from: ${out}`);
  return { valid: +m[1], falseShadow: +m[2], falseLit: +m[3], error: +m[4], mae: +m[5] };
}

// The glTF nodes of one exported frame: node matrices by name (the teapot jumps) and the light's position.
function frameNodes(gltf) {
  const frame = { nodes: {}, light: null };
  for (const n of gltf.nodes) {
    if (n.extensions && n.extensions.KHR_lights_punctual) frame.light = n.translation || [0, 0, 0];
    else if (n.mesh !== undefined) frame.nodes[n.name] = n.matrix || [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  }
  if (!frame.light) throw new Error('the exported glTF has no light node');
  return frame;
}

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
  `${server.url}/w09p2c.html?map-view=off&encoding=${c.encoding}&filter=${c.filter}&bias=default&map-size=${MAP}&aov=${aov}`;

async function openOurs(browser, server, c, aov, problems) {
  const p = await openPage(browser, oursUrl(server, c, aov), problems);
  await p.page.evaluate(() => window.penumbra.ready);
  // The canvas's size is known once the animation loop has drawn a frame.
  await p.page.waitForFunction(() => window.penumbra.frameCount() > 0, null, { timeout: 60000 });
  const s = await p.page.evaluate(() => window.penumbra.state());
  if (s.width !== SIZE || s.height !== SIZE) throw new Error(`penumbra's canvas is ${s.width}x${s.height}`);
  if (s.mapSize !== MAP) throw new Error(`penumbra's map is ${s.mapSize}`);
  if (s.options.encoding !== c.encoding || s.options.filter !== c.filter)
    throw new Error(`penumbra's page took ${s.options.encoding}/${s.options.filter} for ${c.encoding}/${c.filter} (${s.status})`);
  return { ...p, state: s };
}

async function openThree(browser, server, problems) {
  const p = await openPage(browser, `${server.url}/compare/compare.html`, problems);
  await p.page.waitForFunction(() => window.compare !== undefined, null, { timeout: 60000 });
  return p;
}

// ---- the run --------------------------------------------------------------------------------------
async function main() {
  const o = parseArgs(process.argv.slice(2));
  if (o.fromJson) {
    // Measure nothing: the table and the doc again from an earlier run's results.json.
    const j = JSON.parse(readFileSync(o.fromJson, 'utf8'));
    const md = markdown(j.options, j.env, j.rows, j.cameraCheck, j.frustum, j.threeSummary, j.agreement);
    console.log(md.table);
    if (o.doc) writeFileSync(o.doc, md.doc);
    return;
  }
  const started = Date.now();
  const loadBefore = os.loadavg()[0];
  for (const need of [o.cli, path.join(ROOT, 'node_modules/three/build/three.module.js')])
    if (!existsSync(need)) throw new Error(`${need} is missing (build/penumbra: cmake --build --preset ci; three: npm ci)`);
  const site = siteDir();
  const dataDir = path.join(o.outDir, 'data');
  const imgDir = path.join(o.outDir, 'images');
  for (const d of [dataDir, imgDir]) mkdirSync(d, { recursive: true });
  const threePkg = JSON.parse(readFileSync(path.join(ROOT, 'node_modules/three/package.json'), 'utf8'));

  // 1. The scenes: one glTF per time, and the timing frames' nodes (t + k/60, the light and the
  // teapot moving) from one export each.
  log(`exporting the course scene at t = ${o.times.join(', ')} and ${o.frames} timing frames each`);
  const frames = {};
  for (const t of o.times) {
    run(o.cli, ['export', '--scene', 'teapot', '--time', String(t), '--size', `${SIZE}x${SIZE}`,
                '--out', path.join(dataDir, `course_${tname(t)}.gltf`)]);
    frames[t] = [];
    const tmp = path.join(dataDir, 'frame.gltf');
    for (let k = 0; k < o.frames; ++k) {
      run(o.cli, ['export', '--scene', 'teapot', '--time', String(t + k / 60), '--out', tmp]);
      frames[t].push(frameNodes(JSON.parse(readFileSync(tmp, 'utf8'))));
    }
  }

  // 2. The exported camera is penumbra's camera: penumbra's own EGL render of the exported glTF
  // and of the built-in scene give the same visibility image and the same score.
  const cameraCheck = [];
  for (const t of o.times) {
    const a = path.join(imgDir, `egl_teapot_t${tname(t)}.png`);
    const b = path.join(imgDir, `egl_gltf_t${tname(t)}.png`);
    const common = ['--size', `${SIZE}x${SIZE}`, '--map-size', String(MAP), '--encoding', 'rgba', '--filter', 'hard', '--aov', 'visibility'];
    run(o.cli, ['render', '--scene', 'teapot', '--time', String(t), ...common, '--out', a]);
    run(o.cli, ['render', '--scene', path.join(dataDir, `course_${tname(t)}.gltf`), ...common, '--out', b]);
    const pa = PNG.sync.read(readFileSync(a));
    const pb = PNG.sync.read(readFileSync(b));
    let differing = 0;
    for (let i = 0; i < pa.data.length; i += 4) if (pa.data[i] !== pb.data[i]) ++differing;
    cameraCheck.push({ t, differing, teapot: score(o, t, a), gltf: score(o, t, b) });
  }

  // 3. The browser.
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
            round[x.id].push(...await oursPage.page.evaluate(([c, t0, n]) => {
              const p = window.penumbra;
              for (const [k, v] of [['encoding', c.encoding], ['filter', c.filter]]) {
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
            }, [x.c, t, o.frames]));
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

  // 4. Scores against the same ground truth.
  log('scoring against the ground truth (penumbra truth --score)');
  const rows = [];
  const failures = [...problems];
  for (const [kind, list] of [['ours', OURS], ['three', THREE_CONFIGS]]) {
    for (const c of list) {
      const per = o.times.map((t) => {
        const file = images[c.id][t];
        const s = score(o, t, file);
        const h = histogram(PNG.sync.read(readFileSync(file)));
        if (h.lit === h.n || h.dark === h.n) failures.push(`${c.id} at t=${t}: the visibility image is all ${h.lit === h.n ? 'lit' : 'dark'}`);
        if (h.dark + h.grey < 0.01 * h.n) failures.push(`${c.id} at t=${t}: no shadow (${h.dark + h.grey} px)`);
        if (h.lit < 0.1 * h.n) failures.push(`${c.id} at t=${t}: nearly all dark (${h.lit} px lit)`);
        for (const k of ['falseShadow', 'falseLit', 'error', 'mae'])
          if (!(s[k] >= 0 && s[k] <= 100)) failures.push(`${c.id} at t=${t}: ${k} ${s[k]} out of range`);
        if (Math.abs(s.falseShadow + s.falseLit - s.error) > 0.01) failures.push(`${c.id} at t=${t}: error != false shadow + false lit`);
        if (!(s.valid > 0.2 * SIZE * SIZE)) failures.push(`${c.id} at t=${t}: only ${s.valid} valid pixels`);
        if (!(s.error < 50)) failures.push(`${c.id} at t=${t}: error ${s.error} %: the frames do not match`);
        return { t, ...s, hist: h };
      });
      const msId = c.id;
      rows.push({
        kind, id: c.id, label: c.label, c, per,
        falseShadow: mean(per.map((p) => p.falseShadow)), falseLit: mean(per.map((p) => p.falseLit)),
        error: mean(per.map((p) => p.error)), mae: mean(per.map((p) => p.mae)),
        ms: median(ms[msId]), msRounds: ms[msId],
        msStandard: ms[`${c.id}-standard`] ? median(ms[`${c.id}-standard`]) : null,
      });
    }
  }
  const byId = Object.fromEntries(rows.map((r) => [r.id, r]));
  for (const r of rows) {
    if (r.kind !== 'three') continue;
    // The median over the rounds of each round's ratio (both sides measured in the same round).
    const ratio = (other) => median(r.msRounds.map((v, i) => v / byId[other].msRounds[i]));
    r.ratio = ratio(r.c.vs);
    r.ratioDepthtex = ratio(r.c.vs.replace('rgba', 'depthtex'));
  }
  for (const cc of cameraCheck) {
    // The glTF holds the matrices as float32, as penumbra does; a pixel or two on an edge may round the other way.
    if (cc.differing > 1e-4 * SIZE * SIZE) failures.push(`the exported glTF at t=${cc.t} renders ${cc.differing} px differently from the built-in scene`);
    if (Math.abs(cc.teapot.error - cc.gltf.error) > 0.01 || cc.teapot.valid !== cc.gltf.valid)
      failures.push(`the exported glTF at t=${cc.t} scores ${cc.gltf.error} % against the built-in scene's ${cc.teapot.error} %`);
  }
  if (threeInfo && !threeInfo.webgl2) failures.push('three.js did not get a WebGL 2 context');
  // With penumbra's frustum, bias and faces, three.js's one-tap map must see what penumbra's does:
  // pixel by pixel, the matched BasicShadowMap against penumbra's hard filter (and PCF, whose
  // kernels differ, for the record).
  const pairs = [['three-basic-matched', 'depthtex-hard'], ['three-basic-matched', 'rgba-hard'], ['three-pcf-matched', 'rgba-pcf4x4']];
  const agreement = pairs.map(([a, b]) => ({ a, b, per: o.times.map((t) => ({ t, ...imageDiff(images[a][t], images[b][t]) })) }));
  for (const p of agreement[0].per)
    if (p.fraction > 0.01) failures.push(`three.js matched BasicShadowMap and penumbra depthtex hard differ in ${(100 * p.fraction).toFixed(2)} % of the pixels at t=${p.t}`);

  // 5. Outputs.
  const env = {
    date: new Date().toISOString().slice(0, 10), cores: os.cpus().length, cpu: os.cpus()[0]?.model || '?',
    chromium: execFileSync(CHROMIUM, ['--version'], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim(), oursRenderer, threeInfo,
    threeVersion: threePkg.version, seconds: Math.round((Date.now() - started) / 1000),
    load: [loadBefore, os.loadavg()[0]],
  };
  writeFileSync(path.join(o.outDir, 'results.json'), JSON.stringify({ options: o, env, frustum, threeSummary, cameraCheck, agreement, rows, failures }, null, 1));
  writeCsv(path.join(o.outDir, 'results.csv'), rows, env);
  const md = markdown(o, env, rows, cameraCheck, frustum, threeSummary, agreement);
  console.log(md.table);
  if (o.doc) {
    writeFileSync(o.doc, md.doc);
    log(`wrote ${path.relative(ROOT, o.doc)}`);
  }
  log(`wrote ${path.relative(ROOT, o.outDir)}/results.{json,csv} and images/ in ${env.seconds} s`);
  if (failures.length) {
    log(`problems:\n  ${failures.join('\n  ')}`);
    if (o.check) process.exitCode = 1;
  } else if (o.check) {
    console.log(`PASS threejs_compare --check: ${rows.length} renderings x ${o.times.length} frame(s) well formed, the exported camera scores as penumbra's own`);
  }
}

// Rows with the columns of docs/bench/results.csv (`penumbra bench --from-csv` reads them), one per
// frame and technique; the times are the browser's (SwiftShader), not llvmpipe's: do not merge
// them with the EGL bench's rows into one plot.
function writeCsv(file, rows, env) {
  const head = 'scene,time,width,height,technique,encoding,filter,map_size,valid_pixels,false_shadow_pct,false_lit_pct,error_pct,mae_pct,ms_moving,ms_still,frames,settings';
  const lines = [head];
  for (const r of rows)
    for (const p of r.per) {
      const technique = r.kind === 'ours' ? `${r.c.encoding} ${r.c.filter}` : `three.js-${r.c.type}-${r.id.split('-').pop()} ${r.c.type === 'basic' ? 'hard' : 'pcf'}`;
      const settings = r.kind === 'ours' ? `w09p2c.html?encoding=${r.c.encoding}&filter=${r.c.filter}&bias=default&map-size=${MAP}`
        : `three.js r${env.threeInfo?.revision} ${r.c.type === 'basic' ? 'BasicShadowMap' : 'PCFShadowMap'} bias=${r.c.bias} shadowSide=${r.c.shadowSide} mapSize=${MAP}`;
      lines.push([`course@${tname(p.t)}`, p.t.toFixed(3), SIZE, SIZE, technique, r.kind === 'ours' ? r.c.encoding : 'three.js',
                  r.kind === 'ours' ? r.c.filter : r.c.type, MAP, p.valid, p.falseShadow, p.falseLit, p.error, p.mae,
                  r.ms.toFixed(3), '', '', `"${settings}"`].join(','));
    }
  writeFileSync(file, lines.join('\n') + '\n');
}

const f2 = (x) => (x === null || x === undefined || Number.isNaN(x) ? 'n/a' : x.toFixed(2));

function markdown(o, env, rows, cameraCheck, frustum, summary, agreement) {
  const times = o.times.map((t) => `t = ${t}`).join(', ');
  const head = '| renderer | technique | false shadow % | false lit % | error % | mean abs error % | ms/frame (rounds: min-max) | three.js / ours rgba | three.js / ours depthtex |\n' +
               '|---|---|---:|---:|---:|---:|---:|---:|---:|';
  const line = (r) => {
    const renderer = r.kind === 'ours' ? 'penumbra (WebGL 1)' : `three.js r${env.threeInfo?.revision} (WebGL 2)`;
    const tech = r.kind === 'ours' ? `${r.c.encoding} ${r.c.filter}, bias ${r.c.encoding === 'r8' ? '0.005' : '0.0015'} (default)`
      : r.label.replace('three.js ', '');
    const ratio = r.kind === 'three' ? `${f2(r.ratio)} (vs ${r.c.vs.replace('-', ' ')})` : '';
    const ratioD = r.kind === 'three' ? `${f2(r.ratioDepthtex)} (vs ${r.c.vs.replace('rgba', 'depthtex').replace('-', ' ')})` : '';
    const spread = r.msRounds.length > 1 ? ` (${f2(Math.min(...r.msRounds))}-${f2(Math.max(...r.msRounds))})` : '';
    return `| ${renderer} | ${tech} | ${f2(r.falseShadow)} | ${f2(r.falseLit)} | ${f2(r.error)} | ${f2(r.mae)} | ${f2(r.ms)}${spread} | ${ratio} | ${ratioD} |`;
  };
  const table = [
    `The course scene at ${SIZE}x${SIZE}, shadow map ${MAP}, mean over ${times}; ms/frame: median over ` +
    `${o.rounds} round(s) of ${o.frames} moving frames per time; headless Chromium, SwiftShader, ${env.cores} cores ` +
    `(1-minute load average ${env.load[0].toFixed(1)} before the run; the run itself keeps both cores busy).`,
    '', head, ...rows.map(line), ''].join('\n');
  const std = rows.filter((r) => r.msStandard !== null)
    .map((r) => `| ${r.label} | ${f2(r.ms)} | ${f2(r.msStandard)} |`).join('\n');
  const perTime = ['| technique | ' + o.times.map((t) => `t = ${t}: error % / mae %`).join(' | ') + ' |',
                   '|---|' + o.times.map(() => '---:').join('|') + '|',
                   ...rows.map((r) => `| ${r.kind === 'ours' ? 'penumbra ' + r.label : r.label} | ` +
                     r.per.map((p) => `${f2(p.error)} / ${f2(p.mae)}`).join(' | ') + ' |')].join('\n');
  const cam = ['| t | penumbra --scene teapot: error % (valid px) | penumbra --scene exported.gltf: error % (valid px) | pixels that differ |',
               '|---:|---:|---:|---:|',
               ...cameraCheck.map((c) => `| ${c.t} | ${f2(c.teapot.error)} (${c.teapot.valid}) | ${f2(c.gltf.error)} (${c.gltf.valid}) | ${c.differing} |`)].join('\n');
  const agree = ['| three.js | penumbra | ' + o.times.map((t) => `t = ${t}: pixels > 8 levels apart (mean abs diff, levels)`).join(' | ') + ' |',
                 '|---|---|' + o.times.map(() => '---:').join('|') + '|',
                 ...agreement.map((g) => `| ${byLabel(rows, g.a).replace('three.js ', '')} | ${g.b.replace('-', ' ')} | ` +
                   g.per.map((p) => `${p.differing} (${p.meanLevels.toFixed(3)})`).join(' | ') + ' |')].join('\n');
  const basicMax = Math.max(...agreement.slice(0, 2).flatMap((g) => g.per.map((p) => p.differing)));
  const basicSame = basicMax === 0;
  const fr = frustum ? `at t = ${frustum.t}: the light at (${frustum.position.map((v) => v.toFixed(3)).join(', ')}), ` +
    `aimed at (${frustum.aim.map((v) => v.toFixed(3)).join(', ')}), tan of the half-angles ${frustum.tanX.toFixed(4)} x ` +
    `${frustum.tanY.toFixed(4)} (spot angle ${frustum.angleDeg.toFixed(2)} degrees, shadow.aspect ` +
    `${(frustum.tanX / frustum.tanY).toFixed(4)}), near ${frustum.near.toFixed(4)}, far ${frustum.far.toFixed(4)}` : '';
  const doc = `# three.js side by side

The course scene (the teapot on the marble table under the circling point light), exported by
\`penumbra export\` at fixed times, rendered by **three.js** (its GLTFLoader, the same triangles,
camera and light) and by **penumbra's web build** (the W09P2c page) in the same headless Chromium,
at the same canvas size (${SIZE}x${SIZE}) and shadow-map size (${MAP}); both visibility images scored
against the same Embree ground truth with the same metric code (\`penumbra truth --score\`, see
[tradeoffs.md](tradeoffs.md) for the truth, the validity mask and the metrics).

## Regenerating

\`\`\`sh
node tools/threejs_compare.mjs            # about ${Math.max(1, Math.round(env.seconds / 60))} min; prints the table, writes this file and out/threejs/
node tools/threejs_compare.mjs --quick --check --no-doc   # what the web.threejs test runs (t = 0.6, 5 frames)
\`\`\`

It builds nothing: it uses \`build/penumbra\` (export, truth, render), \`build-web/site\` (the W09P2c
page) and \`node_modules\` (\`npm ci\`: playwright-core, pngjs, three). Options: \`--times\`,
\`--frames\`, \`--rounds\`, \`--out-dir\`, \`--doc\` / \`--no-doc\`, \`--cli\`, \`--from-json FILE\` (measure
nothing: the table and this file again from a run's \`results.json\`). Every image it scored
is in \`out/threejs/images/\`, every figure in \`out/threejs/results.json\`, and one row per frame
and technique with the columns of \`docs/bench/results.csv\` in \`out/threejs/results.csv\`
(\`penumbra bench --from-csv out/threejs/results.csv --out-dir DIR\` plots them; the times are
SwiftShader's, so do not merge them with the EGL bench's rows). The three.js page is
\`tests/threejs/compare.html\` + \`compare.js\`; the tool serves it, \`node_modules/three\` and the
exported scenes from the same 127.0.0.1 server as the site.

## Results

Measured on ${env.date} by \`node tools/threejs_compare.mjs\` (${env.seconds} s): ${env.chromium}, headless,
WebGL through ANGLE on SwiftShader (\`${env.threeInfo?.renderer}\`), ${env.cores} cores (${env.cpu});
three.js ${env.threeVersion} (r${env.threeInfo?.revision}) on ${env.threeInfo?.version}, penumbra's W09P2c page on WebGL 1.

${table}
The ratios compare each three.js row with penumbra's rgba (and depthtex) encoding and the same
kind of filter (BasicShadowMap with \`hard\`, PCFShadowMap with \`pcf4x4\`). *defaults*: three.js as it
comes (\`shadow.bias\` 0, \`normalBias\` 0, \`shadowSide\` null, i.e. the back faces of a FrontSide
material into the map). *bias -0.0015*: penumbra's default bias, three.js's sign. *matched*:
penumbra's bias and both faces into the map, as penumbra draws them.

What the figures say:

${findings(rows, agreement, basicSame, basicMax)}

Colour frames with three.js's MeshStandardMaterial as GLTFLoader makes it (physically based),
against the MeshPhongMaterial (Blinn-Phong, closest to penumbra's shading) used above:

| three.js | ms/frame, MeshPhongMaterial | ms/frame, MeshStandardMaterial |
|---|---:|---:|
${std}

Error % / mean absolute error % per frame:

${perTime}

**Matched, the two shadow maps see the same thing.** With penumbra's frustum, bias and faces, three.js's
BasicShadowMap and penumbra's hard filter give ${basicSame ? 'the same visibility image, pixel for pixel' :
  `nearly the same visibility image (at most ${basicMax} of ${SIZE * SIZE} pixels apart)`}; the PCF
kernels differ (see below), so their greys do:

${agree}

**The exported camera is penumbra's camera.** penumbra's own EGL render (rgba hard) of the
exported glTF and of the built-in course scene, scored against the same truth:

${cam}

## How it is measured

- **The scene.** \`penumbra export --scene teapot --time T\`: the same ${summary ? summary.triangles : '6322'} triangles
  (the teapot at penumbra's default tessellation, the table quad: three.js's own TeapotGeometry is
  not used), the camera (yfov 45 degrees, aspect 1, near 0.1, far 30) and the point light
  (\`KHR_lights_punctual\`). three.js loads it with GLTFLoader; the ground truth ray-traces
  penumbra's built-in scene at the same t and reads penumbra's camera, which the table above shows
  to be the exported one.
- **The light.** penumbra draws the point light's shadows with one 2D perspective map aimed from
  the light at the centre of the casters' and receivers' bounds and fitted tightly around them.
  A three.js PointLight would use a cube map (six passes, a cube depth texture), so three.js gets a
  SpotLight at the light's position whose shadow camera is exactly penumbra's frustum: the same aim
  and up vector, angle = atan(tan_y), \`shadow.aspect\` = tan_x / tan_y, the same near and far,
  refitted every frame from the moved teapot's bounds as penumbra refits it (${fr}). Its cone
  covers every caster and receiver, so it lights what the point light lights.
- **Visibility.** penumbra: the page's \`aov=visibility\` (255 lit, 0 shadowed, PCF fractions
  between). three.js: a second render in which every mesh gets a \`ShadowMaterial\` of opacity 1 on
  a white background; it outputs alpha = 1 - visibility, and blending (one minus source alpha,
  zero) writes 255 x visibility into the pixel, replacing rather than compositing over what is
  behind it (so the lit teapot in front of the shadowed table reads as lit). Read back with
  \`readPixels\`, flipped to top row first, scored by \`penumbra truth --score\` as any PNG.
- **Time.** ms per colour frame (penumbra: W09P2c with the map view off; three.js: the loaded scene
  with MeshPhongMaterial, a spot light and an ambient light), each frame drawn and then waited for
  by a one-pixel \`readPixels\` (WebGL's \`finish()\` only flushes in Chromium), clocked with
  \`performance.now()\` in the page around the draw and the readback. The light and the teapot move
  every frame (t + k/60: penumbra's \`setTime\`; three.js gets the same frames' node matrices and
  light position from \`penumbra export\`, set outside the clock), so both redraw the shadow map
  every frame. One page of each, switched between configurations; penumbra's own animation loop is
  paused (\`Module.pauseMainLoop()\`), so only the timed frames draw. ${o.rounds} round(s); in each,
  for each time, every configuration in turn, penumbra's and three.js's alternating: 3 warm-up
  frames, then ${o.frames} frames. A round's figure is the median over its frames, the reported one the
  median of the rounds' (min-max beside it); a ratio is the median of the rounds' ratios.
  \`performance.now()\` is coarsened to 0.1 ms in a page that is not cross-origin isolated: each
  frame's time is a multiple of 0.1 ms, and the medians of many frames carry that grain.
  SwiftShader is a CPU rasteriser: fill rate and shader length dominate, and other jobs on the
  ${env.cores} cores (the load average before the run is given above the table) slow whichever
  configuration runs at that moment.

## What still differs

- **WebGL 2 against WebGL 1.** three.js renders only through WebGL 2 since r163
  (${env.threeInfo?.version}, ${env.threeInfo?.glsl}); penumbra's page is WebGL 1 (GLSL ES 1.00).
  The two run on the same SwiftShader in the same browser, but with different shader languages and
  API paths (three.js: a depth texture, and \`sampler2DShadow\` with hardware comparison for PCF;
  penumbra: a depth encoding of WebGL 1 or \`WEBGL_depth_texture\`).
- **Depth storage and precision.** three.js's map is a 24-bit depth texture (\`DepthTexture\`,
  UnsignedIntType); penumbra's rgba packs the depth into an RGBA8 colour target (exact to 2^-24 under
  highp, the same scores as its depthtex), r8 keeps 8 bits. Both compare in window depth [0, 1] over
  the same near and far planes, so the same bias means the same offset. Both run highp here
  (SwiftShader computes mediump at fp32 anyway).
- **Bias.** three.js's defaults are \`bias\` 0 and \`normalBias\` 0; penumbra's default is 0.0015
  (0.005 for r8). The *bias -0.0015* rows give three.js penumbra's. \`normalBias\` stays 0 (penumbra has
  no normal offset).
- **Faces in the map.** three.js draws a FrontSide material's back faces into the map
  (\`shadowSide\` null), which moves the acne to the faces turned away from the light (left out of
  the score) and can leak light where a caster is thin or open, or touches a receiver (nothing
  measurable on this scene, see t = 0); penumbra draws both faces (its open teapot must cast from
  both sides), which costs three.js a little time too (*matched* against *bias -0.0015*). *matched*
  sets \`shadowSide = DoubleSide\`.
- **The PCF kernels.** penumbra's pcf4x4: 16 NEAREST taps in a 4x4 box at +-0.5 and +-1.5 texels,
  equal weights (17 levels of grey). three.js r${env.threeInfo?.revision}'s PCFShadowMap: 5 taps on a Vogel disk of radius
  \`shadow.radius\` (1 texel), rotated per pixel by interleaved gradient noise, each a hardware 2x2
  bilinear comparison (LinearFilter on a compare texture): a footprint of at most about 4 texels
  across, weighted towards its centre (penumbra's: 4 texels, equal weights), with smoother and
  noisier greys. (PCFSoftShadowMap is gone from three.js; VSMShadowMap is
  not compared.) BasicShadowMap is one NEAREST tap, as penumbra's hard filter.
- **The light type.** A spot light with penumbra's frustum instead of a point light, as above; the
  shadow test is the same map over the same frustum, but the lighting of the colour frames differs
  (the spot's cone, three.js's physically based units with decay 0 and intensity 1), which changes
  nothing in visibility.
- **Shading and colour.** The timing renders colour frames: three.js with MeshPhongMaterial
  (MeshStandardMaterial also given), an ambient light, sRGB output and no tone mapping;
  penumbra with its Blinn-Phong marble and porcelain. The visibility images carry no colour
  management or tone mapping that matters: ShadowMaterial's white stays white and the grey is the
  blend factor.
- **The frame loop.** three.js's \`render()\` walks its scene graph, sorts, updates uniforms and
  redraws its shadow map every frame (\`shadowMap.autoUpdate\`), whatever moved; penumbra redraws
  its map only when the light or a caster moved (here they always do) and does its frustum fit and
  the scene's animation inside the clock (three.js's refit and node updates are outside it).
- **Culling and antialiasing.** Both canvases have no antialiasing, a depth and a stencil buffer,
  a preserved drawing buffer. three.js's frustum culling is off (penumbra culls nothing); the camera
  pass draws front faces in three.js (FrontSide), as the truth sees them.
`;
  return { table, doc };
}

// A few sentences drawn from the figures, so that they stay true when the tool is run again.
function findings(rows, agreement, basicSame, basicMax) {
  const r = Object.fromEntries(rows.map((x) => [x.id, x]));
  const pct = (x) => `${f2(x)} %`;
  const out = [];
  out.push(`- **Matched, three.js's BasicShadowMap is penumbra's hard filter**: ${basicSame ? 'the same pixels' : `the same pixels but ${basicMax} (of ${SIZE * SIZE}) in a frame`}, ` +
    `error ${pct(r['three-basic-matched'].error)} against ${pct(r['rgba-hard'].error)}. The frames, the camera, the light frustum ` +
    'and the depth test agree; what separates the other rows is settings, the filter kernels and the cost.');
  const better = r['three-basic-default'].error < r['rgba-hard'].error;
  const t0 = r['three-basic-default'].per[0];
  out.push(`- **three.js's defaults score ${better ? 'better' : 'worse'} than penumbra's on this scene** (hard: ` +
    `${pct(r['three-basic-default'].error)} against ${pct(r['rgba-hard'].error)}; false shadow ` +
    `${pct(r['three-basic-default'].falseShadow)} against ${pct(r['rgba-hard'].falseShadow)}). With penumbra's bias and ` +
    `three.js's faces: ${pct(r['three-basic-bias'].error)}; with penumbra's bias and faces (matched): ` +
    `${pct(r['three-basic-matched'].error)}. So the faces drawn into the map make the difference, not the bias: three.js ` +
    'draws a FrontSide material\'s back faces, so a lit surface is compared with the far side of its own object and ' +
    'its acne (the teapot\'s terminator, penumbra\'s main false shadow here) goes. ' +
    `At t = ${t0.t}${t0.t === 0 ? ', where the teapot touches the table,' : ''} its false lit is ${pct(t0.falseLit)} ` +
    `(penumbra: ${pct(r['rgba-hard'].per[0].falseLit)}). penumbra draws both faces, as its open teapot and glTF sheets need.`);
  out.push(`- **PCF**: three.js's 5 bilinear compare taps on a rotated disk against penumbra's 16-tap 4x4 box: ` +
    `error ${pct(r['three-pcf-default'].error)} (defaults) and ${pct(r['three-pcf-matched'].error)} (matched) against ` +
    `${pct(r['rgba-pcf4x4'].error)}; mean absolute error ${pct(r['three-pcf-matched'].mae)} matched against ` +
    `${pct(r['rgba-pcf4x4'].mae)}: three.js's kernel is narrower (a radius of one texel plus the bilinear footprint ` +
    'against an equally weighted 4-texel box), so it leaves less grey where the truth is black or white.');
  const rb = r['three-basic-default'].ratio, rp = r['three-pcf-default'].ratio;
  const cmp = (x) => (x > 1.05 ? 'slower' : x < 0.95 ? 'faster' : 'about as fast');
  out.push(`- **Time**: three.js's BasicShadowMap frame is ${cmp(rb)} than penumbra's rgba hard one ` +
    `(${f2(rb)}x: ${f2(r['three-basic-default'].ms)} against ${f2(r['rgba-hard'].ms)} ms/frame), its PCFShadowMap frame ` +
    `${cmp(rp)} than penumbra's rgba pcf4x4 one (${f2(rp)}x: ${f2(r['three-pcf-default'].ms)} against ` +
    `${f2(r['rgba-pcf4x4'].ms)} ms). On SwiftShader every shader instruction is CPU time: penumbra's pcf4x4 pays for ` +
    '16 taps (each unpacking an RGBA8 texel under rgba), three.js\'s PCF for 5 hardware-filtered comparisons; with one ' +
    'tap each, the rest of the frame (three.js\'s scene graph, its larger shaders, WebGL 2 against WebGL 1) decides.');
  return out.join('\n');
}

function byLabel(rows, id) {
  const r = rows.find((x) => x.id === id);
  return r ? r.label : id;
}

main().catch((e) => {
  console.error(`threejs_compare: ${e.stack || e}`);
  process.exitCode = 1;
});
