// The polar editor of a lamp's intensity curve (Dobashi 1995 section 4.1, Fig. 4): control
// points every few degrees on the right half, the curve through them (mirrored on the
// left, the lamp being rotationally symmetric), and beside it the Legendre series the
// lamp is lit with (eq. 2, or eq. 12 with sigma factors), drawn dashed. gamma = 0, the
// lamp's axis, points down. Dragging a point changes its intensity only (its angle is
// fixed); onMove(index, candela) reports it.

const HIT_RADIUS = 9;  // CSS pixels

export class PolarEditor {
  constructor(canvas, onMove, onRelease) {
    this.canvas = canvas;
    this.onMove = onMove;
    this.onRelease = onRelease;
    this.lamp = null;
    this.dragging = -1;
    this.scaleCandela = 1;
    canvas.addEventListener('pointerdown', (event) => this.pointerDown(event));
    canvas.addEventListener('pointermove', (event) => this.pointerMove(event));
    canvas.addEventListener('pointerup', (event) => this.pointerUp(event));
    canvas.addEventListener('pointercancel', (event) => this.pointerUp(event));
  }

  // shows lamp (the API's lamp state); keeps the scale while a point is dragged.
  setLamp(lamp) {
    const sameLamp = this.lamp && lamp && this.lamp.name === lamp.name;
    this.lamp = lamp;
    if (!(sameLamp && this.dragging >= 0)) this.rescale();
    this.draw();
  }

  rescale() {
    if (!this.lamp || !this.lamp.controls) return;
    const highest = Math.max(1, ...this.lamp.controls.candela, ...this.lamp.approximation.candela);
    // a round number of candela for the outer circle
    const magnitude = Math.pow(10, Math.floor(Math.log10(highest)));
    this.scaleCandela = Math.ceil((highest * 1.15) / magnitude) * magnitude;
  }

  geometry() {
    const width = this.canvas.clientWidth, height = this.canvas.clientHeight;
    return {cx: width / 2, cy: height / 2, radius: Math.min(width, height) / 2 - 18};
  }

  // returns the CSS pixel (relative to the canvas) of intensity candela toward gamma
  // (radians); side -1 draws the mirror image.
  toCanvas(gamma, candela, side = 1) {
    const {cx, cy, radius} = this.geometry();
    const r = (Math.max(0, candela) / this.scaleCandela) * radius;
    return [cx + side * r * Math.sin(gamma), cy + r * Math.cos(gamma)];
  }

  // returns the client (page) coordinates of control point index, for tests and tools.
  controlPointClientPosition(index) {
    const rect = this.canvas.getBoundingClientRect();
    const gamma = (this.lamp.controls.angles_deg[index] * Math.PI) / 180;
    const [x, y] = this.toCanvas(gamma, this.lamp.controls.candela[index]);
    return [rect.left + x, rect.top + y];
  }

  // returns the intensity that a pointer at canvas (x, y) gives control point index: the
  // pointer's projection onto the point's ray.
  candelaAt(index, x, y) {
    const {cx, cy, radius} = this.geometry();
    const gamma = (this.lamp.controls.angles_deg[index] * Math.PI) / 180;
    const along = (x - cx) * Math.sin(gamma) + (y - cy) * Math.cos(gamma);
    return (Math.max(0, along) / radius) * this.scaleCandela;
  }

  local(event) {
    const rect = this.canvas.getBoundingClientRect();
    return [event.clientX - rect.left, event.clientY - rect.top];
  }

  pointerDown(event) {
    if (!this.lamp || !this.lamp.controls) return;
    const [x, y] = this.local(event);
    let best = -1, bestDistance = HIT_RADIUS;
    this.lamp.controls.candela.forEach((candela, index) => {
      const gamma = (this.lamp.controls.angles_deg[index] * Math.PI) / 180;
      const [px, py] = this.toCanvas(gamma, candela);
      const distance = Math.hypot(px - x, py - y);
      if (distance <= bestDistance) {
        best = index;
        bestDistance = distance;
      }
    });
    if (best < 0) return;
    this.dragging = best;
    this.canvas.setPointerCapture(event.pointerId);
    event.preventDefault();
  }

  pointerMove(event) {
    if (this.dragging < 0) return;
    const [x, y] = this.local(event);
    const candela = this.candelaAt(this.dragging, x, y);
    this.lamp.controls.candela[this.dragging] = candela;  // shown at once; the server confirms
    this.draw();
    this.onMove(this.dragging, candela);
  }

  pointerUp(event) {
    if (this.dragging < 0) return;
    const index = this.dragging;
    this.dragging = -1;
    if (this.canvas.hasPointerCapture(event.pointerId)) this.canvas.releasePointerCapture(event.pointerId);
    this.rescale();
    this.draw();
    this.onRelease(index);
  }

  draw() {
    const ratio = window.devicePixelRatio || 1;
    const width = this.canvas.clientWidth, height = this.canvas.clientHeight;
    if (this.canvas.width !== Math.round(width * ratio)) this.canvas.width = Math.round(width * ratio);
    if (this.canvas.height !== Math.round(height * ratio)) this.canvas.height = Math.round(height * ratio);
    const g = this.canvas.getContext('2d');
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.clearRect(0, 0, width, height);
    const {cx, cy, radius} = this.geometry();
    // grid: circles at quarters of the scale, rays every 30 degrees
    g.strokeStyle = '#3a3f47';
    g.fillStyle = '#8b93a1';
    g.font = '10px sans-serif';
    g.lineWidth = 1;
    for (let q = 1; q <= 4; ++q) {
      g.beginPath();
      g.arc(cx, cy, (radius * q) / 4, 0, 2 * Math.PI);
      g.stroke();
      g.fillText(`${Math.round((this.scaleCandela * q) / 4)} cd`, cx + 3, cy + (radius * q) / 4 - 2);
    }
    for (let degrees = 0; degrees < 360; degrees += 30) {
      const a = (degrees * Math.PI) / 180;
      g.beginPath();
      g.moveTo(cx, cy);
      g.lineTo(cx + radius * Math.sin(a), cy + radius * Math.cos(a));
      g.stroke();
    }
    if (!this.lamp || !this.lamp.controls) {
      g.fillText('this light has no editable curve', 10, 16);
      return;
    }
    const {angles_deg: angles, candela} = this.lamp.controls;
    const curve = (points, side) => {
      g.beginPath();
      points.forEach(([gamma, value], i) => {
        const [x, y] = this.toCanvas(gamma, value, side);
        if (i === 0) g.moveTo(x, y); else g.lineTo(x, y);
      });
      g.stroke();
    };
    const controlPoints = angles.map((degrees, i) => [(degrees * Math.PI) / 180, candela[i]]);
    const approximation = this.lamp.approximation.candela.map(
        (value, i) => [(i * this.lamp.approximation.step_deg * Math.PI) / 180, value]);
    // the edited curve (linear between control points, section 4.1)
    g.lineWidth = 2;
    g.setLineDash([]);
    g.strokeStyle = '#f0c040';
    curve(controlPoints, 1);
    g.strokeStyle = 'rgba(240, 192, 64, 0.45)';
    curve(controlPoints, -1);
    // the Legendre approximation the room is lit with
    g.setLineDash([6, 4]);
    g.strokeStyle = '#50b4ff';
    curve(approximation, 1);
    curve(approximation, -1);
    g.setLineDash([]);
    controlPoints.forEach(([gamma, value], i) => {
      const [x, y] = this.toCanvas(gamma, value);
      g.beginPath();
      g.arc(x, y, i === this.dragging ? 6 : 4, 0, 2 * Math.PI);
      g.fillStyle = i === this.dragging ? '#ffffff' : '#f0c040';
      g.fill();
    });
    g.fillStyle = '#c8ced8';
    g.fillText('0\u00b0 (axis)', cx + 4, cy + radius + 12);
    g.fillText('180\u00b0', cx + 4, cy - radius - 4);
  }
}
