// The script of a `tessera view` page (inlined by write_view_html.cpp): builds the three.js scene
// from the page's JSON data, one checkbox per layer, hover ids, and window.tesseraSummary.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const data = JSON.parse(document.getElementById('tessera-data').textContent);
const started = performance.now();

function bytes(b64) {
  const text = atob(b64);
  const out = new Uint8Array(text.length);
  for (let i = 0; i < text.length; ++i) out[i] = text.charCodeAt(i);
  return out;
}
const floats = (b64) => new Float32Array(bytes(b64).buffer);
const uints = (b64) => new Uint32Array(bytes(b64).buffer);
const rgb = (c) => new THREE.Color(c[0] / 255, c[1] / 255, c[2] / 255);
// An sRGB byte in three.js's linear working space: unlit layers then show their colours exactly.
const linear = Array.from({ length: 256 }, (_, b) => new THREE.Color().setRGB(b / 255, 0, 0, THREE.SRGBColorSpace).r);

/// The texture of a layer's picture: RGB rows from the top row, laid by the layer's coordinates.
function pictureTexture(picture) {
  const rgbBytes = bytes(picture.pixels);
  const rgba = new Uint8Array(picture.width * picture.height * 4).fill(255);
  for (let i = 0, n = picture.width * picture.height; i < n; ++i)
    rgba.set(rgbBytes.subarray(3 * i, 3 * i + 3), 4 * i);
  const texture = new THREE.DataTexture(rgba, picture.width, picture.height, THREE.RGBAFormat);
  texture.colorSpace = THREE.SRGBColorSpace;
  texture.magFilter = THREE.LinearFilter;
  texture.minFilter = THREE.LinearMipmapLinearFilter;
  texture.generateMipmaps = true;
  texture.needsUpdate = true;
  return texture;
}

const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(window.innerWidth, window.innerHeight);
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xf4f4f0);
scene.add(new THREE.HemisphereLight(0xffffff, 0x606070, 2.0));
const camera = new THREE.PerspectiveCamera(40, window.innerWidth / window.innerHeight, 1e-3, 1e4);
const sun = new THREE.DirectionalLight(0xffffff, 1.5);
camera.add(sun);
scene.add(camera);

const summary = { title: data.title, kind: data.kind, version: data.version, layers: [],
                  errors: window.tesseraErrors, load_ms: 0 };
window.tesseraSummary = summary;
const pickable = [];
const labels = [];
const panel = document.getElementById('layers');

function addToggle(name, objects) {
  const row = document.createElement('label');
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.checked = objects[0].visible;
  box.addEventListener('change', () => {
    objects.forEach((o) => (o.visible = box.checked));
    frame();
  });
  row.append(box, ' ' + name);
  panel.append(row);
}

for (const layer of data.meshes) {
  const positions = floats(layer.positions);
  const triangles = uints(layer.triangles);
  let geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
  const surface = { side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 };
  const material = layer.lit === false
    ? new THREE.MeshBasicMaterial(surface)
    : new THREE.MeshStandardMaterial({ ...surface, flatShading: true, roughness: 0.8 });
  if (layer.texture) {
    geometry.setAttribute('uv', new THREE.BufferAttribute(floats(layer.texture.coordinates), 2));
    material.map = pictureTexture(layer.texture);
  } else if (layer.triangle_colours) {
    geometry = geometry.toNonIndexed();
    const face = bytes(layer.triangle_colours);
    const colours = layer.lit === false ? new Float32Array(face.length * 3) : new Uint8Array(face.length * 3);
    const colour = layer.lit === false ? Float32Array.from(face, (b) => linear[b]) : face;
    for (let t = 0; t < face.length / 3; ++t)
      for (let k = 0; k < 3; ++k) colours.set(colour.subarray(3 * t, 3 * t + 3), 9 * t + 3 * k);
    geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3, layer.lit !== false));
    material.vertexColors = true;
  } else if (layer.vertex_colours) {
    geometry.setAttribute('color', new THREE.BufferAttribute(bytes(layer.vertex_colours), 3, true));
    material.vertexColors = true;
  } else {
    material.color = rgb(layer.colour);
  }
  const mesh = new THREE.Mesh(geometry, material);
  mesh.visible = layer.visible;
  mesh.userData = { layer, triangles, ids: layer.element_ids ? uints(layer.element_ids) : null };
  scene.add(mesh);
  if (layer.pickable !== false) pickable.push(mesh);
  addToggle(layer.name, [mesh]);
  const drawn = { name: layer.name, kind: 'mesh', vertices: positions.length / 3,
                  colours: layer.texture ? 'texture' : layer.triangle_colours ? 'per triangle' : layer.vertex_colours ? 'per vertex' : 'one',
                  triangles: (geometry.index ? geometry.index.count
                                             : geometry.attributes.position.count) / 3 };
  if (mesh.userData.ids) drawn.elements = new Set(mesh.userData.ids).size;
  if (layer.texture) drawn.texture = `${layer.texture.width}x${layer.texture.height}`;
  summary.layers.push(drawn);
}

for (const layer of data.segments) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(floats(layer.segments), 3));
  const lines = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: rgb(layer.colour) }));
  lines.visible = layer.visible;
  scene.add(lines);
  addToggle(layer.name, [lines]);
  summary.layers.push({ name: layer.name, kind: 'segments',
                        segments: geometry.attributes.position.count / 2 });
}

const box = new THREE.Box3();
for (const object of scene.children) if (object.geometry) box.expandByObject(object);
const size = box.isEmpty() ? 1 : box.getSize(new THREE.Vector3()).length();
const centre = box.isEmpty() ? new THREE.Vector3() : box.getCenter(new THREE.Vector3());

for (const layer of data.points) {
  const positions = floats(layer.positions);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  const points = new THREE.Points(geometry, new THREE.PointsMaterial({ color: rgb(layer.colour),
                                                                       size: 9, sizeAttenuation: false }));
  points.visible = layer.visible;
  points.name = layer.name;
  scene.add(points);
  const tags = [];
  (layer.labels || []).slice(0, 300).forEach((text, i) => {
    const tag = document.createElement('div');
    tag.className = 'tag';
    tag.textContent = text;
    document.body.append(tag);
    tags.push(tag);
    labels.push({ tag, owner: points, at: new THREE.Vector3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]) });
  });
  addToggle(layer.name, [points]);
  summary.layers.push({ name: layer.name, kind: 'points', points: positions.length / 3,
                        labels: tags.length });
}

// The camera sees the whole bounding sphere of the scene with a margin, whatever the window's shape.
// A flat scene is seen from above, its rectangle fitted to the window.
const fov = Math.min(camera.fov, THREE.MathUtils.radToDeg(2 * Math.atan(Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2) * camera.aspect)));
const tan = Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2);
const extent = box.isEmpty() ? new THREE.Vector3(1, 1, 1) : box.getSize(new THREE.Vector3());
const distance = data.flat
  ? 1.05 * Math.max(extent.y / 2 / tan, extent.x / 2 / (tan * camera.aspect)) + extent.z / 2
  : (1.05 * size / 2) / Math.sin(THREE.MathUtils.degToRad(fov) / 2);
camera.position.copy(centre).add((data.flat ? new THREE.Vector3(0, 0, 1) : new THREE.Vector3(0.35, 0.45, 1).normalize()).multiplyScalar(distance));
camera.near = size / 1000;
camera.far = size * 100;
camera.updateProjectionMatrix();
const controls = new OrbitControls(camera, renderer.domElement);
controls.target.copy(centre);
controls.update();

const info = document.getElementById('hover');
const raycaster = new THREE.Raycaster();
const pointer = new THREE.Vector2();
// Hover picks at once, then at most every 40 ms while the pointer moves (and once where it stops);
// not while a button is down: a pick casts a ray against every triangle (70-140 ms at 1M
// triangles), and picking on each move of a drag made turning such a mesh stutter.
let lastPick = -Infinity, trailing = 0;
function showHover() {
  lastPick = performance.now();
  const hit = pickAt(pointer.x, pointer.y);
  info.textContent = hit ? hit.text : '';
}
renderer.domElement.addEventListener('pointermove', (event) => {
  if (event.buttons !== 0) {
    clearTimeout(trailing);
    return;
  }
  pointer.set(event.clientX, event.clientY);
  clearTimeout(trailing);
  if (performance.now() - lastPick >= 40) showHover();
  else trailing = setTimeout(showHover, 40);
});

/// The element under window pixel (x, y): {layer, vertex, element_kind, element, figures, text},
/// or null. What hover shows; also window.tesseraPick for tests.
function pickAt(x, y) {
  const ndc = new THREE.Vector2((x / window.innerWidth) * 2 - 1, -(y / window.innerHeight) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  const hit = raycaster.intersectObjects(pickable.filter((m) => m.visible), false)[0];
  if (!hit) return null;
  const { layer, triangles, ids } = hit.object.userData;
  const t = hit.faceIndex;
  const id = ids ? ids[t] : t;
  const figures = (layer.element_figures || [])[id] || '';
  if (layer.hover_vertex === false)
    return { layer: layer.name, vertex: null, element_kind: layer.element_kind, element: id, figures,
             text: `${layer.name}: ${layer.element_kind} ${id}` + (figures ? ` (${figures})` : '') };
  const corners = [0, 1, 2].map((k) => triangles[3 * t + k]);
  const p = hit.object.geometry.attributes.position;
  const index = hit.object.geometry.index;
  let nearest = corners[0], best = Infinity;
  corners.forEach((v, k) => {
    const q = new THREE.Vector3().fromBufferAttribute(p, index ? v : 3 * t + k);
    const d = q.distanceTo(hit.point);
    if (d < best) { best = d; nearest = v; }
  });
  return { layer: layer.name, vertex: nearest, element_kind: layer.element_kind, element: id, figures,
           text: `${layer.name}: vertex ${nearest}, ${layer.element_kind} ${id}` +
                 (figures ? ` (${figures})` : '') };
}
window.tesseraPick = pickAt;

// A label is hidden when a visible surface lies between the camera and its point. Ray casts cost a
// pass over every triangle, so on large scenes they wait until the camera has stopped moving.
const occluder = new THREE.Raycaster();
const triangleCount = pickable.reduce((n, m) => n + m.userData.triangles.length / 3, 0);
const occludeEveryFrame = labels.length * triangleCount < 2e6;
let occlusionTimer = 0;
function occlude() {
  const surfaces = pickable.filter((m) => m.visible);
  for (const label of labels) {
    const to = label.at.clone().sub(camera.position);
    const reach = to.length();
    occluder.set(camera.position, to.normalize());
    occluder.far = reach * (1 - 1e-3) - size * 1e-3;
    label.hidden = occluder.intersectObjects(surfaces, false).length > 0;
  }
}
function placeLabels() {
  for (const { tag, owner, at, hidden } of labels) {
    const s = at.clone().project(camera);
    tag.style.display = owner.visible && !hidden && s.z < 1 ? '' : 'none';
    tag.style.transform = `translate(${((s.x + 1) / 2) * window.innerWidth + 6}px, ${((1 - s.y) / 2) * window.innerHeight - 8}px)`;
  }
}
function frame() {
  renderer.render(scene, camera);
  if (occludeEveryFrame) {
    occlude();
  } else {
    clearTimeout(occlusionTimer);
    occlusionTimer = setTimeout(() => { occlude(); placeLabels(); }, 200);
  }
  placeLabels();
}
controls.addEventListener('change', frame);
window.addEventListener('resize', () => {
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(window.innerWidth, window.innerHeight);
  frame();
});
frame();
for (const layer of summary.layers)
  if (layer.kind === 'points')
    layer.hidden_labels = labels.filter((l) => l.owner.name === layer.name && l.hidden).length;
summary.load_ms = Math.round(performance.now() - started);
document.getElementById('tessera-summary').textContent = JSON.stringify(summary);
