// SPDX-License-Identifier: MIT
// Manifold's floating-point Minkowski sum (npm package manifold-3d, its
// WebAssembly build) on two triangle OFF files, as a benchmark peer; run by
// bench/manifold_peer.py, which installs the package (outside the source
// tree) and checks the output exactly.
//
// usage: node bench/manifold_peer.mjs MODULE_DIR A.off B.off ROUNDS [OUT.off]
//   MODULE_DIR  a directory whose node_modules holds manifold-3d
//   ROUNDS      how many times the sum is timed; the minimum is reported
//   OUT.off     where to write the last round's result, each float32
//               coordinate exactly (as m/2^k), for an exact check
// Prints one JSON object: the wall and CPU times (ms) and Manifold's own account of its
// result (status, vertex and triangle counts, genus, volume).
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { performance } from 'node:perf_hooks';
import { pathToFileURL } from 'node:url';

// The numbers of an OFF file, comments dropped; p/q and decimals become
// the nearest doubles (Manifold rounds them to float32 anyway).
function readOff(path) {
  const tokens = readFileSync(path, 'utf8').split('\n').map((line) => line.replace(/#.*/, ''))
    .join(' ').split(/\s+/).filter((t) => t.length > 0);
  if (tokens.shift() !== 'OFF') throw new Error(`${path}: not an OFF file`);
  const number = (t) => {
    const slash = t.indexOf('/');
    return slash < 0 ? Number(t) : Number(t.slice(0, slash)) / Number(t.slice(slash + 1));
  };
  const [nv, nf] = [Number(tokens[0]), Number(tokens[1])];
  let at = 3;
  const positions = new Float32Array(3 * nv);
  for (let i = 0; i < 3 * nv; ++i) positions[i] = number(tokens[at++]);
  const triangles = new Uint32Array(3 * nf);
  for (let f = 0; f < nf; ++f) {
    if (tokens[at++] !== '3') throw new Error(`${path}: face ${f} is not a triangle`);
    for (let k = 0; k < 3; ++k) triangles[3 * f + k] = Number(tokens[at++]);
  }
  return { positions, triangles };
}

// A float32 value exactly, as an integer or m/2^k.
function exactText(x) {
  let m = x;
  let k = 0n;
  while (!Number.isInteger(m)) {
    m *= 2;
    k += 1n;
  }
  return k === 0n ? `${m}` : `${m}/${2n ** k}`;
}

function writeOff(path, mesh) {
  const stride = mesh.numProp;
  const nv = mesh.vertProperties.length / stride;
  const nt = mesh.triVerts.length / 3;
  const lines = ['OFF', `${nv} ${nt} 0`];
  for (let v = 0; v < nv; ++v) {
    const p = [0, 1, 2].map((i) => exactText(mesh.vertProperties[v * stride + i]));
    lines.push(p.join(' '));
  }
  for (let t = 0; t < nt; ++t) lines.push(`3 ${mesh.triVerts[3 * t]} ${mesh.triVerts[3 * t + 1]} ${mesh.triVerts[3 * t + 2]}`);
  writeFileSync(path, lines.join('\n') + '\n');
}

async function main() {
  const [moduleDir, aPath, bPath, roundsText, outPath] = process.argv.slice(2);
  if (!bPath) throw new Error('usage: node manifold_peer.mjs MODULE_DIR A.off B.off ROUNDS [OUT.off]');
  const url = pathToFileURL(join(moduleDir, 'node_modules', 'manifold-3d', 'manifold.js'));
  const Module = (await import(url.href)).default;
  const wasm = await Module();
  wasm.setup();
  const { Manifold, Mesh } = wasm;
  const operand = (path) => {
    const { positions, triangles } = readOff(path);
    const m = new Manifold(new Mesh({ numProp: 3, vertProperties: positions, triVerts: triangles }));
    if (m.status() !== 'NoError') throw new Error(`${path}: Manifold refuses it: ${m.status()}`);
    return m;
  };
  const a = operand(aPath);
  const b = operand(bPath);
  const times = [];
  const cpuTimes = [];
  let sum = null;
  for (let r = 0; r < Number(roundsText || 1); ++r) {
    if (sum) sum.delete();
    const start = performance.now();
    const cpuStart = process.cpuUsage();
    sum = a.minkowskiSum(b);
    sum.numTri();  // the sum is evaluated by now, whatever Manifold defers
    const cpu = process.cpuUsage(cpuStart);
    times.push(performance.now() - start);
    cpuTimes.push((cpu.user + cpu.system) / 1000);
  }
  const result = {
    ms: Math.min(...times),
    cpu_ms: Math.min(...cpuTimes),
    ms_all: times,
    status: sum.status(),
    vertices: sum.numVert(),
    triangles: sum.numTri(),
    genus: sum.genus(),
    volume: sum.volume(),
    empty: sum.isEmpty(),
  };
  if (outPath) writeOff(outPath, sum.getMesh());
  process.stdout.write(JSON.stringify(result) + '\n');
}

main().catch((e) => {
  process.stderr.write(`${e.stack || e}\n`);
  process.exit(1);
});
