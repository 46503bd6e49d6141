// The map's cells drawn from their ids: a MapLibre custom layer (CustomLayerInterface) that draws every cell from
// typed arrays, with no GeoJSON, no worker and no tiling. The cells are triangles (3 corners, map_densify's
// points on each edge), so each is drawn as a fan of triangles from its centre to its outline; the outline comes
// from the grid's WebAssembly core (cellsToBoundaries) in batches, as the server's GeoJSON polygons have it.
//
// The vertices are longitude/latitude (float32) and the shader puts them on MapLibre's unit sphere itself
// (x = sin(lng) cos(lat), y = sin(lat), z = cos(lng) cos(lat), the frame of MapLibre's projectToSphere), then
// hands them to MapLibre's own projection code (render's options.shaderData: the vertex shader prelude, with
// interpolateProjection on the globe and projectTile on the flat map; options.defaultProjectionData: its
// uniforms, "custom layer globe" in MapLibre's docs). In 3D nothing is special at the poles (a pole is the point
// (0, +-1, 0) whatever its longitude, and a cell round a pole is a fan round it) nor at the antimeridian (a
// cell's longitudes are unwrapped round its centre, sin and cos do the rest; the flat map, beyond the zoom where
// the globe turns flat, draws them in the next world copy, as MapLibre does unwrapped GeoJSON).
//
// A fan's triangles are chords of the sphere: a big cell's (levels 0-5) are cut into smaller ones (their points
// put back on the sphere) until no edge spans more than MAX_CHORD_DEG, so that the sphere bulges less than 1/6500
// of its radius between points (1 - cos 1 degree), under a pixel of the whole globe.
//
// The values are a vertex attribute too; the colour classes are uniforms (the breaks and colours of MapLibre's
// 'step' of app.js), so that a new classing recolours the cells with no new buffers. Each buffer chunk holds
// under 65,536 vertices (16-bit indices) and is one draw call; 1M level-10 cells (9 points an outline: 10 vertices
// of 12 bytes, 27 indices for the fan and 3 for the corners' triangle a cell) are 180 bytes a cell on the GPU.

const MAX_CHORD_DEG = 2;
const MAX_VERTICES = 65536;
const MAX_BREAKS = 6; // app.js's RAMP has 7 colours: 6 breaks at most
const NO_VALUE = -Infinity; // a cell without a value (NaN in map/cells' values)
const DEG = Math.PI / 180;
const BATCH = 16384;
const CORNERS_ONLY_PX = 6; // below this width on the screen a cell is drawn as its corners' triangle // cells a WebAssembly call; the build yields to the page between batches

const VERTEX_SHADER = (prelude, define) => `#version 300 es
precision highp float;
${prelude}
${define}
in vec2 a_lnglat;
in float a_value;
uniform float u_breaks[${MAX_BREAKS}];
uniform int u_break_count;
uniform vec4 u_colours[${MAX_BREAKS + 1}];
uniform vec4 u_no_value;
uniform vec4 u_fixed;   // a fixed colour (the selected cell's outline) where its alpha > 0
flat out vec4 v_colour;
const float DEG = ${DEG};
void main() {
  float lng = a_lnglat.x * DEG;
  float lat = a_lnglat.y * DEG;
  // Web Mercator of the point, 0..1 a world (MapLibre's flat map and its globe's fallback near the poles' limit).
  float clat = clamp(lat, -1.4844222297453324, 1.4844222297453324);
  vec2 merc = vec2(a_lnglat.x / 360.0 + 0.5, 0.5 - log(tan(PI / 4.0 + clat / 2.0)) / (2.0 * PI));
#ifdef GLOBE
  vec3 sphere = vec3(sin(lng) * cos(lat), sin(lat), cos(lng) * cos(lat));
  gl_Position = interpolateProjection(merc, sphere, 0.0);
#else
  gl_Position = projectTile(merc);
#endif
  if (u_fixed.a > 0.0) {
    v_colour = u_fixed;
  } else if (a_value < -3.0e38) {
    v_colour = u_no_value;
  } else {
    int k = 0;
    for (int i = 0; i < ${MAX_BREAKS}; i++) {
      if (i < u_break_count && a_value >= u_breaks[i]) k = i + 1;
    }
    v_colour = u_colours[k];
  }
}`;

const FRAGMENT_SHADER = `#version 300 es
precision highp float;
flat in vec4 v_colour;
out vec4 fragColor;
void main() { fragColor = v_colour; }`;

// '#rrggbb' as premultiplied RGBA with `opacity` (MapLibre blends custom layers with ONE, ONE_MINUS_SRC_ALPHA).
function premultiplied(hex, opacity) {
  const n = parseInt(hex.slice(1), 16);
  return [((n >> 16) & 255) / 255 * opacity, ((n >> 8) & 255) / 255 * opacity, (n & 255) / 255 * opacity, opacity];
}

const wrap180 = (x) => x - 360 * Math.round(x / 360);

// One cell from m (lat, lng) pairs of `pts` at `at`: its centre on the unit sphere (the normalised sum of its
// three corners, the outline's points 0, m/3 and 2m/3), the longitude its vertices unwrap round (the centre's),
// and its fan triangles' subdivisions `s` (from the corners: the spokes to them, and a side's length over the
// points on it); cell.vertices and cell.indices are what its fan needs. Only a cell to be cut up (s > 1, levels
// 0-5) has its whole outline put on the sphere (cell.ring).
function measureCell(pts, at, m, cell) {
  const xyz = cell.ring;
  const third = m / 3;
  let cx = 0;
  let cy = 0;
  let cz = 0;
  const corner = cell.corner;
  for (let c = 0; c < 3; c += 1) {
    const lat = pts[at + 2 * c * third] * DEG;
    const lng = pts[at + 2 * c * third + 1] * DEG;
    const cl = Math.cos(lat);
    corner[3 * c] = Math.sin(lng) * cl;
    corner[3 * c + 1] = Math.sin(lat);
    corner[3 * c + 2] = Math.cos(lng) * cl;
    cx += corner[3 * c];
    cy += corner[3 * c + 1];
    cz += corner[3 * c + 2];
  }
  const norm = Math.hypot(cx, cy, cz);
  cx /= norm;
  cy /= norm;
  cz /= norm;
  const lng0 = Math.atan2(cx, cz) / DEG;
  let widest = 0; // the widest angle (degrees) of a spoke or of an outline's side between two points
  for (let c = 0; c < 3; c += 1) {
    const d = (c + 1) % 3;
    const spoke = cx * corner[3 * c] + cy * corner[3 * c + 1] + cz * corner[3 * c + 2];
    const side = corner[3 * c] * corner[3 * d] + corner[3 * c + 1] * corner[3 * d + 1] + corner[3 * c + 2] * corner[3 * d + 2];
    widest = Math.max(widest, Math.acos(Math.min(1, spoke)) / DEG, Math.acos(Math.min(1, side)) / DEG / third);
  }
  // 1.5: the outline's points off the corners' chords (up to 4.5 % of a cell's width, levels 4-10) may make a
  // spoke to one of them longer than to the corners.
  const s = Math.max(1, Math.ceil((1.5 * widest) / MAX_CHORD_DEG));
  if (s > 1) {
    for (let k = 0; k < m; k += 1) {
      const lat = pts[at + 2 * k] * DEG;
      const lng = pts[at + 2 * k + 1] * DEG;
      const cl = Math.cos(lat);
      xyz[3 * k] = Math.sin(lng) * cl;
      xyz[3 * k + 1] = Math.sin(lat);
      xyz[3 * k + 2] = Math.cos(lng) * cl;
    }
  }
  const vertices = s === 1 ? m + 1 : m * (((s + 1) * (s + 2)) / 2);
  Object.assign(cell, { pts, at, cx, cy, cz, lng0, s, vertices, indices: 3 * m * s * s });
}

// Appends the fan of the cell measureCell() measured to the chunk `out`, each vertex with `value`.
function emitCell(cell, m, value, out) {
  const { ring: xyz, cx, cy, cz, lng0, s } = cell;
  const { lnglat, index } = out;
  const v0 = out.vertices;
  let iv = out.vertices;
  let ii = out.indices;
  const put = (x, y, z) => { // a point of the sphere (normalised here) as lng (unwrapped round lng0), lat
    const r = Math.hypot(x, y, z);
    const lat = Math.asin(Math.max(-1, Math.min(1, y / r))) / DEG;
    const lng = Math.abs(lat) === 90 ? lng0 : lng0 + wrap180(Math.atan2(x, z) / DEG - lng0);
    lnglat[3 * iv] = lng;
    lnglat[3 * iv + 1] = lat;
    lnglat[3 * iv + 2] = value;
    iv += 1;
  };
  if (s === 1) {
    put(cx, cy, cz);
    const { pts, at } = cell;
    for (let k = 0; k < m; k += 1) { // the outline's points as the core gives them, unwrapped round lng0
      const lat = pts[at + 2 * k];
      lnglat[3 * iv] = Math.abs(lat) === 90 ? lng0 : lng0 + wrap180(pts[at + 2 * k + 1] - lng0);
      lnglat[3 * iv + 1] = lat;
      lnglat[3 * iv + 2] = value;
      iv += 1;
    }
    for (let k = 0; k < m; k += 1) {
      index[ii] = v0;
      index[ii + 1] = v0 + 1 + k;
      index[ii + 2] = v0 + 1 + ((k + 1) % m);
      ii += 3;
    }
    // Its corners as one triangle (the outline's points 0, m/3 and 2m/3), drawn instead of the fan where a cell
    // is a few pixels wide (CellsLayer.render).
    const { corners } = out;
    corners[out.cornerCount] = v0 + 1;
    corners[out.cornerCount + 1] = v0 + 1 + m / 3;
    corners[out.cornerCount + 2] = v0 + 1 + (2 * m) / 3;
    out.cornerCount += 3;
  } else {
    // Each fan triangle (centre, ring k, ring k+1) as a barycentric grid of s steps a side.
    for (let k = 0; k < m; k += 1) {
      const j = (k + 1) % m;
      const base = iv;
      for (let a = 0; a <= s; a += 1) { // a steps from the centre towards the ring
        for (let b = 0; b <= a; b += 1) { // b of them towards ring j
          const wc = (s - a) / s;
          const wj = b / s;
          const wk = (a - b) / s;
          put(wc * cx + wk * xyz[3 * k] + wj * xyz[3 * j], wc * cy + wk * xyz[3 * k + 1] + wj * xyz[3 * j + 1],
            wc * cz + wk * xyz[3 * k + 2] + wj * xyz[3 * j + 2]);
        }
      }
      const row = (a) => base + (a * (a + 1)) / 2; // first vertex of row a
      for (let a = 0; a < s; a += 1) {
        for (let b = 0; b <= a; b += 1) {
          index[ii] = row(a) + b;
          index[ii + 1] = row(a + 1) + b;
          index[ii + 2] = row(a + 1) + b + 1;
          ii += 3;
          if (b < a) {
            index[ii] = row(a) + b;
            index[ii + 1] = row(a + 1) + b + 1;
            index[ii + 2] = row(a) + b + 1;
            ii += 3;
          }
        }
      }
    }
  }
  out.vertices = iv;
  out.indices = ii;
}

// The cells' triangles as one Float32Array of (lng, lat, value) vertices and one Uint16Array of indices a chunk,
// built from ids (BigUint64Array) and values (Float64Array, NaN: none) with the WebAssembly core `core`, `densify`
// points an edge, in `projection`. An async generator yielding each chunk as it is full, and between WebAssembly
// batches, so that the page stays live while a million cells are built.
export async function* cellChunks(core, ids, values, { densify, projection }) {
  const m = 3 * (densify + 1);
  const fresh = () => ({
    lnglat: new Float32Array(3 * MAX_VERTICES), index: new Uint16Array(6 * MAX_VERTICES),
    corners: new Uint16Array(MAX_VERTICES), vertices: 0, indices: 0, cornerCount: 0, cells: 0, first: 0, fans: true,
  });
  let out = fresh();
  const cell = { ring: new Float64Array(3 * m), corner: new Float64Array(9) };
  const done = (chunk) => ({
    lnglat: chunk.lnglat.slice(0, 3 * chunk.vertices), index: chunk.index.slice(0, chunk.indices),
    // Each cell's corners as one triangle, where every cell of the chunk is one fan (none cut up).
    corners: chunk.fans ? chunk.corners.slice(0, chunk.cornerCount) : null,
    first: chunk.first, cells: chunk.cells,
  });
  for (let from = 0; from < ids.length; from += BATCH) {
    const batch = ids.subarray(from, Math.min(ids.length, from + BATCH));
    const pts = core.cellsToBoundaries(batch, { densify, projection });
    for (let i = 0; i < batch.length; i += 1) {
      const value = values ? values[from + i] : NaN;
      const v = Number.isNaN(value) ? NO_VALUE : value;
      measureCell(pts, 2 * m * i, m, cell);
      if (out.vertices + cell.vertices > MAX_VERTICES || out.indices + cell.indices > out.index.length) {
        yield done(out);
        out = fresh();
        out.first = from + i;
      }
      emitCell(cell, m, v, out);
      out.fans &&= cell.s === 1;
      out.cells += 1;
    }
    await new Promise((resolve) => { setTimeout(resolve, 0); });
  }
  if (out.cells) yield done(out);
}

// The layer. setCells() builds the buffers (resolving once all are on the GPU), setClasses() recolours,
// pick() finds the cell at a point, select() outlines one.

// The bound vertex buffer's layout, 12 bytes a vertex: attribute 0 the (lng, lat) float32 pair, attribute 1 the
// cell's value (one vertex array for the fans, one for the corners' triangles, over the same buffer).
function vertexLayout(gl) {
  gl.enableVertexAttribArray(0);
  gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 12, 0);
  gl.enableVertexAttribArray(1);
  gl.vertexAttribPointer(1, 1, gl.FLOAT, false, 12, 8);
}
export class CellsLayer {
  // onError(err): called once if the layer cannot draw (its shaders do not compile or link here); it draws nothing
  // after that.
  constructor(id = 'cells-ids', { opacity = 0.8, noValueColour = '#8b949e', onError = null } = {}) {
    this.onError = onError;
    this.failed = null;
    this.id = id;
    this.type = 'custom';
    this.renderingMode = '2d';
    this.opacity = opacity;
    this.noValue = premultiplied(noValueColour, opacity);
    this.chunks = [];       // {vao, buffers, count} on the GPU
    this.breaks = [];
    this.colours = [premultiplied('#ffffb2', opacity)];
    this.programs = new Map(); // by MapLibre's shader variant
    this.cells = null;      // {ids, counts, values, level, densify, projection, sorted, order}
    this.selected = null;   // {vao, buffer, count}: the selected cell's outline
    this.generation = 0;    // the latest setCells(); older builds stop
    this.stats = { cells: 0, vertices: 0, indices: 0, chunks: 0, buildMs: 0 };
  }

  onAdd(map, gl) {
    this.map = map;
    this.gl = gl;
  }

  onRemove() {
    this.clear();
    this.select(null, null);
    for (const { program } of this.programs.values()) this.gl.deleteProgram(program);
    this.programs.clear();
  }

  clear() {
    const { gl } = this;
    this.chunks.forEach((c) => this.release(c));
    this.chunks = [];
  }

  release(c) {
    const { gl } = this;
    gl.deleteVertexArray(c.vao);
    if (c.cornerVao) gl.deleteVertexArray(c.cornerVao);
    c.buffers.forEach((b) => gl.deleteBuffer(b));
  }

  // The program for MapLibre's current projection (its shader prelude differs between the globe and the flat map).
  program(shaderData) {
    const known = this.programs.get(shaderData.variantName);
    if (known) return known;
    const { gl } = this;
    const compile = (type, source) => {
      const shader = gl.createShader(type);
      gl.shaderSource(shader, source);
      gl.compileShader(shader);
      if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`cells shader: ${gl.getShaderInfoLog(shader)}`);
      return shader;
    };
    const program = gl.createProgram();
    gl.attachShader(program, compile(gl.VERTEX_SHADER, VERTEX_SHADER(shaderData.vertexShaderPrelude, shaderData.define)));
    gl.attachShader(program, compile(gl.FRAGMENT_SHADER, FRAGMENT_SHADER));
    gl.bindAttribLocation(program, 0, 'a_lnglat');
    gl.bindAttribLocation(program, 1, 'a_value');
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`cells program: ${gl.getProgramInfoLog(program)}`);
    const names = ['u_projection_matrix', 'u_projection_fallback_matrix', 'u_projection_tile_mercator_coords',
      'u_projection_clipping_plane', 'u_projection_transition', 'u_breaks', 'u_break_count', 'u_colours',
      'u_no_value', 'u_fixed'];
    const u = Object.fromEntries(names.map((n) => [n, gl.getUniformLocation(program, n)]));
    const entry = { program, u };
    this.programs.set(shaderData.variantName, entry);
    return entry;
  }

  upload(chunk) {
    const { gl } = this;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, chunk.lnglat, gl.STATIC_DRAW);
    vertexLayout(gl);
    const ibo = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, chunk.index, gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
    const entry = { vao, buffers: [vbo, ibo], count: chunk.index.length };
    if (chunk.corners) { // a second vertex array: the same vertices, the corners' triangles
      entry.cornerVao = gl.createVertexArray();
      gl.bindVertexArray(entry.cornerVao);
      gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
      vertexLayout(gl);
      const cbo = gl.createBuffer();
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, cbo);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, chunk.corners, gl.STATIC_DRAW);
      gl.bindVertexArray(null);
      gl.bindBuffer(gl.ARRAY_BUFFER, null);
      entry.buffers.push(cbo);
      entry.cornerCount = chunk.corners.length;
    }
    return entry;
  }

  // Draws `ids` (BigUint64Array, one level) with `values` (Float64Array, NaN: none) and `counts` (for pick()).
  // Resolves true once every chunk is on the GPU, false if a newer setCells() came first.
  async setCells(core, ids, { level, densify, projection, values = null, counts = null }) {
    const generation = ++this.generation;
    const t0 = performance.now();
    const built = [];
    const stats = { cells: 0, vertices: 0, indices: 0, chunks: 0, buildMs: 0 };
    for await (const chunk of cellChunks(core, ids, values, { densify, projection })) {
      if (generation !== this.generation) {
        built.forEach((c) => this.release(c));
        return false;
      }
      built.push(this.upload(chunk));
      stats.cells += chunk.cells;
      stats.vertices += chunk.lnglat.length / 3;
      stats.indices += chunk.index.length;
      stats.chunks += 1;
    }
    if (generation !== this.generation) return false;
    this.clear();
    this.chunks = built;
    // A cell's width in radians (the square root of its area), for the fans' level of detail in render().
    const width = Math.sqrt(core.cellArea(level, 'rads^2'));
    this.cells = { ids, counts, values, level, densify, projection, width, sorted: null, order: null };
    stats.buildMs = performance.now() - t0;
    this.stats = stats;
    if (this.map) this.map.triggerRepaint();
    return true;
  }

  // Colour classes as MapLibre's ['step', value, colours[0], breaks[0], colours[1], ...] (app.js's fillColour).
  setClasses(breaks, colours) {
    this.breaks = breaks.slice(0, MAX_BREAKS);
    this.colours = colours.slice(0, MAX_BREAKS + 1).map((c) => premultiplied(c, this.opacity));
    if (this.map) this.map.triggerRepaint();
  }

  // The index of the cell of the map at lng/lat (latLngToCell at the shown level: exact), or -1.
  pick(core, lng, lat) {
    const c = this.cells;
    if (!c || !c.ids.length) return -1;
    if (!c.sorted) { // sorted ids and their places, made at the first pick
      c.order = Uint32Array.from(c.ids.keys()).sort((a, b) => (c.ids[a] < c.ids[b] ? -1 : c.ids[a] > c.ids[b] ? 1 : 0));
      c.sorted = BigUint64Array.from(c.order, (i) => c.ids[i]);
    }
    const id = core.latLngToCell(lat, lng, c.level, { asBigInt: true, projection: c.projection });
    let lo = 0;
    let hi = c.sorted.length;
    while (lo < hi) {
      const mid = (lo + hi) >>> 1;
      if (c.sorted[mid] < id) lo = mid + 1; else hi = mid;
    }
    return lo < c.sorted.length && c.sorted[lo] === id ? c.order[lo] : -1;
  }

  // Outline the cell `id` (BigInt) of the shown level, or none (null).
  select(core, id) {
    const { gl } = this;
    if (this.selected) {
      this.release(this.selected);
      this.selected = null;
    }
    if (id === null || id === undefined || !this.cells) {
      if (this.map) this.map.triggerRepaint();
      return;
    }
    const { densify, projection } = this.cells;
    // The outline with 8 times the points, each pair of neighbours a line (a line loop of points on the sphere).
    const pts = core.cellsToBoundaries(BigUint64Array.of(id), { densify: 8 * (densify + 1) - 1, projection });
    const n = pts.length / 2;
    const lnglat = new Float32Array(3 * n);
    const lng0 = pts[1];
    for (let k = 0; k < n; k += 1) {
      lnglat[3 * k] = lng0 + wrap180(pts[2 * k + 1] - lng0);
      lnglat[3 * k + 1] = pts[2 * k];
    }
    const index = new Uint16Array(2 * n);
    for (let k = 0; k < n; k += 1) {
      index[2 * k] = k;
      index[2 * k + 1] = (k + 1) % n;
    }
    this.selected = this.upload({ lnglat, index });
    if (this.map) this.map.triggerRepaint();
  }

  render(gl, options) {
    if (this.failed || (!this.chunks.length && !this.selected)) return;
    let compiled;
    try {
      compiled = this.program(options.shaderData);
    } catch (err) {
      this.failed = err;
      if (this.onError) setTimeout(() => this.onError(err), 0); // not inside MapLibre's frame
      return;
    }
    const { program, u } = compiled;
    const p = options.defaultProjectionData;
    gl.useProgram(program);
    gl.uniformMatrix4fv(u.u_projection_matrix, false, Float32Array.from(p.mainMatrix));
    if (u.u_projection_fallback_matrix) gl.uniformMatrix4fv(u.u_projection_fallback_matrix, false, Float32Array.from(p.fallbackMatrix));
    if (u.u_projection_tile_mercator_coords) gl.uniform4f(u.u_projection_tile_mercator_coords, ...p.tileMercatorCoords);
    if (u.u_projection_clipping_plane) gl.uniform4f(u.u_projection_clipping_plane, ...p.clippingPlane);
    if (u.u_projection_transition) gl.uniform1f(u.u_projection_transition, p.projectionTransition);
    const breaks = new Float32Array(MAX_BREAKS);
    breaks.set(this.breaks);
    gl.uniform1fv(u.u_breaks, breaks);
    gl.uniform1i(u.u_break_count, this.breaks.length);
    const colours = new Float32Array(4 * (MAX_BREAKS + 1));
    this.colours.forEach((c, i) => colours.set(c, 4 * i));
    gl.uniform4fv(u.u_colours, colours);
    gl.uniform4fv(u.u_no_value, this.noValue);
    gl.uniform4f(u.u_fixed, 0, 0, 0, 0);
    // Where a cell is under CORNERS_ONLY_PX wide on the screen (the globe's radius in pixels, 512 2^zoom / 2 pi
    // device px, times its width in radians), its corners' triangle replaces its fan: the outline's other points
    // are within 4.5 % of its width of its sides (levels 4-10, measured), a quarter of a pixel, and the GPU draws a ninth of the triangles.
    const radiusPx = (512 * 2 ** this.map.getZoom() * window.devicePixelRatio) / (2 * Math.PI);
    const corners = this.cells && this.cells.width * radiusPx < CORNERS_ONLY_PX;
    this.drawnCorners = corners;
    for (const c of this.chunks) {
      if (corners && c.cornerVao) {
        gl.bindVertexArray(c.cornerVao);
        gl.drawElements(gl.TRIANGLES, c.cornerCount, gl.UNSIGNED_SHORT, 0);
      } else {
        gl.bindVertexArray(c.vao);
        gl.drawElements(gl.TRIANGLES, c.count, gl.UNSIGNED_SHORT, 0);
      }
    }
    if (this.selected) {
      gl.uniform4f(u.u_fixed, 1, 1, 1, 1);
      gl.bindVertexArray(this.selected.vao);
      gl.drawElements(gl.LINES, this.selected.count, gl.UNSIGNED_SHORT, 0);
    }
    gl.bindVertexArray(null);
  }
}
