// web.lab, on W09P2c with 4x4 PCF (the hard filter calls offset_lookup with the offset (0, 0) only:
// there no-texmapscale's frame is the answer's): the shader lab's panel (web/lab/lab.js,
// docs/pages.md). Its files are not requested until the "Shader lab" button is pressed; the editor
// (CodeMirror) shows line numbers and GLSL highlighting and starts on the skeleton; the sheet's
// answer, put in by its button, is checked as matching the sheet's answer, each classic mistake of
// the encoding (typed into the editor) gets its hint's name; an empty editor, a comment only and a
// helper only are "no function of the sheet written", never a match; broken code typed from the keyboard is
// marked at its line (gutter, line, message) and the picture keeps the last good frame, also after
// a lost and restored context; the code is in the address and in localStorage: a reload, a visit
// without the address's code and a fresh browser given the link each restore it; the r8 answer
// matches too; the depth texture is refused and said; Reset gives the skeleton back; closing turns
// the lab off.
import { runTest, openPage, frameAt, compare, check, checkNoGlErrors, loseAndRestore } from './harness.mjs';

const T = 0.6;  // the page's frame read before and after the broken code (any fixed time would do)

// The panel's object once open (penumbra-page.js loads lab/lab.js on the button).
async function waitOpen(page) {
  await page.waitForFunction(() => window.penumbraLab && window.penumbraLab.isOpen() && window.penumbraLab.editor(),
                             null, { timeout: 30000 });
}

// Puts `text` in the editor as typing would (a change the editor's listeners see), then waits for
// the debounced compile and, when it compiled, its check. Returns {verdict, problems, status}.
async function enter(page, text) {
  const before = await page.evaluate(() => window.penumbraLab.checks());
  await page.evaluate((t) => window.penumbraLab.editor().setValue(t), text);
  return settle(page, before);
}

async function settle(page, before) {
  await page.waitForFunction((b) => !window.penumbraLab.pending() &&
    (window.penumbraLab.checks() > b || document.getElementById('lab-problems').children.length > 0), before,
  { timeout: 30000 });
  await page.evaluate(() => window.penumbraLab.kept());
  return page.evaluate(() => ({
    verdict: window.penumbraLab.verdict(),
    shown: document.getElementById('lab-verdict').dataset.verdict,
    mistakeShown: document.getElementById('lab-verdict').dataset.mistake,
    verdictText: document.getElementById('lab-verdict').textContent,
    problems: window.penumbraLab.problems(),
    list: [...document.querySelectorAll('#lab-problems li')].map((li) => li.textContent),
    status: document.getElementById('lab-status').textContent,
    truth: document.getElementById('lab-truth').textContent,
  }));
}

const editorText = (page) => page.evaluate(() => window.penumbraLab.editor().getValue());
const moduleText = (page, which) => page.evaluate((w) => Module.UTF8ToString(Module._penumbra_lab_text(w)), which);

await runTest('web.lab', async ({ server, browser }) => {
  const url = `${server.url}/w09p2c.html?map-view=off&filter=pcf4x4`;
  const { page, context, problems } = await openPage(browser, url);
  const labRequests = [];
  context.on('request', (r) => { if (/\/lab\//.test(r.url())) labRequests.push(r.url()); });
  await page.evaluate(() => window.penumbra.pause());

  // Closed: nothing of the lab loaded; the lab off.
  check(labRequests.length === 0 && !(await page.evaluate(() => 'penumbraLab' in window)),
        `the lab's files were requested before the panel opened: ${labRequests.join(', ')}`);
  const state = await page.evaluate(() => JSON.parse(Module.UTF8ToString(Module._penumbra_lab_state())));
  check(state.available && state.refusal === "" && !state.on, `lab state with the panel closed: ${JSON.stringify(state)}`);

  // Open: the editor on the skeleton, with line numbers and GLSL highlighting.
  await page.click('#lab-open');
  await waitOpen(page);
  await settle(page, -1);
  check(labRequests.some((u) => u.endsWith('/lab/codemirror.js')) && labRequests.some((u) => u.endsWith('/lab/lab.js')),
        `opening did not load the editor: ${labRequests.join(', ')}`);
  check((await page.getAttribute('#lab-open', 'aria-expanded')) === 'true', 'the button does not say the panel is open');
  const skeleton = await moduleText(page, 0);
  check((await editorText(page)) === skeleton, 'the editor does not start on the skeleton');
  const looks = await page.evaluate(() => ({
    numbers: document.querySelectorAll('#lab .CodeMirror-linenumber').length,
    highlighted: document.querySelectorAll('#lab .cm-keyword, #lab .cm-type, #lab .cm-variable-3').length,
  }));
  check(looks.numbers >= skeleton.split('\n').length - 1 && looks.highlighted > 0,
        `the editor has ${looks.numbers} line numbers and ${looks.highlighted} highlighted words`);
  check((await page.evaluate(() => JSON.parse(Module.UTF8ToString(Module._penumbra_lab_state())))).on,
        'the lab is not on with the panel open');

  // The sheet's answer (its button): matches.
  let before = await page.evaluate(() => window.penumbraLab.checks());
  await page.click('#lab-answer');
  let r = await settle(page, before);
  const answer = await moduleText(page, 1);
  check((await editorText(page)) === answer, 'the answer button did not put the sheet\'s answer in the editor');
  console.log(`the sheet's answer: ${r.verdict.differingPct}% of the pixels differ (matches up to ${r.verdict.matchPct}%), ` +
              `error against the truth: ${r.truth}`);
  // "Matches" is the module's own rule: at most kLabMatchPct % of the pixels more than one 8-bit
  // step apart (render/lab.h: two programs computing the same function may round edge pixels
  // differently, GLSL ES 1.00 4.6.1); the answer typed in is the reference's own code.
  check(r.verdict.compiles && r.verdict.matches && r.shown === 'matches' && r.problems.length === 0,
        `the sheet's answer: ${JSON.stringify(r)}`);
  check(/^\d+\.\d\d % \(the sheet's answer: \d+\.\d\d %\)$/.test(r.truth), `the error against the truth reads "${r.truth}"`);
  const images = await page.evaluate(() => ['lab-student', 'lab-reference', 'lab-difference'].map((id) => {
    const c = document.getElementById(id);
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let dark = 0, light = 0;
    for (let i = 0; i < d.length; i += 4) (d[i] < 64 ? ++dark : d[i] > 192 ? ++light : 0);
    return { w: c.width, h: c.height, dark, light };
  }));
  // The visibility images show a shadow (dark) and lit ground (light); the difference view is
  // drawn (its grey "same" pixels are neither).
  for (const [i, name] of [[0, 'student'], [1, 'reference']])
    check(images[i].dark > 0 && images[i].light > 0, `the ${name}'s image is not a visibility image: ${JSON.stringify(images[i])}`);
  check(images[2].w === r.verdict.width && images[2].h === r.verdict.height, `the difference view is ${images[2].w}x${images[2].h}`);

  // Each classic mistake of the encoding, typed into the editor: its hint.
  const mistakes = await page.evaluate(() => window.penumbraLab.mistakes());
  check(mistakes.length >= 4, `only ${mistakes.length} classic mistakes for ${state.encoding}`);
  for (const m of mistakes) {
    r = await enter(page, m.text);
    console.log(`mistake ${m.name}: ${r.verdict.differingPct}% differ, named "${r.verdict.mistake}"`);
    check(r.verdict.compiles && r.shown === 'mistake' && r.mistakeShown === m.name && r.verdictText.includes(m.hint),
          `mistake ${m.name}: ${JSON.stringify(r)}`);
  }

  // A cleared editor, a comment only, a helper of its own: no function of the sheet written, never
  // a match. The control is in the frame: each draws the sheet's answer's own frame (0 pixels
  // differ, the functions left out being the answer's), so without the module's rule
  // (render::lab_verdict's NoFunction) each would read "matches".
  for (const [name, text] of [['empty', ''], ['comment only', '// my answer\n/* later */\n'],
                              ['a helper only', 'float half(float x) {\n    return 0.5 * x;\n}\n']]) {
    r = await enter(page, text);
    console.log(`${name}: ${r.verdict.differingPct}% differ, verdict ${r.verdict.verdict}, functions "${r.verdict.functions}"`);
    check(r.verdict.compiles && !r.verdict.matches && r.verdict.verdict === 'no-function' && r.shown === 'no-function' &&
          r.verdictText.startsWith('No function of the sheet written') && r.verdict.functions === '' &&
          r.verdict.differingPct === 0, `${name}: ${JSON.stringify(r)}`);
  }

  // Back to the answer, its frame; then broken code typed on line 3: marked there, frame kept.
  r = await enter(page, answer);
  check(r.verdict.matches, 'the answer again does not match');
  const good = await frameAt(page, T);
  before = await page.evaluate(() => window.penumbraLab.checks());
  await page.evaluate(() => {
    const cm = window.penumbraLab.editor();
    cm.focus();
    cm.setCursor({ line: 2, ch: 0 });
  });
  await page.keyboard.type('float broken = ;\n');
  r = await settle(page, before);
  const broken = await editorText(page);
  check(broken.split('\n')[2] === 'float broken = ;', `line 3 is "${broken.split('\n')[2]}"`);
  check(r.problems.some((p) => p.line === 3) && r.list.some((t) => t.startsWith('line 3: ')),
        `the error is not marked at line 3: ${JSON.stringify(r)}`);
  const marked = await page.evaluate(() => ({
    lines: [...document.querySelectorAll('#lab .lab-error-line')].length,
    markers: [...document.querySelectorAll('#lab .lab-error-marker')].length,
    message: document.querySelector('#lab .lab-error-message')?.textContent || '',
  }));
  check(marked.lines >= 1 && marked.markers >= 1 && marked.message.length > 0, `the marks: ${JSON.stringify(marked)}`);
  check(/keeps your last code/.test(r.status), `the status says "${r.status}"`);
  const kept = compare(good, await frameAt(page, T));
  check(kept.differing === 0, `the frame after the broken code differs from the last good one in ${kept.differing} pixels`);
  // A lost and restored context: the lab's frame (the last good code) drawn again, pixel for pixel.
  await loseAndRestore(page);
  check(compare(good, await frameAt(page, T)).differing === 0, 'after a context restore the lab\'s frame is not the last good one');

  // Kept: a reload (the address's code), then the page without it (localStorage).
  const hash = new URL(page.url()).hash;
  check(/^#lab=[A-Za-z0-9_-]+$/.test(hash), `the address holds no code: ${page.url()}`);
  await page.reload({ waitUntil: 'load' });
  await page.evaluate(() => window.penumbra.ready);
  await waitOpen(page);
  r = await settle(page, -1);
  check((await editorText(page)) === broken, 'a reload did not restore the code');
  check(r.problems.some((p) => p.line === 3), 'after the reload the error is not marked at line 3');
  await page.goto(url, { waitUntil: 'load' });
  await page.evaluate(() => window.penumbra.ready);
  check(!(await page.evaluate(() => !!window.penumbraLab)), 'the panel opened without #lab= in the address');
  await page.click('#lab-open');
  await waitOpen(page);
  await settle(page, -1);
  check((await editorText(page)) === broken, 'the code was not restored from localStorage');

  // Shared: a link with a mistake's code, in a fresh browser context (no storage).
  r = await enter(page, mistakes[0].text);
  const link = page.url();
  const other = await openPage(browser, link);
  await waitOpen(other.page);
  r = await settle(other.page, -1);
  check((await editorText(other.page)) === mistakes[0].text, 'the shared link did not restore the code');
  check(r.mistakeShown === mistakes[0].name, `the shared link's check: ${JSON.stringify(r)}`);
  check(other.problems.length === 0, other.problems.join('; '));
  await other.context.close();

  // The 8-bit encoding: the answer button gives its answer (the depth in the red channel), which
  // matches there too.
  check((await page.evaluate(() => window.penumbra.setOption('encoding', 'r8'))) === '', 'encoding=r8 refused');
  await page.waitForFunction(() => /for r8/.test(document.getElementById('lab-bias').textContent), null, { timeout: 10000 });
  before = await page.evaluate(() => window.penumbraLab.checks());
  await page.click('#lab-answer');
  r = await settle(page, before);
  const answerR8 = await moduleText(page, 1);
  check(answerR8 !== answer && (await editorText(page)) === answerR8, 'the answer button did not give the r8 answer');
  check(r.verdict.matches && r.shown === 'matches', `the r8 answer: ${JSON.stringify(r)}`);
  check((await page.evaluate(() => window.penumbra.setOption('encoding', 'rgba'))) === '', 'encoding=rgba refused');

  // Settings the lab cannot run (the depth texture, where the context has one): said, with the
  // module's reason; back to the page's encoding, the lab runs again.
  if ((await page.evaluate(() => window.penumbra.state())).depthTexture) {
    check((await page.evaluate(() => window.penumbra.setOption('encoding', 'depthtex'))) === '', 'encoding=depthtex refused');
    await page.waitForFunction(() => /off for these settings/.test(document.getElementById('lab-bias').textContent), null,
                               { timeout: 10000 });
    check((await page.evaluate(() => window.penumbra.setOption('encoding', 'rgba'))) === '', 'encoding=rgba refused');
    await page.waitForFunction(() => /constant bias for rgba/.test(document.getElementById('lab-bias').textContent), null,
                               { timeout: 10000 });
  }

  // Reset, then close: the skeleton; the lab off and the address without code.
  before = await page.evaluate(() => window.penumbraLab.checks());
  await page.click('#lab-reset');
  await settle(page, before);
  check((await editorText(page)) === skeleton, 'Reset did not give the skeleton back');
  await page.click('#lab-close');
  check(!(await page.evaluate(() => JSON.parse(Module.UTF8ToString(Module._penumbra_lab_state())).on)),
        'the lab is still on after closing');
  check(new URL(page.url()).hash === '', `the address keeps the code after closing: ${page.url()}`);
  await checkNoGlErrors(page);
  check(problems.length === 0, problems.join('; '));
});
