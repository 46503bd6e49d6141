// The node half of js/tools/libm/ties.py: node compare.mjs DIR. Reads DIR/trace.bin (trace.c's records) and
// DIR/points.txt; writes DIR/musl.bin (musl's result for each record, float64) and DIR/wasm_cells.txt (the JS
// package's cells of the points, as trace.c's cells.txt).
import { readFileSync, writeFileSync } from "node:fs";

import * as dggs from "../../src/dggs.js";

const dir = process.argv[2];
const { instance } = await WebAssembly.instantiate(readFileSync(`${dir}/musl.wasm`), {});
const buf = readFileSync(`${dir}/trace.bin`);
const view = new DataView(buf.buffer, buf.byteOffset, buf.byteLength);
const n = buf.byteLength / 40;
const out = new Float64Array(n);
for (let k = 0; k < n; k++) {
  const o = 40 * k;
  out[k] = instance.exports.libm(view.getInt32(o, true), view.getFloat64(o + 16, true), view.getFloat64(o + 24, true));
}
writeFileSync(`${dir}/musl.bin`, new Uint8Array(out.buffer));

await dggs.init();
const lines = [];
readFileSync(`${dir}/points.txt`, "utf8").trim().split("\n").forEach((line, i) => {
  const [lat, lng] = line.split(" ").map(Number);
  ["ISEA", "IVEA"].forEach((projection, p) => {
    for (let level = 0; level <= 28; level++) {
      lines.push(`${i} ${p} ${level} ${dggs.latLngToCell(lat, lng, level, { asBigInt: true, projection })}`);
    }
  });
});
writeFileSync(`${dir}/wasm_cells.txt`, lines.join("\n") + "\n");
