// The 3D view (Dobashi 1995 sections 3.5 step 4 and 4.3): patches drawn with Gouraud
// shading of the relit vertex luminances, an isolux overlay, lamp markers, orbit and
// walk-through cameras, and the ID buffer of section 4.2 (after Hanrahan and Haeberli
// 1990) that finds the patch under a pixel.

const LEVELS_PER_DECADE = 3;  // isolux levels 1, 2, 5 x 10^k lux

const MAIN_VERTEX = `#version 300 es
uniform mat4 view_projection;
in vec3 position;
in vec3 luminance;
in float lux;
out vec3 v_luminance;
out float v_lux;
void main() {
  v_luminance = luminance;
  v_lux = lux;
  gl_Position = view_projection * vec4(position, 1.0);
}`;

const MAIN_FRAGMENT = `#version 300 es
precision highp float;
uniform float exposure;
uniform bool isolux;
in vec3 v_luminance;
in float v_lux;
out vec4 colour;
vec3 srgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
// the isolux belt of lux: levels 1, 2, 5 x 10^k (Nishita 1985 section 5's colour belts)
float level(float e) {
  float l = log(max(e, 1e-3)) / log(10.0);
  float decade = floor(l);
  float f = l - decade;
  return decade * 3.0 + (f < 0.30103 ? 0.0 : (f < 0.69897 ? 1.0 : 2.0));
}
const vec3 palette[6] = vec3[6](vec3(0.25, 0.35, 0.95), vec3(0.1, 0.75, 0.9), vec3(0.2, 0.8, 0.3),
                                vec3(0.95, 0.9, 0.2), vec3(0.98, 0.55, 0.1), vec3(0.9, 0.15, 0.2));
void main() {
  vec3 shaded = srgb(v_luminance * exposure);
  if (isolux) {
    float index = level(v_lux);
    vec3 belt = palette[int(mod(index + 600.0, 6.0))];
    shaded = mix(shaded, belt, 0.35);
    if (fwidth(index) > 0.0) shaded = vec3(0.05);
  }
  colour = vec4(shaded, 1.0);
}`;

const ID_VERTEX = `#version 300 es
uniform mat4 view_projection;
in vec3 position;
in vec3 id;
flat out vec3 v_id;
void main() {
  v_id = id;
  gl_Position = view_projection * vec4(position, 1.0);
}`;

const ID_FRAGMENT = `#version 300 es
precision highp float;
flat in vec3 v_id;
out vec4 colour;
void main() { colour = vec4(v_id, 1.0); }`;

const LINE_VERTEX = `#version 300 es
uniform mat4 view_projection;
in vec3 position;
in vec3 tint;
out vec3 v_tint;
void main() {
  v_tint = tint;
  gl_Position = view_projection * vec4(position, 1.0);
  gl_PointSize = 9.0;
}`;

const LINE_FRAGMENT = `#version 300 es
precision highp float;
in vec3 v_tint;
out vec4 colour;
void main() { colour = vec4(v_tint, 1.0); }`;

// === Small 4 x 4 matrix helpers (column-major, as WebGL takes them)

function perspective(fovyRadians, aspect, near, far) {
  const f = 1 / Math.tan(fovyRadians / 2);
  const m = new Float32Array(16);
  m[0] = f / aspect; m[5] = f; m[10] = (far + near) / (near - far); m[11] = -1;
  m[14] = (2 * far * near) / (near - far);
  return m;
}

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const normalize = (a) => scale(a, 1 / Math.hypot(a[0], a[1], a[2]));

function lookAt(eye, target, up) {
  const z = normalize(sub(eye, target));
  const x = normalize(cross(up, z));
  const y = cross(z, x);
  return new Float32Array([x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0,
                           -dot(x, eye), -dot(y, eye), -dot(z, eye), 1]);
}

function multiply(a, b) {
  const m = new Float32Array(16);
  for (let c = 0; c < 4; ++c)
    for (let r = 0; r < 4; ++r) {
      let s = 0;
      for (let k = 0; k < 4; ++k) s += a[k * 4 + r] * b[c * 4 + k];
      m[c * 4 + r] = s;
    }
  return m;
}

function invert(m) {
  // cofactor expansion (double precision in JS numbers)
  const inv = new Array(16);
  inv[0] = m[5]*m[10]*m[15] - m[5]*m[11]*m[14] - m[9]*m[6]*m[15] + m[9]*m[7]*m[14] + m[13]*m[6]*m[11] - m[13]*m[7]*m[10];
  inv[4] = -m[4]*m[10]*m[15] + m[4]*m[11]*m[14] + m[8]*m[6]*m[15] - m[8]*m[7]*m[14] - m[12]*m[6]*m[11] + m[12]*m[7]*m[10];
  inv[8] = m[4]*m[9]*m[15] - m[4]*m[11]*m[13] - m[8]*m[5]*m[15] + m[8]*m[7]*m[13] + m[12]*m[5]*m[11] - m[12]*m[7]*m[9];
  inv[12] = -m[4]*m[9]*m[14] + m[4]*m[10]*m[13] + m[8]*m[5]*m[14] - m[8]*m[6]*m[13] - m[12]*m[5]*m[10] + m[12]*m[6]*m[9];
  inv[1] = -m[1]*m[10]*m[15] + m[1]*m[11]*m[14] + m[9]*m[2]*m[15] - m[9]*m[3]*m[14] - m[13]*m[2]*m[11] + m[13]*m[3]*m[10];
  inv[5] = m[0]*m[10]*m[15] - m[0]*m[11]*m[14] - m[8]*m[2]*m[15] + m[8]*m[3]*m[14] + m[12]*m[2]*m[11] - m[12]*m[3]*m[10];
  inv[9] = -m[0]*m[9]*m[15] + m[0]*m[11]*m[13] + m[8]*m[1]*m[15] - m[8]*m[3]*m[13] - m[12]*m[1]*m[11] + m[12]*m[3]*m[9];
  inv[13] = m[0]*m[9]*m[14] - m[0]*m[10]*m[13] - m[8]*m[1]*m[14] + m[8]*m[2]*m[13] + m[12]*m[1]*m[10] - m[12]*m[2]*m[9];
  inv[2] = m[1]*m[6]*m[15] - m[1]*m[7]*m[14] - m[5]*m[2]*m[15] + m[5]*m[3]*m[14] + m[13]*m[2]*m[7] - m[13]*m[3]*m[6];
  inv[6] = -m[0]*m[6]*m[15] + m[0]*m[7]*m[14] + m[4]*m[2]*m[15] - m[4]*m[3]*m[14] - m[12]*m[2]*m[7] + m[12]*m[3]*m[6];
  inv[10] = m[0]*m[5]*m[15] - m[0]*m[7]*m[13] - m[4]*m[1]*m[15] + m[4]*m[3]*m[13] + m[12]*m[1]*m[7] - m[12]*m[3]*m[5];
  inv[14] = -m[0]*m[5]*m[14] + m[0]*m[6]*m[13] + m[4]*m[1]*m[14] - m[4]*m[2]*m[13] - m[12]*m[1]*m[6] + m[12]*m[2]*m[5];
  inv[3] = -m[1]*m[6]*m[11] + m[1]*m[7]*m[10] + m[5]*m[2]*m[11] - m[5]*m[3]*m[10] - m[9]*m[2]*m[7] + m[9]*m[3]*m[6];
  inv[7] = m[0]*m[6]*m[11] - m[0]*m[7]*m[10] - m[4]*m[2]*m[11] + m[4]*m[3]*m[10] + m[8]*m[2]*m[7] - m[8]*m[3]*m[6];
  inv[11] = -m[0]*m[5]*m[11] + m[0]*m[7]*m[9] + m[4]*m[1]*m[11] - m[4]*m[3]*m[9] - m[8]*m[1]*m[7] + m[8]*m[3]*m[5];
  inv[15] = m[0]*m[5]*m[10] - m[0]*m[6]*m[9] - m[4]*m[1]*m[10] + m[4]*m[2]*m[9] + m[8]*m[1]*m[6] - m[8]*m[2]*m[5];
  const det = m[0] * inv[0] + m[1] * inv[4] + m[2] * inv[8] + m[3] * inv[12];
  return inv.map((value) => value / det);
}

function transform(m, p) {
  const x = m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12];
  const y = m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13];
  const z = m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14];
  const w = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
  return [x / w, y / w, z / w, w];
}

function compile(gl, vertexSource, fragmentSource) {
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, vertexSource], [gl.FRAGMENT_SHADER, fragmentSource]]) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader));
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
  return program;
}

// === The camera: an eye and a target, moved as an orbit about the target or as a walk.

export class Camera {
  constructor(eye, target, fovDeg) {
    this.eye = eye.slice();
    this.target = target.slice();
    this.up = [0, 0, 1];
    this.fov = (fovDeg * Math.PI) / 180;
  }
  // turns the eye about the target (orbit) or the target about the eye (walk's look).
  rotate(dx, dy, aroundTarget) {
    const centre = aroundTarget ? this.target : this.eye;
    const moving = aroundTarget ? this.eye : this.target;
    const offset = sub(moving, centre);
    const radius = Math.hypot(...offset);
    let azimuth = Math.atan2(offset[1], offset[0]);
    let elevation = Math.asin(Math.max(-1, Math.min(1, offset[2] / radius)));
    // orbit: dragging right or down swings the eye left or up; walk: the view follows the drag.
    const sign = aroundTarget ? -1 : 1;
    azimuth += sign * dx * 0.008;
    elevation = Math.max(-1.5, Math.min(1.5, elevation - sign * dy * 0.008));
    const moved = add(centre, scale([Math.cos(elevation) * Math.cos(azimuth),
                                     Math.cos(elevation) * Math.sin(azimuth), Math.sin(elevation)], radius));
    if (aroundTarget) this.eye = moved; else this.target = moved;
  }
  // moves eye and target together: forward along the view (level), right, and up.
  walk(forward, right, up) {
    const view = sub(this.target, this.eye);
    const ahead = normalize([view[0], view[1], 0]);
    const side = normalize(cross(ahead, [0, 0, 1]));
    const step = add(add(scale(ahead, forward), scale(side, right)), [0, 0, up]);
    this.eye = add(this.eye, step);
    this.target = add(this.target, step);
  }
  // moves the eye toward the target (orbit zoom), never through it.
  zoom(factor) {
    const offset = sub(this.eye, this.target);
    const distance = Math.max(0.2, Math.hypot(...offset) * factor);
    this.eye = add(this.target, scale(normalize(offset), distance));
  }
  pan(dx, dy) {
    const view = normalize(sub(this.target, this.eye));
    const right = normalize(cross(view, this.up));
    const up = cross(right, view);
    const distance = Math.hypot(...sub(this.target, this.eye));
    const step = add(scale(right, -dx * distance * 0.0015), scale(up, dy * distance * 0.0015));
    this.eye = add(this.eye, step);
    this.target = add(this.target, step);
  }
}

// === The viewer

export class Viewer {
  constructor(canvas, mesh, camera) {
    this.canvas = canvas;
    this.mesh = mesh;
    this.camera = camera;
    this.exposure = 1;
    this.isolux = false;
    this.lamps = [];
    this.selectedLamp = null;
    const gl = canvas.getContext('webgl2', {antialias: true, preserveDrawingBuffer: true});
    if (!gl) throw new Error('this browser has no WebGL 2');
    this.gl = gl;
    this.main = compile(gl, MAIN_VERTEX, MAIN_FRAGMENT);
    this.ids = compile(gl, ID_VERTEX, ID_FRAGMENT);
    this.lines = compile(gl, LINE_VERTEX, LINE_FRAGMENT);
    this.buildMeshBuffers();
    this.idDirty = true;
  }

  buildMeshBuffers() {
    const gl = this.gl;
    const mesh = this.mesh;
    const buffer = (data, target = gl.ARRAY_BUFFER, usage = gl.STATIC_DRAW) => {
      const b = gl.createBuffer();
      gl.bindBuffer(target, b);
      gl.bufferData(target, data, usage);
      return b;
    };
    this.positionBuffer = buffer(mesh.positions);
    this.indexBuffer = buffer(mesh.indices, gl.ELEMENT_ARRAY_BUFFER);
    this.luminanceBuffer = buffer(new Float32Array(mesh.vertices * 3), gl.ARRAY_BUFFER, gl.DYNAMIC_DRAW);
    this.luxBuffer = buffer(new Float32Array(mesh.vertices), gl.ARRAY_BUFFER, gl.DYNAMIC_DRAW);
    // The ID buffer's geometry: every triangle's own three corners carrying its patch
    // number + 1 in 24 bits (0 is the background).
    const corners = new Float32Array(mesh.triangles * 9);
    const ids = new Uint8Array(mesh.triangles * 9);
    for (let t = 0; t < mesh.triangles; ++t) {
      const id = mesh.trianglePatch[t] + 1;
      for (let c = 0; c < 3; ++c) {
        const v = mesh.indices[t * 3 + c];
        corners.set(mesh.positions.subarray(v * 3, v * 3 + 3), (t * 3 + c) * 3);
        ids.set([id & 255, (id >> 8) & 255, (id >> 16) & 255], (t * 3 + c) * 3);
      }
    }
    this.idPositionBuffer = buffer(corners);
    this.idBuffer = buffer(ids);
    this.lineBuffer = gl.createBuffer();
  }

  // uploads relit values: luminance RGB and lux per vertex.
  setRelit(relit) {
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.luminanceBuffer);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, relit.luminance);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.luxBuffer);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, relit.vertexLux);
    this.relit = relit;
  }

  // returns the exposure that maps the 90th percentile of the vertex luminances to 0.8.
  autoExposure() {
    if (!this.relit) return 1;
    const values = [];
    const l = this.relit.luminance;
    for (let i = 0; i < l.length; i += 3) values.push(0.2126 * l[i] + 0.7152 * l[i + 1] + 0.0722 * l[i + 2]);
    values.sort((a, b) => a - b);
    const high = values[Math.floor(values.length * 0.9)] || 1;
    return high > 0 ? 0.8 / high : 1;
  }

  resize() {
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(this.canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(this.canvas.clientHeight * ratio));
    if (this.canvas.width !== width || this.canvas.height !== height) {
      this.canvas.width = width;
      this.canvas.height = height;
      this.idDirty = true;
    }
  }

  viewProjection() {
    const aspect = this.canvas.width / this.canvas.height;
    return multiply(perspective(this.camera.fov, aspect, 0.05, 200),
                    lookAt(this.camera.eye, this.camera.target, this.camera.up));
  }

  attribute(program, name, buffer, size, type = this.gl.FLOAT, normalized = false) {
    const gl = this.gl;
    const location = gl.getAttribLocation(program, name);
    if (location < 0) return;
    gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
    gl.enableVertexAttribArray(location);
    gl.vertexAttribPointer(location, size, type, normalized, 0, 0);
  }

  disableAttributes() {
    for (let i = 0; i < 4; ++i) this.gl.disableVertexAttribArray(i);
  }

  draw() {
    this.resize();
    const gl = this.gl;
    const viewProjection = this.viewProjection();
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.clearColor(0.12, 0.12, 0.14, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.enable(gl.CULL_FACE);  // faces are counter-clockwise seen from outside
    gl.useProgram(this.main);
    gl.uniformMatrix4fv(gl.getUniformLocation(this.main, 'view_projection'), false, viewProjection);
    gl.uniform1f(gl.getUniformLocation(this.main, 'exposure'), this.exposure);
    gl.uniform1i(gl.getUniformLocation(this.main, 'isolux'), this.isolux ? 1 : 0);
    this.disableAttributes();
    this.attribute(this.main, 'position', this.positionBuffer, 3);
    this.attribute(this.main, 'luminance', this.luminanceBuffer, 3);
    this.attribute(this.main, 'lux', this.luxBuffer, 1);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indexBuffer);
    gl.drawElements(gl.TRIANGLES, this.mesh.triangles * 3, gl.UNSIGNED_INT, 0);
    this.drawLamps(viewProjection);
    this.idDirty = true;
  }

  // lamps as points, each with its axis as a line 0.6 m long; the selected one in yellow.
  drawLamps(viewProjection) {
    const gl = this.gl;
    const data = [];
    for (const lamp of this.lamps) {
      if (lamp.kind !== 'point') continue;
      const tint = lamp.name === this.selectedLamp ? [1, 0.9, 0.1] : [0.9, 0.9, 0.9];
      const tip = add(lamp.position, scale(lamp.axis, 0.6));
      data.push(...lamp.position, ...tint, ...tip, ...tint);
    }
    if (data.length === 0) return;
    gl.disable(gl.DEPTH_TEST);
    gl.useProgram(this.lines);
    gl.uniformMatrix4fv(gl.getUniformLocation(this.lines, 'view_projection'), false, viewProjection);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.lineBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(data), gl.DYNAMIC_DRAW);
    this.disableAttributes();
    for (const [name, offset] of [['position', 0], ['tint', 12]]) {
      const location = gl.getAttribLocation(this.lines, name);
      gl.enableVertexAttribArray(location);
      gl.vertexAttribPointer(location, 3, gl.FLOAT, false, 24, offset);
    }
    const count = data.length / 6;
    gl.drawArrays(gl.LINES, 0, count);
    const points = [];
    for (let i = 0; i < count; i += 2) points.push(i);
    for (const first of points) gl.drawArrays(gl.POINTS, first, 1);
    gl.enable(gl.DEPTH_TEST);
  }

  // renders patch numbers into the offscreen ID framebuffer (section 4.2).
  renderIds() {
    const gl = this.gl;
    const width = this.canvas.width, height = this.canvas.height;
    if (!this.idFramebuffer || this.idWidth !== width || this.idHeight !== height) {
      if (this.idFramebuffer) {
        gl.deleteFramebuffer(this.idFramebuffer);
        gl.deleteRenderbuffer(this.idColour);
        gl.deleteRenderbuffer(this.idDepth);
      }
      this.idFramebuffer = gl.createFramebuffer();
      this.idColour = gl.createRenderbuffer();
      this.idDepth = gl.createRenderbuffer();
      gl.bindRenderbuffer(gl.RENDERBUFFER, this.idColour);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.RGBA8, width, height);
      gl.bindRenderbuffer(gl.RENDERBUFFER, this.idDepth);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, width, height);
      gl.bindFramebuffer(gl.FRAMEBUFFER, this.idFramebuffer);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, this.idColour);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, this.idDepth);
      this.idWidth = width;
      this.idHeight = height;
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.idFramebuffer);
    gl.viewport(0, 0, width, height);
    gl.disable(gl.DITHER);
    gl.disable(gl.BLEND);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.enable(gl.CULL_FACE);
    gl.useProgram(this.ids);
    gl.uniformMatrix4fv(gl.getUniformLocation(this.ids, 'view_projection'), false, this.viewProjection());
    this.disableAttributes();
    this.attribute(this.ids, 'position', this.idPositionBuffer, 3);
    this.attribute(this.ids, 'id', this.idBuffer, 3, gl.UNSIGNED_BYTE, true);
    gl.drawArrays(gl.TRIANGLES, 0, this.mesh.triangles * 3);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    this.idDirty = false;
  }

  // returns the patch under canvas CSS pixel (x, y) and the point of its plane there, by
  // the ID buffer and the inverse perspective transformation (section 4.2), or null.
  pick(x, y) {
    const gl = this.gl;
    const ratio = this.canvas.width / this.canvas.clientWidth;
    const px = Math.floor(x * ratio), py = Math.floor(y * ratio);
    if (px < 0 || py < 0 || px >= this.canvas.width || py >= this.canvas.height) return null;
    if (this.idDirty) this.renderIds();
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.idFramebuffer);
    const pixel = new Uint8Array(4);
    gl.readPixels(px, this.canvas.height - 1 - py, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    const id = pixel[0] + pixel[1] * 256 + pixel[2] * 65536;
    if (id === 0) return null;
    const patch = id - 1;
    // The pixel's ray: unproject its centre at the near and far planes.
    const inverse = invert(this.viewProjection());
    const ndcX = ((px + 0.5) / this.canvas.width) * 2 - 1;
    const ndcY = 1 - ((py + 0.5) / this.canvas.height) * 2;
    const near = transform(inverse, [ndcX, ndcY, -1]);
    const far = transform(inverse, [ndcX, ndcY, 1]);
    const direction = sub(far, near);
    const frame = this.mesh.patchFrames.subarray(patch * 6, patch * 6 + 6);
    const centre = [frame[0], frame[1], frame[2]], normal = [frame[3], frame[4], frame[5]];
    const denominator = dot(direction, normal);
    const t = Math.abs(denominator) > 1e-12 ? dot(sub(centre, near), normal) / denominator : 0;
    return {patch, point: add(near.slice(0, 3), scale(direction, t))};
  }

  // returns the CSS pixel of world point p, or null when it is behind the eye.
  project(p) {
    const clip = transform(this.viewProjection(), p);
    if (clip[3] <= 0) return null;
    return [((clip[0] + 1) / 2) * this.canvas.clientWidth, ((1 - clip[1]) / 2) * this.canvas.clientHeight];
  }
}
