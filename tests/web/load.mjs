// web.load: the index and every exercise page load with no console error, no page error, no failed
// request and no WebGL error after some frames; every control has a label; the index links resolve
// and shows a picture of every exercise. Each page's GPU timer (EXT_disjoint_timer_query on
// SwiftShader) once its loop has timed 10 frames: the passes of the frame plan in the state and in
// the readout (gpu_checks.mjs; web.gpu_time checks the timer after a context restore and without
// the extension).
import { runTest, openPage, check, PAGES } from './harness.mjs';
import { checkPageGpu, gpuFigures } from './gpu_checks.mjs';

await runTest('web.load', async ({ server, browser }) => {
  // The index: its links lead to every exercise page.
  {
    const { page, context, problems } = await openPage(browser, `${server.url}/index.html`, { waitReady: false });
    const links = await page.$$eval('a[href]', (as) => as.map((a) => a.getAttribute('href')));
    for (const p of PAGES) check(links.includes(`${p}.html`), `index.html does not link ${p}.html`);
    for (const href of links) {
      const r = await page.request.get(`${server.url}/${href}`);
      check(r.ok(), `index.html links ${href}, which answers ${r.status()}`);
    }
    // Each exercise as a picture (web/thumbs, scripts/thumbs.sh), loaded.
    await page.waitForFunction(() => [...document.images].every((i) => i.complete), null, { timeout: 10000 });
    const pictures = await page.$$eval('ul.exercises img', (imgs) =>
      imgs.map((i) => ({ src: i.getAttribute('src'), width: i.naturalWidth })));
    for (const p of PAGES) {
      const picture = pictures.find((i) => i.src === `thumbs/${p}.png`);
      check(picture && picture.width > 0, `index.html shows no picture of ${p}`);
    }
    check(problems.length === 0, `index.html: ${problems.join('; ')}`);
    await context.close();
  }
  for (const p of PAGES) {
    const { page, context, problems } = await openPage(browser, `${server.url}/${p}.html`);
    // Ten frames timed (their queries are read a few frames late): the frames the load waited for.
    const gpu = await checkPageGpu(page, p, 10);
    const errors = await page.evaluate(() => {
      const out = [];
      for (let e = window.penumbra.glError(), i = 0; e !== 0 && i < 16; e = window.penumbra.glError(), ++i) out.push(e);
      return out;
    });
    check(errors.length === 0, `${p}: glGetError reported ${errors.map((e) => '0x' + e.toString(16)).join(', ')}`);
    const state = await page.evaluate(() => window.penumbra.state());
    check(state.status === 'running', `${p}: status is '${state.status}'`);
    check(state.exercise === p, `${p}: the module runs exercise ${state.exercise}`);
    check(state.frames >= 10 && state.ms > 0, `${p}: no frames timed (${state.frames} frames, ${state.ms} ms)`);
    // The readout is refreshed by a 250 ms poll, so it may trail the frames: give it a few polls.
    await page
      .waitForFunction(() => /ms\/frame/.test(document.getElementById('ms').textContent), null, { timeout: 10000 })
      .catch(() => {});
    const ms = await page.textContent('#ms');
    check(/ms\/frame/.test(ms), `${p}: the ms/frame readout says '${ms}'`);
    // Every control is reachable by its label (or its own text, for buttons).
    const unlabelled = await page.$$eval('#controls input, #controls select, #controls button', (els) =>
      els.filter((el) => (el.tagName === 'BUTTON' ? !el.textContent.trim() : el.labels.length === 0)).map((el) => el.id || el.outerHTML));
    check(unlabelled.length === 0, `${p}: controls without a label: ${unlabelled.join(', ')}`);
    check(problems.length === 0, `${p}: ${problems.join('; ')}`);
    console.log(`${p}: ${state.frames} frames, ${state.ms.toFixed(2)} ms/frame, ${state.renderer}, no errors`);
    console.log(gpuFigures(p, gpu.s, gpu.lines));
    await context.close();
  }
});
