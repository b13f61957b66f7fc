// The three.js side of the side-by-side (tools/threejs_compare.mjs drives it in headless Chromium):
// loads a course scene exported by `penumbra export` with three.js's GLTFLoader and offers a test
// hook, window.compare, much like the exercise pages' window.penumbra:
//   ready                      resolves once the page has its WebGL 2 renderer
//   info()                     three.js's revision, the GL version and renderer strings
//   load(url, options)         loads a glTF; options as configure(); resolves to a summary
//   configure(options)         {shadowType: 'basic'|'pcf', bias, normalBias, shadowSide: 'default'|'double',
//                               material: 'standard'|'phong', mapSize, radius}
//   setFrame({teapot, light})  a node matrix (16 numbers, column-major, by node name) and the light's position
//   frustum()                  the light frustum in use (fitted as penumbra fits it)
//   renderVisibility()         the visibility image, RGBA top row first, base64 (255 lit, 0 shadowed)
//   renderColor()              one colour frame, RGBA top row first, base64
//   timeFrames(frames, warmup) ms of each colour frame, each followed by a one-pixel readback
//
// The light. penumbra renders the exported point light with ONE 2D perspective shadow map, fitted
// tightly to what the camera sees: aimed from the light at the receivers in view, an asymmetric
// frustum around them, the near plane at the nearest caster reaching into it
// (src/shadow/light_frustum.cpp, fit_light_frustum_tight). three.js would give a PointLight six
// cube faces (a cube depth texture), six shadow passes. The fair counterpart is a SpotLight at the
// light's position whose shadow camera is exactly penumbra's frustum: same aim, same up vector,
// the window as a view offset inside a symmetric frame (angle = atan(tan_y), shadow.aspect =
// tan_x / tan_y), same near and far planes, refitted every frame as penumbra refits it. The
// visibility images do not depend on the spot's cone (penumbra 0, decay 0).
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const canvas = document.getElementById('canvas');
const W = canvas.width;
const H = canvas.height;

// As penumbra's canvas (src/platform/emscripten_canvas.cpp): no antialiasing, depth and stencil,
// no alpha, the drawing buffer preserved.
const renderer = new THREE.WebGLRenderer({
  canvas, antialias: false, alpha: false, depth: true, stencil: true, preserveDrawingBuffer: true,
  powerPreference: 'default',
});
renderer.setPixelRatio(1);
renderer.setSize(W, H, false);
renderer.shadowMap.enabled = true;
renderer.toneMapping = THREE.NoToneMapping;
const gl = renderer.getContext();

// penumbra's constants (src/shadow/light_frustum.cpp).
const kMaxTanHalfAngle = Math.tan((75 * Math.PI) / 180);
const kMinTanHalfAngle = 1e-3;
const kSideMargin = 1.01;

let scene = null;
let camera = null;
let light = null;
let ambient = null;
let meshes = [];          // {mesh, colour: {standard, phong}, visibility: ShadowMaterial}
let options = {};
let lastFrustum = null;
const white = new THREE.Color(1, 1, 1);

function defaults() {
  return { shadowType: 'pcf', bias: 0, normalBias: 0, shadowSide: 'default', material: 'phong', mapSize: 1024, radius: 1 };
}

// fit_perspective of src/shadow/light_frustum.cpp, in double: the light looks from its position at
// the centre of the bounds of every caster and receiver; the tangents of the half-angles and the
// depth range cover the 8 corners of those bounds (1 % wider, 2 % deeper).
function fitFrustum(lightPos, box) {
  const aim = box.getCenter(new THREE.Vector3());
  const dir = aim.clone().sub(lightPos);
  const len = dir.length();
  if (!(len > 1e-12)) dir.set(0, -1, 0); else dir.divideScalar(len);
  const up = Math.abs(dir.y) > 0.99 ? new THREE.Vector3(0, 0, 1) : new THREE.Vector3(0, 1, 0);
  const view = new THREE.Matrix4().lookAt(lightPos, aim, up);  // rotation only: camera -> world
  view.setPosition(lightPos);
  const viewInv = view.clone().invert();
  const corners = [];
  for (let i = 0; i < 8; ++i)
    corners.push(new THREE.Vector3(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z));
  let maxDist = 0;
  for (const p of corners) maxDist = Math.max(maxDist, p.distanceTo(lightPos));
  const scale = Math.max(maxDist, 1e-6 * Math.max(1, Math.abs(lightPos.x), Math.abs(lightPos.y), Math.abs(lightPos.z)));
  const frontEps = 1e-4 * scale;
  let zmin = Infinity, zmax = 0, tx = 0, ty = 0, someBehind = false;
  for (const p of corners) {
    const e = p.clone().applyMatrix4(viewInv);
    const depth = -e.z;
    if (!(depth > frontEps)) { someBehind = true; continue; }
    zmin = Math.min(zmin, depth);
    zmax = Math.max(zmax, depth);
    tx = Math.max(tx, Math.abs(e.x) / depth);
    ty = Math.max(ty, Math.abs(e.y) / depth);
  }
  const clamp = (v) => Math.min(Math.max(v, kMinTanHalfAngle), kMaxTanHalfAngle);
  tx = clamp(tx * kSideMargin);
  ty = clamp(ty * kSideMargin);
  let znear, zfar;
  if (zmax <= 0) {
    zfar = maxDist > 0 ? 1.02 * maxDist : 1;
    znear = 0.01 * zfar;
    tx = ty = kMaxTanHalfAngle;
  } else {
    zfar = 1.02 * zmax;
    znear = 0.98 * zmin;
    if (someBehind) znear = Math.min(znear, 0.01 * zfar);
  }
  znear = Math.max(znear, zfar * 1e-4);
  if (!(zfar > znear)) zfar = znear * 1.04 + 1e-6;
  return { aim, up, tx, ty, znear, zfar };
}

function shadowedBounds() {
  const box = new THREE.Box3();
  scene.updateMatrixWorld(true);
  for (const { mesh } of meshes) {
    if (!mesh.castShadow && !mesh.receiveShadow) continue;
    box.union(worldBox(mesh));
  }
  return box;
}

function worldBox(mesh) {
  if (!mesh.geometry.boundingBox) mesh.geometry.computeBoundingBox();
  return mesh.geometry.boundingBox.clone().applyMatrix4(mesh.matrixWorld);
}

// ---- fit_light_frustum_tight of src/shadow/light_frustum.cpp (and src/shadow/convex.cpp), in
// double: the receivers the camera sees, looked at from the light with an asymmetric frustum
// around them, the near plane at the nearest caster that reaches into that window. Points are
// [x, y, z]; a half-space is [nx, ny, nz, d] holding n.p + d >= 0.

const dot3 = (h, p) => h[0] * p[0] + h[1] * p[1] + h[2] * p[2];
const dist = (h, p) => dot3(h, p) + h[3];

function unitHalfSpace(h) {
  const len = Math.hypot(h[0], h[1], h[2]);
  return len > 0 && Number.isFinite(len) ? h.map((v) => v / len) : [0, 0, 0, 1];
}

// The six half-spaces of a view-projection's clip volume (Gribb & Hartmann).
function clipVolumeHalfSpaces(m) {
  const e = m.elements;
  const row = (i) => [e[i], e[4 + i], e[8 + i], e[12 + i]];
  const w = row(3);
  const out = [];
  for (let i = 0; i < 3; ++i) {
    const r = row(i);
    out.push(unitHalfSpace(w.map((v, k) => v + r[k])), unitHalfSpace(w.map((v, k) => v - r[k])));
  }
  return out;
}

function clipPolygon(poly, h, eps) {
  const out = [];
  for (let i = 0; i < poly.length; ++i) {
    const a = poly[i], b = poly[(i + 1) % poly.length];
    const da = dist(h, a), db = dist(h, b);
    const ina = da >= -eps, inb = db >= -eps;
    if (ina) out.push(a);
    if (ina !== inb) {
      const t = Math.min(Math.max(da / (da - db), 0), 1);
      out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]);
    }
  }
  return out;
}

// The vertices of box & the half-spaces: the box's faces clipped by them, and a square on each
// half-space's plane clipped by the box and the others (convex.cpp's clip_box).
function clipBox(box, halfSpaces) {
  const lo = box.min.toArray(), hi = box.max.toArray();
  const centre = lo.map((v, i) => 0.5 * (v + hi[i]));
  const radius = 0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  const scale = Math.max(radius, ...lo.map(Math.abs), ...hi.map(Math.abs));
  const eps = 1e-5 * scale;
  const hs = [];
  for (const h of halfSpaces) {
    const len = Math.hypot(h[0], h[1], h[2]);
    if (!(len > 0) || !Number.isFinite(len)) { if (h[3] < 0) return []; continue; }
    hs.push(h.map((v) => v / len));
  }
  const corners = [];
  for (let i = 0; i < 8; ++i) corners.push([i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]]);
  for (const h of hs) if (corners.every((p) => dist(h, p) < -eps)) return [];
  const boxHs = [[1, 0, 0, -lo[0]], [-1, 0, 0, hi[0]], [0, 1, 0, -lo[1]], [0, -1, 0, hi[1]], [0, 0, 1, -lo[2]], [0, 0, -1, hi[2]]];
  const out = [];
  const clipAll = (poly, skip, withBox) => {
    if (withBox) for (const h of boxHs) { if (!poly.length) break; poly = clipPolygon(poly, h, eps); }
    for (let j = 0; j < hs.length && poly.length; ++j) if (j !== skip) poly = clipPolygon(poly, hs[j], eps);
    out.push(...poly);
  };
  for (let a = 0; a < 3; ++a) {
    const u = (a + 1) % 3, v = (a + 2) % 3;
    for (const side of [lo[a], hi[a]]) {
      const us = [lo[u], hi[u], hi[u], lo[u]], vs = [lo[v], lo[v], hi[v], hi[v]];
      const face = [0, 1, 2, 3].map((k) => { const p = [0, 0, 0]; p[a] = side; p[u] = us[k]; p[v] = vs[k]; return p; });
      clipAll(face, hs.length, false);
    }
  }
  const half = 1.01 * radius + 1e-4 * scale + 1e-30;
  hs.forEach((h, i) => {
    const n = new THREE.Vector3(h[0], h[1], h[2]);
    const c = new THREE.Vector3(...centre);
    const foot = c.clone().addScaledVector(n, -dist(h, centre));
    const t1 = new THREE.Vector3().crossVectors(n, Math.abs(n.x) < 0.9 ? new THREE.Vector3(1, 0, 0) : new THREE.Vector3(0, 1, 0)).normalize();
    const t2 = new THREE.Vector3().crossVectors(n, t1);
    const at = (s1, s2) => foot.clone().addScaledVector(t1, s1 * half).addScaledVector(t2, s2 * half).toArray();
    clipAll([at(-1, -1), at(1, -1), at(1, 1), at(-1, 1)], i, true);
  });
  return out;
}

// 2D: the hull (monotone chain), clipped to a rectangle, its area.
function hullArea(points, lo, hi) {
  const p = points.slice().sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  let h = [];
  if (p.length >= 3) {
    for (const q of p) { while (h.length >= 2 && cross(h[h.length - 2], h[h.length - 1], q) <= 0) h.pop(); h.push(q); }
    const lower = h.length + 1;
    for (let i = p.length - 2; i >= 0; --i) {
      while (h.length >= lower && cross(h[h.length - 2], h[h.length - 1], p[i]) <= 0) h.pop();
      h.push(p[i]);
    }
    h.pop();
  }
  for (const [axis, bound, sign] of [[0, lo[0], 1], [0, hi[0], -1], [1, lo[1], 1], [1, hi[1], -1]]) {
    const next = [];
    for (let i = 0; i < h.length; ++i) {
      const a = h[i], b = h[(i + 1) % h.length];
      const da = sign * (a[axis] - bound), db = sign * (b[axis] - bound);
      if (da >= 0) next.push(a);
      if ((da >= 0) !== (db >= 0)) { const t = da / (da - db); next.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]); }
    }
    h = next;
  }
  let twice = 0;
  for (let i = 0; i < h.length; ++i) twice += h[i][0] * h[(i + 1) % h.length][1] - h[(i + 1) % h.length][0] * h[i][1];
  return Math.abs(twice) / 2;
}

// The light's view looking along dir: camera -> world (rotation and position) and its inverse.
function lightView(lightPos, dir) {
  const up = Math.abs(dir.y) > 0.99 ? new THREE.Vector3(0, 0, 1) : new THREE.Vector3(0, 1, 0);
  const view = new THREE.Matrix4().lookAt(lightPos, lightPos.clone().add(dir), up);
  view.setPosition(lightPos);
  return { dir, up, view, viewInv: view.clone().invert() };
}

// perspective_window: the points' tangents along one direction, widened by the margin, capped.
function perspectiveWindow(lightPos, dir, visible, frontEps) {
  const w = lightView(lightPos, dir);
  let xl = Infinity, xr = -Infinity, yb = Infinity, yt = -Infinity;
  w.zmin = Infinity; w.zmax = 0;
  const tangents = [];
  const e = new THREE.Vector3();
  for (const p of visible) {
    e.fromArray(p).applyMatrix4(w.viewInv);
    const depth = -e.z;
    if (!(depth > frontEps)) return null;
    const t = [e.x / depth, e.y / depth];
    tangents.push(t);
    xl = Math.min(xl, t[0]); xr = Math.max(xr, t[0]); yb = Math.min(yb, t[1]); yt = Math.max(yt, t[1]);
    w.zmin = Math.min(w.zmin, depth); w.zmax = Math.max(w.zmax, depth);
  }
  w.raw = [xl, xr, yb, yt];
  const widen = (lo, hi) => {
    const half = Math.max(0.5 * (hi - lo) * kSideMargin, kMinTanHalfAngle), mid = 0.5 * (lo + hi);
    return [mid - half, mid + half];
  };
  [xl, xr] = widen(xl, xr);
  [yb, yt] = widen(yb, yt);
  const cap = kMaxTanHalfAngle, gap = 2 * kMinTanHalfAngle;
  w.capped = xl < -cap || xr > cap || yb < -cap || yt > cap;
  const clamp = (v, a, b) => Math.min(Math.max(v, a), b);
  w.xl = clamp(xl, -cap, cap - gap); w.xr = clamp(xr, w.xl + gap, cap);
  w.yb = clamp(yb, -cap, cap - gap); w.yt = clamp(yt, w.yb + gap, cap);
  w.use = hullArea(tangents, [w.xl, w.yb], [w.xr, w.yt]) / ((w.xr - w.xl) * (w.yt - w.yb));
  return w;
}

// null where penumbra falls back to the old fit (no receiver in view, the light inside a box, a
// point beside the light).
function fitTight(lightPos, receivers, casters, cameraViewProj) {
  const cam = clipVolumeHalfSpaces(cameraViewProj);
  const visible = receivers.flatMap((b) => clipBox(b, cam));
  if (!visible.length) return null;
  const pos = lightPos.toArray();
  for (const b of [...receivers, ...casters]) {
    const m = 1e-5 * Math.max(1, ...b.min.toArray().map(Math.abs), ...b.max.toArray().map(Math.abs));
    if (pos.every((v, i) => v >= b.min.getComponent(i) - m && v <= b.max.getComponent(i) + m)) return null;
  }
  const centroid = new THREE.Vector3();
  let maxDist = 0;
  for (const p of visible) {
    const q = new THREE.Vector3().fromArray(p);
    centroid.add(q);
    maxDist = Math.max(maxDist, q.distanceTo(lightPos));
  }
  centroid.divideScalar(visible.length);
  const scale = Math.max(maxDist, 1e-6 * Math.max(1, ...pos.map(Math.abs)));
  const toCentroid = centroid.clone().sub(lightPos);
  if (!(toCentroid.length() > 1e-4 * scale)) return null;
  const frontEps = 1e-4 * scale;
  const a = perspectiveWindow(lightPos, toCentroid.clone().normalize(), visible, frontEps);
  let b = null;
  if (a) {
    const ax = 0.5 * (Math.atan(a.raw[0]) + Math.atan(a.raw[1]));
    const ay = 0.5 * (Math.atan(a.raw[2]) + Math.atan(a.raw[3]));
    const eyeDir = new THREE.Vector3(Math.tan(ax), Math.tan(ay), -1).normalize();
    const dir = eyeDir.transformDirection(a.view);  // camera -> world, normalized
    b = perspectiveWindow(lightPos, dir, visible, frontEps);
  }
  if (!a && !b) return null;
  const w = !b ? a : !a ? b : a.capped !== b.capped ? (a.capped ? b : a) : (b.use > a.use ? b : a);
  // The casters reaching into the window's pyramid up to the farthest visible point.
  const rot = new THREE.Matrix3().setFromMatrix4(w.view);
  const toWorld = (h) => {
    const n = new THREE.Vector3(h[0], h[1], h[2]).applyMatrix3(rot);
    return [n.x, n.y, n.z, h[3] - n.dot(lightPos)];
  };
  const win = [[1, 0, w.xl, 0], [-1, 0, -w.xr, 0], [0, 1, w.yb, 0], [0, -1, -w.yt, 0], [0, 0, 1, w.zmax]].map(toWorld);
  let nearest = w.zmin;
  const e = new THREE.Vector3();
  for (const c of casters)
    for (const p of clipBox(c, win)) nearest = Math.min(nearest, -e.fromArray(p).applyMatrix4(w.viewInv).z);
  let zfar = 1.02 * w.zmax;
  const znear = Math.max(0.98 * nearest, zfar * 1e-4);
  if (!(zfar > znear)) zfar = znear * 1.04 + 1e-6;
  return { aim: lightPos.clone().add(w.dir), up: w.up, xl: w.xl, xr: w.xr, yb: w.yb, yt: w.yt, znear, zfar };
}

// Aims the spot light and its shadow camera as penumbra aims its shadow pass: the tight fit, as
// an asymmetric window through the camera's view offset (the full frame symmetric around the
// axis, the window a part of it), or the old fit where penumbra falls back to it.
function refit() {
  camera.updateMatrixWorld();
  const cameraViewProj = camera.projectionMatrix.clone().multiply(camera.matrixWorldInverse);
  const receivers = meshes.filter(({ mesh }) => mesh.receiveShadow).map(({ mesh }) => worldBox(mesh));
  const casters = meshes.filter(({ mesh }) => mesh.castShadow).map(({ mesh }) => worldBox(mesh));
  let f = fitTight(light.position, receivers, casters, cameraViewProj);
  const tight = f !== null;
  if (!tight) {
    const o = fitFrustum(light.position, shadowedBounds());
    f = { aim: o.aim, up: o.up, xl: -o.tx, xr: o.tx, yb: -o.ty, yt: o.ty, znear: o.znear, zfar: o.zfar };
  }
  const tx = Math.max(Math.abs(f.xl), Math.abs(f.xr));
  const ty = Math.max(Math.abs(f.yb), Math.abs(f.yt));
  light.target.position.copy(f.aim);
  light.target.updateMatrixWorld();
  light.angle = Math.atan(ty);
  const shadow = light.shadow;
  shadow.focus = 1;
  shadow.aspect = tx / ty;
  shadow.camera.up.copy(f.up);
  // What SpotLightShadow.updateMatrices would set (fov from the angle, aspect from the map and
  // shadow.aspect, far from light.distance = 0, i.e. the camera's own far), plus the near plane
  // and the window: PerspectiveCamera.updateProjectionMatrix keeps the view offset.
  shadow.camera.fov = THREE.MathUtils.RAD2DEG * 2 * light.angle;
  shadow.camera.aspect = (shadow.mapSize.width / shadow.mapSize.height) * shadow.aspect;
  shadow.camera.near = f.znear;
  shadow.camera.far = f.zfar;
  shadow.camera.setViewOffset(2 * tx, 2 * ty, f.xl + tx, ty - f.yt, f.xr - f.xl, f.yt - f.yb);
  shadow.camera.updateProjectionMatrix();
  lastFrustum = {
    aim: f.aim.toArray(), up: f.up.toArray(), tanX: tx, tanY: ty, window: [f.xl, f.xr, f.yb, f.yt], tight,
    near: f.znear, far: f.zfar, angleDeg: THREE.MathUtils.RAD2DEG * light.angle, position: light.position.toArray(),
  };
}


function applyOptions() {
  const o = options;
  renderer.shadowMap.type = o.shadowType === 'basic' ? THREE.BasicShadowMap : THREE.PCFShadowMap;
  const shadow = light.shadow;
  if (shadow.mapSize.width !== o.mapSize || shadow.mapSize.height !== o.mapSize) {
    shadow.mapSize.set(o.mapSize, o.mapSize);
    if (shadow.map) { shadow.map.dispose(); shadow.map = null; }
  }
  shadow.bias = o.bias;
  shadow.normalBias = o.normalBias;
  shadow.radius = o.radius;
  const side = o.shadowSide === 'double' ? THREE.DoubleSide : null;  // null: three's default (the opposite side)
  for (const m of meshes) {
    for (const mat of [m.colour.standard, m.colour.phong, m.visibility]) {
      mat.shadowSide = side;
      mat.needsUpdate = true;
    }
    m.mesh.material = m.colour[o.material];
  }
  refit();
}

function summary(gltf) {
  let triangles = 0;
  for (const { mesh } of meshes) {
    const g = mesh.geometry;
    triangles += (g.index ? g.index.count : g.attributes.position.count) / 3;
  }
  const cam = camera;
  return {
    meshes: meshes.map(({ mesh }) => mesh.name),
    triangles,
    camera: { fovDeg: cam.fov, aspect: cam.aspect, near: cam.near, far: cam.far,
              position: new THREE.Vector3().setFromMatrixPosition(cam.matrixWorld).toArray() },
    light: { exported: gltf.parser.json.extensions.KHR_lights_punctual.lights[0].type, used: 'SpotLight',
             position: light.position.toArray() },
    frustum: lastFrustum,
  };
}

async function load(url, opts = {}) {
  const gltf = await new GLTFLoader().loadAsync(url);
  scene = new THREE.Scene();  // gltf.scene is a Group: only a Scene has a background
  scene.add(gltf.scene);
  scene.updateMatrixWorld(true);
  const cams = [];
  scene.traverse((o) => { if (o.isCamera) cams.push(o); });
  if (!cams.length) throw new Error('the glTF has no camera');
  camera = cams[0];
  // The exported point light -> a spot light at its world position (see the top of this file).
  let point = null;
  scene.traverse((o) => { if (o.isLight && !point) point = o; });
  if (!point) throw new Error('the glTF has no KHR_lights_punctual light');
  const pos = new THREE.Vector3().setFromMatrixPosition(point.matrixWorld);
  point.parent.remove(point);
  light = new THREE.SpotLight(0xffffff, 1, 0, Math.PI / 4, 0, 0);
  light.name = 'light';
  light.position.copy(pos);
  light.castShadow = true;
  scene.add(light);
  scene.add(light.target);
  ambient = new THREE.AmbientLight(0xffffff, 0.1);
  scene.add(ambient);
  meshes = [];
  scene.traverse((o) => {
    if (!o.isMesh) return;
    const extras = (o.userData && o.userData.penumbra) || {};
    o.castShadow = extras.castsShadow !== false;
    o.receiveShadow = extras.receivesShadow !== false;
    o.frustumCulled = false;  // penumbra culls nothing either
    const standard = o.material;
    const p = (standard.userData && standard.userData.penumbra) || {};
    const phong = new THREE.MeshPhongMaterial({
      color: standard.color.clone(), map: standard.map, shininess: p.shininess ?? 32,
      specular: new THREE.Color().setScalar(p.specular ?? 0.2), side: standard.side,
    });
    // The visibility pass: every receiver (and caster) gets a ShadowMaterial of opacity 1, which
    // outputs alpha = 1 - visibility. Blending (1 - src alpha, zero) makes each fragment REPLACE the
    // pixel with its visibility (white lit, black shadowed) instead of compositing over what is
    // behind it, so a lit teapot in front of the shadowed table reads as lit; depth test and write
    // as usual.
    const visibility = new THREE.ShadowMaterial({
      color: 0xffffff, opacity: 1, transparent: true, depthWrite: true, side: standard.side,
      blending: THREE.CustomBlending, blendEquation: THREE.AddEquation,
      blendSrc: THREE.OneMinusSrcAlphaFactor, blendDst: THREE.ZeroFactor,
    });
    meshes.push({ mesh: o, colour: { standard, phong }, visibility });
  });
  scene.background = new THREE.Color(0.1, 0.1, 0.12);
  options = { ...defaults(), ...opts };
  applyOptions();
  return summary(gltf);
}

function configure(opts) {
  options = { ...options, ...opts };
  applyOptions();
  return options;
}

function byName(name) {
  let found = null;
  scene.traverse((o) => { if (!found && o.name === name) found = o; });
  return found;
}

// One frame of the course's animation: node matrices by name (penumbra export's 'teapot', 'table')
// and the light's world position; the light frustum is refitted as penumbra refits it.
function setFrame(frame) {
  for (const [name, m] of Object.entries(frame.nodes || {})) {
    const o = byName(name);
    if (!o) throw new Error(`no node '${name}'`);
    o.matrix.fromArray(m);
    o.matrix.decompose(o.position, o.quaternion, o.scale);
  }
  if (frame.light) light.position.fromArray(frame.light);
  scene.updateMatrixWorld(true);
  refit();
}

function readAll() {
  const buf = new Uint8Array(W * H * 4);
  gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, buf);
  // WebGL reads bottom row first; the PNGs and penumbra's readback are top row first.
  const out = new Uint8Array(W * H * 4);
  const row = W * 4;
  for (let y = 0; y < H; ++y) out.set(buf.subarray((H - 1 - y) * row, (H - y) * row), y * row);
  return out;
}

function toBase64(bytes) {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

function renderVisibility() {
  const background = scene.background;
  scene.background = white;
  for (const m of meshes) m.mesh.material = m.visibility;
  ambient.visible = false;
  renderer.setRenderTarget(null);
  renderer.render(scene, camera);
  const px = readAll();
  for (const m of meshes) m.mesh.material = m.colour[options.material];
  ambient.visible = true;
  scene.background = background;
  return { width: W, height: H, data: toBase64(px) };
}

function renderColor() {
  renderer.setRenderTarget(null);
  renderer.render(scene, camera);
  return { width: W, height: H, data: toBase64(readAll()) };
}

// Each frame: set the frame (the light and the teapot move, so the map is redrawn, as three.js
// redraws it every frame anyway), draw it, then read one pixel back: WebGL's finish() returns at
// once in Chromium, the readback waits for the frame. The same measure as penumbra's pages.
function timeFrames(frames, warmup = 3) {
  const px = new Uint8Array(4);
  renderer.setRenderTarget(null);
  const ms = [];
  for (let k = -warmup; k < frames.length; ++k) {
    setFrame(frames[Math.max(k, 0)]);  // outside the clock, as the harness's setTime is for penumbra
    const t0 = performance.now();
    renderer.render(scene, camera);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const t1 = performance.now();
    if (k >= 0) ms.push(t1 - t0);
  }
  return ms;
}

function info() {
  const dbg = gl.getExtension('WEBGL_debug_renderer_info');
  return {
    revision: THREE.REVISION,
    webgl2: typeof WebGL2RenderingContext !== 'undefined' && gl instanceof WebGL2RenderingContext,
    version: gl.getParameter(gl.VERSION),
    glsl: gl.getParameter(gl.SHADING_LANGUAGE_VERSION),
    renderer: dbg ? gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
    shadowMapType: renderer.shadowMap.type === THREE.BasicShadowMap ? 'BasicShadowMap' : 'PCFShadowMap',
  };
}

window.compare = {
  ready: Promise.resolve(true),
  info, load, configure, setFrame, frustum: () => lastFrustum, renderVisibility, renderColor, timeFrames,
  glError: () => gl.getError(),
};
