// The exercise pages' script: starts the WebGL module (penumbra.js) for the page's exercise,
// applies the URL's options, binds the controls, keeps the URL in step with them
// (history.replaceState), shows ms/frame and the status (context lost / restored, errors), and
// offers a small test hook, window.penumbra.
//
// The controls are generated with the page (web/pages.py, from examples/exercise_list.cpp and the
// option table); each carries data-option="NAME" (the option names of `penumbra render` and the URL):
//   <select data-option>                          the selected value
//   <button data-option aria-pressed>             on / off
//   <input type=checkbox data-option data-on data-off>  data-on when checked, data-off otherwise
//   <input type=radio name=NAME data-option>      the checked radio's value
//   <input type=range|number data-option>         the number (a slider and its box, kept in step)
//   #bias + radios name=bias-mode                 default (the encoding's), auto, or the number
//                                                 in #bias (fixed)
'use strict';

(function () {
  const exercise = document.body.dataset.exercise;
  const canvas = document.getElementById('canvas');
  const statusEl = document.getElementById('status');
  const msEl = document.getElementById('ms');
  const samplesRow = document.getElementById('samples-row');
  const samplesEl = document.getElementById('samples');
  let api = null;
  let lastStatus = '';
  let note = null; // {text, until}: a problem with the URL or a control, shown beside the status
  let resolveReady;
  let rejectReady;
  const ready = new Promise((resolve, reject) => {
    resolveReady = resolve;
    rejectReady = reject;
  });

  function setStatus(text) {
    if (text !== lastStatus) {
      statusEl.textContent = text;
      lastStatus = text;
    }
  }

  window.Module = {
    canvas: canvas,
    arguments: ['--exercise', exercise],
    print: (text) => console.log(text),
    // The module writes to stderr only when something failed.
    printErr: (text) => console.error(text),
    postRun: [start],
    onAbort: (what) => {
      setStatus('error: the WebGL module stopped: ' + what);
      rejectReady(new Error(String(what)));
    },
  };

  function state() {
    return JSON.parse(Module.UTF8ToString(Module._penumbra_state()));
  }

  function setOption(name, value) {
    if (api.setOption(name, String(value))) return '';
    return api.lastError();
  }

  function updateUrl() {
    const query = api.query();
    const url = location.pathname + (query ? '?' + query : '') + location.hash;
    if (url !== location.pathname + location.search + location.hash) history.replaceState(null, '', url);
  }

  // Puts every control in the state the module holds (after the URL, a key, a clamp...).
  function syncControls() {
    const s = state();
    const o = s.options;
    for (const el of document.querySelectorAll('[data-option]')) {
      const name = el.dataset.option;
      if (!(name in o)) continue;
      const v = o[name];
      if (el.tagName === 'SELECT') {
        el.value = v;
      } else if (el.tagName === 'BUTTON') {
        const on = v === 'on';
        el.setAttribute('aria-pressed', on ? 'true' : 'false');
        el.querySelector('.state').textContent = on ? 'on' : 'off';
      } else if (el.type === 'checkbox') {
        el.checked = v === el.dataset.on;
      } else if (el.type === 'radio') {
        el.checked = el.value === v;
      } else if (el.type === 'range' || el.type === 'number') {
        // A number (the light's radius): a word (scene) leaves the box empty, the slider at its start.
        if (document.activeElement !== el) el.value = isFinite(+v) ? v : '';
        if (el.type === 'number') el.placeholder = isFinite(+v) ? '' : v;
      }
    }
    const enc = document.querySelector('select[data-option="encoding"]');
    if (enc) {
      const opt = enc.querySelector('option[value="depthtex"]');
      opt.dataset.label = opt.dataset.label || opt.textContent;
      opt.disabled = !s.depthTexture;
      opt.textContent = s.depthTexture ? opt.dataset.label : 'depth texture (needs WEBGL_depth_texture)';
    }
    const bias = document.getElementById('bias');
    if (bias) {
      // bias=auto|sheet|a number: the mode's radio, and the number box only for a fixed value
      // (it shows the sheet's constant for the encoding otherwise, the value a switch to fixed starts from).
      const mode = o.bias === 'sheet' || o.bias === 'auto' ? o.bias : 'fixed';
      for (const r of document.querySelectorAll('input[name="bias-mode"]')) r.checked = r.value === mode;
      document.getElementById('bias-sheet-value').textContent = String(+s.sheetBias.toPrecision(6));
      const autoValue = document.getElementById('bias-auto-value');
      if (autoValue) autoValue.textContent = String(+s.autoBias.toPrecision(2));
      bias.disabled = mode !== 'fixed';
      if (document.activeElement !== bias || mode !== 'fixed')
        bias.value = String(+(mode === 'fixed' ? s.bias : s.sheetBias).toPrecision(6));
    }
    const mapSize = document.querySelector('select[data-option="map-size"]');
    if (mapSize) {
      for (const opt of mapSize.options) opt.disabled = +opt.value > s.maxMapSize;
    }
    return s;
  }

  function apply(name, value) {
    const err = setOption(name, value);
    if (err) showNote('not applied: ' + err);
    syncControls();
    updateUrl();
    return err;
  }

  function bindControls() {
    for (const el of document.querySelectorAll('[data-option]')) {
      const name = el.dataset.option;
      if (el.tagName === 'BUTTON') {
        el.addEventListener('click', () => apply(name, el.getAttribute('aria-pressed') === 'true' ? 'off' : 'on'));
      } else if (el.type === 'checkbox') {
        el.addEventListener('change', () => apply(name, el.checked ? el.dataset.on : el.dataset.off));
      } else if (el.type === 'range') {
        // Dragging sets it as it goes (the other box follows); the keys' steps too.
        el.addEventListener('input', () => apply(name, el.value));
      } else if (el.type === 'number') {
        el.addEventListener('change', () => {
          if (el.value !== '') apply(name, el.value);
        });
      } else {
        el.addEventListener('change', () => apply(name, el.value));
      }
    }
    const bias = document.getElementById('bias');
    if (bias) {
      bias.addEventListener('change', () => {
        if (bias.value !== '') apply('bias', bias.value);
      });
      for (const r of document.querySelectorAll('input[name="bias-mode"]')) {
        r.addEventListener('change', () => {
          if (r.checked) apply('bias', r.value === 'fixed' ? bias.value || String(state().sheetBias) : r.value);
        });
      }
    }
  }

  function showNote(text) {
    note = { text: text, until: performance.now() + 8000 };
    poll();
  }

  // Heckbert-Herf's progress: "24 of 256 (converging)" while light samples are being added.
  function samplesText(s) {
    if (!s.area) return '';
    const a = s.area;
    // Still and complete: the frame is the one already drawn; complete but moving: all drawn again.
    const how = a.done < a.total ? ' (converging)' : a.added === 0 ? ' (converged)' : '';
    return a.done + ' of ' + a.total + how;
  }

  function poll() {
    const s = state();
    msEl.textContent = s.frames > 0 ? s.ms.toFixed(2) + ' ms/frame' : '–';
    if (samplesRow) {
      samplesRow.hidden = !s.area;
      samplesEl.textContent = samplesText(s) || '–';
    }
    let text = s.status;
    if (note && performance.now() < note.until) text += ' — ' + note.text;
    setStatus(text);
  }

  function start() {
    api = {
      setOption: Module.cwrap('penumbra_set_option', 'number', ['string', 'string']),
      setQuery: Module.cwrap('penumbra_set_query', 'string', ['string']),
      lastError: () => Module.UTF8ToString(Module._penumbra_last_error()),
      query: () => Module.UTF8ToString(Module._penumbra_query()),
    };
    // The URL's query is read by the module (examples/query.h: decoded, checked, each pair through
    // set_option); what it refused comes back as notes, one a line. A query longer than the module
    // reads (8192 bytes) is cut just past that, so the module notes it rather than the page copying
    // a huge URL onto the wasm stack.
    const search = location.search.length > 8194 ? location.search.slice(0, 8194) : location.search;
    const notes = api.setQuery(search);
    const problems = notes ? notes.split('\n') : [];
    bindControls();
    syncControls();
    updateUrl();
    if (problems.length) {
      console.warn('penumbra: ignored from the URL: ' + problems.join('; '));
      showNote('ignored from the URL: ' + problems.join('; '));
    }
    poll();
    setInterval(poll, 250);
    resolveReady();
  }

  function toBase64(bytes) {
    let s = '';
    for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(s);
  }

  // The test hook: fixed time, frames on demand, pixels, GL errors.
  window.penumbra = {
    ready: ready,
    state: state,
    setTime: (t) => Module._penumbra_set_time(t),
    pause: () => Module._penumbra_pause(1),
    resume: () => Module._penumbra_pause(0),
    frameCount: () => Module._penumbra_frame_count(),
    // Draws a frame now (at the current time), outside the animation loop.
    renderNow: () => Module._penumbra_render_now(0, 0) === 1,
    // The canvas's pixels, RGBA, top row first.
    readPixels: () => {
      const p = Module._penumbra_read_pixels();
      if (!p) return null;
      const w = Module._penumbra_width();
      const h = Module._penumbra_height();
      return { width: w, height: h, data: Module.HEAPU8.slice(p, p + w * h * 4) };
    },
    readPixelsBase64: () => {
      const px = window.penumbra.readPixels();
      return px && { width: px.width, height: px.height, data: toBase64(px.data) };
    },
    glError: () => Module._penumbra_gl_error(),
    // As a control would: sets the option, updates the controls and the URL; '' or the problem.
    setOption: (name, value) => apply(name, value),
    query: () => api.query(),
    plan: () => Module.UTF8ToString(Module._penumbra_plan()),
  };
})();
