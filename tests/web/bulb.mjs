// web.bulb: the point light's cube page (bulb.html), the bulb room. Its controls (the shadow maps,
// the map size, the filter, the bulb's radius, the view) and its fly camera set the module and the
// URL and survive a reload; the faces view shows at least 4 of the cube's six tints in the first
// frame; one map changes the frame; the plan's face lines are on the page; the browser's frames
// match `penumbra render --scene tests/data/bulb_room.gltf` (headless EGL: the file the page's room
// is built from); the context lost and restored draws the cube again; no console or GL error.
// Prints the page's ms/frame (SwiftShader) with the cube and with one map, which it does not check.
// usage: bulb.mjs PENUMBRA_CLI OUT_DIR
import { mkdirSync } from 'node:fs';
import path from 'node:path';
import { runTest, openPage, waitForUrlQuery, frameAt, compare, check, checkNoGlErrors, checkMatchesCli, loopMs, setOptions, savePng, waitFrames, tintShares, loseAndRestore, cliFrame, FACE_TINTS }
  from './harness.mjs';

const [cli, outDir] = process.argv.slice(2);
if (!cli || !outDir) throw new Error('usage: bulb.mjs PENUMBRA_CLI OUT_DIR');
const SCENE = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../data/bulb_room.gltf');
const DEFAULTS = 'cascades=cube&map-size=512&cube-layout=atlas&filter=hard&light-radius=0.05&aov=cascades';
const PRESENT = 0.0005;

function faces(px, what, least) {
  const t = tintShares(px, FACE_TINTS);
  const shown = Object.keys(t).filter((k) => t[k] >= PRESENT);
  const text = Object.entries(t).map(([k, v]) => `${k} ${(100 * v).toFixed(3)}%`).join(', ');
  check(shown.length >= least, `${what}: ${shown.length} face tints shown, want at least ${least} (${text})`);
  return `${shown.length} tints (${text})`;
}

function eglFrame(name, args, size) {
  return cliFrame(cli, ['--scene', SCENE, '--size', `${size.width}x${size.height}`, '--light-radius', '0.05', ...args],
                  path.join(outDir, `${name}.egl.png`));
}

await runTest('web.bulb', async ({ server, browser }) => {
  mkdirSync(outDir, { recursive: true });
  {
    // The first frame, the controls, the fly camera and the URL.
    const { page, context, problems } = await openPage(browser, `${server.url}/bulb.html`);
    let s = await page.evaluate(() => window.penumbra.state());
    check(s.exercise === 'bulb' && s.status === 'running', `state: ${s.exercise}, '${s.status}'`);
    check(s.query === DEFAULTS, `defaults: ${s.query}`);
    check(s.camera && s.camera.moved === false && s.camera.step === 0.25, `the camera: ${JSON.stringify(s.camera)}`);
    const first = await frameAt(page, 0);  // the page's starting settings: the faces view
    console.log(`the first frame: ${faces(first, 'the first frame', 4)}`);
    const start = s.camera;
    await page.selectOption('#cascades', '1');
    await page.selectOption('#map-size', '1024');
    await page.selectOption('#cube-layout', 'cubemap');
    await page.selectOption('#filter', 'pcf4x4');
    await page.fill('#light-radius-number', '0.1');
    await page.press('#light-radius-number', 'Tab');
    await page.selectOption('#aov', 'visibility');
    await page.click('button[data-fly="forward"]');
    await page.focus('#canvas');
    await page.keyboard.press('KeyW');
    s = await page.evaluate(() => window.penumbra.state());
    const c = s.camera;
    const walked = Math.hypot(c.x - start.x, c.y - start.y, c.z - start.z);
    check(c.moved && Math.abs(walked - 0.5) < 0.01, `two steps of 0.25 m moved the camera ${walked.toFixed(3)} m`);
    const want = { cascades: '1', 'map-size': '1024', 'cube-layout': 'cubemap', filter: 'pcf4x4', 'light-radius': '0.1', aov: 'visibility' };
    await waitForUrlQuery(page);
    const params = new URL(page.url()).searchParams;
    for (const [k, v] of Object.entries(want)) check(params.get(k) === v, `URL ${page.url()}: ${k} is not ${v}`);
    for (const [k, v] of Object.entries(want)) check(s.options[k] === v, `module: ${k} = ${s.options[k]}, not ${v}`);
    await page.reload({ waitUntil: 'load' });
    await page.evaluate(() => window.penumbra.ready);
    const r = await page.evaluate(() => window.penumbra.state());
    for (const [k, v] of Object.entries(want)) check(r.options[k] === v, `after reload ${k} = ${r.options[k]}, not ${v}`);
    check(r.camera.moved && Math.hypot(r.camera.x - c.x, r.camera.y - c.y, r.camera.z - c.z) < 0.002,
          `after reload the camera is ${JSON.stringify(r.camera)}, was ${JSON.stringify(c)}`);
    check((await page.inputValue('#cascades')) === '1', 'the shadow maps select lost 1');
    check((await page.inputValue('#filter')) === 'pcf4x4', 'the filter select lost pcf4x4');
    check((await page.inputValue('#light-radius-number')) === '0.1', 'the radius box lost 0.1');
    await page.click('button[data-fly="reset"]');
    check(!new URL(page.url()).searchParams.has('camera'), `after the scene camera button: ${page.url()}`);
    // An eye outside the room in a link: named in the note, not applied.
    const { page: bad, context: badContext, problems: badProblems } = await openPage(browser, `${server.url}/bulb.html?camera=9,1,0,0,0&map-size=256`);
    s = await bad.evaluate(() => window.penumbra.state());
    check(s.options['map-size'] === '256' && s.camera.moved === false, `bad link: ${JSON.stringify(s.options)}`);
    check(/room/.test(await bad.textContent('#note')), 'the note does not say the eye must be in the room');
    await checkNoGlErrors(page, bad);
    check(problems.length === 0 && badProblems.length === 0, problems.concat(badProblems).join('; '));
    console.log(`controls, camera and URL restored: ${page.url()}`);
    await badContext.close();
    await context.close();
  }
  {
    // The frames: the faces, one map, against headless EGL, the plan's lines, the context's loss.
    const { page, context, problems } = await openPage(browser, `${server.url}/bulb.html`);
    const shot = {};
    shot.cube = await frameAt(page, 0);
    await page.waitForFunction(() => (document.getElementById('cascade-plan').textContent.match(/face [+-][xyz]:/g) || []).length >= 4,
                               null, { timeout: 5000 });
    const planText = await page.textContent('#cascade-plan');
    check(/a cube of \d face\(s\) drawn of 6/.test(planText), `the plan's lines on the page:\n${planText}`);
    const cubeFaces = faces(shot.cube, 'the cube', 4);
    await setOptions(page, { cascades: '1' });
    shot.one = await frameAt(page, 0);
    await setOptions(page, { cascades: 'cube', aov: 'color' });
    shot.color = await frameAt(page, 0);
    await setOptions(page, { cascades: '1' });
    shot.colorOne = await frameAt(page, 0);
    await setOptions(page, { cascades: 'cube', filter: 'pcf4x4', aov: 'color' });
    shot.pcf = await frameAt(page, 0);
    // The faces as a WebGL cube map, read with textureCube: the same shadows.
    await setOptions(page, { 'cube-layout': 'cubemap' });
    shot.cubemap = await frameAt(page, 0);
    const cubemapText = await page.textContent('#cascade-plan');
    check(/a cube map of \d face\(s\) drawn of 6/.test(cubemapText), `the plan's lines with a cube map:\n${cubemapText}`);
    await setOptions(page, { 'cube-layout': 'atlas' });
    for (const [k, px] of Object.entries(shot)) savePng(px, path.join(outDir, `${k}.browser.png`));
    const one = compare(shot.cube, shot.one, 16);
    check(one.fraction > 0.05, `one map changes only ${(100 * one.fraction).toFixed(2)}% of the faces view`);
    const oneColor = compare(shot.color, shot.colorOne, 16);
    check(oneColor.fraction > 0.01, `one map changes only ${(100 * oneColor.fraction).toFixed(2)}% of the colour frame`);
    console.log(`the cube: ${cubeFaces}; one map changes ${(100 * one.fraction).toFixed(1)}% of the faces view, ` +
                `${(100 * oneColor.fraction).toFixed(1)}% of the colour frame`);

    const egl = [
      ['cube', ['--cascades', 'cube', '--map-size', '512', '--aov', 'cascades']],
      ['one', ['--cascades', '1', '--map-size', '512', '--aov', 'cascades']],
      ['color', ['--cascades', 'cube', '--map-size', '512']],
      ['colorOne', ['--cascades', '1', '--map-size', '512']],
      ['pcf', ['--cascades', 'cube', '--map-size', '512', '--filter', 'pcf4x4']],
      ['cubemap', ['--cascades', 'cube', '--map-size', '512', '--filter', 'pcf4x4', '--cube-layout', 'cubemap']],
    ];
    checkMatchesCli(shot, egl, eglFrame, outDir);

    // The page's own loop: ms/frame with the cube and one map (printed, not checked). The bulb
    // stands still, so the cube's faces are drawn once and kept: both loops draw the camera pass.
    const ms = {};
    await setOptions(page, { filter: 'hard' });
    await page.evaluate(() => window.penumbra.resume());
    for (const [n, layout] of [['1', 'atlas'], ['cube', 'atlas'], ['cube', 'cubemap']])
      ms[n === '1' ? '1' : layout] = await loopMs(page, { cascades: n, 'cube-layout': layout });
    await setOptions(page, { 'cube-layout': 'atlas' });
    console.log(`SwiftShader, 512x512, map 512: ${ms['1'].toFixed(1)} ms/frame with one map, ${ms.atlas.toFixed(1)} with the cube ` +
                `(x${(ms.atlas / ms['1']).toFixed(2)}), ${ms.cubemap.toFixed(1)} with the cube as a cube map ` +
                `(x${(ms.cubemap / ms['1']).toFixed(2)}; median of 60 frames of the page's loop, each waited for)`);

    // The context lost and restored: the cube drawn again, the same frame.
    await setOptions(page, { aov: 'cascades' });
    const after = await loseAndRestore(page);
    faces(after, 'after the restore', 4);
    await page.evaluate(() => window.penumbra.resume());
    await waitFrames(page, 3);
    await checkNoGlErrors(page);
    check(problems.length === 0, problems.join('; '));
    console.log('context lost and restored: the cube drawn again, the same frame, the loop running, no GL error');
    await context.close();
  }
});
