// web.soft: the soft shadows page (soft.html). Its controls (the light's radius as a slider and a
// number box, the filter, the light samples, converging while still, the reference, PCSS's taps,
// the technique, the view) set the module and the URL and survive a reload; the filter and the
// light samples exclude each other; a bad link value is reported. With 64 light samples and the
// scene still, the page's sample count rises frame by frame to 64 and then the image stops
// changing. In the visibility view PCSS differs from the hard shadow in the penumbra, and at light
// radius 0 it equals it. The browser's frames match `penumbra render`'s (headless EGL):
// Heckbert-Herf (deterministic) closely, PCSS (its taps turned per pixel) within a tolerance for
// its noise. The light's horizon is the triangles' own planes where the browser has derivatives.
// Prints the page's ms/frame for PCSS and for Heckbert-Herf on SwiftShader.
// usage: soft.mjs PENUMBRA_CLI OUT_DIR
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { runTest, openPage, waitFrames, readPixels, frameAt, compare, check, glErrors, setOptions, savePng, checkKeptOverReload } from './harness.mjs';

const [cli, outDir] = process.argv.slice(2);
if (!cli || !outDir) throw new Error('usage: soft.mjs PENUMBRA_CLI OUT_DIR');
const T = 0; // the teapot stands on the table: the penumbra grows away from the contact

// The share of pixels in the penumbra of the visibility view: neither lit nor shadowed.
function penumbra(px) {
  let n = 0;
  for (let i = 0; i < px.width * px.height; ++i) if (px.data[4 * i] > 12 && px.data[4 * i] < 243) ++n;
  return n / (px.width * px.height);
}

async function frameWith(page, options) {
  await setOptions(page, options);
  return frameAt(page, T);
}

// Fixed time, frames drawn now until every light sample is in; the frame and the samples.
async function convergedFrame(page, options) {
  await setOptions(page, options);
  const r = await page.evaluate((time) => {
    window.penumbra.pause();
    window.penumbra.setTime(time);
    for (let i = 0; i < 400; ++i) {
      if (!window.penumbra.renderNow()) return null;
      const a = window.penumbra.state().area;
      if (!a || a.done === a.total) return { area: a, px: window.penumbra.readPixelsBase64() };
    }
    return null;
  }, T);
  if (!r) throw new Error(`no converged frame with ${JSON.stringify(options)}`);
  return { area: r.area, px: { width: r.px.width, height: r.px.height, data: Buffer.from(r.px.data, 'base64') } };
}

function render(name, px, args) {
  const file = path.join(outDir, `${name}.egl.png`);
  execFileSync(cli, ['render', '--time', String(T), '--size', `${px.width}x${px.height}`, '--aov', 'visibility', ...args,
                     '--out', file]);
  const ref = PNG.sync.read(readFileSync(file));
  return { width: ref.width, height: ref.height, data: ref.data };
}

// The median ms of n frames drawn now (each drawn and waited for, as the page's own readout
// times them), the clock paused; `moving`: the time steps each frame, so nothing is kept.
async function timeFrames(page, options, n, moving) {
  await setOptions(page, options);
  return page.evaluate(({ n, moving, time }) => {
    window.penumbra.pause();
    const ms = [];
    for (let i = 0; i < n; ++i) {
      if (moving || i === 0) window.penumbra.setTime(time + (moving ? 0.01 * (i + 1) : 0));
      const t0 = performance.now();
      window.penumbra.renderNow();
      ms.push(performance.now() - t0);
    }
    ms.sort((a, b) => a - b);
    return ms[Math.floor(n / 2)];
  }, { n, moving, time: T });
}

await runTest('web.soft', async ({ server, browser }) => {
  mkdirSync(outDir, { recursive: true });
  {
    // The controls, with the mouse and the keyboard, and the URL.
    const { page, context, problems } = await openPage(browser, `${server.url}/soft.html`);
    let s = await page.evaluate(() => window.penumbra.state());
    check(s.exercise === 'soft' && s.status === 'running', `state: ${s.exercise}, '${s.status}'`);
    check(s.query === 'light=off&jump=off&light-radius=0.3&filter=pcss&area-samples=1&area-per-frame=4&area-interleave=1&reference=off&' +
                      'pcss-search=16&pcss-taps=16&pcss-blockers=layered&technique=shadowmap&aov=color', `defaults: ${s.query}`);
    check((await page.inputValue('#light-radius')) === '0.3' && (await page.inputValue('#light-radius-number')) === '0.3',
          'the radius controls do not show 0.3');
    // The light's horizon from each triangle's own plane (the plan's GEOMETRIC_HORIZON, as
    // `penumbra render` takes it) where the browser has OES_standard_derivatives: the module sees
    // the extension the page enabled.
    const derivatives = await page.evaluate(() =>
      document.createElement('canvas').getContext('webgl').getSupportedExtensions().includes('OES_standard_derivatives'));
    check(s.derivatives === derivatives, `the browser ${derivatives ? 'has' : 'lacks'} OES_standard_derivatives, the module's caps say ${s.derivatives}`);
    const techniques = await page.$$eval('#technique option', (os) => os.map((o) => o.value));
    for (const t of ['shadowmap', 'planar', 'volumes']) check(techniques.includes(t), `no technique ${t}: ${techniques}`);
    // The slider with the arrow keys (0.01 a step); the number box follows.
    await page.focus('#light-radius');
    for (let i = 0; i < 5; ++i) await page.keyboard.press('ArrowRight');
    check((await page.inputValue('#light-radius-number')) === '0.35', `the number box shows ${await page.inputValue('#light-radius-number')}`);
    // The filter and the light samples exclude each other.
    await page.selectOption('#filter', 'pcf4x4');
    await page.selectOption('#area-samples', '16');
    check((await page.inputValue('#filter')) === 'hard', '16 light samples did not put the filter back to hard');
    await page.selectOption('#pcss-search', '32');
    await page.selectOption('#pcss-taps', '8');
    await page.selectOption('#pcss-blockers', 'mean');
    await page.selectOption('#technique', 'planar');
    await page.uncheck('#area-per-frame');
    await page.selectOption('#aov', 'visibility');
    // The reference draws 256 light samples, whatever the method; the readout says how many are in.
    await page.focus('#reference');
    await page.keyboard.press('Space');
    check(await page.isChecked('#reference'), 'Space on the reference box did not tick it');
    await page.waitForFunction(() => /of 256/.test(document.getElementById('samples').textContent), null, { timeout: 20000 });
    check(!(await page.isHidden('#samples-row')), 'the light samples readout is hidden');
    check((await page.evaluate(() => window.penumbra.state())).options.reference === 'on', 'the reference is not on');
    await page.keyboard.press('Space');
    await page.selectOption('#area-samples', '4');
    await page.click('#light');
    const want = { 'light-radius': '0.35', filter: 'hard', 'area-samples': '4', 'area-per-frame': '0', reference: 'off',
                   'pcss-search': '32', 'pcss-taps': '8', 'pcss-blockers': 'mean', technique: 'planar', aov: 'visibility', light: 'on', jump: 'off' };
    s = await checkKeptOverReload(page, want);
    check((await page.inputValue('#light-radius')) === '0.35', 'the slider lost 0.35');
    check((await page.inputValue('#light-radius-number')) === '0.35', 'the number box lost 0.35');
    check((await page.inputValue('#filter')) === 'hard' && (await page.inputValue('#area-samples')) === '4', 'the method selects');
    check((await page.inputValue('#pcss-search')) === '32' && (await page.inputValue('#pcss-taps')) === '8' &&
          (await page.inputValue('#pcss-blockers')) === 'mean', 'the PCSS selects');
    check((await page.inputValue('#technique')) === 'planar', 'the technique select lost planar');
    check(!(await page.isChecked('#area-per-frame')), 'the converge box came back ticked');
    check(!(await page.isChecked('#reference')), 'the reference box came back ticked');
    check((await page.inputValue('#aov')) === 'visibility', 'the view select lost visibility');
    check((await page.getAttribute('#light', 'aria-pressed')) === 'true', 'the light button came back off');
    await page.waitForFunction(() => /^4 of 4/.test(document.getElementById('samples').textContent), null, { timeout: 20000 });
    // The number box; PCSS takes one light sample again.
    await page.fill('#light-radius-number', '0.5');
    await page.dispatchEvent('#light-radius-number', 'change');
    check((await page.inputValue('#light-radius')) === '0.5', `the slider shows ${await page.inputValue('#light-radius')}`);
    await page.selectOption('#filter', 'pcss');
    check((await page.inputValue('#area-samples')) === '1', 'PCSS did not put the light samples back to 1');
    // A bad value in a link: said in the status line, not applied, the rest applied.
    const { page: bad, context: badContext, problems: badProblems } =
      await openPage(browser, `${server.url}/soft.html?filter=pcss9&light-radius=0.2&pcss-taps=500`);
    s = await bad.evaluate(() => window.penumbra.state());
    check(s.options.filter === 'pcss' && s.options['light-radius'] === '0.2' && s.options['pcss-taps'] === '16',
          `bad link: ${JSON.stringify(s.options)}`);
    const note = await bad.textContent('#note');
    check(/pcss9/.test(note) && /pcss-taps/.test(note), `the note does not name the bad values: ${note}`);
    const errs = (await glErrors(page)).concat(await glErrors(bad));
    check(errs.length === 0, `glGetError: ${errs.map((e) => '0x' + e.toString(16)).join(', ')}`);
    check(problems.length === 0 && badProblems.length === 0, problems.concat(badProblems).join('; '));
    console.log(`controls and URL: ${page.url()} restored`);
    await badContext.close();
    await context.close();
  }
  {
    // Progressive: 64 light samples, converging, the scene still (the page's own loop).
    const { page, context, problems } = await openPage(browser, `${server.url}/soft.html?area-samples=64`);
    const seen = [];
    const started = Date.now();
    let first = null;
    for (;;) {
      const s = await page.evaluate(() => ({ area: window.penumbra.state().area, text: document.getElementById('samples').textContent }));
      check(s.area, 'no light samples in the state');
      if (!seen.length || seen[seen.length - 1] !== s.area.done) seen.push(s.area.done);
      if (!first && s.area.done < 64) first = await readPixels(page);
      if (s.area.done === 64) break;
      check(Date.now() - started < 60000, `not converged in 60 s: ${seen.join(', ')}`);
      await page.waitForTimeout(50);
    }
    check(seen.length >= 4 && seen.every((d, i) => i === 0 || d > seen[i - 1]), `the sample count did not rise: ${seen.join(', ')}`);
    await page.waitForFunction(() => /^64 of 64 \(converged\)$/.test(document.getElementById('samples').textContent), null,
                               { timeout: 10000 });
    await waitFrames(page, 3);
    const a = await readPixels(page);
    await page.screenshot({ path: path.join(outDir, 'soft-page.png'), fullPage: true });  // what a student sees
    await waitFrames(page, 10);
    const b = await readPixels(page);
    const still = compare(a, b);
    check(still.differing === 0, `converged, yet ${still.differing} pixels changed over 10 frames`);
    const early = compare(first, b, 8);
    check(early.differing > 0, 'the first frames look like the converged one');
    savePng(a, path.join(outDir, 'converged.browser.png'));
    console.log(`64 light samples, 4 a frame: the count went ${seen.join(', ')}; then still (0 pixels changed over 10 ` +
                `frames); ${early.differing} pixels differ from an early frame`);
    // ms/frame on SwiftShader (each frame drawn and waited for): hard, PCSS and Heckbert-Herf with
    // the scene moving (nothing kept), and a converged still frame (only the camera pass).
    const msStill = await timeFrames(page, {}, 5, false);
    const msHard = await timeFrames(page, { 'area-samples': '1', filter: 'hard' }, 5, true);
    const msPcss = await timeFrames(page, { filter: 'pcss' }, 5, true);
    const ms4 = await timeFrames(page, { 'area-samples': '64', 'area-per-frame': '4' }, 5, true);
    const ms16 = await timeFrames(page, { 'area-samples': '16', 'area-per-frame': '0' }, 3, true);
    const ms64 = await timeFrames(page, { 'area-samples': '64', 'area-per-frame': '0' }, 1, true);
    console.log(`ms/frame (SwiftShader, 512x512, colour, the scene moving): hard ${msHard.toFixed(1)}, PCSS 16+16 taps ` +
                `${msPcss.toFixed(1)}, Heckbert-Herf 4 samples a frame ${ms4.toFixed(1)}, 16 every frame ${ms16.toFixed(1)}, ` +
                `64 every frame ${ms64.toFixed(1)}; 64 converged and still ${msStill.toFixed(1)}`);
    check(problems.length === 0, problems.join('; '));
    await context.close();
  }
  {
    // PCSS against the hard shadow in the visibility view, and against penumbra render.
    const { page, context, problems } = await openPage(browser, `${server.url}/soft.html?aov=visibility`);
    const shot = {
      hard: await frameWith(page, { 'light-radius': '0.3', filter: 'hard' }),
      pcf: await frameWith(page, { 'light-radius': '0.3', filter: 'pcf4x4' }),
      pcss: await frameWith(page, { 'light-radius': '0.3', filter: 'pcss' }),
      hard0: await frameWith(page, { 'light-radius': '0', filter: 'hard' }),
      pcss0: await frameWith(page, { 'light-radius': '0', filter: 'pcss' }),
    };
    for (const [name, px] of Object.entries(shot)) savePng(px, path.join(outDir, `${name}.browser.png`));
    const pen = Object.fromEntries(Object.entries(shot).map(([k, v]) => [k, penumbra(v)]));
    check(pen.hard < 0.001, `the hard shadow has ${(100 * pen.hard).toFixed(2)}% penumbra pixels`);
    check(pen.pcss > 0.005 && pen.pcss > 2 * pen.pcf, `PCSS: ${(100 * pen.pcss).toFixed(2)}% penumbra pixels, PCF ${(100 * pen.pcf).toFixed(2)}%`);
    const softHard = compare(shot.pcss, shot.hard, 32);
    check(softHard.fraction > 0.005, `PCSS differs from hard in only ${(100 * softHard.fraction).toFixed(3)}%`);
    const zero = compare(shot.pcss0, shot.hard0);
    check(zero.differing === 0, `at light radius 0 PCSS differs from hard in ${zero.differing} pixels (max ${zero.max})`);
    // Heckbert-Herf with every technique: soft (penumbra pixels) and like the shadow map's.
    const hh = {};
    for (const t of ['shadowmap', 'planar', 'volumes']) {
      hh[t] = (await convergedFrame(page, { 'light-radius': '0.3', 'area-samples': '64', 'area-per-frame': '0', technique: t })).px;
      savePng(hh[t], path.join(outDir, `hh-${t}.browser.png`));
      check(penumbra(hh[t]) > 0.005, `Heckbert-Herf with ${t}: only ${(100 * penumbra(hh[t])).toFixed(2)}% penumbra pixels`);
    }
    console.log(`penumbra pixels (visibility, radius 0.3, t=${T}): hard ${(100 * pen.hard).toFixed(2)}%, PCF 4x4 ` +
                `${(100 * pen.pcf).toFixed(2)}%, PCSS ${(100 * pen.pcss).toFixed(2)}%, Heckbert-Herf 64 ` +
                `${Object.entries(hh).map(([t, px]) => `${t} ${(100 * penumbra(px)).toFixed(2)}%`).join(', ')}; ` +
                `PCSS against hard ${(100 * softHard.fraction).toFixed(2)}% differ; at radius 0 PCSS = hard`);

    // Against headless EGL: Heckbert-Herf accumulates exact counts, so it matches as closely as
    // the hard shadows do; PCSS's taps are turned per pixel and its blocker search compares
    // depths at the penumbra's edge, so a few pixels may flip between the rasterisers.
    for (const t of ['shadowmap', 'volumes']) {
      const ref = render(`hh-${t}`, hh[t], ['--technique', t, '--light-radius', '0.3', '--area-samples', '64']);
      const d = compare(hh[t], ref, 64);
      const mean = compare(hh[t], ref).mean;
      console.log(`Heckbert-Herf ${t} against penumbra render: ${(100 * d.fraction).toFixed(3)}% differ by more than 64, mean ${mean.toFixed(3)}`);
      check(d.fraction <= 0.005, `Heckbert-Herf ${t}: ${(100 * d.fraction).toFixed(3)}% of the pixels differ from penumbra render's`);
    }
    const ref = render('pcss', shot.pcss, ['--light-radius', '0.3', '--filter', 'pcss']);
    const d = compare(shot.pcss, ref, 64);
    const mean = compare(shot.pcss, ref).mean;
    console.log(`PCSS against penumbra render: ${(100 * d.fraction).toFixed(3)}% differ by more than 64, mean ${mean.toFixed(3)}`);
    check(d.fraction <= 0.01 && mean < 2, `PCSS: ${(100 * d.fraction).toFixed(3)}% differ by more than 64, mean ${mean.toFixed(2)} ` +
                                          `(images in ${outDir})`);
    const errs = await glErrors(page);
    check(errs.length === 0, `glGetError: ${errs.map((e) => '0x' + e.toString(16)).join(', ')}`);
    check(problems.length === 0, problems.join('; '));
    await context.close();
  }
});
