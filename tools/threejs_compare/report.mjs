// threejs_compare's outputs: results.csv (the columns of results/bench/results.csv, so `penumbra
// bench --from-csv` reads it), and the Markdown: the table it prints and docs/threejs.md. The score
// columns in both come from the score table (`penumbra truth --score-columns`).
import { writeFileSync } from 'node:fs';
import { MAP, SIZE, f2, oursOptions, tname } from './config.mjs';

// Rows with the columns of results/bench/results.csv (`penumbra bench --from-csv` reads them), one per
// frame and technique; the times are the browser's (SwiftShader), not llvmpipe's: do not merge
// them with the EGL bench's rows into one plot.
export function writeCsv(file, columns, rows, env) {
  const head = ['scene,time,width,height,technique,encoding,filter,map_size', ...columns.map((c) => c.key),
                'ms_moving,ms_still,frames,settings'].join(',');
  const cell = (c, v) => (v === null || v === undefined ? '' : v.toFixed(c.digits));
  const lines = [head];
  for (const r of rows)
    for (const p of r.per) {
      const technique = r.kind === 'ours' ? `${r.c.encoding} ${r.c.filter}` : `three.js-${r.c.type}-${r.id.split('-').pop()} ${r.c.type === 'basic' ? 'hard' : 'pcf'}`;
      const settings = r.kind === 'ours' ? `w09p2c.html?${new URLSearchParams(oursOptions(r.c))}`
        : `three.js r${env.threeInfo?.revision} ${r.c.type === 'basic' ? 'BasicShadowMap' : 'PCFShadowMap'} bias=${r.c.bias} shadowSide=${r.c.shadowSide} mapSize=${MAP}`;
      lines.push([`course@${tname(p.t)}`, p.t.toFixed(3), SIZE, SIZE, technique, r.kind === 'ours' ? r.c.encoding : 'three.js',
                  r.kind === 'ours' ? r.c.filter : r.c.type, r.kind === 'ours' ? r.c.map : MAP, ...columns.map((c) => cell(c, p.score[c.key])),
                  r.ms.toFixed(3), '', '', `"${settings}"`].join(','));
    }
  writeFileSync(file, lines.join('\n') + '\n');
}

// The Markdown tables' score columns: those the score table shows in tables (table_digits >= 0)
// that some row has (the area-light error never here: no area-light truth).
export function tableColumns(columns, rows) {
  return columns.filter((c) => c.table_digits >= 0 && rows.some((r) => r.score[c.key] !== null && r.score[c.key] !== undefined));
}

export function markdown(o, env, columns, rows, cameraCheck, frustum, summary, agreement) {
  const times = o.times.map((t) => `t = ${t}`).join(', ');
  const shown = tableColumns(columns, rows);
  const fmt = (c, v) => (v === null || v === undefined || Number.isNaN(v) ? 'n/a' : v.toFixed(c.table_digits));
  const head = `| renderer | technique | ${shown.map((c) => c.heading).join(' | ')} | ms/frame (rounds: min-max) | ours / three.js defaults, same filter | error (and PCF's mean abs error) <= three.js's |\n` +
               `|---|---|${shown.map(() => '---:|').join('')}---:|---:|---|`;
  const line = (r) => {
    const renderer = r.kind === 'ours' ? 'penumbra (WebGL 1)' : `three.js r${env.threeInfo?.revision} (WebGL 2)`;
    const tech = r.kind === 'ours' ? r.label : r.label.replace('three.js ', '');
    const ratio = r.ratioThree !== undefined ? f2(r.ratioThree) : '';
    const ratioD = r.notWorse !== undefined ? (r.notWorse ? 'yes' : 'no') : '';
    const spread = r.msRounds.length > 1 ? ` (${f2(Math.min(...r.msRounds))}-${f2(Math.max(...r.msRounds))})` : '';
    return `| ${renderer} | ${tech} | ${shown.map((c) => fmt(c, r.score[c.key])).join(' | ')} | ${f2(r.ms)}${spread} | ${ratio} | ${ratioD} |`;
  };
  const table = [
    `The course scene at ${SIZE}x${SIZE}, shadow map ${MAP}, mean over ${times}; ms/frame: median over ` +
    `${o.rounds} round(s) of ${o.frames} moving frames per time; headless Chromium, SwiftShader, ${env.cores} cores ` +
    `(1-minute load average ${env.load[0].toFixed(1)} before the run; the run itself keeps both cores busy).`,
    '', head, ...rows.map(line), ''].join('\n');
  const std = rows.filter((r) => r.msStandard !== null)
    .map((r) => `| ${r.label} | ${f2(r.ms)} | ${f2(r.msStandard)} |`).join('\n');
  const perTime = ['| technique | ' + o.times.map((t) => `t = ${t}: error % / mae %`).join(' | ') + ' |',
                   '|---|' + o.times.map(() => '---:').join('|') + '|',
                   ...rows.map((r) => `| ${r.kind === 'ours' ? 'penumbra ' + r.label : r.label} | ` +
                     r.per.map((p) => `${f2(p.score.error_pct)} / ${f2(p.score.mae_pct)}`).join(' | ') + ' |')].join('\n');
  const cam = ['| t | penumbra --scene teapot: error % (valid px) | penumbra --scene exported.gltf: error % (valid px) | pixels that differ |',
               '|---:|---:|---:|---:|',
               ...cameraCheck.map((c) => `| ${c.t} | ${f2(c.teapot.error_pct)} (${c.teapot.valid_pixels}) | ${f2(c.gltf.error_pct)} (${c.gltf.valid_pixels}) | ${c.differing} |`)].join('\n');
  const agree = ['| three.js | penumbra | ' + o.times.map((t) => `t = ${t}: pixels > 8 levels apart (mean abs diff, levels)`).join(' | ') + ' |',
                 '|---|---|' + o.times.map(() => '---:').join('|') + '|',
                 ...agreement.map((g) => `| ${byLabel(rows, g.a).replace('three.js ', '')} | ${g.b.replace('-', ' ')} | ` +
                   g.per.map((p) => `${p.differing} (${p.meanLevels.toFixed(3)})`).join(' | ') + ' |')].join('\n');
  const basicMax = Math.max(...agreement[0].per.map((p) => p.differing));
  const basicSame = basicMax === 0;
  const win = frustum && frustum.window ? frustum.window : frustum ? [-frustum.tanX, frustum.tanX, -frustum.tanY, frustum.tanY] : null;
  const fr = frustum ? `at t = ${frustum.t}: the light at (${frustum.position.map((v) => v.toFixed(3)).join(', ')}), ` +
    `aimed at (${frustum.aim.map((v) => v.toFixed(3)).join(', ')}), the window's tangents ${win[0].toFixed(4)} .. ${win[1].toFixed(4)} x ` +
    `${win[2].toFixed(4)} .. ${win[3].toFixed(4)} (spot angle ${frustum.angleDeg.toFixed(2)} degrees, shadow.aspect ` +
    `${(frustum.tanX / frustum.tanY).toFixed(4)}), near ${frustum.near.toFixed(4)}, far ${frustum.far.toFixed(4)}` +
    (frustum.tight === false ? ' (the fit around the whole scene: penumbra\'s fallback)' : '') : '';
  const doc = `# three.js side by side

The course scene (the teapot on the marble table under the circling point light), exported by
\`penumbra export\` at fixed times, rendered by **three.js** (its GLTFLoader, the same triangles,
camera and light) and by **penumbra's web build** (the W09P2c page) in the same headless Chromium,
at the same canvas size (${SIZE}x${SIZE}) and shadow-map size (${MAP}); both visibility images scored
against the same Embree ground truth with the same metric code (\`penumbra truth --score --json\`, see
[tradeoffs.md](tradeoffs.md) for the truth, the validity mask and the metrics).

## Regenerating

\`\`\`sh
node tools/threejs_compare.mjs            # about ${Math.max(1, Math.round(env.seconds / 60))} min; prints the table, writes this file and out/threejs/
node tools/threejs_compare.mjs --quick --check --no-doc   # what the web.threejs test runs (t = 0.6, 5 frames, the default rows)
\`\`\`

It builds nothing: it uses \`build/penumbra\` (export, truth, render), \`build-web/site\` (the W09P2c
page) and \`node_modules\` (\`npm ci\`: playwright-core, pngjs, three). Options: \`--times\`,
\`--frames\`, \`--rounds\`, \`--out-dir\`, \`--doc\` / \`--no-doc\`, \`--cli\`, \`--from-json FILE\` (measure
nothing: the table and this file again from a run's \`results.json\`). Every image it scored
is in \`out/threejs/images/\`, every figure in \`out/threejs/results.json\`, and one row per frame
and technique with the columns of \`results/bench/results.csv\` in \`out/threejs/results.csv\`
(\`penumbra bench --from-csv out/threejs/results.csv --out-dir DIR\` plots them; the times are
SwiftShader's, so do not merge them with the EGL bench's rows). The three.js page is
\`tests/threejs/compare.html\` + \`compare.js\`; the tool serves it, \`node_modules/three\` and the
exported scenes from the same 127.0.0.1 server as the site.

## Results

Measured on ${env.date} by \`node tools/threejs_compare.mjs\` (${env.seconds} s): ${env.chromium}, headless,
WebGL through ANGLE on SwiftShader (\`${env.threeInfo?.renderer}\`), ${env.cores} cores (${env.cpu});
three.js ${env.threeVersion} (r${env.threeInfo?.revision}) on ${env.threeInfo?.version}, penumbra's W09P2c page on WebGL 1.

${table}
The ratios compare each three.js row with penumbra's rgba (and depthtex) encoding and the same
kind of filter (BasicShadowMap with \`hard\`, PCFShadowMap with \`pcf4x4\`). *defaults*: three.js as it
comes (\`shadow.bias\` 0, \`normalBias\` 0, \`shadowSide\` null, i.e. the back faces of a FrontSide
material into the map). *matched*: the sheet's bias (0.0015, three.js's sign) and both faces into
the map, as penumbra draws them with \`--bias sheet --map-faces both\`. three.js's rows use penumbra's
tight light frustum (around the receivers in view); penumbra's rows its default, the shadows fit (the
window cut to where the casters' shadows can fall), unless the row says otherwise.

What the figures say:

${findings(rows, agreement, basicSame, basicMax)}

Colour frames with three.js's MeshStandardMaterial as GLTFLoader makes it (physically based),
against the MeshPhongMaterial (Blinn-Phong, closest to penumbra's shading) used above:

| three.js | ms/frame, MeshPhongMaterial | ms/frame, MeshStandardMaterial |
|---|---:|---:|
${std}

Error % / mean absolute error % per frame:

${perTime}

**Matched, the two shadow maps see the same thing.** With penumbra's frustum, bias and faces, three.js's
BasicShadowMap and penumbra's hard filter give ${basicSame ? 'the same visibility image, pixel for pixel' :
  `nearly the same visibility image (at most ${basicMax} of ${SIZE * SIZE} pixels apart)`} (the PCF
kernels differ, see below):

${agree}

**The exported camera is penumbra's camera.** penumbra's own EGL render (rgba hard) of the
exported glTF and of the built-in course scene, scored against the same truth:

${cam}

## How it is measured

- **The scene.** \`penumbra export --scene teapot --time T\`: the same ${summary ? summary.triangles : '6322'} triangles
  (the teapot at penumbra's default tessellation, the table quad: three.js's own TeapotGeometry is
  not used), the camera (yfov 45 degrees, aspect 1, near 0.1, far 30) and the point light
  (\`KHR_lights_punctual\`). three.js loads it with GLTFLoader; the ground truth ray-traces
  penumbra's built-in scene at the same t and reads penumbra's camera, which the table above shows
  to be the exported one.
- **The light.** penumbra draws the point light's shadows with one 2D perspective map fitted
  tightly to what the camera sees: aimed from the light at the receivers in view, an asymmetric
  frustum around them, the near plane at the nearest caster that reaches into it
  (\`shadow::fit_light_frustum_tight\`). A three.js PointLight would use a cube map (six passes, a
  cube depth texture), so three.js gets a SpotLight at the light's position whose shadow camera is
  exactly penumbra's frustum, fitted by the same steps in double (\`tests/threejs/compare.js\`):
  the same aim and up vector, angle = atan(tan_y) and \`shadow.aspect\` = tan_x / tan_y over the
  symmetric frame around the axis, the window a view offset inside it
  (\`PerspectiveCamera.setViewOffset\`), the same near and far, refitted every frame from the moved
  teapot's bounds as penumbra refits it (${fr}). Its cone lights the receivers in view (the
  visibility images do not depend on it).
- **Visibility.** penumbra: the page's \`aov=visibility\` (255 lit, 0 shadowed, PCF fractions
  between). three.js: a second render in which every mesh gets a \`ShadowMaterial\` of opacity 1 on
  a white background; it outputs alpha = 1 - visibility, and blending (one minus source alpha,
  zero) writes 255 x visibility into the pixel, replacing rather than compositing over what is
  behind it (so the lit teapot in front of the shadowed table reads as lit). Read back with
  \`readPixels\`, flipped to top row first, scored by \`penumbra truth --score --json\` as any PNG.
- **Time.** ms per colour frame (penumbra: W09P2c with the map view off; three.js: the loaded scene
  with MeshPhongMaterial, a spot light and an ambient light), each frame drawn and then waited for
  by a one-pixel \`readPixels\` (WebGL's \`finish()\` only flushes in Chromium), clocked with
  \`performance.now()\` in the page around the draw and the readback. The light and the teapot move
  every frame (t + k/60: penumbra's \`setTime\`; three.js gets the same frames' node matrices and
  light position from \`penumbra export\`, set outside the clock), so both redraw the shadow map
  every frame. One page of each, switched between configurations; penumbra's own animation loop is
  paused (\`Module.pauseMainLoop()\`), so only the timed frames draw. ${o.rounds} round(s); in each,
  for each time, every configuration in turn, penumbra's and three.js's alternating: 3 warm-up
  frames, then ${o.frames} frames. A round's figure is the median over its frames, the reported one the
  median of the rounds' (min-max beside it); a ratio is the median of the rounds' ratios.
  \`performance.now()\` is coarsened to 0.1 ms in a page that is not cross-origin isolated: each
  frame's time is a multiple of 0.1 ms, and the medians of many frames carry that grain.
  SwiftShader is a CPU rasteriser: fill rate and shader length dominate, and other jobs on the
  ${env.cores} cores (the load average before the run is given above the table) slow whichever
  configuration runs at that moment.

## What still differs

- **WebGL 2 against WebGL 1.** three.js renders only through WebGL 2 since r163
  (${env.threeInfo?.version}, ${env.threeInfo?.glsl}); penumbra's page is WebGL 1 (GLSL ES 1.00).
  The two run on the same SwiftShader in the same browser, but with different shader languages and
  API paths (three.js: a depth texture, and \`sampler2DShadow\` with hardware comparison for PCF;
  penumbra: a depth encoding of WebGL 1 or \`WEBGL_depth_texture\`).
- **Depth storage and precision.** three.js's map is a 24-bit depth texture (\`DepthTexture\`,
  UnsignedIntType); penumbra's rgba packs the depth into an RGBA8 colour target (exact to 2^-24 under
  highp, the same scores as its depthtex), r8 keeps 8 bits. Both compare in window depth [0, 1] over
  the same near and far planes, so the same bias means the same offset. Both run highp here
  (SwiftShader computes mediump at fp32 anyway).
- **Bias.** three.js's defaults are \`bias\` 0 and \`normalBias\` 0; penumbra's default is \`auto\`
  (a constant of the encoding's precision plus a term that grows with the slope of the receiver as
  the light sees it); the sheet's constant (0.0015, 0.005 for r8) is \`--bias sheet\`, and the
  *matched* rows give it to three.js. \`normalBias\` stays 0 (penumbra has no normal offset).
- **Faces in the map.** three.js draws a FrontSide material's back faces into the map
  (\`shadowSide\` null), which moves the acne to the faces turned away from the light (left out of
  the score) and can leak light where a caster is thin or open, or touches a receiver (nothing
  measurable on this scene, see t = 0); penumbra (\`--map-faces auto\`) draws the back faces of a
  closed mesh and both faces of an open one (the Newell teapot is open and must cast from both
  sides; the table top is one face). *matched* sets \`shadowSide = DoubleSide\`.
- **The PCF kernels.** penumbra's pcf4x4: 16 NEAREST taps in a 4x4 box at +-0.5 and +-1.5 texels,
  equal weights (17 levels of grey). three.js r${env.threeInfo?.revision}'s PCFShadowMap: 5 taps on a Vogel disk of radius
  \`shadow.radius\` (1 texel), rotated per pixel by interleaved gradient noise, each a hardware 2x2
  bilinear comparison (LinearFilter on a compare texture): a footprint of at most about 4 texels
  across, weighted towards its centre (penumbra's: 4 texels, equal weights), with smoother and
  noisier greys. (PCFSoftShadowMap is gone from three.js; VSMShadowMap is
  not compared.) BasicShadowMap is one NEAREST tap, as penumbra's hard filter.
- **The light type.** A spot light with penumbra's frustum instead of a point light, as above; the
  shadow test is the same map over the same frustum, but the lighting of the colour frames differs
  (the spot's cone, three.js's physically based units with decay 0 and intensity 1), which changes
  nothing in visibility.
- **Shading and colour.** The timing renders colour frames: three.js with MeshPhongMaterial
  (MeshStandardMaterial also given), an ambient light, sRGB output and no tone mapping;
  penumbra with its Blinn-Phong marble and porcelain. The visibility images carry no colour
  management or tone mapping that matters: ShadowMaterial's white stays white and the grey is the
  blend factor.
- **The frame loop.** three.js's \`render()\` walks its scene graph, sorts, updates uniforms and
  redraws its shadow map every frame (\`shadowMap.autoUpdate\`), whatever moved; penumbra redraws
  its map only when the light or a caster moved (here they always do) and does its frustum fit and
  the scene's animation inside the clock (three.js's refit and node updates are outside it).
- **Culling and antialiasing.** Both canvases have no antialiasing, a depth and a stencil buffer,
  a preserved drawing buffer. three.js's frustum culling is off (penumbra leaves out of its map the
  casters outside the light's window, which changes no pixel of the map); the camera
  pass draws front faces in three.js (FrontSide), as the truth sees them.
`;
  return { table, doc };
}

// A few sentences drawn from the figures, so that they stay true when the tool is run again.
function findings(rows, agreement, basicSame, basicMax) {
  const r = Object.fromEntries(rows.map((x) => [x.id, x]));
  const pct = (x) => `${f2(x)} %`;
  const out = [];
  out.push(`- **Matched, three.js's BasicShadowMap is penumbra's hard filter**: ${basicSame ? 'the same pixels' : `the same pixels but ${basicMax} (of ${SIZE * SIZE}) in a frame`}, ` +
    `error ${pct(r['three-basic-matched'].score.error_pct)} against ${pct(r['depthtex-hard-matched'].score.error_pct)} (the sheet's bias, both faces, ` +
    'the tight light frustum in both). The frames, the camera, the light frustum ' +
    'and the depth test agree; what separates the other rows is settings, the filter kernels and the cost.');
  const hard = r['rgba-hard'], pcf = r['rgba-pcf4x4'], tb = r['three-basic-default'], tp = r['three-pcf-default'];
  out.push(`- **Accuracy at the defaults**: penumbra's rgba hard ${pct(hard.score.error_pct)} against three.js's BasicShadowMap ` +
    `${pct(tb.score.error_pct)} (before issue 9: ${pct(r['rgba-hard-sheet'].score.error_pct)}); rgba pcf4x4 ${pct(pcf.score.error_pct)} ` +
    `(mean abs ${pct(pcf.score.mae_pct)}) against PCFShadowMap ${pct(tp.score.error_pct)} (${pct(tp.score.mae_pct)}). ` +
    'The bias that follows the slope (auto) removes the teapot\'s acne without three.js\'s back faces, and the shadows ' +
    `fit puts the map's texels where shadows can fall (the tight fit, given to three.js too: ${pct(r['rgba-hard-tight'].score.error_pct)}).`);
  const cmp = (x) => (x > 1.05 ? 'slower' : x < 0.95 ? 'faster' : 'about as fast');
  const timeLine = (x) => `${x.label} ${f2(x.ms)} ms (${f2(x.ratioThree)}x three.js's, error ${x.notWorse ? '<=' : '>'} three.js's)`;
  out.push(`- **Time** (ours / three.js's defaults with the same kind of filter, median of the rounds' ratios): ` +
    `${timeLine(hard)}: ${cmp(hard.ratioThree)}; ${timeLine(pcf)}: ${cmp(pcf.ratioThree)}; ` +
    `${timeLine(r['rgba-hard-512'])}; ${timeLine(r['rgba-pcf4x4-512'])}; ${timeLine(r['depthtex-hard'])}; ` +
    `${timeLine(r['depthtex-hard-512'])}; ${timeLine(r['depthtex-pcf4x4'])}; ${timeLine(r['depthtex-pcf4x4-512'])}; ` +
    `before issue 37, ${timeLine(r['rgba-hard-tight'])}; before issue 9, ${timeLine(r['rgba-hard-sheet'])}. ` +
    'On SwiftShader every shader instruction is CPU time: PCF\'s early exit reads 4 taps where the corners agree, ' +
    'a smaller map costs less to draw and to clear, a depth texture\'s pass writes no colour, and the camera pass ' +
    '(marble, Phong) is the same work in both. The defaults cost more than the settings before issue 9 (on llvmpipe ' +
    'too: results/bench/results.md, the defaults against the settings before): the auto bias adds its slope term to ' +
    'every fragment that looks up the map, and with the tight fit the shadow pass costs more (the receivers in view ' +
    'fill the map, so more of it is drawn).');
  // Issue 37's goals: hard at most 0.5x BasicShadowMap's time, PCF at most 0.7x PCFShadowMap's, at no more error.
  const best = (filter) => rows.filter((x) => x.kind === 'ours' && x.c.filter === filter && x.notWorse)
    .sort((a, b) => a.ratioThree - b.ratioThree)[0];
  const goal = (filter, limit, name) => {
    const b = best(filter);
    return b ? `${name} ${f2(b.ratioThree)}x (${b.label}; goal ${limit}x: ${b.ratioThree <= limit ? 'met' : 'not met'})`
      : `${name}: no row at three.js's error or below (goal ${limit}x: not met)`;
  };
  out.push(`- **The fastest row at no more error than three.js's defaults** (issue 37's goals): ${goal('hard', 0.5, 'hard')}; ` +
    `${goal('pcf4x4', 0.7, 'pcf4x4')}.`);
  return out.join('\n');
}

function byLabel(rows, id) {
  const r = rows.find((x) => x.id === id);
  return r ? r.label : id;
}

