// What threejs_compare asks of build/penumbra: the exported scenes (`export`), penumbra's own EGL
// renders (`render`), and the scores against the ground truth (`truth --score --json`), whose keys
// are the score table's (src/measure/score_columns.cpp, listed by `truth --score-columns`).
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { MAP, SIZE, log, tname } from './config.mjs';

export function run(cli, args) {
  return execFileSync(cli, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

// The score columns: [{key, heading, digits, table_digits, optional, required, meaning}, ...].
export function scoreColumns(cli) {
  const columns = JSON.parse(run(cli, ['truth', '--score-columns']));
  if (!Array.isArray(columns) || !columns.length || columns.some((c) => typeof c.key !== 'string'))
    throw new Error(`${cli} truth --score-columns: not a list of columns`);
  return columns;
}

// `penumbra truth --score PNG --json`: {scene, time, width, height, <one key per score column>};
// returns the score part, every column's key present (null where the score has none).
export function score(o, columns, t, png) {
  const dir = path.join(o.outDir, 'truth', `t${tname(t)}`);
  const out = run(o.cli, ['truth', '--scene', 'teapot', '--time', String(t), '--size', `${SIZE}x${SIZE}`, '--out-dir', dir,
                          '--score', png, '--json']);
  let j;
  try {
    j = JSON.parse(out);
  } catch (e) {
    throw new Error(`cannot read the score of ${png} from: ${out} (${e.message})`);
  }
  const { scene, time, width, height, ...s } = j;
  if (width !== SIZE || height !== SIZE || Math.abs(time - t) > 1e-9)
    throw new Error(`the score of ${png} is of ${scene} at t = ${time}, ${width}x${height}`);
  for (const c of columns)
    if (!(c.key in s)) throw new Error(`the score of ${png} has no ${c.key}`);
  return s;
}

// The glTF nodes of one exported frame: node matrices by name (the teapot jumps) and the light's position.
function frameNodes(gltf) {
  const frame = { nodes: {}, light: null };
  for (const n of gltf.nodes) {
    if (n.extensions && n.extensions.KHR_lights_punctual) frame.light = n.translation || [0, 0, 0];
    else if (n.mesh !== undefined) frame.nodes[n.name] = n.matrix || [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  }
  if (!frame.light) throw new Error('the exported glTF has no light node');
  return frame;
}

// The scenes: one glTF per time, and the timing frames' nodes (t + k/60, the light and the teapot
// moving) from one export each. Returns {t: [frame, ...]}.
export function exportScenes(o, dataDir) {
  log(`exporting the course scene at t = ${o.times.join(', ')} and ${o.frames} timing frames each`);
  const frames = {};
  for (const t of o.times) {
    run(o.cli, ['export', '--scene', 'teapot', '--time', String(t), '--size', `${SIZE}x${SIZE}`,
                '--out', path.join(dataDir, `course_${tname(t)}.gltf`)]);
    frames[t] = [];
    const tmp = path.join(dataDir, 'frame.gltf');
    for (let k = 0; k < o.frames; ++k) {
      run(o.cli, ['export', '--scene', 'teapot', '--time', String(t + k / 60), '--out', tmp]);
      frames[t].push(frameNodes(JSON.parse(readFileSync(tmp, 'utf8'))));
    }
  }
  return frames;
}

// The exported camera is penumbra's camera: penumbra's own EGL render of the exported glTF and of
// the built-in scene give the same visibility image and the same score.
export function checkCamera(o, columns, dataDir, imgDir) {
  const cameraCheck = [];
  for (const t of o.times) {
    const a = path.join(imgDir, `egl_teapot_t${tname(t)}.png`);
    const b = path.join(imgDir, `egl_gltf_t${tname(t)}.png`);
    const common = ['--size', `${SIZE}x${SIZE}`, '--map-size', String(MAP), '--encoding', 'rgba', '--filter', 'hard', '--aov', 'visibility'];
    run(o.cli, ['render', '--scene', 'teapot', '--time', String(t), ...common, '--out', a]);
    run(o.cli, ['render', '--scene', path.join(dataDir, `course_${tname(t)}.gltf`), ...common, '--out', b]);
    const pa = PNG.sync.read(readFileSync(a));
    const pb = PNG.sync.read(readFileSync(b));
    let differing = 0;
    for (let i = 0; i < pa.data.length; i += 4) if (pa.data[i] !== pb.data[i]) ++differing;
    cameraCheck.push({ t, differing, teapot: score(o, columns, t, a), gltf: score(o, columns, t, b) });
  }
  return cameraCheck;
}
