// The page web.first_frame times three.js's first frame with, beside the exercise pages: what a
// course would write with three.js r187 for W09P1's scene. A Newell teapot (TeapotGeometry) on a
// table top, both Phong-shaded, under a spot light circling above, with PCF shadows from a
// 1024 x 1024 map (penumbra's default map size), drawn by setAnimationLoop from its first frame.
// The canvas's backing store is ?w=W&h=H (default 512 x 512): the harness passes the exercise
// pages' own, so both draw as many pixels.
import * as THREE from 'three';
import { TeapotGeometry } from 'three/addons/geometries/TeapotGeometry.js';

const canvas = document.getElementById('canvas');
const q = new URLSearchParams(location.search);
const W = Math.max(1, Math.min(4096, +q.get('w') || 512));
const H = Math.max(1, Math.min(4096, +q.get('h') || 512));
canvas.style.width = `${W}px`;
canvas.style.height = `${H}px`;

const renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
renderer.setPixelRatio(1);
renderer.setSize(W, H, false);
renderer.shadowMap.enabled = true;
renderer.shadowMap.type = THREE.PCFShadowMap;

const scene = new THREE.Scene();
scene.background = new THREE.Color(0x333333);
const camera = new THREE.PerspectiveCamera(65, W / H, 0.1, 100);
camera.position.set(0, 0.9, 0.4);
camera.lookAt(0, -0.8, -2.6);

scene.add(new THREE.AmbientLight(0xffffff, 0.25));
const light = new THREE.SpotLight(0xffffff, 3, 0, Math.PI / 3, 0.2, 0);
light.castShadow = true;
light.shadow.mapSize.set(1024, 1024);
light.shadow.camera.near = 0.5;
light.shadow.camera.far = 20;
light.target.position.set(0, -1, -3);
scene.add(light, light.target);

const table = new THREE.Mesh(new THREE.BoxGeometry(4, 0.1, 4), new THREE.MeshPhongMaterial({ color: 0xb0a89c }));
table.position.set(0, -1.05, -3);
table.receiveShadow = true;
scene.add(table);

const teapot = new THREE.Mesh(new TeapotGeometry(0.6, 10), new THREE.MeshPhongMaterial({ color: 0xc8c8d0, shininess: 60 }));
teapot.castShadow = true;
teapot.receiveShadow = true;
scene.add(teapot);

let frames = 0;
const start = performance.now();
renderer.setAnimationLoop(() => {
  const t = (performance.now() - start) / 1000;
  // The course's motion: the teapot jumps, the light circles above the table.
  teapot.position.set(0, -1 + 0.6 + 0.5 * Math.abs(Math.sin(2 * t)), -3);
  light.position.set(2 * Math.cos(t), 2.5, -3 + 2 * Math.sin(t));
  renderer.render(scene, camera);
  ++frames;
});

// As the exercise pages' window.penumbra: the frames drawn so far.
window.penumbra = { frameCount: () => frames };
