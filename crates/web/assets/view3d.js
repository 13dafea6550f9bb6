// The 3D view of a cubic solution: every figure's voxels coloured by piece,
// side by side, turned with the mouse (three.js OrbitControls, vendored).

import * as THREE from '/vendor/three/three.module.js';
import { OrbitControls } from '/vendor/three/OrbitControls.js';

let current = null;

export function show(host, solution, colour) {
  if (current) current.dispose();
  host.textContent = '';
  const width = host.clientWidth || 640;
  const height = host.clientHeight || 380;
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  } catch (e) {
    host.textContent = `3D view unavailable (no WebGL): ${e.message}`;
    return;
  }
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(width, height);
  renderer.setClearColor(0xffffff);
  host.append(renderer.domElement);
  const hint = document.createElement('div');
  hint.className = 'hint';
  hint.textContent = 'drag to turn · wheel to zoom · right-drag to pan';
  host.append(hint);

  const scene = new THREE.Scene();
  scene.add(new THREE.AmbientLight(0xffffff, 1.2));
  const sun = new THREE.DirectionalLight(0xffffff, 2.2);
  sun.position.set(3, 5, 4);
  scene.add(sun);

  const box = new THREE.BoxGeometry(0.96, 0.96, 0.96);
  const edges = new THREE.EdgesGeometry(box);
  const materials = new Map();
  const meshes = [];
  let offset = 0;
  let maxExtent = 1;
  for (const fig of solution.figures) {
    let w = 0, h = 0, d = 0;
    for (const p of fig.pieces) for (const [x, y, z] of p) { w = Math.max(w, x + 1); h = Math.max(h, y + 1); d = Math.max(d, z + 1); }
    fig.pieces.forEach((p, i) => {
      if (!materials.has(i)) materials.set(i, new THREE.MeshLambertMaterial({ color: colour(i), transparent: true }));
      for (const [x, y, z] of p) {
        // Figure x to the right, layers z upwards, rows y towards the viewer.
        const m = new THREE.Mesh(box, materials.get(i));
        m.position.set(offset + x + 0.5, z + 0.5, y + 0.5);
        m.userData.piece = i;
        const line = new THREE.LineSegments(edges, new THREE.LineBasicMaterial({ color: 0x333333 }));
        m.add(line);
        scene.add(m);
        meshes.push(m);
      }
    });
    offset += w + 2;
    maxExtent = Math.max(maxExtent, h, d);
  }
  const centre = new THREE.Vector3((offset - 2) / 2, maxExtent / 2, maxExtent / 2);
  const camera = new THREE.PerspectiveCamera(40, width / height, 0.1, 1000);
  // Far enough for the whole row of figures to fit the view, seen from above and in front.
  const tan = Math.tan((40 / 2) * Math.PI / 180);
  const fit = Math.max((offset - 2) / (2 * tan * (width / height)), maxExtent / (2 * tan));
  const dir = new THREE.Vector3(0.35, 0.75, 1).normalize();
  camera.position.copy(centre).addScaledVector(dir, fit * 1.4 + maxExtent * 1.5);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  controls.update();

  const onHighlight = (ev) => {
    const hot = ev.detail;
    for (const [i, mat] of materials) mat.opacity = hot < 0 || hot === i ? 1 : 0.15;
    render();
  };
  document.addEventListener('piece-highlight', onHighlight);

  // Hovering a cube highlights its piece everywhere.
  const ray = new THREE.Raycaster();
  const pointer = new THREE.Vector2();
  renderer.domElement.addEventListener('pointermove', (ev) => {
    if (ev.buttons) return;
    const r = renderer.domElement.getBoundingClientRect();
    pointer.set(((ev.clientX - r.left) / r.width) * 2 - 1, -((ev.clientY - r.top) / r.height) * 2 + 1);
    ray.setFromCamera(pointer, camera);
    const hit = ray.intersectObjects(meshes, false)[0];
    const i = hit ? hit.object.userData.piece : -1;
    window.dispatchEvent(new CustomEvent('studio-hover-piece', { detail: i }));
  });

  function render() {
    renderer.render(scene, camera);
  }
  controls.addEventListener('change', render);
  render();
  current = {
    dispose() {
      document.removeEventListener('piece-highlight', onHighlight);
      controls.dispose();
      renderer.dispose();
    },
  };
}
