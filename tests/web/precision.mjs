// web.precision, on W09P2c: the precision select (highp / emulated mediump) changes the visibility
// the way fp16 along the depth path should (docs/precision.md, sections 1 and 2). At a fixed t, in
// the visibility view (white lit, black shadowed), hard filter, set through the page's controls
// (the precision select, the bias radios and the number box):
//  - rgba at a fixed bias of 0.0002, below mediump's depth step (2^-11 = 0.00049 for depths in
//    [0.5, 1)): the acne pattern changes over a large part of the frame, both ways: mediump adds
//    acne where the stored and the fragment's depth round to neighbouring fp16 values, and takes
//    some away on the table, where highp's slope acne lies within a step and both round alike;
//  - rgba at the sheet's bias (the encoding's default, 0.0015 = 2^-10 + e, which covers that step):
//    far fewer pixels change, and those that do are mostly acne that only mediump shows;
//  - r8 at its default (0.005 = 2^-8 + e): the 8-bit step dominates, mediump changes little;
//  - mediump compares the depth with the biased depth rounded to fp16, so the bias only counts in
//    whole depth steps: 0.0003 and 0.0007 (both one step of 2^-11 once rounded, for depths in
//    [0.5, 1)) give nearly the same image under mediump, while under highp the larger bias removes
//    thousands of acne pixels. Nearly: the light's frustum is fitted tightly (its near plane at
//    the nearest caster), so the teapot's depths lie below 0.5 too, where fp16's steps are finer
//    and the two biases round to different counts of steps.
import { runTest, openPage, frameAt, check } from './harness.mjs';

const T = 0.6;

// Pixels dark (shadowed) in a only, in b only, and all that differ.
function darkDiff(a, b) {
  let aOnly = 0, bOnly = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    const da = a.data[i] < 128, db = b.data[i] < 128;
    if (da && !db) ++aOnly;
    if (db && !da) ++bOnly;
  }
  return { aOnly, bOnly, differing: aOnly + bOnly };
}

function darkCount(img) {
  let n = 0;
  for (let i = 0; i < img.data.length; i += 4) if (img.data[i] < 128) ++n;
  return n;
}

await runTest('web.precision', async ({ server, browser }) => {
  const { page, problems } = await openPage(browser, `${server.url}/w09p2c.html?map-view=off&filter=hard`);
  await page.selectOption('#aov', 'visibility');
  check((await page.inputValue('#precision')) === 'highp', 'the precision select does not start at highp');

  // The page's controls: encoding, bias mode (the encoding's default or a fixed value) and precision.
  async function frame(encoding, bias, precision) {
    await page.selectOption('#encoding', encoding);
    if (bias === 'sheet') {
      await page.check('#bias-sheet');
    } else {
      await page.check('#bias-fixed');
      await page.fill('#bias', bias);
      await page.dispatchEvent('#bias', 'change');
    }
    await page.selectOption('#precision', precision);
    const params = new URL(page.url()).searchParams;
    check(params.get('precision') === precision && params.get('bias') === bias && params.get('encoding') === encoding,
          `the URL does not hold encoding=${encoding}, bias=${bias}, precision=${precision}: ${page.url()}`);
    return frameAt(page, T);
  }

  const n = 512 * 512;
  const pct = (k) => `${(100 * k / n).toFixed(2)}%`;
  const small = { highp: await frame('rgba', '0.0002', 'highp'), mediump: await frame('rgba', '0.0002', 'mediump') };
  const sheet = { highp: await frame('rgba', 'sheet', 'highp'), mediump: await frame('rgba', 'sheet', 'mediump') };
  const r8 = { highp: await frame('r8', 'sheet', 'highp'), mediump: await frame('r8', 'sheet', 'mediump') };
  const step = {
    highp3: await frame('rgba', '0.0003', 'highp'), highp7: await frame('rgba', '0.0007', 'highp'),
    mediump3: await frame('rgba', '0.0003', 'mediump'), mediump7: await frame('rgba', '0.0007', 'mediump'),
  };

  const dSmall = darkDiff(small.mediump, small.highp);
  const dSheet = darkDiff(sheet.mediump, sheet.highp);
  const dR8 = darkDiff(r8.mediump, r8.highp);
  const dStepHigh = darkDiff(step.highp3, step.highp7);
  const dStepMed = darkDiff(step.mediump3, step.mediump7);
  console.log(`rgba, bias 0.0002: ${dSmall.differing} pixels (${pct(dSmall.differing)}) differ between highp and ` +
              `mediump (${dSmall.aOnly} dark only in mediump, ${dSmall.bOnly} only in highp; dark in all: ` +
              `highp ${darkCount(small.highp)}, mediump ${darkCount(small.mediump)})`);
  console.log(`rgba, the sheet's bias 0.0015: ${dSheet.differing} differ (${pct(dSheet.differing)}): ${dSheet.aOnly} dark ` +
              `only in mediump, ${dSheet.bOnly} only in highp`);
  console.log(`r8, the sheet's bias 0.005: ${dR8.differing} differ (${pct(dR8.differing)}): ${dR8.aOnly} dark only in ` +
              `mediump, ${dR8.bOnly} only in highp`);
  console.log(`rgba, bias 0.0003 vs 0.0007: highp ${dStepHigh.differing} pixels differ (${dStepHigh.aOnly} acne ` +
              `pixels gone at 0.0007), mediump ${dStepMed.differing}`);

  check(dSmall.differing > 0.05 * n, `at bias 0.0002 mediump changes only ${dSmall.differing} pixels`);
  check(dSmall.aOnly > 1000 && dSmall.bOnly > 1000,
        `at bias 0.0002 mediump should move the acne both ways: ${JSON.stringify(dSmall)}`);
  check(dSheet.differing * 10 < dSmall.differing,
        `the sheet's bias should absorb most of mediump's effect: ${dSheet.differing} vs ${dSmall.differing} pixels`);
  check(dSheet.aOnly > dSheet.bOnly && darkCount(sheet.mediump) > darkCount(sheet.highp),
        `at the sheet's bias mediump should show more acne than highp: ${JSON.stringify(dSheet)}`);
  check(dR8.differing < 0.01 * n, `r8 at its default bias: mediump changes ${dR8.differing} pixels`);
  check(dStepHigh.differing > 5000, `under highp, bias 0.0003 -> 0.0007 changes only ${dStepHigh.differing} pixels`);
  check(dStepMed.differing * 4 < dStepHigh.differing, `under mediump, bias 0.0003 and 0.0007 (one depth step each ` +
        `in [0.5, 1)) differ in ${dStepMed.differing} pixels, not far fewer than under highp (${dStepHigh.differing})`);

  // Back to highp gives the highp image again (the variant is switched, not left behind).
  const again = await frame('rgba', '0.0002', 'highp');
  check(darkDiff(again, small.highp).differing === 0, 'switching back to highp does not restore the highp image');
  check(problems.length === 0, problems.join('; '));
});
