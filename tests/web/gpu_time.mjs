// web.gpu_time: each pass's GPU time on the pages (docs/gpu_time.md). Headless Chromium's
// SwiftShader offers WebGL 1 EXT_disjoint_timer_query: on every page the module times the loop's
// frames (GL_TIME_ELAPSED_EXT around each pass), the state JSON has each pass's median over the
// last frames read back (gpu: {frames, total, passes: [{name, ms, frames}]}), every pass named as
// in the frame plan, and the readout beside ms/frame lists the same passes with non-negative times.
// After a context loss and restore the timer works again (the canvas fetches the extension's object
// again). A page whose browser does not hand out the extension says "GPU timer: not available" and
// draws as before. Behaviour only, never a timing: the figures are printed (512x512, each page's
// default options, the loop running: the light and the jump move).
//
// usage: node tests/web/gpu_time.mjs [--pages w09p1,w09p2c]
import { runTest, openPage, waitFrames, check, checkNoGlErrors, PAGES } from './harness.mjs';

const at = process.argv.indexOf('--pages');
const pages = at > 0 ? process.argv[at + 1].split(',') : PAGES;
const WINDOW = 30; // CourseApp::kGpuWindow: the frames the medians are over

// Waits for the state's GPU medians over at least `frames` frames; returns the state.
async function gpuState(page, frames, what) {
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
async function readout(page, what) {
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

function checkGpu(s, plan, what) {
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

await runTest('web.gpu_time', async ({ server, browser }) => {
  for (const p of pages) {
    const { page, context, problems } = await openPage(browser, `${server.url}/${p}.html`);
    const s = await gpuState(page, WINDOW, p);
    checkGpu(s, await page.evaluate(() => window.penumbra.plan()), p);
    const lines = await readout(page, p);
    for (const l of lines.slice(0, -1))
      check(/ \d+\.\d\d ms( \(\d+ of \d+ frames\))?$/.test(l), `${p}: readout line '${l}'`);
    check(/^total \d+\.\d\d ms\/frame$/.test(lines.at(-1)), `${p}: readout's last line '${lines.at(-1)}'`);
    await checkNoGlErrors(page);
    check(problems.length === 0, `${p}: ${problems.join('; ')}`);
    const options = Object.entries(s.options).map(([k, v]) => `${k}=${v}`).join('&');
    console.log(`${p}: GPU ms per pass, median of ${s.gpu.frames} frames (${s.width}x${s.height}, ${options || 'defaults'}): ` +
                `${s.gpu.passes.map((x) => `${x.name} ${x.ms.toFixed(3)}`).join(', ')}; total ${s.gpu.total.toFixed(3)} ` +
                `GPU ms/frame; loop ${s.ms.toFixed(2)} ms/frame; ${s.gpu.discarded} discarded (disjoint)`);
    console.log(`${p}: readout: ${lines.join(' | ')}`);

    // A context loss and restore: the restored context's timer is fetched again and times frames.
    if (p === 'w09p2c' || (p === pages[0] && !pages.includes('w09p2c'))) {
      await page.evaluate(() => {
        window.__lose = document.getElementById('canvas').getContext('webgl').getExtension('WEBGL_lose_context');
        window.__lose.loseContext();
      });
      await page.waitForFunction(() => window.penumbra.state().lost, null, { timeout: 10000 });
      await page.waitForFunction(() => document.getElementById('gpu').textContent === '– (no context)', null,
                                 { timeout: 5000 }).catch(() => {});
      check(await page.textContent('#gpu') === '– (no context)', `${p}: readout while lost: '${await page.textContent('#gpu')}'`);
      await page.evaluate(() => window.__lose.restoreContext());
      await page.waitForFunction(() => window.penumbra.state().generation === 2, null, { timeout: 10000 });
      const r = await gpuState(page, 5, `${p} after a restore`);
      checkGpu(r, await page.evaluate(() => window.penumbra.plan()), `${p} after a restore`);
      await checkNoGlErrors(page);
      check(problems.length === 0, `${p} after a restore: ${problems.join('; ')}`);
      console.log(`${p} after a context restore: ${r.gpu.frames} frames timed: ` +
                  `${r.gpu.passes.map((x) => `${x.name} ${x.ms.toFixed(3)}`).join(', ')}`);
    }
    await context.close();
  }

  // A browser that lists the extension but does not hand it out (getExtension null): no timer, the
  // readout says so, and the page draws with no error.
  const hide = () => {
    const get = WebGLRenderingContext.prototype.getExtension;
    WebGLRenderingContext.prototype.getExtension = function (name) {
      return /disjoint_timer_query/i.test(name) ? null : get.call(this, name);
    };
  };
  const { page, context, problems } = await openPage(browser, `${server.url}/${pages[0]}.html`, { init: hide });
  await waitFrames(page, 5);
  const s = await page.evaluate(() => window.penumbra.state());
  check(s.gpu === null, `without the extension: the state's gpu is ${JSON.stringify(s.gpu)}`);
  await page.waitForFunction(() => document.getElementById('gpu').textContent === 'GPU timer: not available', null,
                             { timeout: 5000 }).catch(() => {});
  const text = await page.textContent('#gpu');
  check(text === 'GPU timer: not available', `without the extension: the readout says '${text}'`);
  check(s.ms > 0 && /running/.test(s.status), `without the extension: ms ${s.ms}, status '${s.status}'`);
  await checkNoGlErrors(page);
  check(problems.length === 0, `without the extension: ${problems.join('; ')}`);
  console.log(`${pages[0]} without EXT_disjoint_timer_query: '${text}', ${s.ms.toFixed(2)} ms/frame`);
  await context.close();
});
