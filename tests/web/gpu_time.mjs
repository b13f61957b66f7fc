// web.gpu_time: each pass's GPU time on the pages (docs/gpu_time.md). Headless Chromium's
// SwiftShader offers WebGL 1 EXT_disjoint_timer_query: on every page the module times the loop's
// frames (GL_TIME_ELAPSED_EXT around each pass), the state JSON has each pass's median over the
// last frames read back (gpu: {frames, total, passes: [{name, ms, frames}]}), every pass named as
// in the frame plan, and the readout beside ms/frame lists the same passes with non-negative times.
// After a context loss and restore the timer works again (the canvas fetches the extension's object
// again). A page whose browser does not hand out the extension says "GPU timer: not available" and
// draws as before. Behaviour only, never a timing: the figures are printed (512x512, each page's
// default options, the loop running: the light and the jump move).
// ctest runs it on W09P2c alone (--pages w09p2c): web.load checks every page's timer as it loads
// it (gpu_checks.mjs), so each page is loaded once for both.
//
// usage: node tests/web/gpu_time.mjs [--pages w09p1,w09p2c]
import { runTest, openPage, waitFrames, check, checkNoGlErrors, PAGES } from './harness.mjs';
import { gpuState, checkGpu, checkPageGpu, gpuFigures } from './gpu_checks.mjs';

const at = process.argv.indexOf('--pages');
const pages = at > 0 ? process.argv[at + 1].split(',') : PAGES;
await runTest('web.gpu_time', async ({ server, browser }) => {
  for (const p of pages) {
    const { page, context, problems } = await openPage(browser, `${server.url}/${p}.html`);
    const { s, lines } = await checkPageGpu(page, p);
    await checkNoGlErrors(page);
    check(problems.length === 0, `${p}: ${problems.join('; ')}`);
    console.log(gpuFigures(p, s, lines));

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
