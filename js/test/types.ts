// Compiled by `make typecheck-js` (tsc --noEmit --strict): the declarations of src/dggs.d.ts as a user meets them.
import * as dggs from "../src/dggs.js";

async function main(): Promise<void> {
  const api: dggs.Dggs = await dggs.init();
  const s: string = api.latLngToCell(48.85, 2.35, 10);
  const b: bigint = dggs.latLngToCell(48.85, 2.35, 10, { asBigInt: true, projection: "IVEA" });
  const [lat, lng]: [number, number] = dggs.cellToLatLng(s);
  const ring: [number, number][] = dggs.cellToBoundary(b, { densify: 2 });
  const parent: string = dggs.cellToParent(s);
  const parentId: bigint = dggs.cellToParent(b, 3);
  const kids: string[] = dggs.cellToChildren(s, 12, { maxCells: 100 });
  const disk: bigint[] = dggs.gridDisk(b, 2);
  const ids: BigUint64Array = dggs.latLngToCells(new Float64Array([lat]), new Float64Array([lng]), 17);
  const centres: Float64Array = dggs.cellsToLatLngs(ids);
  const rings: Float64Array = dggs.cellsToBoundaries(ids, { densify: 1 });
  const compact: BigUint64Array = dggs.compactCells(ids);
  const strings: string[] = dggs.uncompactCells(kids, 13);
  const filled: string[] = dggs.polygonToCells([[[40, 0], [50, 0], [50, 10]]], 5, { mode: "overlaps" });
  const filledIds: BigUint64Array = dggs.polygonToCells([[[0, 40], [0, 50], [10, 50]]], 5, { geoJson: true, asBigInt: true });
  const ok: boolean = dggs.isValidCell("C401") && dggs.getLevel(s) === 10 && dggs.getFace(b) >= 0;
  const area: number = dggs.cellArea(s, "km^2") + dggs.cellArea(17) + dggs.getNumCells(3) + dggs.gridDistance(s, s);
  try {
    dggs.cellToLatLng("X");
  } catch (e) {
    if (e instanceof dggs.DggsError) console.log(e.code, e.errorName);
  }
  console.log(parent, parentId, disk, centres, rings, compact, strings, filled, filledIds, ok, area, ring);
}

void main();
