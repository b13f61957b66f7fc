// The shader lab (docs/pages.md, docs/snippets.md): a panel on W09P2c where a student writes the
// sheet's shader functions (packDepth, unpackDepth, shadowTest, offset_lookup), compiled as they
// type into the renderer's own programs and checked against the sheet's answer and the ray-traced
// truth. penumbra-page.js loads this file only when the "Shader lab" button is pressed or the
// address holds #lab=...; this file then loads the editor (CodeMirror 5, lab/codemirror.js and its
// clike mode for GLSL) and lab/lab.css, and fills <section id="lab">.
//
// The module's exports it uses (examples/course_web.cpp): penumbra_lab_state, penumbra_lab_enable,
// penumbra_lab_set, penumbra_lab_text, penumbra_lab_mistakes, penumbra_lab_check, penumbra_lab_image.
// The code is kept in the address (#lab= and the text, deflated and base64url) and in localStorage.
'use strict';

(function () {
  // The check frame: fixed, so that the committed truth (lab/truth-visibility.png and
  // lab/truth-mask.png, `penumbra truth --time 0.6 --size 256x192`) is of the same frame.
  const CHECK = { time: 0.6, width: 256, height: 192 };
  const DEBOUNCE_MS = 300;  // after the last key, the text is compiled
  const CHECK_DELAY_MS = 400;  // and this much later, if no key came, checked
  const POLL_MS = 500;  // the page's settings (encoding, filter) are watched this often while open
  // Texts longer than this are not handed to the module at all (its own limit, 64 KiB, is said by
  // its scan for anything between).
  const MAX_CHARS = 256 * 1024;
  const exercise = document.body.dataset.exercise;
  const STORE = 'penumbra.lab.' + exercise;
  const panel = document.getElementById('lab');
  const openButton = document.getElementById('lab-open');

  let built = null;  // the promise of the panel built (editor loaded)
  let editor = null;
  let isOpen = false;
  let ready = false;  // open, and the editor holds the starting text
  let timer = null;  // the compile's
  let checkTimer = null;  // the check's
  let pollTimer = null;
  let lastGood = null;  // the last text that compiled
  let lastState = '';  // the module's lab state (JSON) at the last poll
  let marks = [];  // the editor's error marks: {line, widget}
  let truth = null;  // {vis, mask}: the truth's visibility and valid pixels, a byte a pixel
  let truthFailed = false;
  let verdict = null;  // the last check's {…, verdict}
  let checks = 0;  // how many checks ran (the tests wait for the next)
  const el = {};

  // ---- loading ------------------------------------------------------------------------------------
  function loadScript(src) {
    return new Promise((resolve, reject) => {
      const s = document.createElement('script');
      s.src = src;
      s.onload = resolve;
      s.onerror = () => reject(new Error(src + ' did not load'));
      document.head.appendChild(s);
    });
  }
  function loadCss(href) {
    return new Promise((resolve, reject) => {
      const l = document.createElement('link');
      l.rel = 'stylesheet';
      l.href = href;
      l.onload = resolve;
      l.onerror = () => reject(new Error(href + ' did not load'));
      document.head.appendChild(l);
    });
  }
  function loadImage(src) {
    return new Promise((resolve, reject) => {
      const img = new Image();
      img.onload = () => {
        const c = document.createElement('canvas');
        c.width = img.width;
        c.height = img.height;
        const ctx = c.getContext('2d');
        ctx.drawImage(img, 0, 0);
        const rgba = ctx.getImageData(0, 0, c.width, c.height).data;
        const grey = new Uint8Array(c.width * c.height);
        for (let i = 0; i < grey.length; ++i) grey[i] = rgba[4 * i];
        resolve({ width: c.width, height: c.height, data: grey });
      };
      img.onerror = () => reject(new Error(src + ' did not load'));
      img.src = src;
    });
  }

  // ---- the module ---------------------------------------------------------------------------------
  const M = () => window.Module;
  const labState = () => JSON.parse(M().UTF8ToString(M()._penumbra_lab_state()));
  const labText = (which) => M().UTF8ToString(M()._penumbra_lab_text(which));
  const mistakes = () => JSON.parse(M().UTF8ToString(M()._penumbra_lab_mistakes()));
  function setSnippets(text) {
    if (text.length > MAX_CHARS)
      return { ok: false, problems: [{ line: 0, message: 'the text is longer than ' + MAX_CHARS + ' characters' }] };
    return JSON.parse(M().ccall('penumbra_lab_set', 'string', ['string'], [text]));
  }
  function runCheck(text) {
    const v = JSON.parse(M().ccall('penumbra_lab_check', 'string', ['string', 'number', 'number', 'number'],
                                   [text, CHECK.width, CHECK.height, CHECK.time]));
    const image = (which) => {
      const p = M()._penumbra_lab_image(which);
      return p ? M().HEAPU8.slice(p, p + v.width * v.height * 4) : null;
    };
    v.images = v.compiles ? [image(0), image(1), image(2)] : [null, null, null];
    return v;
  }

  // ---- kept and shared: the address (#lab=) and localStorage ------------------------------------
  function toBase64Url(bytes) {
    let s = '';
    for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(s).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
  }
  function fromBase64Url(s) {
    const b = atob(s.replace(/-/g, '+').replace(/_/g, '/'));
    const out = new Uint8Array(b.length);
    for (let i = 0; i < b.length; ++i) out[i] = b.charCodeAt(i);
    return out;
  }
  async function through(bytes, stream) {
    return new Uint8Array(await new Response(new Blob([bytes]).stream().pipeThrough(stream)).arrayBuffer());
  }
  // "z" + the UTF-8 text deflated (raw) in base64url, or "b" + the text itself in base64url where
  // the browser has no CompressionStream.
  async function encode(text) {
    const bytes = new TextEncoder().encode(text);
    if (window.CompressionStream) return 'z' + toBase64Url(await through(bytes, new CompressionStream('deflate-raw')));
    return 'b' + toBase64Url(bytes);
  }
  async function decode(code) {
    const bytes = fromBase64Url(code.slice(1));
    if (code[0] === 'b') return new TextDecoder().decode(bytes);
    if (code[0] === 'z' && window.DecompressionStream)
      return new TextDecoder().decode(await through(bytes, new DecompressionStream('deflate-raw')));
    throw new Error('this browser cannot read the code in the address');
  }
  function hashCode() {
    const m = /^#lab=([A-Za-z0-9_-]+)$/.exec(location.hash);
    return m ? m[1] : null;
  }
  let keepSeq = 0;
  let kept = Promise.resolve();  // the last keep(), for tests
  async function keep(text) {
    try {
      localStorage.setItem(STORE, text);
    } catch (e) {
      // Storage full or refused (a private window): the address still holds it.
    }
    const seq = ++keepSeq;
    const code = await encode(text);
    if (seq !== keepSeq || !isOpen) return;  // a later text (or the panel closed) won
    history.replaceState(null, '', location.pathname + location.search + '#lab=' + code);
  }
  function dropHash() {
    ++keepSeq;
    if (location.hash) history.replaceState(null, '', location.pathname + location.search);
  }
  async function startingText() {
    const code = hashCode();
    if (code) {
      try {
        return await decode(code);
      } catch (e) {
        setStatus('The code in the address could not be read (' + e.message + '): your last code instead.');
      }
    }
    let stored = null;
    try {
      stored = localStorage.getItem(STORE);
    } catch (e) {
      stored = null;
    }
    return stored !== null ? stored : labText(0);
  }

  // ---- the panel ----------------------------------------------------------------------------------
  const PACKING_NOTE =
    'Where the sheet\'s answer differs from the renderer\'s own packing: the renderer stores each byte b ' +
    'as (b + 0.25) / 255, so that the 8-bit store gives b back whatever its rounding, and reads the bytes ' +
    'back exactly. The sheet\'s bit-shift packing writes multiples of 1/256 (fract(z·256^k), less the next ' +
    'channel\'s share), which the store rounds to its steps of 1/255, and its unpackDepth weights the ' +
    'channels by powers of 1/256: a depth comes back up to about 0.002 from the one written (half a step ' +
    'of 1/255 in the red channel). The lab checks your code against the sheet\'s answer, so the sheet\'s ' +
    'code matches exactly; with the lab closed the page draws with the renderer\'s exact packing.';

  function build() {
    panel.innerHTML = `
  <div class="lab-head">
    <h2>Shader lab</h2>
    <button type="button" id="lab-close">Close the lab</button>
  </div>
  <p class="hint">Write any of the sheet's functions in GLSL ES 1.00:
    <code>vec4 packDepth(float z)</code>, <code>float unpackDepth(const in vec4 rgbaDepth)</code>,
    <code>float shadowTest(float zLight, float depth, float bias)</code> (1.0 lit, 0.0 shadowed) and
    <code>vec4 offset_lookup(sampler2D map, vec3 shadowCoord, vec2 offset)</code> (with
    <code>texmapscale</code>, one texel; the 4x4 PCF uses it: tick PCF above). The ones you leave out
    are the sheet's answer's. The picture
    above is drawn with your code as you type; <span id="lab-bias"></span></p>
  <div class="lab-grid">
    <div class="lab-edit">
      <div class="row">
        <button type="button" id="lab-reset">Reset</button>
        <button type="button" id="lab-answer">Show the sheet's answer</button>
        <span class="hint">Tab indents; Esc leaves the editor</span>
      </div>
      <div id="lab-editor"></div>
      <p id="lab-status" role="status" aria-live="polite"></p>
      <ul id="lab-problems" aria-label="Problems"></ul>
    </div>
    <div class="lab-check">
      <p id="lab-verdict" role="status" aria-live="polite">Not checked yet.</p>
      <div class="lab-images">
        <figure><canvas id="lab-student" width="${CHECK.width}" height="${CHECK.height}"></canvas>
          <figcaption>Your code</figcaption></figure>
        <figure><canvas id="lab-reference" width="${CHECK.width}" height="${CHECK.height}"></canvas>
          <figcaption>The sheet's answer</figcaption></figure>
        <figure><canvas id="lab-difference" width="${CHECK.width}" height="${CHECK.height}"></canvas>
          <figcaption>Difference (red: yours darker, green: lighter)</figcaption></figure>
      </div>
      <p class="readout">Differing pixels: <output id="lab-differing">–</output></p>
      <p class="readout">Error against the ray-traced truth: <output id="lab-truth">–</output></p>
      <p class="hint">The check frame: the visibility (white lit, black shadowed) at t = ${CHECK.time} s,
        ${CHECK.width} x ${CHECK.height} pixels, with the page's encoding, filter and map size and the lab's
        constant bias. Differing pixels: those whose visibility is not the sheet's answer's. The error against
        the truth: the mean of |your visibility - the ray-traced hard shadow's| over the pixels the truth
        can judge (not the background, the silhouettes or surfaces facing away from the light), in %
        (<code>penumbra truth --time ${CHECK.time} --size ${CHECK.width}x${CHECK.height}</code>).</p>
      <p class="hint" id="lab-packing">${PACKING_NOTE}</p>
    </div>
  </div>`;
    for (const id of ['lab-close', 'lab-reset', 'lab-answer', 'lab-editor', 'lab-status', 'lab-problems', 'lab-verdict',
                      'lab-student', 'lab-reference', 'lab-difference', 'lab-differing', 'lab-truth', 'lab-bias'])
      el[id] = document.getElementById(id);
    el['lab-close'].addEventListener('click', close);
    el['lab-reset'].addEventListener('click', () => editor.setValue(labText(0)));
    el['lab-answer'].addEventListener('click', () => editor.setValue(labText(1)));
  }

  function setStatus(text) {
    if (el['lab-status'] && el['lab-status'].textContent !== text) el['lab-status'].textContent = text;
  }

  // The problems: a marker in the gutter, the line's background and the message under it; those
  // naming no line in the list only.
  function showProblems(problems) {
    editor.operation(() => {
      for (const m of marks) {
        editor.removeLineClass(m.handle, 'background', 'lab-error-line');
        editor.setGutterMarker(m.handle, 'lab-errors', null);
        m.widget.clear();
      }
      marks = [];
      const list = el['lab-problems'];
      list.textContent = '';
      for (const p of problems) {
        const li = document.createElement('li');
        li.textContent = (p.line > 0 ? 'line ' + p.line + ': ' : '') + p.message;
        list.appendChild(li);
        if (!(p.line > 0)) continue;
        const line = Math.min(p.line, editor.lineCount()) - 1;
        const handle = editor.getLineHandle(line);
        const marker = document.createElement('span');
        marker.className = 'lab-error-marker';
        marker.textContent = '●';
        marker.title = p.message;
        editor.setGutterMarker(handle, 'lab-errors', marker);
        editor.addLineClass(handle, 'background', 'lab-error-line');
        const msg = document.createElement('div');
        msg.className = 'lab-error-message';
        msg.textContent = p.message;
        marks.push({ line: line + 1, handle, widget: editor.addLineWidget(handle, msg, { coverGutter: false }) });
      }
    });
  }

  function draw(canvas, rgba, width, height) {
    const ctx = canvas.getContext('2d');
    if (!rgba) {
      ctx.clearRect(0, 0, canvas.width, canvas.height);
      return;
    }
    canvas.width = width;
    canvas.height = height;
    ctx.putImageData(new ImageData(new Uint8ClampedArray(rgba), width, height), 0, 0);
  }

  // Mean |visibility - truth| over the truth's valid pixels, % (null when the sizes differ).
  function errorVsTruth(rgba, width, height) {
    if (!truth || !rgba || truth.vis.width !== width || truth.vis.height !== height) return null;
    let sum = 0, n = 0;
    for (let i = 0; i < width * height; ++i) {
      if (truth.mask.data[i] < 128) continue;
      sum += Math.abs(rgba[4 * i] - truth.vis.data[i]);
      ++n;
    }
    return n ? (100 * sum) / (255 * n) : null;
  }

  // The error against the truth of the last verdict's images (again once the truth has loaded).
  function showTruth() {
    const v = verdict;
    if (!v) return;
    v.truthPct = errorVsTruth(v.images[0], v.width, v.height);
    v.referenceTruthPct = errorVsTruth(v.images[1], v.width, v.height);
    el['lab-truth'].textContent = v.truthPct !== null
      ? v.truthPct.toFixed(2) + ' % (the sheet\'s answer: ' + v.referenceTruthPct.toFixed(2) + ' %)'
      : !v.compiles ? '–' : truthFailed ? 'the truth image did not load' : 'loading the truth…';
  }

  function check(text) {
    const v = runCheck(text);
    ++checks;
    // The module's verdict (render::lab_verdict): error, no-function, matches, mistake or differs.
    v.verdict = !v.compiles ? 'error' : v.verdict || 'differs';
    verdict = v;
    const out = el['lab-verdict'];
    out.dataset.verdict = v.verdict;
    out.dataset.mistake = v.mistake || '';
    if (v.verdict === 'error') {
      out.textContent = 'Not checked: ' + v.problems.map((p) => p.message).join('; ');
    } else if (v.verdict === 'no-function') {
      out.textContent = v.hint || 'No function of the sheet written.';
    } else if (v.verdict === 'matches') {
      out.textContent = v.hint || 'Matches the sheet\'s answer.';
    } else if (v.verdict === 'mistake') {
      out.textContent = 'Looks like a classic mistake (' + v.mistake + '): ' + v.hint;
    } else {
      out.textContent = v.hint || 'Differs from the sheet\'s answer.';
    }
    for (const [i, id] of [[0, 'lab-student'], [1, 'lab-reference'], [2, 'lab-difference']])
      draw(el[id], v.images[i], v.width, v.height);
    el['lab-differing'].textContent = v.compiles
      ? (+v.differingPct.toFixed(3)) + ' % of ' + v.width + ' x ' + v.height + ' pixels' : '–';
    showTruth();
    return v;
  }

  // Compiles the editor's text into the renderer's programs and keeps it; the check (up to ten
  // frames drawn and read back: seven took 0.7 s on SwiftShader, the compile 40 ms) follows once the typing
  // has paused a little longer, so a student who goes on typing is not held up by it.
  function compileNow() {
    clearTimeout(timer);
    timer = null;
    clearTimeout(checkTimer);
    checkTimer = null;
    const text = editor.getValue();
    kept = keep(text);
    const r = setSnippets(text);
    showProblems(r.problems);
    if (r.ok) {
      lastGood = text;
      setStatus('Compiled: the picture uses your code; checking…');
      checkTimer = setTimeout(() => {
        checkTimer = null;
        check(text);
        setStatus('Compiled: the picture uses your code.');
      }, CHECK_DELAY_MS);
    } else {
      setStatus(lastGood === null ? 'Not compiled: the picture has no code of yours yet.'
        : 'Not compiled: the picture keeps your last code that compiled (the check shows it too).');
    }
    return r;
  }

  // The page's settings changed (encoding, filter...): said, and the code compiled and checked again.
  function poll() {
    const json = M().UTF8ToString(M()._penumbra_lab_state());
    if (json === lastState) return;
    const first = lastState === '';
    lastState = json;
    const s = JSON.parse(json);
    el['lab-bias'].textContent = s.available
      ? 'it draws with the sheet\'s constant bias for ' + s.encoding + ', ' + (+s.bias.toPrecision(6)) + '.'
      : 'the lab is off for these settings: ' + s.refusal;
    openButton.classList.toggle('lab-refused', !s.available);
    if (!first && isOpen) compileNow();
  }

  async function ensureBuilt() {
    if (!built) {
      built = (async () => {
        await Promise.all([loadCss('lab/codemirror.css'), loadCss('lab/lab.css'), loadScript('lab/codemirror.js')]);
        await loadScript('lab/clike.js');  // the GLSL mode needs CodeMirror loaded
        build();
        Promise.all([loadImage('lab/truth-visibility.png'), loadImage('lab/truth-mask.png')]).then(([vis, mask]) => {
          truth = { vis, mask };
          showTruth();
        }).catch((e) => {
          truthFailed = true;
          showTruth();
          console.warn('penumbra lab: ' + e.message);
        });
      })();
    }
    return built;
  }

  let opening = false;
  async function open() {
    if (isOpen || opening) return;
    opening = true;
    try {
      await ensureBuilt();
    } finally {
      opening = false;
    }
    panel.hidden = false;
    openButton.setAttribute('aria-expanded', 'true');
    isOpen = true;
    const text = await startingText();
    M()._penumbra_lab_enable(1);
    if (!editor) {
      editor = window.CodeMirror(el['lab-editor'], {
        value: text, mode: 'x-shader/x-fragment', lineNumbers: true, indentUnit: 4,
        gutters: ['CodeMirror-linenumbers', 'lab-errors'], viewportMargin: Infinity,
        // Tab indents; Esc leaves the editor, so that Tab moves on from there (keyboard users).
        extraKeys: { Tab: (cm) => cm.replaceSelection('    '), Esc: (cm) => cm.getInputField().blur() },
      });
      editor.on('changes', () => {
        clearTimeout(timer);
        timer = setTimeout(compileNow, DEBOUNCE_MS);
      });
    } else {
      editor.setValue(text);
      editor.refresh();
    }
    lastState = '';
    poll();
    pollTimer = setInterval(poll, POLL_MS);
    compileNow();
    ready = true;
    panel.scrollIntoView({ block: 'nearest' });
  }

  function close() {
    if (!isOpen) return;
    isOpen = false;
    ready = false;
    clearTimeout(timer);
    timer = null;
    clearTimeout(checkTimer);
    checkTimer = null;
    clearInterval(pollTimer);
    M()._penumbra_lab_enable(0);
    panel.hidden = true;
    openButton.setAttribute('aria-expanded', 'false');
    dropHash();
    openButton.focus();
  }

  window.penumbraLab = {
    open,
    close,
    toggle: () => (isOpen ? close() : open()),
    // Open and the editor holding its text (the test hook waits for both).
    isOpen: () => isOpen && ready,
    editor: () => editor,
    // For tests: the text compiled now (not waiting for the debounce; its check follows), its result; the last
    // verdict; how many checks ran; the classic mistakes of the encoding in use; the module's state.
    compileNow: () => compileNow(),
    pending: () => timer !== null || checkTimer !== null,
    kept: () => kept,
    verdict: () => verdict && Object.assign({}, verdict, { images: undefined }),
    checks: () => checks,
    mistakes,
    state: labState,
    problems: () => marks.map((m) => ({ line: m.line })),
  };
})();
