// web.stencil: the stencil effects page (stencil.html). It opens with the outline on: pixels of the
// outline's colour (ff8c00) around the teapot; choosing no effects takes every one of them away and
// choosing the outline again brings them back; a wider slider value gives more of them; another
// colour from the select paints the same pixels in it; planar shadows and shadow volumes (which
// keep their own values in the stencil) give the same outline; the mirror changes the table's
// pixels only (more of them with a higher reflectivity), and with the outline keeps its orange
// pixels; the portal changes only the pixels of the frame's region and shows the other scene's
// lawn there; the controls reach the URL and survive a reload; the browser's frame matches
// `penumbra render --effects ...` (headless EGL) within web.egl_match's tolerance, for the shadow
// map and shadow volumes with the outline, for the mirror and for all three effects; no console
// or GL error. W09P1's page, whose module has no mirror's code, refuses effects=mirror and says why.
// usage: stencil.mjs PENUMBRA_CLI OUT_DIR
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { runTest, openPage, frameAt, compare, check, glErrors, setOptions, savePng } from './harness.mjs';

const [cli, outDir] = process.argv.slice(2);
if (!cli || !outDir) throw new Error('usage: stencil.mjs PENUMBRA_CLI OUT_DIR');
const T = 0.6;
// web.egl_match's tolerance.
const MAX_MEAN = 1.5;
const LEVELS = 16;
const MAX_FRACTION = 0.005;

// The pixels within 2 levels of the colour RRGGBB in each channel.
function countColour(px, hex) {
  const c = [0, 2, 4].map((i) => parseInt(hex.slice(i, i + 2), 16));
  let n = 0;
  for (let i = 0; i < px.width * px.height; ++i)
    if (Math.abs(px.data[4 * i] - c[0]) <= 2 && Math.abs(px.data[4 * i + 1] - c[1]) <= 2 &&
        Math.abs(px.data[4 * i + 2] - c[2]) <= 2) ++n;
  return n;
}

// The slider moved as a person drags it: its value set and the input event the page listens to.
async function slide(page, value) {
  await page.$eval('#outline-width', (el, v) => {
    el.value = v;
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }, String(value));
}

await runTest('web.stencil', async ({ server, browser }) => {
  mkdirSync(outDir, { recursive: true });
  const { page, problems } = await openPage(browser, `${server.url}/stencil.html`);
  let s = await page.evaluate(() => window.penumbra.state());
  check(s.exercise === 'stencil' && s.status === 'running', `state: ${s.exercise}, '${s.status}'`);
  check(s.query === 'light=on&jump=on&effects=outline&outline-width=3&outline-color=ff8c00&reflectivity=0.5&' +
        'technique=shadowmap', `defaults: ${s.query}`);
  check((await page.inputValue('#effects')) === 'outline', 'the effects select does not show the outline on opening');
  check((await page.inputValue('#outline-color')) === 'ff8c00', 'the colour select does not show ff8c00');
  check((await page.inputValue('#technique')) === 'shadowmap', 'the technique select does not show shadowmap');

  const shots = {};
  const shoot = async (name) => {
    shots[name] = await frameAt(page, T);
    savePng(shots[name], path.join(outDir, `${name}.browser.png`));
    return shots[name];
  };
  const n = 512 * 512;
  const pct = (x) => `${(100 * x / n).toFixed(2)}%`;

  const on = countColour(await shoot('outline'), 'ff8c00');
  check(on > 0.002 * n && on < 0.05 * n, `outline on: ${on} orange pixels (${pct(on)}), want 0.2..5% of the frame`);
  await page.selectOption('#effects', 'none');
  const off = countColour(await shoot('none'), 'ff8c00');
  check(off === 0, `no effects: still ${off} orange pixels`);
  check(new URL(page.url()).searchParams.get('effects') === 'none', `URL ${page.url()}: effects is not none`);
  // Only the outline's pixels changed.
  const onOff = compare(shots.outline, shots.none, 16);
  check(onOff.differing >= on && onOff.differing <= on * 1.05 + 50,
        `the outline changed ${onOff.differing} pixels, ${on} of them orange`);
  await page.selectOption('#effects', 'outline');
  const again = countColour(await shoot('again'), 'ff8c00');
  check(again === on, `outline again: ${again} orange pixels, first ${on}`);

  // The mirror: only the table's pixels change (the table's are those that differ from the
  // background's colour in the frame without effects; the darkest of its shadow can come within 2
  // levels of it, and the mirror moves those by a level: a change counts off the table when it is
  // more than 4 levels), more with a higher reflectivity.
  await page.selectOption('#effects', 'mirror');
  const mirrorShot = await shoot('mirror');
  const bg = [0, 1, 2].map((i) => shots.none.data[i]);  // the top left corner: the background
  let onTable = 0, offTable = 0;
  for (let i = 0; i < n; ++i) {
    const d = [0, 1, 2].some((c) => Math.abs(mirrorShot.data[4 * i + c] - shots.none.data[4 * i + c]) > 4);
    if (!d) continue;
    const table = [0, 1, 2].some((c) => Math.abs(shots.none.data[4 * i + c] - bg[c]) > 2);
    if (table) ++onTable; else ++offTable;
  }
  check(onTable > 0.05 * n && offTable === 0, `mirror: ${onTable} table pixels changed by more than 4 levels, ${offTable} elsewhere`);
  await page.$eval('#reflectivity', (el) => {
    el.value = '1';
    el.dispatchEvent(new Event('input', { bubbles: true }));
  });
  s = await page.evaluate(() => window.penumbra.state());
  check(s.options.reflectivity === '1', `the slider set reflectivity=${s.options.reflectivity}, not 1`);
  const perfect = compare(await shoot('mirror-1'), shots.none, 16);
  const half = compare(mirrorShot, shots.none, 16);
  check(perfect.differing > half.differing, `reflectivity 1 changed ${perfect.differing} pixels by > 16 levels, ` +
        `0.5 ${half.differing}`);
  await page.selectOption('#effects', 'outline,mirror');
  const both = countColour(await shoot('outline-mirror'), 'ff8c00');
  check(Math.abs(both - on) <= 0.02 * on, `outline and mirror: ${both} orange pixels, the outline alone ${on}`);
  console.log(`mirror: ${onTable} table pixels changed by > 4 levels (${pct(onTable)}), none elsewhere; > 16 levels: ` +
              `${half.differing} at 0.5, ${perfect.differing} at 1; with the outline ${both} orange pixels`);
  // The portal: another scene seen through a frame at the back of the table. Only the pixels of
  // the frame's region change (everything below its sill and outside its sides stays), and the
  // other scene's lawn (green) appears there, none of it without the portal.
  await page.selectOption('#effects', 'portal');
  const portalShot = await shoot('portal');
  const green = (px, i) => px.data[4 * i + 1] > px.data[4 * i] + 25 && px.data[4 * i + 1] > px.data[4 * i + 2] + 25;
  let lawn = 0, lawnBefore = 0, changed = 0, box = { x0: 512, x1: -1, y0: 512, y1: -1 };
  for (let i = 0; i < n; ++i) {
    lawn += green(portalShot, i);
    lawnBefore += green(shots.none, i);
    if (![0, 1, 2].some((c) => portalShot.data[4 * i + c] !== shots.none.data[4 * i + c])) continue;
    ++changed;
    const x = i % 512, y = Math.floor(i / 512);
    box = { x0: Math.min(box.x0, x), x1: Math.max(box.x1, x), y0: Math.min(box.y0, y), y1: Math.max(box.y1, y) };
  }
  check(lawn > 0.005 * n && lawnBefore === 0, `portal: ${lawn} lawn pixels (${lawnBefore} without the portal)`);
  // The frame stands at the back of the table: its pixels lie in the upper middle of the frame.
  check(box.x0 > 100 && box.x1 < 412 && box.y1 < 300, `portal: pixels changed from (${box.x0}, ${box.y0}) to ` +
        `(${box.x1}, ${box.y1}), beyond the frame's region`);
  s = await page.evaluate(() => window.penumbra.state());
  check(s.options.effects === 'portal', `the select set effects=${s.options.effects}, not portal`);
  console.log(`portal: ${changed} pixels changed, within (${box.x0}, ${box.y0})-(${box.x1}, ${box.y1}); ` +
              `${lawn} lawn pixels (${pct(lawn)}), none without it`);
  await page.selectOption('#effects', 'outline');
  await page.$eval('#reflectivity', (el) => {
    el.value = '0.5';
    el.dispatchEvent(new Event('input', { bubbles: true }));
  });

  await slide(page, 8);
  s = await page.evaluate(() => window.penumbra.state());
  check(s.options['outline-width'] === '8', `the slider set outline-width=${s.options['outline-width']}, not 8`);
  check((await page.inputValue('#outline-width-number')) === '8', 'the number box did not follow the slider');
  const wide = countColour(await shoot('width8'), 'ff8c00');
  check(wide > 2 * on, `width 8: ${wide} orange pixels, not more than twice width 3's ${on}`);
  await slide(page, 3);

  await page.selectOption('#outline-color', '00ffff');
  const cyanShot = await shoot('cyan');
  const cyan = countColour(cyanShot, '00ffff');
  check(countColour(cyanShot, 'ff8c00') === 0, 'orange pixels left after choosing cyan');
  check(Math.abs(cyan - on) <= 0.02 * on, `cyan: ${cyan} pixels, orange had ${on}`);
  await page.selectOption('#outline-color', 'ff8c00');

  const byTechnique = { shadowmap: on };
  for (const t of ['volumes', 'planar']) {
    await page.selectOption('#technique', t);
    s = await page.evaluate(() => window.penumbra.state());
    check(s.options.technique === t, `technique select: ${s.options.technique}, not ${t}`);
    byTechnique[t] = countColour(await shoot(t), 'ff8c00');
    // The outline's own stencil bit: the same pixels whatever the technique keeps in the others.
    check(Math.abs(byTechnique[t] - on) <= 0.02 * on, `${t}: ${byTechnique[t]} orange pixels, shadowmap had ${on}`);
    const shadowed = compare(shots[t], shots.outline, 16);
    check(shadowed.differing > 0, `${t}: the frame is the shadow map's`);
  }
  console.log(`orange pixels: ${on} (${pct(on)}) at 3 px, ${wide} at 8 px, 0 unticked; cyan ${cyan}; ` +
              `volumes ${byTechnique.volumes}, planar ${byTechnique.planar}`);

  // The controls in the URL, and a reload keeps them.
  await page.selectOption('#outline-color', 'ff00ff');
  await page.selectOption('#technique', 'volumes');
  await slide(page, 5);
  const want = { effects: 'outline', 'outline-width': '5', 'outline-color': 'ff00ff', technique: 'volumes' };
  const params = new URL(page.url()).searchParams;
  for (const [k, v] of Object.entries(want)) check(params.get(k) === v, `URL ${page.url()}: ${k} is not ${v}`);
  await page.reload({ waitUntil: 'load' });
  await page.evaluate(() => window.penumbra.ready);
  s = await page.evaluate(() => window.penumbra.state());
  for (const [k, v] of Object.entries(want)) check(s.options[k] === v, `after reload ${k} = ${s.options[k]}, not ${v}`);
  check((await page.inputValue('#outline-color')) === 'ff00ff', 'the colour select lost ff00ff');
  check((await page.inputValue('#technique')) === 'volumes', 'the technique select lost volumes');
  check((await page.inputValue('#outline-width')) === '5', 'the slider lost 5');
  // A colour that is not offered: said in the note, not applied.
  const { page: bad, context: badContext, problems: badProblems } = await openPage(browser, `${server.url}/stencil.html?outline-color=123456`);
  s = await bad.evaluate(() => window.penumbra.state());
  check(s.options['outline-color'] === 'ff8c00', `bad link: outline-color=${s.options['outline-color']}`);
  check(/123456/.test(await bad.textContent('#note')), 'the note does not name the colour refused');
  // Closed once read: a page left open keeps drawing (two pages share this machine's cores).
  const badErrs = await glErrors(bad);
  await badContext.close();

  // The browser's frames against headless EGL's `penumbra render` of the same settings.
  await page.evaluate(() => window.penumbra.setCanvasSize(512, 512));
  for (const [name, query, args] of [
    ['shadowmap', { technique: 'shadowmap', 'outline-color': 'ff8c00', 'outline-width': '3' }, ['--technique', 'shadowmap']],
    ['volumes', { technique: 'volumes', 'outline-color': 'ff00ff', 'outline-width': '8' },
     ['--technique', 'volumes', '--outline-color', 'ff00ff', '--outline-width', '8']],
    ['mirror', { technique: 'shadowmap', effects: 'outline,mirror', reflectivity: '0.75' },
     ['--technique', 'shadowmap', '--effects', 'outline,mirror', '--reflectivity', '0.75', '--outline-color', 'ff00ff',
      '--outline-width', '8']],
    ['portal', { technique: 'shadowmap', effects: 'outline,mirror,portal' },
     ['--technique', 'shadowmap', '--effects', 'outline,mirror,portal', '--reflectivity', '0.75',
      '--outline-color', 'ff00ff', '--outline-width', '8']],
  ]) {
    await setOptions(page, query);
    const px = await frameAt(page, T);
    savePng(px, path.join(outDir, `${name}-match.browser.png`));
    const file = path.join(outDir, `${name}-match.egl.png`);
    const effects = args.includes('--effects') ? [] : ['--effects', 'outline'];
    execFileSync(cli, ['render', ...effects, '--time', String(T), '--size', `${px.width}x${px.height}`, ...args,
                       '--out', file]);
    const ref = PNG.sync.read(readFileSync(file));
    const d = compare(px, { width: ref.width, height: ref.height, data: ref.data }, LEVELS);
    console.log(`${name} against penumbra render: mean ${d.mean.toFixed(3)}, ${(100 * d.fraction).toFixed(3)}% differ by more than ${LEVELS}`);
    check(d.mean <= MAX_MEAN && d.fraction <= MAX_FRACTION,
          `${name}: the browser's frame differs from penumbra render's (mean ${d.mean.toFixed(3)}, ` +
          `${(100 * d.fraction).toFixed(3)}% > ${LEVELS} levels; images in ${outDir})`);
  }

  // Each page's module holds only the technique and effect modules its exercise names: W09P1's has
  // no mirror, so it refuses the effect with the reason, where this page (the control) takes it.
  const { page: w09p1, problems: w09p1Problems } = await openPage(browser, `${server.url}/w09p1.html`);
  const refused = await w09p1.evaluate(() => window.penumbra.setOption('effects', 'mirror'));
  check(/not in this page's code/.test(refused), `w09p1 took effects=mirror: '${refused}'`);
  check((await w09p1.evaluate(() => window.penumbra.state())).status === 'running', 'w09p1 stopped after the refusal');
  const taken = await page.evaluate(() => window.penumbra.setOption('effects', 'mirror'));
  check(taken === '', `the stencil page refused effects=mirror: '${taken}'`);
  await w09p1.close();

  const errs = (await glErrors(page)).concat(badErrs);
  check(errs.length === 0, `glGetError: ${errs.map((e) => '0x' + e.toString(16)).join(', ')}`);
  check(problems.length === 0 && badProblems.length === 0 && w09p1Problems.length === 0,
        problems.concat(badProblems, w09p1Problems).join('; '));
});
