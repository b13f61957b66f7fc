// The GPU timer's checks on a page (docs/gpu_time.md), shared by web.load (every page, its loop
// running) and web.gpu_time (a page's timer after a context restore, and a browser without the
// extension): the state's per-pass medians name the frame plan's passes with non-negative times,
// and the readout beside ms/frame lists the same passes. Behaviour only, never a timing.
import { check } from './harness.mjs';

export const WINDOW = 30; // CourseApp::kGpuWindow: the frames the medians are over

// Waits for the state's GPU medians over at least `frames` frames; returns the state.
export async function gpuState(page, frames, what) {
  await page.waitForFunction((n) => {
    const s = window.penumbra.state();
    return s.gpu === null || s.gpu.frames >= n;
  }, frames, { timeout: 120000 });
  const s = await page.evaluate(() => window.penumbra.state());
  check(s.gpu !== null, `${what}: the state has no GPU timer (gpu: null), yet SwiftShader offers EXT_disjoint_timer_query`);
  return s;
}

// The readout's lines once they list the passes the state has at that moment (the page's poll runs
// every 250 ms; a pass that is sometimes reused, as the soft page's shadow map, comes and goes).
export async function readout(page, what) {
  const same = () => {
    const g = window.penumbra.state().gpu;
    const lines = document.getElementById('gpu').textContent.split('\n');
    const names = lines.slice(0, -1).map((l) => l.replace(/ [0-9.]+ ms( \(\d+ of \d+ frames\))?$/, ''));
    return g && g.passes.map((x) => x.name).join('\n') === names.join('\n') ? lines : null;
  };
  try {
    return await (await page.waitForFunction(same, null, { timeout: 10000 })).jsonValue();
  } catch {
    const s = await page.evaluate(() => window.penumbra.state());
    throw new Error(`${what}: the readout '${await page.textContent('#gpu')}' does not list the passes of the state ` +
                    `(${JSON.stringify(s.gpu)})`);
  }
}

export function checkGpu(s, plan, what) {
  const g = s.gpu;
  check(g.frames >= 1 && g.passes.length > 0, `${what}: no pass timed (${JSON.stringify(g)})`);
  check(Number.isFinite(g.total) && g.total >= 0, `${what}: total ${g.total}`);
  const planNames = plan.split('\n').map((l) => (/^\d+\. (.*?): /.exec(l.trim()) || [])[1]).filter(Boolean);
  for (const p of g.passes) {
    check(Number.isFinite(p.ms) && p.ms >= 0, `${what}: pass '${p.name}' took ${p.ms} ms`);
    check(p.frames >= 1 && p.frames <= g.frames, `${what}: pass '${p.name}' in ${p.frames} of ${g.frames} frames`);
    // "texture: camera" (a second plan's), "camera #2" (a second pass of one name): a pass of the
    // plan's kind (the last frame's plan: "shadow-map clear" runs only in a frame that draws the
    // bulb's whole cube, "shadow-map face +x" in the others).
    const kind = p.name.replace(/^(texture|map view): /, '').split(' ')[0];
    check(planNames.some((n) => n.split(' ')[0] === kind),
          `${what}: pass '${p.name}' is of no kind in the frame plan (${planNames.join(', ')})`);
  }
  check(g.passes.some((p) => p.name === 'camera'), `${what}: the camera pass is not timed`);
}

// The page's timer once `frames` frames are timed (the medians are over the last WINDOW): the
// state's passes and the readout's lines checked. Returns {s: the state, lines: the readout's lines}.
export async function checkPageGpu(page, what, frames = WINDOW) {
  const s = await gpuState(page, frames, what);
  checkGpu(s, await page.evaluate(() => window.penumbra.plan()), what);
  const lines = await readout(page, what);
  for (const l of lines.slice(0, -1))
    check(/ \d+\.\d\d ms( \(\d+ of \d+ frames\))?$/.test(l), `${what}: readout line '${l}'`);
  check(/^total \d+\.\d\d ms\/frame$/.test(lines.at(-1)), `${what}: readout's last line '${lines.at(-1)}'`);
  return { s, lines };
}

// The figures a page's timer gave, for the log.
export function gpuFigures(p, s, lines) {
  const options = Object.entries(s.options).map(([k, v]) => `${k}=${v}`).join('&');
  return `${p}: GPU ms per pass, median of ${s.gpu.frames} frames (${s.width}x${s.height}, ${options || 'defaults'}): ` +
         `${s.gpu.passes.map((x) => `${x.name} ${x.ms.toFixed(3)}`).join(', ')}; total ${s.gpu.total.toFixed(3)} ` +
         `GPU ms/frame; loop ${s.ms.toFixed(2)} ms/frame; ${s.gpu.discarded} discarded (disjoint)\n` +
         `${p}: readout: ${lines.join(' | ')}`;
}
