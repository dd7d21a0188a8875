// The lighting-design page (Dobashi 1995 section 4; docs/serve.md): a relit view of the
// room, a polar editor per lamp, aiming by clicking, colour, dimming, isolux overlay,
// saving and loading the lighting. The weighted sums of eq. (18) run on the server; this
// page fetches the per-vertex luminances after every edit and draws them (Gouraud).
//
// For tests and tools, window.penumbra exposes readiness and a few queries;
// document.body.dataset.ready becomes "true" once the first relit frame is drawn.

import * as api from './api.js';
import {Camera, Viewer} from './viewer.js';
import {PolarEditor} from './polar_editor.js';

const $ = (id) => document.getElementById(id);

const app = {
  scene: null,
  mesh: null,
  viewer: null,
  editor: null,
  lamps: new Map(),   // name -> the API's lamp state
  selected: null,
  aiming: false,
  navigation: 'orbit',
  autoExposure: 1,
  pendingMove: null,  // the latest control-point move not yet sent
  moveInFlight: false,
  relightInFlight: false,
  relightQueued: null,  // the edit time of a relight asked for while one was in flight
  latencies: [],        // edit -> frame drawn, ms
};

// What tests and tools may read (see the file comment).
const exposed = {
  ready: false,
  busy: 0,            // requests in flight or queued
  relitFrames: 0,     // frames drawn with new relit values
  lastLatencyMs: null,
  lastServerMs: null,
  lastAim: null,
  selectedLamp: () => app.selected,
  selectLamp: (name) => selectLamp(name),
  controlPointClientPosition: (index) => app.editor.controlPointClientPosition(index),
  // returns the client coordinates of world point p in the view, or null.
  worldToClient: (p) => {
    const position = app.viewer.project(p);
    if (!position) return null;
    const rect = app.viewer.canvas.getBoundingClientRect();
    return [rect.left + position[0], rect.top + position[1]];
  },
  pickClient: (x, y) => {
    const rect = app.viewer.canvas.getBoundingClientRect();
    return app.viewer.pick(x - rect.left, y - rect.top);
  },
};
window.penumbra = exposed;

function setStatus(text, error = false) {
  $('status').textContent = text;
  $('status').classList.toggle('error', error);
}

function report(error) {
  console.error(error);
  setStatus(error.message || String(error), true);
}

// === Colours: the page shows sRGB, the server multiplies linear channels.

const toLinear = (c) => (c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4));
const toSrgb = (c) => (c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055);

function hexToLinear(hex) {
  return [1, 3, 5].map((i) => toLinear(parseInt(hex.slice(i, i + 2), 16) / 255));
}

function linearToHex(colour) {
  const peak = Math.max(1, ...colour);
  return '#' + colour.map((c) => Math.round(toSrgb(Math.max(0, c) / peak) * 255)
                                        .toString(16).padStart(2, '0')).join('');
}

// === Relighting. An edit's answer carries the relit values (one round trip); a plain
// refresh (start, a loaded lighting file) asks for them alone, one request at a time.

// shows relit values fetched for an edit made at editTime (performance.now()).
function showRelit(relit, editTime, asked) {
  const fetched = performance.now();
  app.viewer.setRelit(relit);
  if (!exposed.ready) {
    app.autoExposure = app.viewer.autoExposure();
    applyExposure();
  }
  drawView();
  const drawn = performance.now();
  const latency = drawn - editTime;
  // where the time went: before the request, the request (edit and relight), upload and draw
  exposed.lastBreakdown = {beforeMs: asked - editTime, fetchMs: fetched - asked, drawMs: drawn - fetched};
  exposed.relitFrames++;
  exposed.lastLatencyMs = latency;
  exposed.lastServerMs = relit.serverMs;
  app.latencies.push(latency);
  if (app.latencies.length > 50) app.latencies.shift();
  showStats();
  updateLegend();
  if (!exposed.ready) {
    exposed.ready = true;
    document.body.dataset.ready = 'true';
    setStatus('ready');
  }
}

async function relight(editTime = performance.now()) {
  if (app.relightInFlight) {
    if (app.relightQueued === null) {
      app.relightQueued = editTime;
      exposed.busy++;
    }
    return;
  }
  app.relightInFlight = true;
  exposed.busy++;
  try {
    const asked = performance.now();
    showRelit(await api.getRelight(app.mesh), editTime, asked);
  } catch (error) {
    report(error);
  } finally {
    app.relightInFlight = false;
    exposed.busy--;
    if (app.relightQueued !== null) {
      const queued = app.relightQueued;
      app.relightQueued = null;
      exposed.busy--;
      relight(queued);
    }
  }
}

function drawView() {
  app.viewer.selectedLamp = app.selected;
  app.viewer.lamps = [...app.lamps.values()];
  app.viewer.draw();
}

function showStats() {
  const sorted = [...app.latencies].sort((a, b) => a - b);
  const median = sorted.length ? sorted[Math.floor(sorted.length / 2)] : 0;
  $('stats').textContent =
      `${app.scene.patches} patches, ${app.mesh.vertices} vertices, ${app.mesh.triangles} triangles\n` +
      `relight on the server (eq. 18): ${exposed.lastServerMs.toFixed(2)} ms\n` +
      `edit -> frame: last ${exposed.lastLatencyMs.toFixed(1)} ms, median ${median.toFixed(1)} ms`;
}

// === Lamps

function lampState(name) {
  return app.lamps.get(name);
}

function setLampState(state) {
  app.lamps.set(state.name, state);
  if (state.name === app.selected) showLamp();
}

function showLamp() {
  const lamp = lampState(app.selected);
  if (!lamp) return;
  if (!(app.editor.dragging >= 0 && app.pendingMove)) app.editor.setLamp(lamp);
  $('sigma').checked = !!lamp.sigma;
  $('sigma').disabled = !lamp.editable;
  $('aim').disabled = lamp.kind !== 'point';
  $('colour').value = linearToHex(lamp.colour);
  $('dimming').value = Math.round(lamp.scale * 100);
  $('dimming-value').textContent = `${Math.round(lamp.scale * 100)} %`;
  $('weights').textContent = lamp.weights
      ? 'w_l (eq. 19-21): ' + lamp.weights.map((w) => w.toFixed(2)).join(', ')
      : `${lamp.kind} source: colour and dimming only`;
}

function selectLamp(name) {
  if (!app.lamps.has(name)) return;
  app.selected = name;
  $('lamp-select').value = name;
  showLamp();
  drawView();
}

async function changeLamp(changes) {
  const editTime = performance.now();
  exposed.busy++;
  try {
    const {lamp, relit} = await api.updateLightRelit(app.selected, changes, app.mesh);
    setLampState(lamp);
    showRelit(relit, editTime, editTime);
  } catch (error) {
    report(error);
  } finally {
    exposed.busy--;
  }
}

// Section 4.1: a control point dragged. Only the latest position is sent; the server
// updates the weights by eq. (21) and answers the lamp's new state and the relit values.
function controlMoved(index, candela) {
  if (app.pendingMove === null) exposed.busy++;
  app.pendingMove = {name: app.selected, index, candela, editTime: performance.now()};
  sendMoves();
}

async function sendMoves() {
  if (app.moveInFlight || app.pendingMove === null) return;
  const move = app.pendingMove;
  app.pendingMove = null;
  app.moveInFlight = true;
  try {
    const asked = performance.now();
    const {lamp, relit} = await api.moveControlPointRelit(move.name, move.index, move.candela, app.mesh);
    app.lamps.set(lamp.name, lamp);
    if (app.pendingMove === null && lamp.name === app.selected) showLamp();
    showRelit(relit, move.editTime, asked);
  } catch (error) {
    report(error);
  } finally {
    app.moveInFlight = false;
    exposed.busy--;
    sendMoves();
  }
}

// === The view: navigation, aiming, lux under the cursor

function applyExposure() {
  app.viewer.exposure = app.autoExposure * Math.pow(2, Number($('exposure').value));
}

function updateLegend() {
  const legend = $('legend');
  legend.hidden = !app.viewer.isolux;
  if (legend.hidden || !app.viewer.relit) return;
  const lux = app.viewer.relit.vertexLux;
  let low = Infinity, high = 0;
  for (const e of lux) if (e > 0) { low = Math.min(low, e); high = Math.max(high, e); }
  low = Math.max(low, high * 1e-3);  // three decades at most: the belts that matter
  const palette = ['#4059f2', '#1abfe6', '#33cc4d', '#f2e633', '#fa8c1a', '#e6263a'];
  const parts = [];
  for (let decade = Math.floor(Math.log10(Math.max(low, 1e-3))); decade <= Math.log10(Math.max(high, 1e-3)); ++decade)
    [1, 2, 5].forEach((m, j) => {
      const level = m * Math.pow(10, decade);
      if (level > high || level * (j === 2 ? 2 : 2.5) < low) return;
      const index = decade * 3 + j;
      parts.push(`<span style="background:${palette[((index % 6) + 6) % 6]}"></span>${level >= 1 ? level : level.toPrecision(1)}`);
    });
  legend.innerHTML = 'lx ' + parts.join('');
}

async function aimAt(x, y) {
  const hit = app.viewer.pick(x, y);
  if (!hit) return;
  exposed.lastAim = hit;
  app.aiming = false;
  $('aim').classList.remove('active');
  $('view').classList.remove('aiming');
  await changeLamp({aim: hit.point});
}

// The lux under the cursor: the ID buffer names the patch, the server its illuminance
// (one request at a time; the latest position wins).
const hover = {frame: null, inFlight: false, next: null};
function showLuxUnderCursor(x, y) {
  if (hover.frame !== null) cancelAnimationFrame(hover.frame);
  hover.frame = requestAnimationFrame(() => {
    hover.frame = null;
    const hit = app.viewer.relit ? app.viewer.pick(x, y) : null;
    if (!hit) {
      $('cursor-lux').hidden = true;
      return;
    }
    hover.next = {patch: hit.patch, x, y};
    fetchLuxUnderCursor();
  });
}

async function fetchLuxUnderCursor() {
  if (hover.inFlight || hover.next === null) return;
  const {patch, x, y} = hover.next;
  hover.next = null;
  hover.inFlight = true;
  try {
    const {lux, object} = await api.luxAtPatch(patch);
    const label = $('cursor-lux');
    label.textContent = `${lux.toFixed(lux < 10 ? 2 : 0)} lx · ${object}`;
    label.style.left = `${x + 14}px`;
    label.style.top = `${y + 14}px`;
    label.hidden = false;
  } catch (error) {
    report(error);
  } finally {
    hover.inFlight = false;
    fetchLuxUnderCursor();
  }
}

function installViewControls() {
  const canvas = $('view');
  let down = null;
  canvas.addEventListener('contextmenu', (event) => event.preventDefault());
  canvas.addEventListener('pointerdown', (event) => {
    down = {x: event.offsetX, y: event.offsetY, lastX: event.offsetX, lastY: event.offsetY,
            button: event.button, shift: event.shiftKey, moved: false};
    canvas.setPointerCapture(event.pointerId);
    canvas.focus();
  });
  canvas.addEventListener('pointermove', (event) => {
    if (!down) {
      showLuxUnderCursor(event.offsetX, event.offsetY);
      return;
    }
    const dx = event.offsetX - down.lastX, dy = event.offsetY - down.lastY;
    down.lastX = event.offsetX;
    down.lastY = event.offsetY;
    if (Math.hypot(event.offsetX - down.x, event.offsetY - down.y) > 3) down.moved = true;
    if (!down.moved) return;
    const camera = app.viewer.camera;
    if (down.button === 2 || down.shift) camera.pan(dx, dy);
    else camera.rotate(dx, dy, app.navigation === 'orbit');
    drawView();
  });
  canvas.addEventListener('pointerup', (event) => {
    const click = down && !down.moved && down.button === 0;
    down = null;
    if (canvas.hasPointerCapture(event.pointerId)) canvas.releasePointerCapture(event.pointerId);
    if (click && app.aiming) aimAt(event.offsetX, event.offsetY);
  });
  canvas.addEventListener('pointerleave', () => ($('cursor-lux').hidden = true));
  canvas.addEventListener('wheel', (event) => {
    event.preventDefault();
    const camera = app.viewer.camera;
    if (app.navigation === 'orbit') camera.zoom(Math.exp(event.deltaY * 0.001));
    else camera.walk(-event.deltaY * 0.002, 0, 0);
    drawView();
  }, {passive: false});
  // Walk-through: WASD or arrows to move, Q / E down and up (either mode).
  window.addEventListener('keydown', (event) => {
    if (event.target instanceof HTMLInputElement || event.target instanceof HTMLSelectElement) return;
    const step = event.shiftKey ? 0.3 : 0.1;
    const moves = {w: [step, 0, 0], ArrowUp: [step, 0, 0], s: [-step, 0, 0], ArrowDown: [-step, 0, 0],
                   a: [0, -step, 0], ArrowLeft: [0, -step, 0], d: [0, step, 0], ArrowRight: [0, step, 0],
                   q: [0, 0, -step], e: [0, 0, step]};
    const move = moves[event.key];
    if (!move) return;
    event.preventDefault();
    app.viewer.camera.walk(...move);
    drawView();
  });
  window.addEventListener('resize', () => drawView());
}

function initialCamera() {
  const camera = app.scene.camera;
  if (camera) return new Camera(camera.eye, camera.target, camera.fov_deg);
  const {min, max} = app.scene.bounds;
  const centre = [0, 1, 2].map((i) => (min[i] + max[i]) / 2);
  const size = Math.max(...[0, 1, 2].map((i) => max[i] - min[i]));
  return new Camera([centre[0] + size, centre[1] - size, centre[2] + size * 0.6], centre, 50);
}

// === Panel controls

function download(blob, name) {
  const link = document.createElement('a');
  link.href = URL.createObjectURL(blob);
  link.download = name;
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 1000);
}

function installPanel() {
  $('lamp-select').addEventListener('change', (event) => selectLamp(event.target.value));
  $('sigma').addEventListener('change', (event) => changeLamp({sigma: event.target.checked}));
  $('colour').addEventListener('input', (event) => changeLamp({colour: hexToLinear(event.target.value)}));
  $('dimming').addEventListener('input', (event) => {
    $('dimming-value').textContent = `${event.target.value} %`;
    changeLamp({scale: Number(event.target.value) / 100});
  });
  $('aim').addEventListener('click', () => {
    app.aiming = !app.aiming;
    $('aim').classList.toggle('active', app.aiming);
    $('view').classList.toggle('aiming', app.aiming);
  });
  for (const radio of document.querySelectorAll('input[name="navigation"]'))
    radio.addEventListener('change', (event) => {
      app.navigation = event.target.value;
      $('hint').textContent = app.navigation === 'orbit'
          ? 'drag: orbit · right-drag: pan · wheel: zoom · WASD/QE: walk'
          : 'drag: look · wheel or WASD: walk · QE: down/up';
    });
  $('reset-view').addEventListener('click', () => {
    app.viewer.camera = initialCamera();
    drawView();
  });
  $('exposure').addEventListener('input', () => {
    applyExposure();
    drawView();
  });
  $('auto-exposure').addEventListener('click', () => {
    app.autoExposure = app.viewer.autoExposure();
    $('exposure').value = 0;
    applyExposure();
    drawView();
  });
  $('isolux').addEventListener('change', (event) => {
    app.viewer.isolux = event.target.checked;
    updateLegend();
    drawView();
  });
  $('save').addEventListener('click', async () => {
    try {
      const lighting = await api.getLighting();
      download(new Blob([JSON.stringify(lighting, null, 2)], {type: 'application/json'}), 'lighting.json');
    } catch (error) {
      report(error);
    }
  });
  $('load').addEventListener('change', async (event) => {
    const file = event.target.files[0];
    event.target.value = '';
    if (!file) return;
    const editTime = performance.now();
    try {
      await api.putLighting(JSON.parse(await file.text()));
      for (const lamp of (await api.getLights()).lights) app.lamps.set(lamp.name, lamp);
      showLamp();
      relight(editTime);
      setStatus(`loaded ${file.name}`);
    } catch (error) {
      report(error);
    }
  });
  $('export').addEventListener('click', () => {
    drawView();
    app.viewer.canvas.toBlob((blob) => download(blob, 'penumbra.png'), 'image/png');
  });
  $('hint').textContent = 'drag: orbit · right-drag: pan · wheel: zoom · WASD/QE: walk';
}

async function start() {
  try {
    const [scene, mesh] = await Promise.all([api.getScene(), api.getMesh()]);
    app.scene = scene;
    app.mesh = mesh;
    $('scene-name').textContent = scene.scene_file;
    for (const lamp of scene.lights) app.lamps.set(lamp.name, lamp);
    app.viewer = new Viewer($('view'), mesh, initialCamera());
    app.editor = new PolarEditor($('polar'), controlMoved, () => showLamp());
    const select = $('lamp-select');
    for (const lamp of scene.lights) select.add(new Option(`${lamp.name} (${lamp.kind})`, lamp.name));
    installPanel();
    installViewControls();
    const first = scene.lights.find((lamp) => lamp.editable) || scene.lights[0];
    if (first) selectLamp(first.name);
    await relight();
  } catch (error) {
    report(error);
  }
}

start();
