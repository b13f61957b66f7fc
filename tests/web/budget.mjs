// web.budget, on W09P2c: the "faster / more accurate" select (budget-ms). Off, the page draws with
// its own settings and hides the budget's readout; on, the readout says what the controller chose,
// the URL keeps the budget, and the extremes hold whatever SwiftShader's speed: a second a frame
// climbs to the largest map, a microsecond stays at the smallest and says it is over; the readout
// gives the model's predicted error, more for the smallest map than the largest. A value the
// select does not list (from the URL or the module) is taken as it is. A page whose exercise offers
// no such control refuses it by name. Never a timing check.
import { runTest, openPage, waitFrames, check } from './harness.mjs';

const state = (page) => page.evaluate(() => window.penumbra.state());
const readout = async (page) => ({ hidden: await page.isHidden('#budget-row'), text: await page.textContent('#budget') });

// Waits (frame by frame, up to `frames`) until the state's budget satisfies `want`.
async function waitBudget(page, want, frames) {
  for (let i = 0; i < frames; i += 10) {
    const s = await state(page);
    if (s.budget && want(s.budget)) return s.budget;
    await waitFrames(page, 10);
  }
  return (await state(page)).budget;
}

await runTest('web.budget', async ({ server, browser }) => {
  const { page, context, problems } = await openPage(browser, `${server.url}/w09p2c.html`);
  // Off (the default): no controller, the readout hidden, the select on "off".
  check((await page.inputValue('#budget-ms')) === '0', `the select starts at ${await page.inputValue('#budget-ms')}`);
  check((await state(page)).budget === null, 'a budget while off');
  await waitFrames(page, 5);
  check((await readout(page)).hidden, 'the budget readout shows while off');
  check((await state(page)).mapSize === 1024, 'the page does not draw its own map size while off');

  // The select: the URL keeps it; the readout says the choice.
  await page.selectOption('#budget-ms', '33');
  check(new URL(page.url()).searchParams.get('budget-ms') === '33', `the URL does not keep budget-ms=33: ${page.url()}`);
  const chosen = await waitBudget(page, () => true, 40);
  check(chosen !== null, 'no budget after 40 frames at 33 ms');
  const m = chosen.mapSize;
  check(m >= 128 && m <= 4096 && (m & (m - 1)) === 0, `map ${m} is not a power of two in [128, 4096]`);
  check(chosen.filter === 'hard' && ['depthtex', 'rgba'].includes(chosen.encoding), JSON.stringify(chosen));
  // The readout follows the state at the page's next poll.
  await page.waitForFunction(() => !document.getElementById('budget-row').hidden &&
    document.getElementById('budget').textContent.startsWith('budget 33.00 ms: '), null, { timeout: 10000 })
    .catch(() => {});
  const shown = await readout(page);
  check(!shown.hidden && shown.text.startsWith('budget 33.00 ms: '), `the readout: ${JSON.stringify(shown)}`);

  // A second a frame: every map fits; it climbs to the largest (128 .. 4096, 10 frames a step).
  await page.evaluate(() => window.penumbra.setOption('budget-ms', '1000'));
  const largest = Math.min(4096, (await state(page)).maxMapSize);
  const wide = await waitBudget(page, (b) => b.mapSize === largest && b.why.includes('the largest map'), 160);
  check(wide && wide.mapSize === largest && wide.why.includes('the largest map'), `a second a frame: ${JSON.stringify(wide)}`);
  // The model's predicted error for the choice, once measured on the frame's shadow edges.
  const predicted = await waitBudget(page, (b) => b.predictedErrorPct !== null && b.mapSize === largest, 40);
  check(predicted && predicted.predictedErrorPct > 0 && predicted.predictedErrorPct < 100,
        `a predicted error at the largest map: ${JSON.stringify(predicted)}`);
  await page.waitForFunction(() => / predicted error [0-9.]+ % of the truth$/.test(document.getElementById('budget').textContent),
    null, { timeout: 10000 }).catch(() => {});
  check(/; predicted error [0-9.]+ % of the truth$/.test((await readout(page)).text), `the readout: ${(await readout(page)).text}`);
  // A microsecond: nothing fits; the smallest map, said to be over.
  await page.evaluate(() => window.penumbra.setOption('budget-ms', '0.001'));
  const tight = await waitBudget(page, (b) => b.mapSize === 128 && b.why.includes('over the budget'), 80);
  check(tight && tight.mapSize === 128 && /over the budget at the smallest map$/.test(tight.why),
        `a microsecond: ${JSON.stringify(tight)}`);
  // Coarser texels, more error predicted: the smallest map's prediction is over the largest's.
  const coarse = await waitBudget(page, (b) => b.predictedErrorPct !== null && b.mapSize === 128, 40);
  check(coarse && predicted && coarse.predictedErrorPct > predicted.predictedErrorPct,
        `map 128 predicted ${coarse && coarse.predictedErrorPct} %, the largest ${predicted && predicted.predictedErrorPct} %`);

  // Off again: the page's own settings, the readout hidden.
  await page.selectOption('#budget-ms', '0');
  await waitFrames(page, 3);
  const off = await state(page);
  check(off.budget === null && off.mapSize === 1024, `off again: budget ${JSON.stringify(off.budget)}, map ${off.mapSize}`);
  await page.waitForSelector('#budget-row', { state: 'hidden', timeout: 10000 }).catch(() => {});
  check((await readout(page)).hidden, 'the readout stays after the budget is off');
  check(problems.length === 0, problems.join('; '));
  await context.close();

  // From the URL: the select shows it, the state keeps it.
  const again = await openPage(browser, `${server.url}/w09p2c.html?budget-ms=16`);
  check((await again.page.inputValue('#budget-ms')) === '16', `the select after a load: ${await again.page.inputValue('#budget-ms')}`);
  check((await state(again.page)).options['budget-ms'] === '16', JSON.stringify((await state(again.page)).options));
  check(again.problems.length === 0, again.problems.join('; '));
  await again.context.close();

  // A page whose exercise offers neither control has neither's code (Exercise::trade): W09P1's
  // refuses both by name and runs on, where this page (the control, above) takes them.
  const other = await openPage(browser, `${server.url}/w09p1.html`);
  for (const [name, value] of [['budget-ms', '16'], ['max-error', '0.1']]) {
    const refused = await other.page.evaluate(([n, v]) => window.penumbra.setOption(n, v), [name, value]);
    check(new RegExp(`^${name} ${value}: not in this page's code`).test(refused), `w09p1 took ${name}=${value}: '${refused}'`);
  }
  await waitFrames(other.page, 3);
  const rest = await state(other.page);
  check(rest.status === 'running' && rest.budget === null && rest.errorTarget === null && !('budget-ms' in rest.options),
        `w09p1 after the refusals: ${JSON.stringify({ status: rest.status, budget: rest.budget, errorTarget: rest.errorTarget })}`);
  check(other.problems.length === 0, other.problems.join('; '));
  await other.context.close();
});
