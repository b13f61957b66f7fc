// web.encoding, on W09P2c: 8-bit red vs bit-shift RGBA changes the visibility where the sheet says
// precision matters. With the same bias (0.0015, the RGBA default derived for 10 bits), the 8-bit
// map's depth steps of 2^-8 exceed the bias and the lit table shadows itself in bands: many pixels
// dark in r8 that RGBA keeps lit. With r8's own default (0.005 = 2^-8 + e) the bands are gone.
// The controls used are the page's: the encoding select, the bias field and its default box.
import { runTest, openPage, frameAt, check } from './harness.mjs';

const T = 0.6;

function shadowedOnlyInFirst(a, b) {
  let n = 0, differing = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    const da = a.data[i] < 128, db = b.data[i] < 128;
    if (da !== db) ++differing;
    if (da && !db) ++n;
  }
  return { n, differing };
}

await runTest('web.encoding', async ({ server, browser }) => {
  const { page, problems } = await openPage(browser, `${server.url}/w09p2c.html?map-view=off&filter=hard`);
  await page.selectOption('#aov', 'visibility');
  await page.selectOption('#encoding', 'rgba');
  check((await page.textContent('#bias-sheet-value')) === '0.0015', 'the RGBA default bias shown is not 0.0015');
  await page.check('#bias-fixed');
  await page.fill('#bias', '0.0015');
  await page.dispatchEvent('#bias', 'change');
  const rgba = await frameAt(page, T);

  await page.selectOption('#encoding', 'r8');
  check((await page.textContent('#bias-sheet-value')) === '0.005', 'the 8-bit default bias shown is not 0.005');
  const s = await page.evaluate(() => window.penumbra.state());
  check(Math.abs(s.bias - 0.0015) < 1e-6 && s.options.encoding === 'r8', `expected r8 at bias 0.0015: ${JSON.stringify(s.options)}`);
  const r8 = await frameAt(page, T);

  await page.check('#bias-sheet');
  const r8Default = await frameAt(page, T);

  const same = shadowedOnlyInFirst(r8, rgba);
  const fixed = shadowedOnlyInFirst(r8Default, rgba);
  console.log(`bias 0.0015: ${same.n} pixels shadowed in r8 but lit in rgba (${same.differing} differ); ` +
              `r8 at its default 0.005: ${fixed.n} (${fixed.differing} differ)`);
  check(same.n > 5000, `r8 at bias 0.0015 darkens only ${same.n} pixels that rgba keeps lit`);
  check(same.n >= 0.95 * same.differing, `r8 vs rgba: of ${same.differing} differing pixels only ${same.n} are r8's self-shadowing`);
  check(fixed.n * 10 < same.n, `r8's default bias leaves ${fixed.n} of the ${same.n} self-shadowed pixels`);
  check(problems.length === 0, problems.join('; '));
});
