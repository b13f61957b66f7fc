// The exercise pages' script: starts the page's WebGL module (NAME.js, NAME.wasm: its exercise's code alone),
// sizes the canvas's backing store to its CSS size x devicePixelRatio (at most 2048 a side),
// applies the URL's options, binds the controls, keeps the URL in step with them
// (history.replaceState), shows the status (context lost / restored, errors), the note of the last
// change (a value refused, or changed to one offered; it clears with the next good change),
// ms/frame, each pass's GPU time (where the browser has EXT_disjoint_timer_query), the first frame's
// time and the picture's size, and offers a small test hook,
// window.penumbra.
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
//   #fly with <button data-fly=MOVE>              the fly camera of an exercise with a scene of
//                                                 its own (the cascades and bulb pages; a press
//                                                 moves the state's camera.step metres): the buttons, keys on the
//                                                 focused canvas, a drag on it to look around; the
//                                                 camera goes into the URL (camera=x,y,z,yaw,pitch)
//   #cascade-plan                                 the last frame plan's cascade or cube face lines, where it has them
//                                                 (CourseApp::tile_lines: penumbra_tile_lines)
//   #lab-open, #lab                               the shader lab (W09P2c): lab/lab.js, loaded when the
//                                                 button is pressed or the address holds #lab=...
'use strict';

(function () {
  const exercise = document.body.dataset.exercise;
  const canvas = document.getElementById('canvas');
  const statusEl = document.getElementById('status');
  const msEl = document.getElementById('ms');
  const budgetRow = document.getElementById('budget-row'), budgetEl = document.getElementById('budget');
  const errorRow = document.getElementById('error-row'), errorEl = document.getElementById('error-target');
  const gpuEl = document.getElementById('gpu');
  const noteEl = document.getElementById('note');
  const firstEl = document.getElementById('first-frame');
  const readyEl = document.getElementById('ready');
  const pictureEl = document.getElementById('picture');
  const lostEl = document.getElementById('lost');
  const frameNoteEl = document.getElementById('frame-note');
  const MAX_SIDE = 2048; // the backing store's cap, a side
  const samplesRow = document.getElementById('samples-row');
  const samplesEl = document.getElementById('samples');
  const flyEl = document.getElementById('fly');
  const cameraEl = document.getElementById('camera');
  const planRow = document.getElementById('cascade-plan-row');
  const planEl = document.getElementById('cascade-plan');
  let api = null;
  let lastStatus = '';
  let firstFrameMs = null; // navigation start to the first frame drawn
  let readyMs = null; // navigation start to the scene whole (ready)
  let bound = false; // the controls bound and set from the module (after the first frame: start)
  let fixedSize = false; // the test hook set the backing store's size
  let capped = false;
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

  // The backing store follows the canvas's CSS size x devicePixelRatio, so the picture is drawn at
  // the screen's own resolution (a phone's 3x too), capped at MAX_SIDE a side. Done before the
  // module starts (the first frame is drawn at this size) and again whenever the size changes.
  function fitCanvas() {
    if (fixedSize) return;
    const r = canvas.getBoundingClientRect();
    if (!(r.width > 0 && r.height > 0)) return;
    const dpr = window.devicePixelRatio || 1;
    let w = Math.round(r.width * dpr);
    let h = Math.round(r.height * dpr);
    const k = Math.min(1, MAX_SIDE / Math.max(w, h));
    capped = k < 1;
    w = Math.max(1, Math.floor(w * k));
    h = Math.max(1, Math.floor(h * k));
    if (canvas.width !== w || canvas.height !== h) {
      canvas.width = w;
      canvas.height = h;
    }
    showPicture();
  }

  function showPicture() {
    const r = canvas.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    let text = canvas.width + ' x ' + canvas.height + ' pixels';
    if (fixedSize) text += ' (set by a test)';
    else if (dpr !== 1) text += ' (' + Math.round(r.width) + ' x ' + Math.round(r.height) + ' at ' + +dpr.toFixed(2) + 'x)';
    if (capped) text += ', capped at ' + MAX_SIDE + ' a side';
    pictureEl.textContent = text;
  }

  fitCanvas();
  if (window.ResizeObserver) new ResizeObserver(fitCanvas).observe(canvas);
  window.addEventListener('resize', fitCanvas);

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

  // Puts every control in the state the module holds (after the URL, a key, a clamp...); a box being
  // typed in keeps its text unless `force` (its value was refused: it shows the value in effect).
  function syncControls(force = false) {
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
        if (force || document.activeElement !== el) el.value = isFinite(+v) ? v : '';
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
      if (force || document.activeElement !== bias || mode !== 'fixed')
        bias.value = String(+(mode === 'fixed' ? s.bias : s.sheetBias).toPrecision(6));
    }
    const mapSize = document.querySelector('select[data-option="map-size"]');
    if (mapSize) {
      for (const opt of mapSize.options) opt.disabled = +opt.value > s.maxMapSize;
    }
    return s;
  }

  // A change's note: what was refused or changed; the next good change clears it.
  function setNote(text) {
    noteEl.textContent = text;
    noteEl.hidden = !text;
  }

  function apply(name, value) {
    const err = setOption(name, value);
    setNote(err ? 'not applied: ' + err : state().note);
    syncControls(err !== '');
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

  // Heckbert-Herf's progress: "24 of 256 (converging)" while light samples are being added.
  function samplesText(s) {
    if (!s.area) return '';
    const a = s.area;
    // Still and complete: the frame is the one already drawn; complete but moving: all drawn again.
    const how = a.done < a.total ? ' (converging)' : a.added === 0 ? ' (converged)' : '';
    return a.done + ' of ' + a.total + how;
  }

  // ---- the fly camera (an exercise with a scene of its own: the terrain, the room) -----------
  // A press moves 2 m (the room: 0.25 m) or turns 5 degrees (looks up or down 3); Shift: 10 times as
  // far (turns 4 times).
  const MOVES = {
    forward: [2, 0, 0, 0, 0], back: [-2, 0, 0, 0, 0], left: [0, -2, 0, 0, 0], right: [0, 2, 0, 0, 0],
    rise: [0, 0, 2, 0, 0], sink: [0, 0, -2, 0, 0], 'turn-left': [0, 0, 0, -5, 0], 'turn-right': [0, 0, 0, 5, 0],
    'look-up': [0, 0, 0, 0, 3], 'look-down': [0, 0, 0, 0, -3],
  };
  const FLY_KEYS = {
    KeyW: 'forward', ArrowUp: 'forward', KeyS: 'back', ArrowDown: 'back', KeyA: 'left', KeyD: 'right',
    ArrowLeft: 'turn-left', ArrowRight: 'turn-right', KeyE: 'rise', KeyQ: 'sink', KeyR: 'look-up', KeyF: 'look-down',
  };
  const DRAG_DEGREES = 0.25; // a CSS pixel of drag turns the view this much
  let urlTimer = null;

  function showCamera(s) {
    if (!cameraEl || !s.camera) return;
    const c = s.camera;
    const text = c.x.toFixed(1) + ', ' + c.y.toFixed(1) + ', ' + c.z.toFixed(1) + ' m, heading ' + c.yaw.toFixed(0) +
      '°, pitch ' + c.pitch.toFixed(0) + '°' + (c.moved ? '' : ' (the scene\'s camera)');
    if (cameraEl.textContent !== text) cameraEl.textContent = text;
  }

  // After a move: the readout at once, the URL a moment later (a drag moves the camera at every
  // mouse event; browsers limit how often a page may replace its URL).
  function cameraMoved(now = false) {
    showCamera(state());
    if (now) {
      clearTimeout(urlTimer);
      urlTimer = null;
      updateUrl();
    } else if (!urlTimer) {
      urlTimer = setTimeout(() => {
        urlTimer = null;
        updateUrl();
      }, 200);
    }
  }

  function flyBy(forward, right, up, yaw, pitch) {
    return Module._penumbra_fly(forward, right, up, yaw, pitch) === 1;
  }

  function flyMove(move, shift) {
    const m = MOVES[move];
    // MOVES are in 2 m steps (the terrain's); the room's camera moves its own step a press.
    const step = (state().camera || {}).step || 2;
    const k = (shift ? 10 : 1) * step / 2;
    const turn = shift ? 4 : 1;
    flyBy(m[0] * k, m[1] * k, m[2] * k, m[3] * turn, m[4] * turn);
    cameraMoved();
  }

  function bindFly() {
    if (!flyEl) return;
    for (const b of flyEl.querySelectorAll('button[data-fly]')) {
      b.addEventListener('click', (e) => {
        if (b.dataset.fly === 'reset') {
          Module._penumbra_reset_camera();
          cameraMoved(true);
        } else {
          flyMove(b.dataset.fly, e.shiftKey);
        }
      });
    }
    // The canvas takes the keys once clicked (or reached by Tab), and a drag on it looks around.
    canvas.tabIndex = 0;
    canvas.setAttribute('aria-describedby', 'fly-hint');
    canvas.addEventListener('keydown', (e) => {
      const move = FLY_KEYS[e.code];
      if (!move || e.ctrlKey || e.metaKey || e.altKey) return;
      e.preventDefault();
      flyMove(move, e.shiftKey);
    });
    let drag = null;
    canvas.addEventListener('pointerdown', (e) => {
      drag = { x: e.clientX, y: e.clientY };
      canvas.setPointerCapture(e.pointerId);
      canvas.focus();
    });
    canvas.addEventListener('pointermove', (e) => {
      if (!drag) return;
      const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
      drag = { x: e.clientX, y: e.clientY };
      if (dx || dy) {
        flyBy(0, 0, 0, dx * DRAG_DEGREES, -dy * DRAG_DEGREES);
        cameraMoved();
      }
    });
    const endDrag = () => { drag = null; };
    canvas.addEventListener('pointerup', endDrag);
    canvas.addEventListener('pointercancel', endDrag);
  }

  // The plan's cascade and cube face lines, from the last frame's plans (penumbra_tile_lines:
  // CourseApp::tile_lines): a pass per cascade ("cascade N: ... view depth A..B, texel T, ...") or
  // per cube face ("face +x: ... tile at (X, Y), ... depth A..B, N of M caster(s)"), a pass drawn
  // before and kept said "reused: ...", and the camera pass's cascades and blend, or the cube's faces drawn.
  function cascadePlan() {
    return Module.UTF8ToString(Module._penumbra_tile_lines());
  }

  // Each pass's median GPU ms, a line each (and in how many frames, where not in all: a shadow map
  // drawn once and reused), and their frames' total (state's gpu: null without a timer).
  function gpuText(s) {
    if (s.lost) return '– (no context)';
    const g = s.gpu;
    if (!g) return 'GPU timer: not available';
    if (!g.frames) return '–';
    return g.passes.map((p) => p.name + ' ' + p.ms.toFixed(2) + ' ms' +
      (p.frames < g.frames ? ' (' + p.frames + ' of ' + g.frames + ' frames)' : '')).join('\n') +
      '\ntotal ' + g.total.toFixed(2) + ' ms/frame';
  }

  function poll() {
    const s = state();
    showCamera(s);
    if (planRow) {
      const lines = cascadePlan();
      planRow.hidden = !lines;
      if (planEl.textContent !== lines) planEl.textContent = lines;
    }
    msEl.textContent = s.lost ? '– (no context)' : s.ms > 0 ? s.ms.toFixed(2) + ' ms/frame' : '–';
    const gpu = gpuText(s);
    if (gpuEl.textContent !== gpu) gpuEl.textContent = gpu;
    lostEl.hidden = !s.lost;
    // What the frame had to change for this canvas (W09P2b: a copy no larger than the canvas).
    if (frameNoteEl.textContent !== s.frameNote) frameNoteEl.textContent = s.frameNote;
    frameNoteEl.hidden = !s.frameNote;
    // budget-ms: the settings chosen, their time and the next map's, and the error the model
    // predicts for them against the truth (once it has measured the frame's shadow edges).
    budgetRow.hidden = !s.budget;
    const predicted = s.budget && s.budget.predictedErrorPct !== null
      ? '; predicted error ' + s.budget.predictedErrorPct.toFixed(3) + ' % of the truth' : '';
    const budget = s.budget ? s.budget.why + predicted : '–';
    if (budgetEl.textContent !== budget) budgetEl.textContent = budget;
    // max-error: the map chosen for the error target and the model's prediction, or why none can be.
    errorRow.hidden = !s.errorTarget;
    const target = s.errorTarget ? s.errorTarget.why : '–';
    if (errorEl.textContent !== target) errorEl.textContent = target;
    if (samplesRow) {
      samplesRow.hidden = !s.area;
      samplesEl.textContent = samplesText(s) || '–';
    }
    setStatus(s.status);
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
    // The controls are bound and set from the module's state once the first frame is painted, not
    // before it: that takes the main thread for 30 to 90 ms on a page's start here, and the first
    // frame needs none of it (the module holds its options, the URL's among them). The module's loop
    // asked for its animation frame in main(), before this one, so this callback runs after the
    // first frame's; the timeout lets that frame be painted first (docs/payload.md).
    requestAnimationFrame(() => setTimeout(() => {
      bindControls();
      bindFly();
      bindLab();
      syncControls();
      updateUrl();
      if (problems.length) {
        console.warn('penumbra: from the URL: ' + problems.join('; '));
        setNote('from the URL: ' + problems.join('; '));
      }
      poll();
      setInterval(poll, 250);
      bound = true;
    }, 0));
    watchFirstFrame();
    watchComplete();
  }

  // The module draws its first frame before the scene is whole (the marble's noise comes after it:
  // examples/course_web.cpp); the page is ready, for a student and for the tests, once it is and
  // its controls are bound (start).
  function watchComplete() {
    if (bound && Module._penumbra_scene_complete()) {
      readyMs = performance.now();
      readyEl.textContent = Math.round(readyMs) + ' ms';
      resolveReady();
      return;
    }
    requestAnimationFrame(watchComplete);
  }

  // The first frame: the module's loop draws in an animation frame callback registered before this
  // one, so the first callback that sees a frame counted runs just after it was drawn (and waited
  // for: the module reads a pixel back).
  function watchFirstFrame() {
    if (Module._penumbra_frame_count() > 0) {
      firstFrameMs = performance.now();
      firstEl.textContent = Math.round(firstFrameMs) + ' ms';
      console.log('penumbra: first frame ' + firstFrameMs.toFixed(0) + ' ms after navigation start');
      return;
    }
    requestAnimationFrame(watchFirstFrame);
  }

  // The shader lab (docs/pages.md): its script, editor and style are loaded only when the button is
  // pressed or the address holds #lab=... (lab/lab.js fills #lab), so a page that never opens it
  // downloads and runs none of it.
  const labButton = document.getElementById('lab-open');
  let labLoaded = null;
  function lab() {
    if (!labLoaded) {
      labLoaded = new Promise((resolve, reject) => {
        const s = document.createElement('script');
        s.src = 'lab/lab.js';
        s.onload = () => resolve(window.penumbraLab);
        s.onerror = () => reject(new Error('lab/lab.js did not load'));
        document.head.appendChild(s);
      });
    }
    return labLoaded;
  }
  function bindLab() {
    if (!labButton) return;
    labButton.addEventListener('click', () => lab().then((l) => l.toggle()));
    if (/^#lab=/.test(location.hash)) lab().then((l) => l.open());
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
    // At the backing store's size now: the loop's last frame may predate a setCanvasSize (a slow
    // page's frame had not run since, and renderNow drew at the old size: web.context_loss once
    // read 748x748 after setting 512x512).
    renderNow: () => Module._penumbra_render_now(canvas.width, canvas.height) === 1,
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
    // The fly camera: metres forward, right, up, then degrees of yaw and pitch; the URL follows
    // at once. False where the page has no fly camera.
    fly: (forward, right, up, yaw, pitch) => {
      const ok = flyBy(forward, right, up, yaw, pitch);
      cameraMoved(true);
      return ok;
    },
    resetCamera: () => {
      Module._penumbra_reset_camera();
      cameraMoved(true);
    },
    // The shader lab's object (lab/lab.js: window.penumbraLab), loaded if it was not: a promise.
    lab: () => lab(),
    // The first frame's time after navigation start (ms), null until it is drawn.
    firstFrameMs: () => firstFrameMs,
    // The time the scene was whole (the marble made, window.penumbra.ready resolved), null until then.
    readyMs: () => readyMs,
    // Fixes the backing store at w x h pixels (the tests compare with 512x512 renders); no
    // arguments: back to following the CSS size x devicePixelRatio.
    setCanvasSize: (w, h) => {
      fixedSize = w > 0 && h > 0;
      if (fixedSize) {
        canvas.width = w;
        canvas.height = h;
        capped = false;
        showPicture();
      } else {
        fitCanvas();
      }
    },
  };
})();
