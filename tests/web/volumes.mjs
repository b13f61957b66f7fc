// web.volumes: the shadow volumes page (volumes.html). Its controls (volume method, show the
// volumes, the eye in a shadow, the view) set the module and the URL and survive a reload; with the
// eye inside the teapot's shadow at a fixed time, depth-pass's visibility differs from depth-fail's
// in a large share of the pixels (its count starts one too low) and auto's equals depth-fail's;
// the eye, the volumes and the stencil count view each change the picture; the browser's frames
// match `penumbra render`'s (headless EGL) for the eye in the shadow; no console or GL error; a page
// whose exercise does not offer the eye (W09P1) refuses it by name.
// usage: volumes.mjs PENUMBRA_CLI OUT_DIR
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { runTest, openPage, frameAt, compare, check, glErrors, setOptions, savePng, checkKeptOverReload } from './harness.mjs';

const [cli, outDir] = process.argv.slice(2);
if (!cli || !outDir) throw new Error('usage: volumes.mjs PENUMBRA_CLI OUT_DIR');
const T = 0.6;

// The share of pixels whose red channel is below 64 (the visibility view: black = shadowed).
function shadowed(px) {
  let n = 0;
  for (let i = 0; i < px.width * px.height; ++i) if (px.data[4 * i] < 64) ++n;
  return n / (px.width * px.height);
}

async function frameWith(page, options) {
  await setOptions(page, options);
  return frameAt(page, T);
}

await runTest('web.volumes', async ({ server, browser }) => {
  mkdirSync(outDir, { recursive: true });
  {
    // The controls, with the mouse and the keyboard, and the URL.
    const { page, context, problems } = await openPage(browser, `${server.url}/volumes.html`);
    let s = await page.evaluate(() => window.penumbra.state());
    check(s.exercise === 'volumes' && s.status === 'running', `state: ${s.exercise}, '${s.status}'`);
    check(s.query === 'light=on&jump=on&volume-method=auto&show-volumes=off&eye=scene&aov=color', `defaults: ${s.query}`);
    await page.selectOption('#volume-method', 'zpass');
    await page.check('#show-volumes');
    await page.focus('#eye');
    await page.keyboard.press('Space');
    check(await page.isChecked('#eye'), 'Space on the eye box did not tick it');
    await page.selectOption('#aov', 'stencil-count');
    await page.click('#jump');
    const want = { 'volume-method': 'zpass', 'show-volumes': 'on', eye: 'in-shadow', aov: 'stencil-count', jump: 'off',
                   light: 'on' };
    s = await checkKeptOverReload(page, want);
    check((await page.inputValue('#volume-method')) === 'zpass', 'the method select lost zpass');
    check(await page.isChecked('#show-volumes'), 'the show-the-volumes box lost its tick');
    check(await page.isChecked('#eye'), 'the eye box lost its tick');
    check((await page.inputValue('#aov')) === 'stencil-count', 'the view select lost the stencil count');
    check((await page.getAttribute('#jump', 'aria-pressed')) === 'false', 'the jump button came back on');
    // A bad value in a link: said in the status line, not applied, the rest applied.
    const { page: bad, context: badContext, problems: badProblems } =
      await openPage(browser, `${server.url}/volumes.html?volume-method=zmaybe&eye=in-shadow`);
    s = await bad.evaluate(() => window.penumbra.state());
    check(s.options['volume-method'] === 'auto' && s.options.eye === 'in-shadow', `bad link: ${JSON.stringify(s.options)}`);
    check(/zmaybe/.test(await bad.textContent('#note')), 'the note does not name the bad value');
    const errs = (await glErrors(page)).concat(await glErrors(bad));
    check(errs.length === 0, `glGetError: ${errs.map((e) => '0x' + e.toString(16)).join(', ')}`);
    check(problems.length === 0 && badProblems.length === 0, problems.concat(badProblems).join('; '));
    console.log(`controls and URL: ${page.url()} restored`);
    await badContext.close();
    await context.close();
  }
  {
    // Depth-pass against depth-fail with the eye in the shadow, in the visibility view.
    const { page, context, problems } = await openPage(browser, `${server.url}/volumes.html`);
    const shot = {};
    const frames = {
      scene: { eye: 'scene', aov: 'visibility', 'volume-method': 'auto' },
      zpass: { eye: 'in-shadow', aov: 'visibility', 'volume-method': 'zpass' },
      zfail: { eye: 'in-shadow', aov: 'visibility', 'volume-method': 'zfail' },
      auto: { eye: 'in-shadow', aov: 'visibility', 'volume-method': 'auto' },
      color: { eye: 'in-shadow', aov: 'color', 'volume-method': 'auto', 'show-volumes': 'off' },
      shown: { eye: 'in-shadow', aov: 'color', 'volume-method': 'auto', 'show-volumes': 'on' },
      count: { eye: 'in-shadow', aov: 'stencil-count', 'volume-method': 'auto', 'show-volumes': 'off' },
    };
    for (const [name, o] of Object.entries(frames)) {
      shot[name] = await frameWith(page, o);
      savePng(shot[name], path.join(outDir, `${name}.browser.png`));
    }
    const scene = shadowed(shot.scene);
    check(scene > 0.02 && scene < 0.4, `eye=scene: ${(100 * scene).toFixed(1)}% shadowed (want 2..40%)`);
    const passFail = compare(shot.zpass, shot.zfail, 64);
    check(passFail.fraction > 0.2, `eye in the shadow: depth-pass differs from depth-fail in only ${(100 * passFail.fraction).toFixed(2)}%`);
    const autoFail = compare(shot.auto, shot.zfail, 64);
    check(autoFail.fraction <= 0.001, `eye in the shadow: auto differs from depth-fail in ${(100 * autoFail.fraction).toFixed(3)}%`);
    const eyeMoved = compare(shot.scene, shot.auto, 64);
    check(eyeMoved.fraction > 0.2, `the eye moved, yet only ${(100 * eyeMoved.fraction).toFixed(2)}% of the picture changed`);
    const volumes = compare(shot.color, shot.shown, 16);
    check(volumes.fraction > 0.05, `show the volumes changed only ${(100 * volumes.fraction).toFixed(2)}% of the picture`);
    // The stencil count: counts 1..6 in blue, green, yellow, orange, magenta, white over the unlit
    // image; a strongly coloured share of the pixels differs from the colour view.
    const count = compare(shot.color, shot.count, 64);
    check(count.fraction > 0.2, `the stencil count view differs from colour in only ${(100 * count.fraction).toFixed(2)}%`);
    const errs = await glErrors(page);
    check(errs.length === 0, `glGetError: ${errs.map((e) => '0x' + e.toString(16)).join(', ')}`);
    check(problems.length === 0, problems.join('; '));
    console.log(`eye=scene ${(100 * scene).toFixed(1)}% shadowed; eye in the shadow: depth-pass against depth-fail ` +
                `${(100 * passFail.fraction).toFixed(1)}% differ, auto against depth-fail ${autoFail.differing} pixels; ` +
                `the volumes shown change ${(100 * volumes.fraction).toFixed(1)}%, the stencil count ${(100 * count.fraction).toFixed(1)}%`);

    // The browser's frames against headless EGL's (`penumbra render`), as web.egl_match does.
    for (const [name, args] of [['zfail', ['--volume-method', 'zfail']], ['zpass', ['--volume-method', 'zpass']]]) {
      const file = path.join(outDir, `${name}.egl.png`);
      execFileSync(cli, ['render', '--technique', 'volumes', '--eye', 'in-shadow', '--aov', 'visibility', '--time', String(T),
                         '--size', `${shot[name].width}x${shot[name].height}`, ...args, '--out', file]);
      const ref = PNG.sync.read(readFileSync(file));
      const d = compare(shot[name], { width: ref.width, height: ref.height, data: ref.data }, 64);  // pngjs: RGBA
      console.log(`${name} against penumbra render: ${(100 * d.fraction).toFixed(3)}% of the pixels differ`);
      check(d.fraction <= 0.005, `${name}: the browser's frame differs from penumbra render's in ${(100 * d.fraction).toFixed(3)}% ` +
                                 `(images in ${outDir})`);
    }
    await context.close();
  }

  // The eye moved into a shadow is in this page's module (its exercise offers it) and in no page
  // whose exercise does not: W09P1's refuses it by name and runs on.
  const other = await openPage(browser, `${server.url}/w09p1.html`);
  const refused = await other.page.evaluate(() => window.penumbra.setOption('eye', 'in-shadow'));
  check(/^eye in-shadow: not in this page's code/.test(refused), `w09p1 took eye=in-shadow: '${refused}'`);
  check((await other.page.evaluate(() => window.penumbra.setOption('eye', 'scene'))) === '', 'w09p1 refused eye=scene');
  check((await other.page.evaluate(() => window.penumbra.state())).status === 'running', 'w09p1 stopped after the refusal');
  check(other.problems.length === 0, other.problems.join('; '));
  await other.context.close();
});
