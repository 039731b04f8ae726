// Reads an IFC file (2x3, 4, 4x3) with web-ifc for boxlod (toolkit/formats/ifc_io.h),
// which runs it under node in a child process and embeds this file in its
// program. Usage: node - WEB_IFC_FOLDER IFC_FILE; the answer goes to file
// descriptor 3 (web-ifc logs to stdout and stderr): an 8-byte little-endian
// length, a JSON header of that length, then the vertex and index bytes the
// header's pieces point into. On failure the header is {"error": "..."}.
'use strict';
const crypto = require('crypto');
const fs = require('fs');
const Module = require('module');
const path = require('path');
const vm = require('vm');

function answer(header, chunks) {
  const json = Buffer.from(JSON.stringify(header));
  const length = Buffer.alloc(8);
  length.writeBigUInt64LE(BigInt(json.length));
  for (const bytes of [length, json, ...chunks]) {
    for (let done = 0; done < bytes.length;) done += fs.writeSync(3, bytes, done);
  }
}

// The length of the well-formed UTF-8 sequence at bytes[i], 0 if none.
function utf8Sequence(bytes, i) {
  const b = bytes[i], next = (k, low = 0x80, high = 0xbf) => bytes[i + k] >= low && bytes[i + k] <= high;
  if (b < 0x80) return 1;
  if (b >= 0xc2 && b <= 0xdf) return next(1) ? 2 : 0;
  if (b >= 0xe0 && b <= 0xef) {
    const ok = next(1, b === 0xe0 ? 0xa0 : 0x80, b === 0xed ? 0x9f : 0xbf) && next(2);
    return ok ? 3 : 0;
  }
  if (b >= 0xf0 && b <= 0xf4) {
    const ok = next(1, b === 0xf0 ? 0x90 : 0x80, b === 0xf4 ? 0x8f : 0xbf) && next(2) && next(3);
    return ok ? 4 : 0;
  }
  return 0;
}

// The file's bytes as UTF-8: a byte that starts no UTF-8 sequence is read as
// Latin-1, as older exporters wrote names (base/utf8.h; web-ifc would garble
// them, and a name in UTF-8 beside it stays as it is). Byte by byte: a file
// of gigabytes is no JavaScript string.
function utf8OrLatin1(bytes) {
  if (require('buffer').isUtf8(bytes)) return new Uint8Array(bytes);
  let size = 0;
  for (let i = 0; i < bytes.length;) {
    const n = utf8Sequence(bytes, i);
    size += n || 2;
    i += n || 1;
  }
  const out = new Uint8Array(size);
  for (let i = 0, o = 0; i < bytes.length;) {
    const n = utf8Sequence(bytes, i);
    if (n) {
      for (let k = 0; k < n; ++k) out[o++] = bytes[i + k];
      i += n;
    } else {  // U+0080..U+00FF in two bytes
      out[o++] = 0xc0 | (bytes[i] >> 6);
      out[o++] = 0x80 | (bytes[i] & 0x3f);
      i += 1;
    }
  }
  return out;
}

// A lone surrogate (a bad \X2\ escape) as U+FFFD: it would not survive JSON.
const wellFormed = (text) =>
  text.replace(/[\uD800-\uDBFF](?![\uDC00-\uDFFF])|(?<![\uD800-\uDBFF])[\uDC00-\uDFFF]/g, '\uFFFD');

// An entity as a node: its Name, IFC type and GlobalId, under `parent`.
function describe(api, model, id, parent) {
  const line = api.GetLine(model, id);
  const text = (field) =>
    (line && line[field] && typeof line[field].value === 'string' ? wellFormed(line[field].value) : '');
  return {name: text('Name'), type: api.GetNameFromTypeCode(api.GetLineType(model, id)) || '',
          global_id: text('GlobalId'), parent};
}

// Each entity's children in the spatial structure, as web-ifc's
// getSpatialStructure gathers them: IfcRelAggregates, then
// IfcRelContainedInSpatialStructure, each in file order. (Its walk of them
// visits every node twice per level, 2^depth for a deeply nested file.)
function spatialChildren(WebIFC, api, model) {
  const children = new Map();
  for (const [type, relating, related] of [
    [WebIFC.IFCRELAGGREGATES, 'RelatingObject', 'RelatedObjects'],
    [WebIFC.IFCRELCONTAINEDINSPATIALSTRUCTURE, 'RelatingStructure', 'RelatedElements']]) {
    const ids = api.GetLineIDsWithType(model, type, true);
    for (let i = 0; i < ids.size(); ++i) {
      let rel = null;
      try {
        rel = api.GetLine(model, ids.get(i), false);
      } catch (unread) {  // web-ifc's reading of an attribute fails on what it does not expect
        rel = null;
      }
      if (!rel || !rel[relating] || !Array.isArray(rel[related]))
        throw new Error(`#${ids.get(i)}: ${relating} or the list ${related} missing`);
      const from = rel[relating].value;
      if (!children.has(from)) children.set(from, []);
      for (const r of rel[related]) children.get(from).push(r.value);
    }
  }
  return children;
}

// Nodes of the spatial structure (Project > Site > Building > Storey >
// element > its parts), parents first, with names and GlobalIds.
function spatialNodes(WebIFC, api, model) {
  const children = spatialChildren(WebIFC, api, model);
  const projects = api.GetLineIDsWithType(model, WebIFC.IFCPROJECT);
  const nodes = [], indexOf = new Map(), pending = [];
  if (projects.size() > 0)
    pending.push([projects.get(0), -1, 0]);
  else  // not schema-valid, yet read as before: every element under an empty root
    nodes.push({name: '', type: '', global_id: '', parent: -1});
  while (pending.length > 0) {
    const [id, parent, depth] = pending.pop();
    if (indexOf.has(id)) continue;  // an element under two parents stays under the first
    if (depth > 200) throw new Error(`#${id}: spatial relationships nested more than 200 levels deep`);
    indexOf.set(id, nodes.length);
    nodes.push(describe(api, model, id, parent));
    const index = nodes.length - 1, below = children.get(id) || [];
    for (let c = below.length - 1; c >= 0; --c) pending.push([below[c], index, depth + 1]);
  }
  return {nodes, indexOf};
}

const maxCoordinate = 1e9;  // metres, as parameter files' positions (toolkit/lod/lod_parameters.h)

// Each placed geometry in world coordinates (y up, as web-ifc gives them), in
// double, and the bounds of them all (no second pass over the vertices).
function pieces(api, model, nodes, indexOf) {
  const out = [], low = [Infinity, Infinity, Infinity], high = [-Infinity, -Infinity, -Infinity];
  api.StreamAllMeshes(model, (mesh) => {
    let node = indexOf.get(mesh.expressID);
    if (node === undefined) {  // an element outside the spatial structure: under the root
      node = nodes.length;
      indexOf.set(mesh.expressID, node);
      nodes.push(describe(api, model, mesh.expressID, 0));
    }
    for (let g = 0; g < mesh.geometries.size(); ++g) {
      const placed = mesh.geometries.get(g);
      const geometry = api.GetGeometry(model, placed.geometryExpressID);
      const data = api.GetVertexArray(geometry.GetVertexData(), geometry.GetVertexDataSize());
      const indices = new Uint32Array(api.GetIndexArray(geometry.GetIndexData(), geometry.GetIndexDataSize()));
      if (indices.length === 0) {  // web-ifc meshed it to nothing: it neither draws nor keeps its node
        geometry.delete();
        continue;
      }
      const t = placed.flatTransformation;  // column-major 4x4
      const count = data.length / 6;
      const positions = new Float64Array(count * 3), normals = new Float32Array(count * 3);
      for (let v = 0; v < count; ++v) {
        const x = data[v * 6], y = data[v * 6 + 1], z = data[v * 6 + 2];
        const nx = data[v * 6 + 3], ny = data[v * 6 + 4], nz = data[v * 6 + 5];
        for (let r = 0; r < 3; ++r) {
          const p = t[r] * x + t[4 + r] * y + t[8 + r] * z + t[12 + r];
          // Far beyond any map's coordinates, a double no longer holds a building's metres.
          if (!(Math.abs(p) <= maxCoordinate))
            throw new Error(`#${mesh.expressID}: a coordinate of ${p} m, outside [-1e9, 1e9]`);
          positions[v * 3 + r] = p;
          normals[v * 3 + r] = t[r] * nx + t[4 + r] * ny + t[8 + r] * nz;
          if (p < low[r]) low[r] = p;
          if (p > high[r]) high[r] = p;
        }
      }
      geometry.delete();
      const c = placed.color;
      out.push({node, color: [c.x, c.y, c.z, c.w], positions, normals, indices});
    }
  });
  return {placed: out, low, high};
}

// The nodes that draw something, themselves or below them, and the root:
// an IFC file's annotations and spaces (which web-ifc does not mesh) would
// be hundreds of empty leaves. Renumbered in order, parents first.
function drawnNodes(nodes, placed) {
  const keep = new Array(nodes.length).fill(false);
  keep[0] = nodes.length > 0;
  for (const piece of placed)
    for (let n = piece.node; n >= 0 && !keep[n]; n = nodes[n].parent) keep[n] = true;
  const renumbered = [], kept = [];
  nodes.forEach((node, n) => {
    if (!keep[n]) return;
    renumbered[n] = kept.length;
    kept.push({...node, parent: node.parent < 0 ? -1 : renumbered[node.parent]});
  });
  for (const piece of placed) piece.node = renumbered[piece.node];
  return kept;
}

// A model far from its file's origin (a georeferenced one) is moved, in
// double, to the middle of its bounds in whole units, which the answer names
// as its origin; a near one keeps the file's coordinates.
function originOf({placed, low, high}) {
  const middle = low.map((l, r) => (l + high[r]) / 2);
  return placed.length > 0 && Math.hypot(...middle) > 1e4 ? middle.map(Math.round) : [0, 0, 0];
}

function packed(placed, origin) {
  const out = [], chunks = [];
  let offset = 0;
  for (const piece of placed) {
    const positions = new Float32Array(piece.positions.length);
    for (let i = 0; i < positions.length; i += 3)
      for (let r = 0; r < 3; ++r) positions[i + r] = piece.positions[i + r] - origin[r];
    const bytes = [Buffer.from(positions.buffer), Buffer.from(piece.normals.buffer), Buffer.from(piece.indices.buffer)];
    const count = positions.length / 3;
    out.push({node: piece.node, color: piece.color, positions: [offset, count], normals: [offset + bytes[0].length, count],
              indices: [offset + bytes[0].length + bytes[1].length, piece.indices.length]});
    for (const b of bytes) { chunks.push(b); offset += b.length; }
  }
  return {out, chunks};
}

// web-ifc's API is 5.9 MB of JavaScript that V8 takes about 0.3 s to compile
// on each read: compiled once, its code is kept in web-ifc's folder as V8's
// code cache (vm.Script's cachedData), skipped where the folder is read-only.
// V8 checks a cache against its own version and the source's length only, so
// the file starts with a line of the SHA-256 of the source and of the cache
// bytes: a cache of another source, a damaged one, or one V8 rejects (after a
// node upgrade) is made again. Written under a temporary name and renamed, so
// that readers running at once never see half of one; a temporary whose
// reader was killed is removed by the next reader that writes a cache.
const cacheSuffix = '.v8-code-cache', temporaryMark = '.boxlod-tmp';

const sha256 = (bytes) => crypto.createHash('sha256').update(bytes).digest('hex');

function cachedCode(cacheFile, stamp) {
  let bytes;
  try { bytes = fs.readFileSync(cacheFile); } catch (error) { return undefined; }
  const end = bytes.indexOf(10);
  const [named, digest] = end < 0 ? [] : bytes.subarray(0, end).toString().split('|');
  const code = bytes.subarray(end + 1);
  return named === stamp && digest === sha256(code) ? code : undefined;
}

function removeDeadTemporaries(folder, cacheName) {
  for (const name of fs.readdirSync(folder)) {
    if (!name.startsWith(cacheName + temporaryMark)) continue;
    const pid = name.slice(cacheName.length + temporaryMark.length);
    if (!/^[0-9]{1,9}$/.test(pid)) continue;
    try { process.kill(Number(pid), 0); } catch (error) {
      if (error.code === 'ESRCH') try { fs.unlinkSync(path.join(folder, name)); } catch (ignored) { /* gone */ }
    }
  }
}

// web-ifc reports what it cannot read and goes on: a real file gets some
// such lines (the FZK-Haus 16, each naming its face), but some broken
// entities (a relationship without its list) make it report the same line
// for ever. Its printing (console's log and error, taken when it starts) ends
// the read at the 10,000th same line in a row, answering at once: web-ifc's
// C++ catches any exception thrown.
const maxRepeatedErrors = 10000;
function limitWebIfcErrors() {
  let last = '', repeated = 0;
  for (const name of ['log', 'error', 'warn']) {
    const print = console[name].bind(console);
    console[name] = (...args) => {
      const line = String(args[0]);
      repeated = line === last ? repeated + 1 : 1;
      last = line;
      if (repeated >= maxRepeatedErrors && line.startsWith('[WEB-IFC][error]')) {
        answer({error: `it reported ${maxRepeatedErrors} times in a row ${line.slice('[WEB-IFC][error]'.length)}`}, []);
        process.exit(0);
      }
      print(...args);
    };
  }
}

function requireWithCodeCache(folder) {
  const file = path.join(folder, 'web-ifc-api-node.js'), cacheFile = file + cacheSuffix;
  const source = fs.readFileSync(file, 'utf8');
  const stamp = sha256(source), cachedData = cachedCode(cacheFile, stamp);
  const script = new vm.Script(Module.wrap(source), {filename: file, cachedData});
  const module = {exports: {}};
  script.runInThisContext().call(module.exports, module.exports, Module.createRequire(file), module, file, folder);
  const keep = () => {
    if (cachedData !== undefined && !script.cachedDataRejected) return;
    const temporary = `${cacheFile}${temporaryMark}${process.pid}`;
    try {
      fs.accessSync(folder, fs.constants.W_OK);  // before making the cache (tens of milliseconds)
      removeDeadTemporaries(folder, path.basename(cacheFile));
      const code = script.createCachedData();
      fs.writeFileSync(temporary, Buffer.concat([Buffer.from(`${stamp}|${sha256(code)}\n`), code]));
      fs.renameSync(temporary, cacheFile);
    } catch (error) {
      try { fs.unlinkSync(temporary); } catch (ignored) { /* never written */ }
    }
  };
  return {WebIFC: module.exports, keep};
}

(async () => {
  try {
    limitWebIfcErrors();
    const {WebIFC, keep} = requireWithCodeCache(process.argv[2]);
    const api = new WebIFC.IfcAPI();
    await api.Init();
    const model = api.OpenModel(utf8OrLatin1(fs.readFileSync(process.argv[3])), {COORDINATE_TO_ORIGIN: false});
    if (model < 0) throw new Error('web-ifc cannot open it');
    const {nodes, indexOf} = spatialNodes(WebIFC, api, model);
    const meshes = pieces(api, model, nodes, indexOf);
    const origin = originOf(meshes);
    const drawn = drawnNodes(nodes, meshes.placed);
    const {out, chunks} = packed(meshes.placed, origin);
    answer({schema: api.GetModelSchema(model), origin, nodes: drawn, pieces: out}, chunks);
    keep();  // after a read, with the functions it compiled
  } catch (error) {
    answer({error: String(error && error.message ? error.message : error)}, []);
  }
})();
