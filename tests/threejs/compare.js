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
// The light. penumbra renders the exported point light with ONE 2D perspective shadow map, aimed
// from the light at the centre of the casters' and receivers' bounds and fitted tightly around
// them (src/shadow/light_frustum.cpp). three.js would give a PointLight six cube faces
// (a cube depth texture), six shadow passes. The fair counterpart is a SpotLight at the light's
// position whose shadow camera is exactly penumbra's frustum: same aim, same up vector, same
// horizontal and vertical half-angles (angle = atan(tan_y), shadow.aspect = tan_x / tan_y), same
// near and far planes, refitted every frame as penumbra refits it. The spot's cone (penumbra 0,
// decay 0) covers every caster and receiver, so it lights what the point light lights.
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
    if (!mesh.geometry.boundingBox) mesh.geometry.computeBoundingBox();
    box.union(mesh.geometry.boundingBox.clone().applyMatrix4(mesh.matrixWorld));
  }
  return box;
}

// Aims the spot light and its shadow camera as penumbra aims its shadow pass.
function refit() {
  const f = fitFrustum(light.position, shadowedBounds());
  light.target.position.copy(f.aim);
  light.target.updateMatrixWorld();
  light.angle = Math.atan(f.ty);
  const shadow = light.shadow;
  shadow.focus = 1;
  shadow.aspect = f.tx / f.ty;
  shadow.camera.up.copy(f.up);
  // What SpotLightShadow.updateMatrices would set (fov from the angle, aspect from the map and
  // shadow.aspect, far from light.distance = 0, i.e. the camera's own far), plus the near plane.
  shadow.camera.fov = THREE.MathUtils.RAD2DEG * 2 * light.angle;
  shadow.camera.aspect = (shadow.mapSize.width / shadow.mapSize.height) * shadow.aspect;
  shadow.camera.near = f.znear;
  shadow.camera.far = f.zfar;
  shadow.camera.updateProjectionMatrix();
  lastFrustum = {
    aim: f.aim.toArray(), up: f.up.toArray(), tanX: f.tx, tanY: f.ty, near: f.znear, far: f.zfar,
    angleDeg: THREE.MathUtils.RAD2DEG * light.angle, position: light.position.toArray(),
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
