// web.cascades: the cascaded shadow maps page (cascades.html), the kilometre of terrain under a low
// sun. Its controls (the number of cascades, the split slider, the snap box, the blend slider, the
// map size, the view) and its fly camera (the buttons, the keys on the focused canvas, a drag on
// it) set the module and the URL and survive a reload; a bad camera in a link is refused with a
// note and the rest applied. The cascades view shows four tints with 4 cascades and one with 1;
// the plan's cascade lines are on the page; moving the camera changes the frame and the scene's
// camera brings it back; the browser's frames match `penumbra render --scene
// tests/data/terrain_km.gltf` (headless EGL: the file the page's scene is built from) with the same
// options; the context lost and restored draws the same frame again; no console or GL error.
// Prints the page's ms/frame (SwiftShader) with 1 and 4 cascades, which it does not check.
// usage: cascades.mjs PENUMBRA_CLI OUT_DIR
import { mkdirSync } from 'node:fs';
import path from 'node:path';
import { runTest, openPage, waitForUrlQuery, frameAt, compare, check, checkNoGlErrors, checkMatchesCli, loopMs, setOptions, savePng, waitFrames, tintShares, loseAndRestore, cliFrame, CASCADE_TINTS }
  from './harness.mjs';

const [cli, outDir] = process.argv.slice(2);
if (!cli || !outDir) throw new Error('usage: cascades.mjs PENUMBRA_CLI OUT_DIR');
const SCENE = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../data/terrain_km.gltf');
const DEFAULTS = 'cascades=4&cascade-split=0.95&cascade-snap=on&cascade-blend=0.1&map-size=1024&aov=cascades';

// The cascades view's tints (red, green, blue, yellow from near to far): the share of the picture
// each holds (harness.mjs: tintShares).
const TINTS = CASCADE_TINTS;
const tints = (px) => tintShares(px, TINTS);
const PRESENT = 0.0005, ABSENT = 0.0001;
function checkTints(px, n, what) {
  const t = tints(px);
  const text = Object.entries(t).map(([k, v]) => `${k} ${(100 * v).toFixed(3)}%`).join(', ');
  TINTS.forEach(([name], i) => {
    if (i < n) check(t[name] >= PRESENT, `${what}: ${name} (cascade ${i}) holds ${(100 * t[name]).toFixed(4)}% (${text})`);
    else check(t[name] <= ABSENT, `${what}: ${name} holds ${(100 * t[name]).toFixed(4)}% with ${n} cascade(s) (${text})`);
  });
  return text;
}

async function frame(page, options) {
  if (options) await setOptions(page, options);
  return frameAt(page, 0);
}

function eglFrame(name, args, size) {
  return cliFrame(cli, ['--scene', SCENE, '--size', `${size.width}x${size.height}`, ...args],
                  path.join(outDir, `${name}.egl.png`));
}

await runTest('web.cascades', async ({ server, browser }) => {
  mkdirSync(outDir, { recursive: true });
  {
    // The controls, the fly camera and the URL.
    const { page, context, problems } = await openPage(browser, `${server.url}/cascades.html`);
    let s = await page.evaluate(() => window.penumbra.state());
    check(s.exercise === 'cascades' && s.status === 'running', `state: ${s.exercise}, '${s.status}'`);
    check(s.query === DEFAULTS, `defaults: ${s.query}`);
    check(s.camera && s.camera.moved === false, `the camera: ${JSON.stringify(s.camera)}`);
    const start = s.camera;
    await page.selectOption('#cascades', '2');
    await page.fill('#cascade-split-number', '0.5');
    await page.press('#cascade-split-number', 'Tab');
    await page.focus('#cascade-blend');  // the slider by its keys: one step of 0.05 up
    await page.keyboard.press('ArrowRight');
    await page.uncheck('#cascade-snap');
    await page.selectOption('#map-size', '2048');
    await page.selectOption('#aov', 'color');
    // The camera: two presses of Forward, W on the focused canvas, a drag to the right and up.
    await page.click('button[data-fly="forward"]');
    await page.click('button[data-fly="forward"]');
    await page.focus('#canvas');
    await page.keyboard.press('KeyW');
    const box = await page.locator('#canvas').boundingBox();
    await page.mouse.move(box.x + 200, box.y + 200);
    await page.mouse.down();
    await page.mouse.move(box.x + 240, box.y + 190, { steps: 4 });
    await page.mouse.up();
    s = await page.evaluate(() => window.penumbra.state());
    const c = s.camera;
    const walked = Math.hypot(c.x - start.x, c.y - start.y, c.z - start.z);
    check(c.moved && Math.abs(walked - 6) < 0.01, `three steps of 2 m moved the camera ${walked.toFixed(3)} m`);
    check(Math.abs(c.yaw - (start.yaw + 10)) < 0.01 && Math.abs(c.pitch - (start.pitch + 2.5)) < 0.01,
          `a drag of 40 px right and 10 px up: yaw ${start.yaw} -> ${c.yaw}, pitch ${start.pitch} -> ${c.pitch}`);
    check(/heading/.test(await page.textContent('#camera')), `the camera readout: '${await page.textContent('#camera')}'`);
    const want = { cascades: '2', 'cascade-split': '0.5', 'cascade-blend': '0.15', 'cascade-snap': 'off', 'map-size': '2048',
                   aov: 'color' };
    await waitForUrlQuery(page);
    const params = new URL(page.url()).searchParams;
    for (const [k, v] of Object.entries(want)) check(params.get(k) === v, `URL ${page.url()}: ${k} is not ${v}`);
    check(params.get('camera') === s.options.camera, `URL camera ${params.get('camera')}, module ${s.options.camera}`);
    for (const [k, v] of Object.entries(want)) check(s.options[k] === v, `module: ${k} = ${s.options[k]}, not ${v}`);
    await page.reload({ waitUntil: 'load' });
    await page.evaluate(() => window.penumbra.ready);
    const r = await page.evaluate(() => window.penumbra.state());
    for (const [k, v] of Object.entries(want)) check(r.options[k] === v, `after reload ${k} = ${r.options[k]}, not ${v}`);
    check(r.camera.moved && Math.hypot(r.camera.x - c.x, r.camera.y - c.y, r.camera.z - c.z) < 0.002 &&
          Math.abs(r.camera.yaw - c.yaw) < 0.01 && Math.abs(r.camera.pitch - c.pitch) < 0.01,
          `after reload the camera is ${JSON.stringify(r.camera)}, was ${JSON.stringify(c)}`);
    check((await page.inputValue('#cascades')) === '2', 'the cascades select lost 2');
    check((await page.inputValue('#cascade-split-number')) === '0.5', 'the split box lost 0.5');
    check((await page.inputValue('#cascade-split')) === '0.5', 'the split slider lost 0.5');
    check((await page.inputValue('#cascade-blend')) === '0.15', 'the blend slider lost 0.15');
    check(!(await page.isChecked('#cascade-snap')), 'the snap box came back ticked');
    check((await page.inputValue('#aov')) === 'color', 'the view select lost colour');
    // The scene's camera again: the URL drops it.
    await page.click('button[data-fly="reset"]');
    check(!new URL(page.url()).searchParams.has('camera'), `after the scene camera button: ${page.url()}`);
    // A bad camera in a link: named in the note, not applied, the rest applied.
    const { page: bad, context: badContext, problems: badProblems } = await openPage(browser, `${server.url}/cascades.html?camera=1,2,3&cascades=3`);
    s = await bad.evaluate(() => window.penumbra.state());
    check(s.options.cascades === '3' && s.camera.moved === false, `bad link: ${JSON.stringify(s.options)}, ${JSON.stringify(s.camera)}`);
    check(/camera/.test(await bad.textContent('#note')), 'the note does not name the bad camera');
    await checkNoGlErrors(page, bad);
    check(problems.length === 0 && badProblems.length === 0, problems.concat(badProblems).join('; '));
    console.log(`controls, camera and URL restored: ${page.url()}`);
    await badContext.close();
    await context.close();
  }
  {
    // The frames: tints, the camera, against headless EGL, the plan's lines, the context's loss.
    const { page, context, problems } = await openPage(browser, `${server.url}/cascades.html`);
    const shot = {};
    shot.four = await frame(page, { cascades: '4', aov: 'cascades' });
    const plan4 = await page.evaluate(() => window.penumbra.plan());
    await page.waitForFunction(() => (document.getElementById('cascade-plan').textContent.match(/cascade \d+:/g) || []).length === 4,
                               null, { timeout: 5000 });
    check(!(await page.locator('#cascade-plan-row').isHidden()), 'the plan\'s cascade lines are hidden');
    const fourTints = checkTints(shot.four, 4, '4 cascades');
    shot.one = await frame(page, { cascades: '1' });
    const oneTints = checkTints(shot.one, 1, '1 cascade');
    check((plan4.match(/shadow-map cascade \d+: .*view depth/g) || []).length === 4, `the plan of 4 cascades:\n${plan4}`);
    shot.color = await frame(page, { cascades: '4', aov: 'color' });
    shot.nosnap = await frame(page, { 'cascade-snap': 'off', 'cascade-split': '0.5', 'cascade-blend': '0.2', aov: 'cascades' });
    await setOptions(page, { 'cascade-snap': 'on', 'cascade-split': '0.95', 'cascade-blend': '0.1' });
    shot.moved = await page.evaluate(() => window.penumbra.fly(8, 1, 0, -5, 0)).then(() => frame(page));
    await page.evaluate(() => window.penumbra.resetCamera());
    shot.back = await frame(page);
    for (const [k, px] of Object.entries(shot)) savePng(px, path.join(outDir, `${k}.browser.png`));
    const moved = compare(shot.four, shot.moved, 16);
    check(moved.fraction > 0.05, `the camera moved 8 m, yet only ${(100 * moved.fraction).toFixed(2)}% of the picture changed`);
    checkTints(shot.moved, 4, '4 cascades, moved');
    const back = compare(shot.four, shot.back);
    check(back.differing === 0, `the scene's camera again: ${back.differing} pixels differ from the first frame`);
    const view = compare(shot.four, shot.color, 16);
    check(view.fraction > 0.3, `the cascades view differs from colour in only ${(100 * view.fraction).toFixed(2)}%`);
    console.log(`4 cascades: ${fourTints}; 1 cascade: ${oneTints}; moving 8 m changes ${(100 * moved.fraction).toFixed(1)}%`);

    // Against `penumbra render` of the glTF file (headless EGL, llvmpipe).
    const egl = [
      ['four', ['--cascades', '4', '--aov', 'cascades']],
      ['one', ['--cascades', '1', '--aov', 'cascades']],
      ['color', ['--cascades', '4']],
      ['nosnap', ['--cascades', '4', '--aov', 'cascades', '--cascade-snap', 'off', '--cascade-split', '0.5', '--cascade-blend', '0.2']],
    ];
    checkMatchesCli(shot, egl, eglFrame, outDir);

    // The page's own loop: ms/frame with 1 and 4 cascades (printed, not checked).
    const ms = {};
    await setOptions(page, { aov: 'color' });
    await page.evaluate(() => window.penumbra.resume());
    for (const n of ['1', '4']) ms[n] = await loopMs(page, { cascades: n });
    console.log(`SwiftShader, 512x512, map 1024: ${ms['1'].toFixed(1)} ms/frame with 1 cascade, ${ms['4'].toFixed(1)} with 4 ` +
                `(x${(ms['4'] / ms['1']).toFixed(2)}; median of 60 frames of the page's loop, each waited for)`);

    // The context lost and restored: the same frame again.
    await setOptions(page, { aov: 'cascades' });
    const after = await loseAndRestore(page);
    checkTints(after, 4, 'after the restore');
    await page.evaluate(() => window.penumbra.resume());
    await waitFrames(page, 3);
    await checkNoGlErrors(page);
    check(problems.length === 0, problems.join('; '));
    console.log('context lost and restored: the same frame, the loop running, no GL error');
    await context.close();
  }
});
