// web.first_frame: how long each exercise page takes from navigation start to its first drawn
// frame, measured by the test itself: each page is loaded 5 times, each in a fresh browser
// context (nothing cached: the test server sends Cache-Control: no-store), and the first frame is
// the first animation frame after which the canvas's pixels, read back with gl.readPixels right
// after the frame's requestAnimationFrame callback (before the browser presents and clears the
// drawing buffer), are not all black. The time is performance.now() then (0 = navigation start).
// Prints per page the median of the 5 loads and where the time went (the wasm's download, its
// compile, main() up to the WebGL context, the context to the first frame, the first frame's
// own draw), plus the page's own figure (window.penumbra.firstFrameMs) where the page has one.
// Asserts behaviour only: every load drew a non-black frame with no page error and gave every
// figure; never a time. The payload (each page's NAME.wasm + NAME.js, gzip -9) is printed against
// issue 16's goal of 120 KB, not asserted (docs/payload.md).
//
// usage: node tests/web/first_frame.mjs [--loads N] [--pages a,b] [--json FILE]
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import path from 'node:path';
import { runTest, check, siteDir, PAGES } from './harness.mjs';

const args = process.argv.slice(2);
const arg = (name, dflt) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : dflt;
};
const LOADS = +arg('--loads', 5);
const pages = arg('--pages', PAGES.join(',')).split(',');
const jsonOut = arg('--json', null);
// A page's NAME.wasm + NAME.js, gzip -9: the goal of issue 16 (120 KB), in bytes.
const PAYLOAD_GOAL = 120 * 1000;

// Runs in the page before its scripts: captures the WebGL contexts, times the wasm's compile and
// the module's first WebGL context, and after every animation-frame callback (until the first
// non-black frame) reads the canvas back.
function probe() {
  const ff = { frame: null, frameStart: null, instantiateStart: null, instantiated: null, context: null, frames: 0 };
  window.__firstFrame = ff;
  const contexts = [];
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (type, attrs) {
    const c = getContext.call(this, type, attrs);
    if (c && /webgl/.test(type) && !contexts.includes(c)) {
      contexts.push(c);
      if (ff.context === null) ff.context = performance.now();
    }
    return c;
  };
  for (const name of ['instantiateStreaming', 'instantiate']) {
    const f = WebAssembly[name];
    WebAssembly[name] = function (...a) {
      if (ff.instantiateStart === null) ff.instantiateStart = performance.now();
      return f.apply(this, a).then((r) => {
        if (ff.instantiated === null) ff.instantiated = performance.now();
        return r;
      });
    };
  }
  function nonBlack(gl) {
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    if (!w || !h || gl.isContextLost()) return false;
    const fb = gl.getParameter(gl.FRAMEBUFFER_BINDING);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    const px = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
    for (let i = 0; i < px.length; i += 4) if (px[i] | px[i + 1] | px[i + 2]) return true;
    return false;
  }
  const raf = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (cb) =>
    raf((ts) => {
      const start = performance.now();
      cb(ts);
      if (ff.frame !== null || contexts.length === 0) return;
      ++ff.frames;
      if (contexts.some(nonBlack)) {
        ff.frame = performance.now();
        ff.frameStart = start;
      }
    });
}

// The page's own figure (window.penumbra.firstFrameMs, a number or a function giving one), or null.
function pageFigure() {
  const f = window.penumbra && window.penumbra.firstFrameMs;
  const v = typeof f === 'function' ? f() : f;
  return typeof v === 'number' && v > 0 ? v : null;
}

function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
}

async function loadOnce(browser, url) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  try {
    const page = await context.newPage();
    const problems = [];
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
    await page.addInitScript(probe);
    await page.goto(url, { waitUntil: 'commit' });
    await page.waitForFunction(() => window.__firstFrame && window.__firstFrame.frame !== null, null,
                               { timeout: 60000, polling: 50 });
    // The page's own figure, where it has one (it is polled each animation frame: give it a few).
    await page.waitForFunction(pageFigure, null, { timeout: 2000 }).catch(() => {});
    const name = new URL(url).pathname.split('/').pop().replace(/\.html$/, '');
    const r = await page.evaluate(([figureSource, module]) => {
      const figure = eval(figureSource);  // eslint-disable-line no-eval
      const ff = window.__firstFrame;
      const res = (name) => performance.getEntriesByType('resource').find((e) => e.name.endsWith('/' + name));
      const wasm = res(module + '.wasm'), js = res(module + '.js');
      const nav = performance.getEntriesByType('navigation')[0];
      return {
        firstFrame: ff.frame, frameStart: ff.frameStart, instantiateStart: ff.instantiateStart,
        instantiated: ff.instantiated, context: ff.context, framesBefore: ff.frames - 1,
        jsEnd: js ? js.responseEnd : null, wasmStart: wasm ? wasm.startTime : null,
        wasmEnd: wasm ? wasm.responseEnd : null, domContentLoaded: nav ? nav.domContentLoadedEventEnd : null,
        pageFigure: figure(),
        frameCount: window.penumbra && window.penumbra.frameCount ? window.penumbra.frameCount() : null,
      };
    }, [`(${pageFigure})`, name]);
    check(problems.length === 0, `${url}: ${problems.join('; ')}`);
    return r;
  } finally {
    await context.close();
  }
}

await runTest('web.first_frame', async ({ server, browser }) => {
  const site = siteDir();
  const gz = (f) => gzipSync(readFileSync(path.join(site, f)), { level: 9 }).length;
  const raw = (f) => readFileSync(path.join(site, f)).length;
  // Each page's own module (NAME.wasm, NAME.js).
  const payload = {};
  for (const p of pages) {
    payload[p] = { wasmRaw: raw(`${p}.wasm`), wasmGzip: gz(`${p}.wasm`), jsRaw: raw(`${p}.js`), jsGzip: gz(`${p}.js`) };
    const q = payload[p];
    console.log(`payload: ${p}.wasm ${q.wasmRaw} B (${q.wasmGzip} B gzipped), ${p}.js ${q.jsRaw} B ` +
                `(${q.jsGzip} B gzipped); together ${q.wasmGzip + q.jsGzip} B gzipped`);
  }

  const results = {};
  // One load first, not counted: Chromium's own first-use costs (its GPU process, SwiftShader's
  // start) belong to no page.
  await loadOnce(browser, `${server.url}/${pages[0]}.html`);
  const fmt = (x) => (x === null ? '-' : x.toFixed(0));
  console.log(`first frame (ms from navigation start; median of ${LOADS} fresh loads; headless Chromium, SwiftShader):`);
  console.log(`  ${'page'.padEnd(8)} ${'first'.padStart(6)} ${'js'.padStart(5)} ${'wasm'.padStart(5)} ` +
              `${'inst.'.padStart(6)} ${'ctx'.padStart(5)} ${'f.start'.padStart(7)} ${'draw'.padStart(5)} ` +
              `${'page fig.'.padStart(9)}   all loads`);
  for (const p of pages) {
    const loads = [];
    for (let i = 0; i < LOADS; ++i) loads.push(await loadOnce(browser, `${server.url}/${p}.html`));
    for (const [i, l] of loads.entries()) {
      check(l.firstFrame > 0, `${p} load ${i}: no first frame time`);
      for (const k of ['instantiated', 'context', 'wasmEnd', 'jsEnd'])
        check(l[k] !== null && l[k] > 0, `${p} load ${i}: no '${k}' time`);
    }
    const m = (k) => (loads.every((l) => l[k] !== null) ? median(loads.map((l) => l[k])) : null);
    const row = {
      firstFrame: m('firstFrame'), jsEnd: m('jsEnd'), wasmEnd: m('wasmEnd'), instantiated: m('instantiated'),
      context: m('context'), frameStart: m('frameStart'), draw: median(loads.map((l) => l.firstFrame - l.frameStart)),
      pageFigure: m('pageFigure'), loads: loads.map((l) => +l.firstFrame.toFixed(1)), detail: loads,
    };
    results[p] = row;
    console.log(`  ${p.padEnd(8)} ${fmt(row.firstFrame).padStart(6)} ${fmt(row.jsEnd).padStart(5)} ` +
                `${fmt(row.wasmEnd).padStart(5)} ${fmt(row.instantiated).padStart(6)} ${fmt(row.context).padStart(5)} ` +
                `${fmt(row.frameStart).padStart(7)} ${fmt(row.draw).padStart(5)} ${fmt(row.pageFigure).padStart(9)}` +
                `   ${row.loads.map((x) => x.toFixed(0)).join(' ')}`);
  }
  console.log('  (js, wasm: their download ends; inst.: the wasm compiled and instantiated; ctx: main() makes the ' +
              'WebGL context; f.start: the first drawn frame\'s callback starts; draw: that frame\'s own time; ' +
              'page fig.: window.penumbra.firstFrameMs)');
  const all = median(Object.values(results).map((r) => r.firstFrame));
  console.log(`first frame over all pages (median of the pages' medians): ${all.toFixed(0)} ms`);
  if (jsonOut) {
    mkdirSync(path.dirname(jsonOut), { recursive: true });
    writeFileSync(jsonOut, JSON.stringify({ payload, pages: results }, null, 2));
  }
  // Not asserted: the module is not yet within the goal (docs/payload.md says what is left).
  for (const p of pages) {
    const over = payload[p].wasmGzip + payload[p].jsGzip - PAYLOAD_GOAL;
    console.log(over > 0 ? `payload: ${p}: ${over} B over the goal of ${PAYLOAD_GOAL} B` : `payload: ${p}: within the goal`);
  }
});
