// The HTML report's 3D view: reads the page's data blocks (base64 typed arrays described by the
// JSON block #mesh-info), loads the embedded three.js through blob URLs (the page is one file,
// opened without a network), and draws the surface, its boundary loops and the distance colours.
// It records how far it got in document.body.dataset.view ("rendered", "empty", "failed"), which
// the tests read.

const info = JSON.parse(document.getElementById('mesh-info').textContent);
const viewBox = document.getElementById('view');
const viewMessage = document.getElementById('view-message');

function setState(state, message) {
  document.body.dataset.view = state;
  if (message !== undefined) {
    viewMessage.textContent = message;
    viewMessage.hidden = false;
  } else {
    viewMessage.hidden = true;
  }
}

function decode(id, ArrayType) {
  const element = document.getElementById(id);
  if (!element) return new ArrayType(0);
  const text = atob(element.textContent.trim());
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
  return new ArrayType(bytes.buffer);
}

function moduleUrl(source) {
  return URL.createObjectURL(new Blob([source], { type: 'text/javascript' }));
}

// three.js as modules without a server: the module from a blob URL, and the controls with
// their import of 'three' pointed at that URL.
async function loadThree() {
  const threeUrl = moduleUrl(document.getElementById('three-module').textContent);
  const THREE = await import(threeUrl);
  const controlsSource = document.getElementById('orbit-controls').textContent
    .replace(/from\s*['"]three['"]/g, "from '" + threeUrl + "'");
  const { OrbitControls } = await import(moduleUrl(controlsSource));
  return { THREE, OrbitControls };
}

// Perceptual colour scale (viridis, 9 stops), t in [0, 1].
const scaleStops = [[0.267, 0.005, 0.329], [0.279, 0.175, 0.483], [0.230, 0.322, 0.546], [0.173, 0.449, 0.558],
                    [0.128, 0.567, 0.551], [0.153, 0.680, 0.504], [0.369, 0.789, 0.383], [0.678, 0.864, 0.190],
                    [0.993, 0.906, 0.144]];
function scaleColor(t, out, offset) {
  const x = Math.min(Math.max(t, 0), 1) * (scaleStops.length - 1);
  const i = Math.min(Math.floor(x), scaleStops.length - 2);
  const f = x - i;
  for (let c = 0; c < 3; ++c) out[offset + c] = scaleStops[i][c] * (1 - f) + scaleStops[i + 1][c] * f;
}
const loopPalette = ['#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf', '#e377c2', '#8c564b', '#bcbd22',
                     '#1f77b4', '#7f7f7f'];

function formatNumber(x) {
  return Math.abs(x) >= 1e4 || (x !== 0 && Math.abs(x) < 1e-3) ? x.toExponential(3) : x.toPrecision(4);
}

function addLegend(top, max) {
  const legend = document.getElementById('legend');
  const stops = scaleStops.map((c, i) =>
    'rgb(' + c.map((v) => Math.round(255 * v)).join(',') + ') ' + (100 * i / (scaleStops.length - 1)) + '%');
  legend.innerHTML = '';
  const title = document.createElement('div');
  title.textContent = info.distance.label;
  const bar = document.createElement('div');
  bar.className = 'bar';
  bar.style.background = 'linear-gradient(to right, ' + stops.join(', ') + ')';
  const ends = document.createElement('div');
  ends.className = 'ends';
  const low = document.createElement('span');
  low.textContent = '0';
  const high = document.createElement('span');
  high.textContent = formatNumber(top) + (max > top ? ' (max ' + formatNumber(max) + ')' : '');
  ends.append(low, high);
  legend.append(title, bar, ends);
}

// A closed polyline as a curve through its vertices at parameters i / n, for TubeGeometry.
function polylineCurve(THREE, points) {
  const n = points.length;
  class ClosedPolyline extends THREE.Curve {
    getPoint(t, target = new THREE.Vector3()) {
      const x = (((t % 1) + 1) % 1) * n;
      const i = Math.min(Math.floor(x), n - 1);
      return target.copy(points[i]).lerp(points[(i + 1) % n], x - i);
    }
    getPointAt(u, target) { return this.getPoint(u, target); }
    getTangent(t, target = new THREE.Vector3()) {
      const i = Math.round((((t % 1) + 1) % 1) * n) % n;
      target.subVectors(points[(i + 1) % n], points[(i + n - 1) % n]);
      if (target.lengthSq() === 0) target.set(1, 0, 0);
      return target.normalize();
    }
    getTangentAt(u, target) { return this.getTangent(u, target); }
  }
  return new ClosedPolyline();
}

function addLoops(THREE, group, radius) {
  const coords = decode('data-loop-points', Float32Array);
  const key = document.getElementById('loop-key');
  const total = info.loops.reduce((a, b) => a + b, 0);
  // Tubes read well but cost 7 vertices per loop vertex: beyond that, one-pixel lines.
  const useTubes = total <= 300000;
  let start = 0;
  info.loops.forEach((count, index) => {
    const color = new THREE.Color(loopPalette[index % loopPalette.length]);
    const points = [];
    for (let i = 0; i < count; ++i) {
      points.push(new THREE.Vector3(coords[3 * (start + i)], coords[3 * (start + i) + 1], coords[3 * (start + i) + 2]));
    }
    start += count;
    if (useTubes && count >= 3) {
      const tube = new THREE.TubeGeometry(polylineCurve(THREE, points), count, radius, 6, true);
      group.add(new THREE.Mesh(tube, new THREE.MeshLambertMaterial({ color })));
    } else {
      const line = new THREE.BufferGeometry().setFromPoints(points);
      group.add(new THREE.LineLoop(line, new THREE.LineBasicMaterial({ color })));
    }
    if (index < 12) {
      const row = document.createElement('div');
      const swatch = document.createElement('span');
      swatch.className = 'swatch';
      swatch.style.background = '#' + color.getHexString();
      row.append(swatch, 'loop ' + index);
      key.append(row);
    } else if (index === 12) {
      key.append('and ' + (info.loops.length - 12) + ' more');
    }
  });
  key.hidden = info.loops.length === 0;
}

async function main() {
  if (info.vertices === 0) {
    document.getElementById('toolbar').hidden = true;
    setState('empty', info.empty_message);
    return;
  }
  let three;
  try {
    three = await loadThree();
  } catch (error) {
    setState('failed', 'The 3D view could not start (three.js did not load: ' + error.message + ').');
    return;
  }
  const { THREE, OrbitControls } = three;
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true });
  } catch (error) {
    setState('failed', 'The 3D view needs WebGL, which this browser does not offer here: ' + error.message);
    return;
  }
  renderer.setPixelRatio(window.devicePixelRatio);
  viewBox.prepend(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  const positions = decode('data-positions', Float32Array);
  const faces = decode('data-faces', Uint32Array);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  const radius = Math.max(info.radius, 1e-12);
  const content = new THREE.Group();
  scene.add(content);
  let front = null;
  let back = null;
  if (faces.length > 0) {
    geometry.setIndex(new THREE.BufferAttribute(faces, 1));
    geometry.computeVertexNormals();
    // Front and back faces in the colours of `envcrust render`, so an open surface reads as open.
    front = new THREE.MeshPhongMaterial({ color: 0xccccd9, side: THREE.FrontSide, shininess: 20,
                                          polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
    back = new THREE.MeshPhongMaterial({ color: 0xd97359, side: THREE.BackSide, shininess: 10,
                                         polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
    content.add(new THREE.Mesh(geometry, front), new THREE.Mesh(geometry, back));
  } else {
    content.add(new THREE.Points(geometry, new THREE.PointsMaterial({ color: 0x4a5a78, size: 3, sizeAttenuation: false })));
  }
  const loops = new THREE.Group();
  addLoops(THREE, loops, 0.004 * radius);
  content.add(loops);

  scene.add(new THREE.HemisphereLight(0xffffff, 0x808080, 1.2));
  const camera = new THREE.PerspectiveCamera(35, 1, radius / 100, radius * 100);
  camera.up.set(0, 0, 1);
  const headlight = new THREE.DirectionalLight(0xffffff, 1.8);
  headlight.position.set(-0.5, 1, 1);  // from the upper left of the viewer
  camera.add(headlight);
  scene.add(camera);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = false;
  function resetView() {
    // As `envcrust render`'s default: azimuth 45 degrees about +z, elevation 30, +z up.
    // The bounding sphere fits the narrower of the view's two angles.
    const aspect = Math.max(viewBox.clientWidth, 1) / Math.max(viewBox.clientHeight, 1);
    const halfHeight = (camera.fov / 2) * Math.PI / 180;
    const halfAngle = Math.min(halfHeight, Math.atan(Math.tan(halfHeight) * aspect));
    const distance = radius / Math.sin(halfAngle) * 1.05;
    const az = Math.PI / 4;
    const el = Math.PI / 6;
    camera.position.set(distance * Math.cos(el) * Math.cos(az), distance * Math.cos(el) * Math.sin(az), distance * Math.sin(el));
    controls.target.set(0, 0, 0);
    camera.lookAt(0, 0, 0);
    controls.update();
  }
  function draw() {
    renderer.render(scene, camera);
  }
  // Until the user turns or zooms the view, a new size of the window frames the result again.
  let isMovedByUser = false;
  function resize() {
    const width = Math.max(viewBox.clientWidth, 1);
    const height = Math.max(viewBox.clientHeight, 1);
    renderer.setSize(width, height, false);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    if (!isMovedByUser) resetView();
    draw();
  }
  controls.addEventListener('start', () => { isMovedByUser = true; });
  controls.addEventListener('change', draw);
  new ResizeObserver(resize).observe(viewBox);
  resetView();

  const loopToggle = document.getElementById('show-loops');
  loopToggle.addEventListener('change', () => { loops.visible = loopToggle.checked; draw(); });
  document.getElementById('reset-view').addEventListener('click', () => { isMovedByUser = false; resetView(); draw(); });

  const distanceToggle = document.getElementById('show-distance');
  if (info.distance && front) {
    const distances = decode('data-distances', Float32Array);
    const colors = new Float32Array(3 * distances.length);
    const top = info.distance.scale_top > 0 ? info.distance.scale_top : 1;
    for (let i = 0; i < distances.length; ++i) scaleColor(distances[i] / top, colors, 3 * i);
    geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
    addLegend(info.distance.scale_top, info.distance.max);
    const apply = () => {
      const on = distanceToggle.checked;
      for (const material of [front, back]) {
        material.vertexColors = on;
        material.color.set(on ? 0xffffff : material === front ? 0xccccd9 : 0xd97359);
        material.needsUpdate = true;
      }
      document.getElementById('legend').hidden = !on;
      draw();
    };
    distanceToggle.addEventListener('change', apply);
    if (window.location.hash === '#distance') distanceToggle.checked = true;  // a link can open the map
    apply();
  } else {
    distanceToggle.disabled = true;
    distanceToggle.parentElement.classList.add('disabled');
    distanceToggle.parentElement.title = info.no_distance_reason;
  }
  resize();
  setState('rendered');
}

main().catch((error) => setState('failed', 'The 3D view failed: ' + error.message));
