// web.soak: W09P2c drawn frame after frame while its settings change every 50 frames, walking its
// real controls (the selects, boxes, buttons and bias radios, as a student would) through a fixed
// cycle of 12 settings that visits every value of every control the exercise offers and every
// combination of encoding x filter x precision. Asserts:
//   - no GL error: every non-zero WebGL getError (the renderer checks once a frame here), the
//     module's pending glGetError after each batch of frames, no frame that failed, no console error;
//   - GL objects flat: the live textures, buffers, framebuffers, renderbuffers, programs and shaders
//     (WebGLRenderingContext's create*/delete* wrapped before the page's scripts) at the end of each
//     full cycle equal those at the end of the first one (shader variants are compiled on first use,
//     so they may grow during the first cycle only);
//   - the wasm heap flat: malloc's bytes in use (penumbra_heap_used) after the first cycle never
//     more than HEAP_BOUND above what it was at the end of the first cycle.
// Frames: the page's own frame function (window.penumbra.renderNow), as fast as it draws: the page
// paused, its animation loop stopped (Module.pauseMainLoop: every frame is one this test draws), its
// clock moved 1/60 s per frame while the light or the jump is on (both off: the same frame again,
// the shadow map reused, as on the page). One frame after each control a step changes (as the
// page's loop would draw between two clicks), then the rest of the step's 50.
//
//   node tests/web/soak.mjs [--frames N (default 1200: two cycles)] [--per-change N (default 50)]
//        [--canvas PX (default: the page's 512)] [--minutes M (stop after the last whole cycle that
//        fits)] [--out FILE.json]
// The full soak: --frames 20000. The figures are printed as a table and written as JSON to --out
// (default build/test-output/web/soak.json).
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import os from 'node:os';
import { runTest, openPage, check } from './harness.mjs';

const args = process.argv.slice(2);
function arg(name, fallback) {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
}
const FRAMES = Number(arg('--frames', '1200'));
const CANVAS = Number(arg('--canvas', '0')); // 0: the page's own size (512)
const MINUTES = Number(arg('--minutes', '0')); // >0: stop after the last whole cycle that fits
const OUT = path.resolve(arg('--out', path.join(path.dirname(new URL(import.meta.url).pathname), '../../build/test-output/web/soak.json')));
const PER_CHANGE = Number(arg('--per-change', '50'));
// Malloc's bytes in use differ by a few strings' capacity between two samples (the state JSON and
// the plan text the module keeps for the page, which carry timings): trial runs swung by up to
// 2.9 KB after the first cycle. The bound is about 5 times that; a leak of 1 byte a frame over the
// full soak (19,400 frames after the first cycle) or of 50 bytes a settings change exceeds it.
const HEAP_BOUND = 16 * 1024;
check(Number.isInteger(FRAMES) && FRAMES > 0, `--frames ${FRAMES}`);
check(Number.isInteger(PER_CHANGE) && PER_CHANGE > 0, `--per-change ${PER_CHANGE}`);

// The cycle: each step the whole state of the controls; a step touches only the controls whose value
// changes. encoding, filter, precision: all 12 combinations; bias auto / sheet / two fixed values
// (period 4, so with each encoding); every map size, face choice and view; light and jump on and off,
// 4096 while both are off (the map drawn once, then reused: 4096 redrawn every frame takes 0.3 s on
// SwiftShader). The last step leads back to the first.
const ENC = ['r8', 'rgba', 'depthtex'];
const BIAS = ['auto', 'sheet', '0.003', '0.0008'];
const SIZES = ['1024', '256', '512', '2048', '1024', '4096', '512', '256', '2048', '1024', '512', '256'];
const FACES = ['auto', 'front', 'back', 'both'];
const MOTION = [[1, 1], [1, 1], [1, 0], [1, 1], [0, 1], [0, 0], [1, 1], [0, 1], [1, 0], [1, 1], [1, 1], [0, 0]];
const CYCLE = Array.from({ length: 12 }, (_, i) => ({
  encoding: ENC[i % 3],
  filter: Math.floor(i / 3) % 2 ? 'pcf4x4' : 'hard',
  precision: Math.floor(i / 6) % 2 ? 'mediump' : 'highp',
  bias: BIAS[i % 4],
  'map-size': SIZES[i],
  'map-faces': FACES[(i * 3 + 1) % 4],
  aov: [0, 3, 7, 8].includes(i) ? 'visibility' : 'color',
  'map-view': [4, 9].includes(i) ? 'off' : 'on',
  light: MOTION[i][0] ? 'on' : 'off',
  jump: MOTION[i][1] ? 'on' : 'off',
}));
const KINDS = ['textures', 'buffers', 'framebuffers', 'renderbuffers', 'programs', 'shaders'];

// In the page before its scripts: live GL objects per kind and every non-zero getError.
function wrapWebGL() {
  const P = WebGLRenderingContext.prototype;
  const kinds = { Texture: 'textures', Buffer: 'buffers', Framebuffer: 'framebuffers', Renderbuffer: 'renderbuffers',
                  Program: 'programs', Shader: 'shaders' };
  const live = {};
  const made = {};
  for (const [type, kind] of Object.entries(kinds)) {
    live[kind] = new Set();
    made[kind] = 0;
    const create = P['create' + type];
    const remove = P['delete' + type];
    P['create' + type] = function (...a) {
      const o = create.apply(this, a);
      if (o) { live[kind].add(o); ++made[kind]; }
      return o;
    };
    P['delete' + type] = function (o) {
      if (o) live[kind].delete(o);
      return remove.call(this, o);
    };
  }
  const errors = []; // the first 64 codes
  let errorCount = 0;
  const getError = P.getError;
  P.getError = function () {
    const e = getError.call(this);
    if (e !== 0) {
      ++errorCount;
      if (errors.length < 64) errors.push(e);
    }
    return e;
  };
  window.__soak = {
    live: () => Object.fromEntries(Object.entries(live).map(([k, s]) => [k, s.size])),
    made: () => ({ ...made }),
    errors,
    errorCount: () => errorCount,
  };
}

// Sets one control as a student would; checks that the module took the value.
async function setControl(page, name, value) {
  if (name === 'light' || name === 'jump') {
    if ((await page.getAttribute(`#${name}`, 'aria-pressed')) !== (value === 'on' ? 'true' : 'false')) await page.click(`#${name}`);
  } else if (name === 'filter') {
    await page.setChecked('#filter', value === 'pcf4x4');
  } else if (name === 'map-view') {
    await page.setChecked('#map-view', value === 'on');
  } else if (name === 'bias') {
    if (value === 'auto' || value === 'sheet') {
      await page.check(`#bias-${value}`);
    } else {
      await page.check('#bias-fixed');
      await page.fill('#bias', value);
      await page.dispatchEvent('#bias', 'change');
    }
  } else {
    await page.selectOption(`#${name}`, value);
  }
}

async function sample(page) {
  return page.evaluate(() => ({
    heapUsed: Module._penumbra_heap_used() >>> 0,
    heapSize: Module.HEAP8.length,
    live: window.__soak.live(),
    made: window.__soak.made(),
    frames: window.penumbra.frameCount(),
    webglErrors: window.__soak.errorCount(),
  }));
}

function fmtBytes(n) { return n >= 1 << 20 ? `${(n / (1 << 20)).toFixed(2)} MiB` : `${(n / 1024).toFixed(1)} KiB`; }

await runTest('web.soak', async ({ server, browser }) => {
  const { page, problems } = await openPage(browser, `${server.url}/w09p2c.html`, { init: wrapWebGL });
  if (CANVAS > 0) await page.evaluate((s) => { const c = document.getElementById('canvas'); c.width = c.height = s; }, CANVAS);
  const s0 = await page.evaluate(() => window.penumbra.state());
  check(s0.depthTexture, 'this browser offers no WEBGL_depth_texture: the cycle needs encoding=depthtex');
  check(s0.maxMapSize >= 4096, `maxMapSize ${s0.maxMapSize} < 4096`);
  // The page's own state (its defaults) is not in the cycle: the first step starts from it.
  // Paused: the clock moves only as the batches move it. The page's animation loop stopped
  // (Emscripten's main loop): every frame is one this test draws.
  await page.evaluate(() => { window.penumbra.pause(); Module.pauseMainLoop(); });

  const samples = [];
  const failures = [];
  let driven = 0;
  let t = 0;
  let step = 0;
  // Draws n frames (the page's frame function), the clock moved 1/60 s before each while the light
  // or the jump is on; notes failed frames and pending GL errors.
  async function draw(n, where) {
    const r = await page.evaluate(({ n, t }) => {
      const o = window.penumbra.state().options;
      const moving = o.light === 'on' || o.jump === 'on';
      let failed = 0;
      for (let i = 0; i < n; ++i) {
        if (moving) t += 1 / 60;
        window.penumbra.setTime(t);
        if (!window.penumbra.renderNow()) ++failed;
      }
      const pending = [];
      for (let e = window.penumbra.glError(); e !== 0 && pending.length < 16; e = window.penumbra.glError()) pending.push(e);
      return { t, failed, pending, status: window.penumbra.state().status };
    }, { n, t });
    t = r.t;
    driven += n;
    if (r.failed || r.pending.length)
      failures.push(`${where}: ${r.failed} frames failed, pending GL errors [${r.pending}], status '${r.status}'`);
    return r.pending.length;
  }
  const started = Date.now();
  const deadline = MINUTES > 0 ? started + MINUTES * 60000 : Infinity;
  let cycleStarted = started;
  const first = await sample(page);
  while (driven < FRAMES) {
    const want = CYCLE[step % CYCLE.length];
    const before = (await page.evaluate(() => window.penumbra.state())).options;
    // One control at a time, a frame after each (as the page's loop would draw one), then the rest
    // of the 50 frames.
    let pending = 0;
    let drawn = 0;
    for (const [name, value] of Object.entries(want)) {
      if (before[name] === value || drawn >= PER_CHANGE - 1 || driven >= FRAMES) continue;
      await setControl(page, name, value);
      pending += await draw(1, `step ${step}, after ${name}=${value}`);
      ++drawn;
    }
    const st = await page.evaluate(() => window.penumbra.state());
    for (const [name, value] of Object.entries(want))
      check(st.options[name] === value, `step ${step}: ${name} is ${st.options[name]}, not ${value} after its control`);
    const n = Math.min(PER_CHANGE - drawn, FRAMES - driven);
    if (n > 0) pending += await draw(n, `step ${step}`);
    const s = await sample(page);
    s.step = step;
    s.driven = driven;
    s.ms = Date.now() - started;
    s.pending = pending;
    samples.push(s);
    ++step;
    if (step % CYCLE.length === 0) {
      const now = Date.now();
      const fps = driven / (s.ms / 1000);
      console.log(`cycle ${step / CYCLE.length}: ${driven} frames, ${(s.ms / 1000).toFixed(0)} s (${fps.toFixed(1)} frames/s), heap used ${s.heapUsed} of ${s.heapSize}, ` +
                  KINDS.map((k) => `${k} ${s.live[k]}`).join(' ') + `, WebGL errors ${s.webglErrors}`);
      // --minutes: no cycle begun that would end after the deadline (by the last cycle's time, +20%).
      if (now + 1.2 * (now - cycleStarted) > deadline) {
        console.log(`stopping after ${driven} frames: another cycle would pass the ${MINUTES}-minute deadline`);
        break;
      }
      cycleStarted = now;
    }
  }
  const wall = (Date.now() - started) / 1000;
  const last = samples[samples.length - 1];
  const cycles = Math.floor(samples.length / CYCLE.length);
  const cycleEnds = Array.from({ length: cycles }, (_, c) => samples[(c + 1) * CYCLE.length - 1]);
  const afterWarm = cycles >= 1 ? samples.slice(CYCLE.length) : [];
  const base = cycleEnds[0];
  const stat = (f, list = samples) => ({ first: f(list[0]), last: f(list[list.length - 1]), max: Math.max(...list.map(f)), min: Math.min(...list.map(f)) });
  const figures = {
    page: 'w09p2c', date: new Date().toISOString(), machine: `${os.cpus().length} cores, ${os.cpus()[0]?.model}; ${s0.renderer}`,
    framesAsked: FRAMES, framesDriven: driven, framesDrawn: last.frames - first.frames, perChange: PER_CHANGE, changes: samples.length,
    cycleSteps: CYCLE.length, cycles, canvas: CANVAS || 512, wallSeconds: +wall.toFixed(1), framesPerSecond: +(driven / wall).toFixed(2),
    heapUsed: { ...stat((s) => s.heapUsed), atLoad: first.heapUsed, endOfFirstCycle: base?.heapUsed ?? null,
                maxAfterFirstCycle: afterWarm.length ? Math.max(...afterWarm.map((s) => s.heapUsed)) : null, bound: HEAP_BOUND,
                atCycleEnds: cycleEnds.map((s) => s.heapUsed) },
    heapSize: { ...stat((s) => s.heapSize), atLoad: first.heapSize },
    live: Object.fromEntries(KINDS.map((k) => [k, { atLoad: first.live[k], ...stat((s) => s.live[k]), endOfFirstCycle: base?.live[k] ?? null }])),
    created: Object.fromEntries(KINDS.map((k) => [k, last.made[k]])),
    glErrors: { webglGetError: last.webglErrors, pendingAfterBatches: samples.reduce((a, s) => a + s.pending, 0), failures },
    problems,
    cycle: CYCLE,
    samples: samples.map((s) => ({ step: s.step, driven: s.driven, ms: s.ms, heapUsed: s.heapUsed, heapSize: s.heapSize, live: s.live })),
  };
  mkdirSync(path.dirname(OUT), { recursive: true });
  writeFileSync(OUT, JSON.stringify(figures, null, 1) + '\n');

  const row = (label, v) => console.log(`  ${label.padEnd(26)} ${v}`);
  console.log(`W09P2c soak: ${figures.machine}`);
  row('frames', `${driven} of ${FRAMES} asked (module's count ${figures.framesDrawn}), ${samples.length} changes, ${cycles} cycles of ${CYCLE.length}`);
  row('wall time', `${wall.toFixed(1)} s, ${figures.framesPerSecond} frames/s (canvas ${figures.canvas} px)`);
  row('heap used', `load ${first.heapUsed}, first ${figures.heapUsed.first}, end of cycle 1 ${base?.heapUsed ?? '-'}, last ${last.heapUsed}, max ${figures.heapUsed.max}` +
                   (afterWarm.length ? ` (max after cycle 1: +${figures.heapUsed.maxAfterFirstCycle - base.heapUsed} B, bound ${HEAP_BOUND})` : ''));
  if (cycles > 1) row('heap used at cycle ends', `min ${Math.min(...figures.heapUsed.atCycleEnds)}, max ${Math.max(...figures.heapUsed.atCycleEnds)} (${cycles} cycles)`);
  row('heap size', `load ${fmtBytes(first.heapSize)}, last ${fmtBytes(last.heapSize)}, max ${fmtBytes(figures.heapSize.max)}`);
  console.log(`  ${'GL objects (live)'.padEnd(26)} ${'load'.padStart(5)} ${'first'.padStart(6)} ${'cyc1'.padStart(5)} ${'last'.padStart(5)} ${'max'.padStart(5)} ${'created'.padStart(8)}`);
  for (const k of KINDS) {
    const l = figures.live[k];
    console.log(`    ${k.padEnd(24)} ${String(l.atLoad).padStart(5)} ${String(l.first).padStart(6)} ${String(l.endOfFirstCycle ?? '-').padStart(5)} ${String(l.last).padStart(5)} ${String(l.max).padStart(5)} ${String(figures.created[k]).padStart(8)}`);
  }
  row('GL errors', `${last.webglErrors} from WebGL getError, ${figures.glErrors.pendingAfterBatches} pending after batches, ${failures.length} failed batches`);
  row('JSON', OUT);

  check(failures.length === 0, failures.join('; '));
  check(last.webglErrors === 0, `${last.webglErrors} GL errors seen by getError: ${await page.evaluate(() => window.__soak.errors.join(','))}`);
  check(problems.length === 0, problems.join('; '));
  check(cycles >= 2, `${cycles} full cycles: the flatness checks need 2 (--frames >= ${2 * CYCLE.length * PER_CHANGE})`);
  for (let c = 1; c < cycles; ++c)
    for (const k of KINDS)
      check(cycleEnds[c].live[k] === base.live[k], `${k}: ${cycleEnds[c].live[k]} live after cycle ${c + 1}, ${base.live[k]} after cycle 1`);
  const grown = figures.heapUsed.maxAfterFirstCycle - base.heapUsed;
  check(grown <= HEAP_BOUND, `heap used grew by ${grown} bytes after the first cycle (bound ${HEAP_BOUND})`);
});
