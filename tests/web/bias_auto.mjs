// web.bias_auto, on W09P2c: the bias control's "auto" (the encoding's quantum plus a receiver-slope
// term per fragment) removes the acne rings that the sheet's constant bias leaves on the teapot's
// curved, light-facing side. At a fixed t, in the visibility view, rgba encoding, with the 4x4 PCF
// (whose outer taps reach 1.5 texels and show the rings most) and with the hard filter. The teapot
// is found by its colour in the colour view, as in web.pcf. Auto must darken fewer teapot pixels,
// and the pixels it changes there must be ones it lights (acne gone), not new shadow.
import { runTest, openPage, frameAt, check } from './harness.mjs';

const T = 0.6;

function teapotMask(colour) {
  const m = new Uint8Array(colour.width * colour.height);
  for (let i = 0; i < m.length; ++i) {
    const [r, g, b] = [colour.data[4 * i], colour.data[4 * i + 1], colour.data[4 * i + 2]];
    if (r > 20 && r > 1.25 * g && r > 1.5 * b) m[i] = 1;  // porcelain orange, lit or not; marble is white-blue
  }
  return m;
}

// On the mask: pixels dark in a, dark in b, dark in a but lit in b, and lit in a but dark in b.
function teapotCounts(a, b, mask) {
  let darkA = 0, darkB = 0, aOnly = 0, bOnly = 0;
  for (let i = 0; i < mask.length; ++i) {
    if (!mask[i]) continue;
    const da = a.data[4 * i] < 128, db = b.data[4 * i] < 128;
    if (da) ++darkA;
    if (db) ++darkB;
    if (da && !db) ++aOnly;
    if (db && !da) ++bOnly;
  }
  return { darkA, darkB, aOnly, bOnly };
}

await runTest('web.bias_auto', async ({ server, browser }) => {
  const { page, problems } = await openPage(browser, `${server.url}/w09p2c.html?map-view=off&encoding=rgba&filter=hard`);
  const mask = teapotMask(await frameAt(page, T));
  const teapot = mask.reduce((s, v) => s + v, 0);
  check(teapot > 5000, `the teapot covers only ${teapot} pixels in the colour view`);
  await page.selectOption('#aov', 'visibility');

  // The sheet's constant, then auto (the page's default), through the bias radios.
  check(await page.isChecked('#bias-auto'), 'the bias does not start on auto');
  check(await page.isDisabled('#bias'), 'the number box is enabled with the auto bias');
  const label = await page.textContent('label:has(#bias-auto)');
  check(/precision/.test(label) && /slope/.test(label), `the auto choice does not say what it does: '${label}'`);
  const results = {};
  for (const filter of ['hard', 'pcf4x4']) {
    await page.setChecked('#filter', filter === 'pcf4x4');
    await page.check('#bias-sheet');
    const byDefault = await frameAt(page, T);
    await page.check('#bias-auto');
    const s = await page.evaluate(() => window.penumbra.state());
    check(s.options.bias === 'auto' && new URL(page.url()).searchParams.get('bias') === 'auto',
          `after the auto radio: bias ${s.options.bias}, URL ${page.url()}`);
    check(await page.isDisabled('#bias'), 'the number box is enabled with the auto bias');
    check((await page.textContent('#bias-auto-value')) === String(+s.autoBias.toPrecision(2)),
          'the auto choice does not show its constant part');
    const auto = await frameAt(page, T);
    const c = teapotCounts(byDefault, auto, mask);
    results[filter] = c;
    console.log(`${filter}: of ${teapot} teapot pixels, ${c.darkA} dark with the sheet's bias ${s.sheetBias}, ` +
                `${c.darkB} with auto (constant ${s.autoBias} + slope); auto lights ${c.aOnly}, darkens ${c.bOnly}`);
  }
  for (const [filter, c] of Object.entries(results)) {
    check(c.darkB < 0.85 * c.darkA, `${filter}: auto leaves ${c.darkB} of the ${c.darkA} dark teapot pixels`);
    check(c.aOnly > 500, `${filter}: auto lights only ${c.aOnly} teapot pixels the sheet's bias shadows`);
    check(c.bOnly * 10 < c.aOnly, `${filter}: auto darkens ${c.bOnly} teapot pixels (lights ${c.aOnly})`);
  }
  check(problems.length === 0, problems.join('; '));
});
