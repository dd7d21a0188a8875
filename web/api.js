// The server's API (docs/serve.md, "API"): JSON for state, little-endian binary for the
// mesh and the relit values, read straight into typed arrays.

async function check(response) {
  if (!response.ok) {
    let message = response.statusText;
    try {
      message = (await response.json()).error || message;
    } catch (ignored) {}
    throw new Error(`${response.status}: ${message}`);
  }
  return response;
}

async function getJson(path) {
  return (await check(await fetch(path))).json();
}

async function sendJson(method, path, body) {
  const response = await fetch(path, {
    method,
    headers: {'Content-Type': 'application/json'},
    body: JSON.stringify(body),
  });
  return (await check(response)).json();
}

export const getScene = () => getJson('/api/scene');
export const getLights = () => getJson('/api/lights');
export const getLighting = () => getJson('/api/lighting');
export const putLighting = (lighting) => sendJson('PUT', '/api/lighting', lighting);
export const luxAtPatch = (patch) => getJson(`/api/lux?patch=${patch}`);

// The mesh (mesh_payload.h): header of four u32, then positions, triangles, the patch of
// each triangle, patch centres and normals, the object of each patch.
export async function getMesh() {
  const buffer = await (await check(await fetch('/api/mesh'))).arrayBuffer();
  const [vertices, triangles, patches] = new Uint32Array(buffer, 0, 4);
  let offset = 16;
  const take = (Type, count) => {
    const array = new Type(buffer, offset, count);
    offset += count * 4;
    return array;
  };
  return {
    vertices, triangles, patches,
    positions: take(Float32Array, vertices * 3),
    indices: take(Uint32Array, triangles * 3),
    trianglePatch: take(Uint32Array, triangles),
    patchFrames: take(Float32Array, patches * 6),
    patchObject: take(Uint32Array, patches),
  };
}

// The relit values (relit_payload) at byte offset of buffer: luminance RGB per vertex,
// lux per vertex; serverMs, the server's time for the weighted sums (eq. 18).
function relitFrom(buffer, offset, mesh, response) {
  const v = mesh.vertices;
  return {
    luminance: new Float32Array(buffer, offset, v * 3),
    vertexLux: new Float32Array(buffer, offset + v * 12, v),
    serverMs: Number(response.headers.get('X-Relight-Ms')),
  };
}

export async function getRelight(mesh) {
  const response = await check(await fetch('/api/relight'));
  return relitFrom(await response.arrayBuffer(), 0, mesh, response);
}

// An edit answered with the relit values in the same response (?relight=1,
// edited_payload): u32 JSON length, the lamp's JSON padded to 4 bytes, the relit values.
async function sendEdit(path, body, mesh) {
  const response = await check(await fetch(`${path}?relight=1`, {
    method: 'POST',
    headers: {'Content-Type': 'application/json'},
    body: JSON.stringify(body),
  }));
  const buffer = await response.arrayBuffer();
  const length = new Uint32Array(buffer, 0, 1)[0];
  const lamp = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, length)));
  return {lamp, relit: relitFrom(buffer, 4 + Math.ceil(length / 4) * 4, mesh, response)};
}

export const updateLightRelit = (name, changes, mesh) =>
  sendEdit(`/api/lights/${encodeURIComponent(name)}`, changes, mesh);
// Section 4.1: one control point moved; the server updates the weights by eq. (21).
export const moveControlPointRelit = (name, index, candela, mesh) =>
  sendEdit(`/api/lights/${encodeURIComponent(name)}/control`, {index, candela}, mesh);
